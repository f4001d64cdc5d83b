//! `dcf2bin`: reads a CANopen device configuration file (DCF) or electronic
//! data sheet (EDS, CiA 306) and writes the binary DCF container of the cop
//! dynamic object dictionary (SYS TEC CcmDyn format, seed manual L-1087d
//! chapter 2; layout in `cop::od::dcf`).
//!
//! # What goes into the container
//! * One index-segment entry per subindex of every object section
//!   (`[XXXX]`, `[XXXXsubN]`, and `CompactSubObj` arrays), ascending by
//!   index and subindex, with the configured value: `ParameterValue` (a
//!   DCF) if present, else `DefaultValue`, else 0 / empty. Values are read
//!   and encoded as [`value`] describes (CiA 306 forms, CiA 301 encodings).
//! * One attribute byte per entry: BOOLEAN 0x01, VISIBLE_STRING 0x08,
//!   NUMERIC_VALUE 0x10 (integers and reals), none for the others (copied
//!   bytewise as DOMAIN), READ 0x20 (`ro`, `rw`, `rwr`, `rww`, `const`),
//!   WRITE 0x40 (`wo`, `rw`, `rwr`, `rww`), PDO_MAPP 0x80 (`PDOMapping=1`).
//!   The container has no room for the data type (seed 2.1.4, Tabelle 1):
//!   a new NUMERIC object becomes UNSIGNEDn of its size in the dynamic OD,
//!   with the same bytes.
//! * The address segment (one WORD per process-image candidate): network
//!   variables 0xA000–0xA8FF get the offset of the CiA 302/405 rule (seed
//!   chapter 6: inputs from 0, outputs after them on the next multiple of
//!   8, `cop::od::dcf::PiLayout`); every other candidate 0xFFFF.
//! * The process-image parameter segment with the resulting sizes, when
//!   the file has network variables.
//!
//! # What is refused, skipped or left out
//! * Refused (nothing written, the error names file, line, section and
//!   key): malformed lines, a section or key given twice, a subindex
//!   described twice, values that do not fit their type, a value outside
//!   `LowLimit`..`HighLimit`, network variables of the wrong type (an
//!   UNSIGNED8 under 0xA580), inconsistent safety keys ([`safety`]).
//! * Skipped with a warning ([`WarningKind::Skipped`]), refused with
//!   `--strict`: subindices of a data type the container cannot carry
//!   (python-canopen skips them too), and a subindex without value whose
//!   limits exclude 0.
//! * Tolerated with a warning ([`WarningKind::Tolerated`]), refused with
//!   `--strict`: forms outside CiA 306 whose meaning is clear (a C integer
//!   suffix, BOOLEAN `True`/`False`, a DOMAIN `0`, a VISIBLE_STRING with
//!   characters outside 0x20..0x7E, a wrong `SubNumber`, safety keys
//!   without `CANopenSafetySupported=1`), and a number without value
//!   (written as 0).
//! * Left out with a note ([`WarningKind::LeftOut`], also with `--strict`):
//!   objects whose write is a command, not a configuration ([`is_command_object`]),
//!   and subindices of 0x1003 / 0x1010 / 0x1011 without value ([`describes_device`]).
//!
//! # Limits
//! `LowLimit`/`HighLimit` are checked here, at conversion time: the
//! container format has no room for them (seed 2.1.4: one attribute byte
//! per entry). An existing object of the node keeps the range its firmware
//! gives it and checks every value written, container values included.

pub mod check;
pub mod container;
pub mod ini;
pub mod node;
pub mod safety;
pub mod value;

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::path::{Path, PathBuf};

use cop::od::DataType;
use cop::od::dcf::{self, attr};

pub use safety::write_crcs;
pub use value::parse_int;
use value::{Number, type_name};

/// An error with the place it comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    /// The file.
    pub file: PathBuf,
    /// 1-based line, when known.
    pub line: Option<usize>,
    /// Section (without brackets), when the error is about one.
    pub section: Option<String>,
    /// Key, when the error is about one.
    pub key: Option<String>,
    /// What is wrong.
    pub msg: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file.display())?;
        if let Some(l) = self.line {
            write!(f, ":{l}")?;
        }
        write!(f, ":")?;
        match (&self.section, &self.key) {
            (Some(s), Some(k)) => write!(f, " [{s}] {k}:")?,
            (Some(s), None) => write!(f, " [{s}]:")?,
            (None, Some(k)) => write!(f, " {k}:")?,
            _ => {}
        }
        write!(f, " {}", self.msg)
    }
}

impl std::error::Error for Error {}

impl ini::IniError {
    /// The error with the file it is in.
    pub fn in_file(self, file: &Path) -> Error {
        Error {
            file: file.to_path_buf(),
            line: Some(self.line),
            section: self.section,
            key: self.key,
            msg: self.msg,
        }
    }
}

impl Error {
    /// An error about the whole file.
    pub fn whole(file: &Path, msg: impl Into<String>) -> Error {
        Error {
            file: file.to_path_buf(),
            line: None,
            section: None,
            key: None,
            msg: msg.into(),
        }
    }
}

/// Why a warning was given.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WarningKind {
    /// Something the container cannot carry was left out (refused with
    /// `--strict`).
    Skipped,
    /// A form outside CiA 306 was accepted (refused with `--strict`).
    Tolerated,
    /// An object that is no configuration was left out (always).
    LeftOut,
}

/// A warning, with the place it is about.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Warning {
    /// Why.
    pub kind: WarningKind,
    /// Where and what.
    pub at: Error,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let what = match self.kind {
            WarningKind::Skipped => "warning (skipped)",
            WarningKind::Tolerated => "warning (tolerated)",
            WarningKind::LeftOut => "note (left out)",
        };
        write!(f, "{what}: {}", self.at)
    }
}

/// How a file is read.
#[derive(Debug, Clone, Copy, Default)]
pub struct Options {
    /// Node-ID for `$NODEID` (else `[DeviceComissioning] NodeID`).
    pub node_id: Option<u8>,
    /// Refuse what would be skipped or tolerated with a warning.
    pub strict: bool,
}

/// One subindex with its configured value.
#[derive(Debug, Clone, PartialEq)]
pub struct Object {
    /// Index.
    pub index: u16,
    /// Subindex.
    pub sub: u8,
    /// CiA 301 data type number.
    pub data_type: u16,
    /// `AccessType` as written (lower case).
    pub access: String,
    /// `PDOMapping=1`.
    pub pdo_mapping: bool,
    /// The value in CANopen byte order.
    pub data: Vec<u8>,
    /// The attribute byte of the container.
    pub attr: u8,
    /// The section that describes the subindex.
    pub section: String,
    /// Line of that section.
    pub line: usize,
    /// Line of the key the value comes from (the section's without one).
    pub value_line: usize,
    /// `LowLimit` and `HighLimit`, when given.
    pub limits: (Option<Number>, Option<Number>),
    /// `SRDOMapping=1` (CiA 306, CANopen safety).
    pub srdo_mapping: bool,
    /// `InvertedSRAD`: index and subindex of the inverted safety
    /// application data (CiA 306), with its line.
    pub inverted_srad: Option<(u16, u8, usize)>,
}

impl Object {
    /// The data type.
    pub fn typ(&self) -> DataType {
        DataType::from_code(self.data_type).unwrap_or(DataType::Domain)
    }
}

/// A parsed DCF/EDS.
#[derive(Debug, Clone)]
pub struct Dcf {
    /// The file it came from.
    pub file: PathBuf,
    /// Node-ID used for `$NODEID`.
    pub node_id: Option<u8>,
    /// Every subindex, ascending.
    pub objects: Vec<Object>,
    /// What was skipped, tolerated or left out.
    pub warnings: Vec<Warning>,
    /// `[DeviceInfo] CANopenSafetySupported`, when given.
    pub safety_supported: Option<bool>,
}

/// Objects whose write is a command, not a configuration: the container
/// leaves them out (an EDS describes them with the value they read).
/// * 0x1023 OS command, 0x1F25 configure slave, 0x1F51 program control:
///   writing starts an action (CiA 301, CiA 302).
///
/// 0x1003 (pre-defined error field) and 0x1010 / 0x1011 (store / restore
/// capabilities) describe the device: `DynBuildOd` checks their entries
/// and writes nothing (`cop::od::dynamic::describes_structure`), so they
/// go into the container with the values the file gives; a subindex of
/// them without value is left out ([`describes_device`]).
pub fn is_command_object(index: u16) -> Option<&'static str> {
    Some(match index {
        0x1023 => "0x1023 (OS command): writing executes a command (CiA 301)",
        0x1F25 => "0x1F25 (configure slave): writing starts a configuration (CiA 302)",
        0x1F51 => "0x1F51 (program control): writing starts or stops a program (CiA 302-3)",
        _ => return None,
    })
}

/// Objects whose entries describe the device (see [`is_command_object`]):
/// a subindex without value is left out with a note instead of carrying 0.
pub fn describes_device(index: u16) -> Option<&'static str> {
    Some(match index {
        0x1003 => {
            "0x1003 (pre-defined error field) without value: left out (its entries describe the device's error history; DynBuildOd checks them, writes nothing)"
        }
        0x1010 | 0x1011 => {
            "0x1010 / 0x1011 (store / restore capability) without value: left out (DynBuildOd checks them, writes nothing)"
        }
        _ => return None,
    })
}

/// The container attribute of an object.
pub fn attribute(t: DataType, access: &str, pdo_mapping: bool) -> u8 {
    let mut a = match t {
        DataType::Bool => attr::BOOLEAN,
        DataType::VString => attr::VISIBLE_STRING,
        t if t.is_numeric() => attr::NUMERIC,
        _ => 0,
    };
    if matches!(access, "ro" | "rw" | "rwr" | "rww" | "const") {
        a |= attr::READ;
    }
    if matches!(access, "wo" | "rw" | "rwr" | "rww") {
        a |= attr::WRITE;
    }
    if pdo_mapping {
        a |= attr::PDO_MAPP;
    }
    a
}

fn is_object_section(name: &str) -> Option<u16> {
    (name.len() == 4 && name.chars().all(|c| c.is_ascii_hexdigit()))
        .then(|| u16::from_str_radix(name, 16).ok())
        .flatten()
}

/// `XXXXsubN` (`sub` in any case, N hex).
fn is_sub_section(name: &str) -> Option<(u16, u8)> {
    let lower = name.to_ascii_lowercase();
    let (i, s) = lower.split_once("sub")?;
    if i.len() != 4 || s.is_empty() || s.len() > 2 {
        return None;
    }
    if !(i.chars().all(|c| c.is_ascii_hexdigit()) && s.chars().all(|c| c.is_ascii_hexdigit())) {
        return None;
    }
    Some((
        u16::from_str_radix(i, 16).ok()?,
        u8::from_str_radix(s, 16).ok()?,
    ))
}

/// Where the value of a subindex is written.
struct ValueAt<'a> {
    section: String,
    key: String,
    text: &'a str,
}

/// Reads one file.
struct Reader<'a> {
    file: &'a Path,
    ini: &'a ini::Ini,
    opts: Options,
    node_id: Option<u8>,
    warnings: Vec<Warning>,
}

impl<'a> Reader<'a> {
    fn place(&self, section: &str, key: Option<&str>) -> Error {
        let s = self.ini.section(section);
        let line = match (s, key) {
            (Some(s), Some(k)) => s.key(k).map(|k| k.line).or(Some(s.line)),
            (Some(s), None) => Some(s.line),
            _ => None,
        };
        Error {
            file: self.file.to_path_buf(),
            line,
            section: Some(section.to_string()),
            key: key.map(str::to_string),
            msg: String::new(),
        }
    }

    fn err(&self, section: &str, key: Option<&str>, msg: impl Into<String>) -> Error {
        Error {
            msg: msg.into(),
            ..self.place(section, key)
        }
    }

    /// Records a warning; with `--strict` a skipped or tolerated one is an
    /// error.
    fn warn(
        &mut self,
        kind: WarningKind,
        section: &str,
        key: Option<&str>,
        msg: impl Into<String>,
    ) -> Result<(), Error> {
        let at = self.err(section, key, msg);
        if self.opts.strict && kind != WarningKind::LeftOut {
            return Err(Error {
                msg: format!("{} (refused: --strict)", at.msg),
                ..at
            });
        }
        self.warnings.push(Warning { kind, at });
        Ok(())
    }

    fn get(&self, sec: &str, key: &str) -> Option<&'a str> {
        self.ini.get(sec, key)
    }

    fn flag(&mut self, sec: &str, key: &str) -> Result<Option<bool>, Error> {
        let Some(v) = self.get(sec, key).filter(|v| !v.is_empty()) else {
            return Ok(None);
        };
        let v = v.to_string();
        match v.to_ascii_lowercase().as_str() {
            "true" | "false" => {
                self.warn(
                    WarningKind::Tolerated,
                    sec,
                    Some(key),
                    format!("`{v}`: CiA 306 booleans are 0 or 1"),
                )?;
                Ok(Some(v.eq_ignore_ascii_case("true")))
            }
            _ => match parse_int(&v, None) {
                Ok(0) => Ok(Some(false)),
                Ok(1) => Ok(Some(true)),
                _ => Err(self.err(sec, Some(key), format!("`{v}`: a boolean is 0 or 1"))),
            },
        }
    }

    /// The data type of a variable section, or `None` (with a warning) when
    /// the container cannot carry it.
    fn data_type(&mut self, sec: &str) -> Result<Option<DataType>, Error> {
        let text = self
            .get(sec, "DataType")
            .filter(|v| !v.is_empty())
            .ok_or_else(|| self.err(sec, None, "no DataType"))?
            .to_string();
        let code = parse_int(&text, None).map_err(|m| self.err(sec, Some("DataType"), m))?;
        match u16::try_from(code).ok().and_then(DataType::from_code) {
            Some(t) => Ok(Some(t)),
            None => {
                let why = match code {
                    0x20..=0x25 => "a structure type of CiA 301 (only its subindices are values)",
                    0x0E | 0x17 => "reserved in CiA 301",
                    0x40..=0x25F => "a manufacturer or profile type (CiA 301 7.4.7)",
                    _ => "not a CiA 301 basic type",
                };
                self.warn(
                    WarningKind::Skipped,
                    sec,
                    Some("DataType"),
                    format!(
                        "data type 0x{code:04X} is {why}; the container cannot carry it: object {sec} left out"
                    ),
                )?;
                Ok(None)
            }
        }
    }

    /// The value of a variable: `ParameterValue`, else `DefaultValue`, as
    /// (key, text).
    fn value_key(&self, sec: &str) -> (String, &'a str) {
        match (
            self.get(sec, "ParameterValue"),
            self.get(sec, "DefaultValue"),
        ) {
            (Some(v), _) => ("ParameterValue".into(), v),
            (None, Some(v)) => ("DefaultValue".into(), v),
            (None, None) => ("DefaultValue".into(), ""),
        }
    }

    /// One subindex described by section `sec` (or, for compact arrays, by
    /// the object's section with a value from `value`).
    fn variable(
        &mut self,
        sec: &str,
        index: u16,
        sub: u8,
        value: Option<ValueAt<'_>>,
    ) -> Result<Option<Object>, Error> {
        let Some(t) = self.data_type(sec)? else {
            return Ok(None);
        };
        if let Some(nv) = dcf::network_variable(index) {
            if sub != 0 && nv.typ != t {
                return Err(self.err(
                    sec,
                    Some("DataType"),
                    format!(
                        "0x{index:04X} holds {} (CiA 405 network variables, seed table 2), not {}",
                        type_name(nv.typ),
                        type_name(t)
                    ),
                ));
            }
        }
        let access = self
            .get(sec, "AccessType")
            .ok_or_else(|| self.err(sec, None, "no AccessType"))?
            .to_ascii_lowercase();
        if !matches!(
            access.as_str(),
            "ro" | "wo" | "rw" | "rwr" | "rww" | "const"
        ) {
            return Err(self.err(
                sec,
                Some("AccessType"),
                format!("`{access}` is not an access type (ro, wo, rw, rwr, rww, const)"),
            ));
        }
        let pdo_mapping = self.flag(sec, "PDOMapping")?.unwrap_or(false);
        let v = match value {
            Some(v) => v,
            None => {
                let (key, text) = self.value_key(sec);
                ValueAt {
                    section: sec.to_string(),
                    key,
                    text,
                }
            }
        };
        let (value_sec, key, text) = (v.section, v.key, v.text);
        let enc = value::encode(t, text, self.node_id)
            .map_err(|m| self.err(&value_sec, Some(&key), m))?;
        for note in &enc.tolerated {
            self.warn(WarningKind::Tolerated, &value_sec, Some(&key), note.clone())?;
        }
        let limits = self.limits(sec, t)?;
        let no_value = text.trim().is_empty() && t.wire_size().is_some();
        if let Err(m) = in_limits(t, &enc.data, limits, text) {
            if !text.trim().is_empty() {
                return Err(self.err(&value_sec, Some(&key), m));
            }
            // No value: 0 would be an invented value the object refuses.
            self.warn(
                WarningKind::Skipped,
                sec,
                Some(&key),
                format!("{m}: subindex left out (give it a ParameterValue)"),
            )?;
            return Ok(None);
        }
        if no_value {
            if let Some(why) = describes_device(index) {
                self.warn(WarningKind::LeftOut, sec, None, why)?;
                return Ok(None);
            }
            self.warn(
                WarningKind::Tolerated,
                &value_sec,
                Some(&key),
                "no value: 0 goes into the container (for an object the node has, its value is replaced)",
            )?;
        }
        let srdo_mapping = self.flag(sec, "SRDOMapping")?.unwrap_or(false);
        let inverted_srad = self.inverted_srad(sec)?;
        let line = self.ini.section(sec).map_or(0, |s| s.line);
        let value_line = self
            .ini
            .section(&value_sec)
            .and_then(|s| s.key(&key))
            .map_or(line, |k| k.line);
        Ok(Some(Object {
            index,
            sub,
            data_type: t.code().into(),
            attr: attribute(t, &access, pdo_mapping),
            access,
            pdo_mapping,
            data: enc.data,
            section: sec.to_string(),
            line,
            value_line,
            limits,
            srdo_mapping,
            inverted_srad,
        }))
    }

    /// Reads `LowLimit`/`HighLimit` (and checks their order).
    fn limits(
        &mut self,
        sec: &str,
        t: DataType,
    ) -> Result<(Option<Number>, Option<Number>), Error> {
        let mut out = [None, None];
        for (slot, name) in out.iter_mut().zip(["LowLimit", "HighLimit"]) {
            let Some(v) = self.get(sec, name).filter(|v| !v.is_empty()) else {
                continue;
            };
            if !value::has_limits(t) {
                self.warn(
                    WarningKind::Tolerated,
                    sec,
                    Some(name),
                    format!("{name} has no meaning for {}: ignored", type_name(t)),
                )?;
                continue;
            }
            let mut tolerated = Vec::new();
            let n = value::limit(t, v, self.node_id, &mut tolerated)
                .map_err(|m| self.err(sec, Some(name), m))?;
            for note in tolerated {
                self.warn(WarningKind::Tolerated, sec, Some(name), note)?;
            }
            *slot = Some(n);
        }
        let [low, high] = out;
        if let (Some(l), Some(h)) = (low, high) {
            if l > h {
                return Err(self.err(
                    sec,
                    Some("HighLimit"),
                    format!("HighLimit {h} is below LowLimit {l}"),
                ));
            }
        }
        Ok((low, high))
    }

    /// `InvertedSRAD=0xIIIISS` (CiA 306: index in four hex digits, then
    /// subindex in two).
    fn inverted_srad(&mut self, sec: &str) -> Result<Option<(u16, u8, usize)>, Error> {
        let Some(v) = self.get(sec, "InvertedSRAD").filter(|v| !v.is_empty()) else {
            return Ok(None);
        };
        let v = v.to_string();
        let line = self
            .ini
            .section(sec)
            .and_then(|s| s.key("InvertedSRAD"))
            .map_or(0, |k| k.line);
        let digits = v
            .strip_prefix("0x")
            .or_else(|| v.strip_prefix("0X"))
            .filter(|d| d.len() == 6 && d.chars().all(|c| c.is_ascii_hexdigit()))
            .ok_or_else(|| {
                self.err(
                    sec,
                    Some("InvertedSRAD"),
                    format!(
                        "`{v}`: CiA 306 writes the inverted object as 0x, four hex digits of the index, two of the subindex (0x620102)"
                    ),
                )
            })?;
        let index = u16::from_str_radix(&digits[..4], 16).unwrap_or(0);
        let sub = u8::from_str_radix(&digits[4..], 16).unwrap_or(0);
        Ok(Some((index, sub, line)))
    }
}

/// Checks a value against `LowLimit`/`HighLimit`.
fn in_limits(
    t: DataType,
    data: &[u8],
    (low, high): (Option<Number>, Option<Number>),
    text: &str,
) -> Result<(), String> {
    let Some(v) = value::number(t, data).filter(|_| value::has_limits(t)) else {
        return Ok(());
    };
    let shown = if text.trim().is_empty() {
        "no value (0)".to_string()
    } else {
        format!("`{}` ({v})", text.trim())
    };
    if let Some(l) = low.filter(|l| v < *l) {
        return Err(format!("{shown} is below LowLimit {l}"));
    }
    if let Some(h) = high.filter(|h| v > *h) {
        return Err(format!("{shown} is above HighLimit {h}"));
    }
    Ok(())
}

/// Parses the text of a DCF/EDS (`file` names it in errors).
pub fn parse(text: &str, file: &Path, node_override: Option<u8>) -> Result<Dcf, Error> {
    parse_with(
        text,
        file,
        Options {
            node_id: node_override,
            strict: false,
        },
    )
}

/// Parses the text of a DCF/EDS with `opts`.
pub fn parse_with(text: &str, file: &Path, opts: Options) -> Result<Dcf, Error> {
    let ini = ini::Ini::parse(text).map_err(|e| e.in_file(file))?;
    let mut r = Reader {
        file,
        ini: &ini,
        opts,
        node_id: None,
        warnings: Vec::new(),
    };
    r.node_id = match opts.node_id {
        Some(n) => Some(n),
        None => match r.get("DeviceComissioning", "NodeID") {
            Some(v) if !v.is_empty() => {
                let n = parse_int(v, None)
                    .map_err(|m| r.err("DeviceComissioning", Some("NodeID"), m))?;
                Some(
                    u8::try_from(n)
                        .ok()
                        .filter(|n| (1..=127).contains(n))
                        .ok_or_else(|| {
                            r.err(
                                "DeviceComissioning",
                                Some("NodeID"),
                                format!("{n} is not a node-ID (1..127)"),
                            )
                        })?,
                )
            }
            _ => None,
        },
    };
    let safety_supported = r.flag("DeviceInfo", "CANopenSafetySupported")?;
    // Which section describes each subindex, to refuse a second one.
    let mut objects: BTreeMap<(u16, u8), Object> = BTreeMap::new();
    let mut described: BTreeMap<(u16, u8), (String, usize)> = BTreeMap::new();
    let mut claim = |r: &Reader<'_>, key: (u16, u8), sec: &str| -> Result<(), Error> {
        let line = ini.section(sec).map_or(0, |s| s.line);
        if let Some((first, first_line)) = described.get(&key) {
            return Err(r.err(
                sec,
                None,
                format!(
                    "0x{:04X} sub {} is already described by [{first}] at line {first_line}: one subindex described twice",
                    key.0, key.1
                ),
            ));
        }
        described.insert(key, (sec.to_string(), line));
        Ok(())
    };
    let mut kinds: BTreeMap<u16, i128> = BTreeMap::new();
    let mut left_out: BTreeSet<u16> = BTreeSet::new();
    for s in &ini.sections {
        let name = s.name.as_str();
        let Some(index) = is_object_section(name) else {
            continue;
        };
        let object_type = match r.get(name, "ObjectType") {
            Some(v) if !v.is_empty() => {
                parse_int(v, None).map_err(|m| r.err(name, Some("ObjectType"), m))?
            }
            _ => 7,
        };
        kinds.insert(index, object_type);
        if let Some(why) = is_command_object(index) {
            r.warn(WarningKind::LeftOut, name, None, why)?;
            left_out.insert(index);
            continue;
        }
        match object_type {
            2 | 7 => {
                claim(&r, (index, 0), name)?;
                if let Some(o) = r.variable(name, index, 0, None)? {
                    objects.insert((index, 0), o);
                }
            }
            8 | 9 => {
                let Some(n) = r.get(name, "CompactSubObj").filter(|v| !v.is_empty()) else {
                    continue;
                };
                // CiA 306 compact array: subindices 1..n share the object's
                // description; values may come from [XXXXValue].
                let n = parse_int(n, None).map_err(|m| r.err(name, Some("CompactSubObj"), m))?;
                let n = u8::try_from(n)
                    .ok()
                    .filter(|n| *n >= 1 && *n < 255)
                    .ok_or_else(|| r.err(name, Some("CompactSubObj"), "must be 1..254"))?;
                claim(&r, (index, 0), name)?;
                objects.insert(
                    (index, 0),
                    Object {
                        index,
                        sub: 0,
                        data_type: DataType::UInt8.code().into(),
                        access: "ro".into(),
                        pdo_mapping: false,
                        data: vec![n],
                        attr: attr::NUMERIC | attr::READ,
                        section: name.to_string(),
                        line: s.line,
                        value_line: s.line,
                        limits: (None, None),
                        srdo_mapping: false,
                        inverted_srad: None,
                    },
                );
                let values = format!("{index:04X}Value");
                let (dkey, dvalue) = r.value_key(name);
                let (dkey, dvalue) = (dkey, dvalue.to_string());
                for sub in 1..=n {
                    claim(&r, (index, sub), name)?;
                    let v = match ini.get(&values, &sub.to_string()) {
                        Some(v) => ValueAt {
                            section: values.clone(),
                            key: sub.to_string(),
                            text: v,
                        },
                        None => ValueAt {
                            section: name.to_string(),
                            key: dkey.clone(),
                            text: &dvalue,
                        },
                    };
                    let Some(o) = r.variable(name, index, sub, Some(v))? else {
                        // The type is the array's: nothing of it can go in.
                        objects.remove(&(index, 0));
                        break;
                    };
                    objects.insert((index, sub), o);
                }
            }
            other => {
                return Err(r.err(
                    name,
                    Some("ObjectType"),
                    format!(
                        "object type {other} is not VAR (7), DOMAIN (2), ARRAY (8) or RECORD (9)"
                    ),
                ));
            }
        }
    }
    for s in &ini.sections {
        let name = s.name.as_str();
        let Some((index, sub)) = is_sub_section(name) else {
            continue;
        };
        let parent = format!("{index:04X}");
        match kinds.get(&index) {
            None => {
                return Err(r.err(
                    name,
                    None,
                    format!("subindex of [{parent}], which does not exist"),
                ));
            }
            Some(7 | 2) => {
                return Err(r.err(
                    name,
                    None,
                    format!("[{parent}] is a VAR, which has no subindex sections"),
                ));
            }
            Some(_) => {}
        }
        if left_out.contains(&index) {
            continue;
        }
        claim(&r, (index, sub), name)?;
        if let Some(o) = r.variable(name, index, sub, None)? {
            objects.insert((index, sub), o);
        }
    }
    // SubNumber names how many subindex sections follow (CiA 306 4.6.3).
    for s in &ini.sections {
        let Some(index) = is_object_section(&s.name) else {
            continue;
        };
        if !matches!(kinds.get(&index), Some(8 | 9)) || s.get("CompactSubObj").is_some() {
            continue;
        }
        let Some(v) = s.get("SubNumber").filter(|v| !v.is_empty()) else {
            continue;
        };
        let Ok(n) = parse_int(v, None) else {
            return Err(r.err(&s.name, Some("SubNumber"), format!("`{v}` is not a number")));
        };
        let have = described.range((index, 0)..=(index, 255)).count() as i128;
        if n != have && !left_out.contains(&index) {
            r.warn(
                WarningKind::Tolerated,
                &s.name,
                Some("SubNumber"),
                format!("{n} subindices announced, {have} sections found"),
            )?;
        }
    }
    let mut dcf = Dcf {
        file: file.to_path_buf(),
        node_id: r.node_id,
        objects: objects.into_values().collect(),
        warnings: Vec::new(),
        safety_supported,
    };
    safety::check_keys(&dcf, &mut r)?;
    dcf.warnings = r.warnings;
    dcf.warnings.sort_by_key(|w| w.at.line);
    Ok(dcf)
}

/// Reads and parses a file.
pub fn load(path: &Path, node_override: Option<u8>) -> Result<(String, Dcf), Error> {
    load_with(
        path,
        Options {
            node_id: node_override,
            strict: false,
        },
    )
}

/// Reads and parses a file with `opts`.
pub fn load_with(path: &Path, opts: Options) -> Result<(String, Dcf), Error> {
    let bytes = std::fs::read(path).map_err(|e| Error::whole(path, e.to_string()))?;
    let (text, latin1) = ini::decode(&bytes);
    let mut d = parse_with(&text, path, opts)?;
    if latin1 {
        let w = Warning {
            kind: WarningKind::Tolerated,
            at: Error::whole(path, "not UTF-8: read as ISO 8859-1"),
        };
        if opts.strict {
            return Err(w.at);
        }
        d.warnings.insert(0, w);
    }
    Ok((text, d))
}

impl Dcf {
    /// The data type of every subindex, for the EDS export of the node
    /// after the build (`cop::od::eds::EdsInfo::types`).
    pub fn types(&self) -> Vec<(u16, u8, DataType)> {
        self.objects
            .iter()
            .map(|o| (o.index, o.sub, o.typ()))
            .collect()
    }

    /// The value of a subindex.
    pub fn get(&self, index: u16, sub: u8) -> Option<&Object> {
        self.objects
            .binary_search_by_key(&(index, sub), |o| (o.index, o.sub))
            .ok()
            .and_then(|i| self.objects.get(i))
    }
}

/// Writes `bytes` to `path` through a temporary file in the same folder
/// and a rename, so that a failure leaves no partial file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("out");
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let r = std::fs::write(&tmp, bytes).and_then(|()| std::fs::rename(&tmp, path));
    if r.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    r
}
