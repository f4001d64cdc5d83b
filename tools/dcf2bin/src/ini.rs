//! The INI text of a DCF/EDS (CiA 306 section 4), read line by line so
//! that every section and key keeps the line it came from.
//!
//! Rules (CiA 306 4.1 and what the common readers do):
//! * `[name]` opens a section, `key=value` belongs to the last one; names
//!   compare without regard to case (CiA 306: "not case sensitive").
//! * A line whose first non-blank character is `;` (CiA 306) or `#` is a
//!   comment. A `;` after white space ends the value: the rest of the line
//!   is a comment, as python-canopen's reader (configparser with
//!   `inline_comment_prefixes=(';',)`) has it. A `;` glued to the value
//!   (`a;b`) is part of it.
//! * White space around names and values is not part of them.
//! * A section named twice, or a key named twice in one section, is refused
//!   with both lines: the readers disagree on which one wins (python-canopen
//!   refuses, others take the first or the last), so the file says two
//!   things.
//! * A UTF-8 byte order mark is skipped; a file that is not UTF-8 is read
//!   as ISO 8859-1 (what Windows tools write), which the caller reports.
//!
//! Why not an INI crate (rust-ini, configparser): their maps keep neither
//! the line of a key nor the fact that a key or section came twice, and
//! both are what a user needs in a message about a tool's file.

use std::collections::BTreeMap;

/// One `key=value` line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Key {
    /// The key as written.
    pub name: String,
    /// The value without surrounding white space and trailing comment.
    pub value: String,
    /// 1-based line.
    pub line: usize,
}

/// One `[section]` with its keys.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Section {
    /// The name as written (without brackets).
    pub name: String,
    /// 1-based line of the `[name]` line.
    pub line: usize,
    /// The keys in file order.
    pub keys: Vec<Key>,
}

impl Section {
    /// The key `name` (any case).
    pub fn key(&self, name: &str) -> Option<&Key> {
        self.keys.iter().find(|k| k.name.eq_ignore_ascii_case(name))
    }

    /// The value of key `name`.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.key(name).map(|k| k.value.as_str())
    }
}

/// A whole file.
#[derive(Debug, Clone, Default)]
pub struct Ini {
    /// The sections in file order.
    pub sections: Vec<Section>,
    by_name: BTreeMap<String, usize>,
}

/// What is wrong with a line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IniError {
    /// 1-based line.
    pub line: usize,
    /// The section, when the line is inside one.
    pub section: Option<String>,
    /// The key, when the line names one.
    pub key: Option<String>,
    /// What is wrong.
    pub msg: String,
}

/// Decodes the bytes of a file: UTF-8 (a leading byte order mark
/// skipped), otherwise ISO 8859-1. The flag tells that the fallback was
/// taken.
pub fn decode(bytes: &[u8]) -> (String, bool) {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    match std::str::from_utf8(bytes) {
        Ok(s) => (s.to_string(), false),
        Err(_) => (bytes.iter().map(|b| char::from(*b)).collect(), true),
    }
}

/// Cuts a trailing comment: `;` after white space (or at the start).
fn strip_comment(value: &str) -> &str {
    let mut prev_blank = true;
    for (i, c) in value.char_indices() {
        if c == ';' && prev_blank {
            return &value[..i];
        }
        prev_blank = c.is_whitespace();
    }
    value
}

impl Ini {
    /// Reads `text`.
    pub fn parse(text: &str) -> Result<Ini, IniError> {
        let mut ini = Ini::default();
        for (n, raw) in text.lines().enumerate() {
            let line = n + 1;
            let t = raw.trim();
            if t.is_empty() || t.starts_with(';') || t.starts_with('#') {
                continue;
            }
            let current = ini.sections.last().map(|s| s.name.clone());
            if let Some(rest) = t.strip_prefix('[') {
                let Some((name, after)) = rest.split_once(']') else {
                    return Err(IniError {
                        line,
                        section: None,
                        key: None,
                        msg: format!("`{t}`: a section name ends with `]`"),
                    });
                };
                let name = name.trim();
                let after = strip_comment(after).trim();
                if name.is_empty() || !after.is_empty() {
                    return Err(IniError {
                        line,
                        section: None,
                        key: None,
                        msg: format!("`{t}` is not a section line (`[name]`)"),
                    });
                }
                let folded = name.to_ascii_lowercase();
                if let Some(&i) = ini.by_name.get(&folded) {
                    let first = &ini.sections[i];
                    return Err(IniError {
                        line,
                        section: Some(name.to_string()),
                        key: None,
                        msg: format!(
                            "section [{}] already opened at line {}: one object described twice",
                            first.name, first.line
                        ),
                    });
                }
                ini.by_name.insert(folded, ini.sections.len());
                ini.sections.push(Section {
                    name: name.to_string(),
                    line,
                    keys: Vec::new(),
                });
                continue;
            }
            let Some((k, v)) = t.split_once('=') else {
                return Err(IniError {
                    line,
                    section: current,
                    key: None,
                    msg: format!("`{t}` is neither `[section]` nor `key=value` nor a comment"),
                });
            };
            let k = k.trim();
            let v = strip_comment(v).trim();
            let Some(section) = ini.sections.last_mut() else {
                return Err(IniError {
                    line,
                    section: None,
                    key: Some(k.to_string()),
                    msg: "key before the first section".into(),
                });
            };
            if k.is_empty() {
                return Err(IniError {
                    line,
                    section: current,
                    key: None,
                    msg: format!("`{t}` has no key before `=`"),
                });
            }
            if let Some(first) = section.key(k) {
                return Err(IniError {
                    line,
                    section: current,
                    key: Some(k.to_string()),
                    msg: format!(
                        "{} already given at line {} (`{}`): which one holds is undefined",
                        first.name, first.line, first.value
                    ),
                });
            }
            section.keys.push(Key {
                name: k.to_string(),
                value: v.to_string(),
                line,
            });
        }
        Ok(ini)
    }

    /// The section `name` (any case).
    pub fn section(&self, name: &str) -> Option<&Section> {
        self.by_name
            .get(&name.to_ascii_lowercase())
            .and_then(|i| self.sections.get(*i))
    }

    /// The value of `key` in `section`.
    pub fn get(&self, section: &str, key: &str) -> Option<&str> {
        self.section(section).and_then(|s| s.get(key))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_comments_and_case() {
        let ini = Ini::parse(
            "; header comment\n[FileInfo]\nFileName = a.eds ; trailing\n\n[2000]\n;StorageLocation=RAM\n# other comment\nDataType=0x0007\nParameterName=a;b\n",
        )
        .unwrap();
        assert_eq!(ini.get("fileinfo", "FILENAME"), Some("a.eds"));
        let s = ini.section("2000").unwrap();
        assert_eq!(s.line, 5);
        assert_eq!(s.key("datatype").unwrap().line, 8);
        assert_eq!(s.get("ParameterName"), Some("a;b"), "a glued ; stays");
        assert_eq!(s.get("StorageLocation"), None, "commented-out key");
    }

    #[test]
    fn duplicates_are_refused_with_both_lines() {
        let e = Ini::parse("[2000]\nDataType=7\n[2001]\n[2000]\n").unwrap_err();
        assert_eq!(e.line, 4);
        assert!(e.msg.contains("already opened at line 1"), "{}", e.msg);
        let e = Ini::parse("[2000]\nDefaultValue=1\ndefaultvalue=2\n").unwrap_err();
        assert_eq!((e.line, e.key.as_deref()), (3, Some("defaultvalue")));
        assert!(e.msg.contains("already given at line 2 (`1`)"), "{}", e.msg);
    }

    #[test]
    fn malformed_lines() {
        assert_eq!(Ini::parse("x=1\n").unwrap_err().line, 1);
        assert_eq!(Ini::parse("[a]\njunk\n").unwrap_err().line, 2);
        assert_eq!(Ini::parse("[a\n").unwrap_err().line, 1);
        assert!(Ini::parse("[a] ; comment\n").is_ok());
    }

    #[test]
    fn encodings() {
        assert_eq!(decode(b"\xEF\xBB\xBF[a]"), ("[a]".to_string(), false));
        assert_eq!(decode(b"x=\xB0C"), ("x=\u{B0}C".to_string(), true));
    }
}
