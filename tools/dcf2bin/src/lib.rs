//! `dcf2bin`: reads a CANopen device configuration file (DCF) or electronic
//! data sheet (EDS, CiA 306) and writes the binary DCF container of the cop
//! dynamic object dictionary (SYS TEC CcmDyn format, seed manual L-1087d
//! chapter 2; layout in `cop::od::dcf`).
//!
//! # What goes into the container
//! * One index-segment entry per subindex of every object section
//!   (`[XXXX]`, `[XXXXsubN]`, and `CompactSubObj` arrays), ascending by
//!   index and subindex, with the configured value: `ParameterValue` (a
//!   DCF) if present, else `DefaultValue`, else 0 / empty. `$NODEID` is
//!   replaced by the node-ID (`--node-id`, else `[DeviceComissioning]
//!   NodeID`). Numbers are written little-endian in the width of their
//!   type, strings as their bytes, OCTET_STRING and DOMAIN values from hex
//!   digits.
//! * One attribute byte per entry: BOOLEAN 0x01, VISIBLE_STRING 0x08,
//!   NUMERIC_VALUE 0x10 (integers and reals), none for the others (copied
//!   bytewise as DOMAIN), READ 0x20 (`ro`, `rw`, `rwr`, `rww`, `const`),
//!   WRITE 0x40 (`wo`, `rw`, `rwr`, `rww`), PDO_MAPP 0x80 (`PDOMapping=1`).
//! * The address segment (one WORD per process-image candidate): network
//!   variables 0xA000–0xA8FF get the offset of the CiA 302/405 rule (seed
//!   chapter 6: inputs from 0, outputs after them on the next multiple of
//!   8, `cop::od::dcf::PiLayout`); every other candidate 0xFFFF.
//! * The process-image parameter segment with the resulting sizes, when
//!   the file has network variables.
//!
//! Network variables must have the data type of seed table 2 (an
//! UNSIGNED8 under 0xA580 is refused with the line of its `DataType`).

use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

use cop::od::DataType;
use cop::od::dcf::{self, EntrySpec, NOT_PLACED, PiLayout, PiParams, attr};
use ini::{Ini, ParseOption};

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
            _ => {}
        }
        write!(f, " {}", self.msg)
    }
}

impl std::error::Error for Error {}

/// One subindex with its configured value.
#[derive(Debug, Clone, PartialEq, Eq)]
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
}

/// Finds the 1-based line of `[section]` (and of `key` inside it) in
/// `text`: rust-ini does not keep line numbers, so errors look them up.
pub fn locate(text: &str, section: &str, key: Option<&str>) -> Option<usize> {
    let mut in_section = false;
    let mut section_line = None;
    for (n, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if let Some(rest) = line.strip_prefix('[') {
            let name = rest.split(']').next().unwrap_or("").trim();
            if in_section {
                break;
            }
            in_section = name.eq_ignore_ascii_case(section);
            if in_section {
                section_line = Some(n + 1);
                if key.is_none() {
                    return section_line;
                }
            }
            continue;
        }
        if in_section {
            if let (Some(k), Some((lhs, _))) = (key, line.split_once('=')) {
                if lhs.trim().eq_ignore_ascii_case(k) {
                    return Some(n + 1);
                }
            }
        }
    }
    section_line
}

struct Ctx<'a> {
    file: &'a Path,
    text: &'a str,
}

impl Ctx<'_> {
    fn err(&self, section: &str, key: Option<&str>, msg: impl Into<String>) -> Error {
        Error {
            file: self.file.to_path_buf(),
            line: locate(self.text, section, key),
            section: Some(section.to_string()),
            key: key.map(str::to_string),
            msg: msg.into(),
        }
    }
}

/// Parses an integer the CiA 306 way: `0x` hex, a leading `0` octal,
/// otherwise decimal, optionally negative; `$NODEID` (with `+` on either
/// side) adds the node-ID.
pub fn parse_int(v: &str, node_id: Option<u8>) -> Result<i128, String> {
    let compact: String = v.chars().filter(|c| !c.is_whitespace()).collect();
    let upper = compact.to_ascii_uppercase();
    if upper.contains("$NODEID") {
        let node = node_id.ok_or(
            "uses $NODEID but no node-ID is known (give --node-id or [DeviceComissioning] NodeID)",
        )?;
        let rest = upper.replace("$NODEID", "");
        let rest = rest.trim_matches('+');
        let base = if rest.is_empty() {
            0
        } else {
            parse_int(rest, None)?
        };
        return Ok(base + i128::from(node));
    }
    let (neg, digits) = match upper.strip_prefix('-') {
        Some(d) => (true, d),
        None => (false, upper.as_str()),
    };
    let magnitude = if let Some(h) = digits.strip_prefix("0X") {
        i128::from_str_radix(h, 16)
    } else if digits.len() > 1 && digits.starts_with('0') {
        i128::from_str_radix(&digits[1..], 8)
    } else {
        digits.parse::<i128>()
    }
    .map_err(|_| format!("`{v}` is not a number"))?;
    Ok(if neg { -magnitude } else { magnitude })
}

/// Encodes `value` (the text of the file) for data type `t`.
fn encode_value(t: DataType, value: &str, node_id: Option<u8>) -> Result<Vec<u8>, String> {
    let value = value.trim();
    match t {
        DataType::VString | DataType::UString => Ok(value.as_bytes().to_vec()),
        DataType::OString | DataType::Domain => {
            let hex: String = value.chars().filter(|c| !c.is_whitespace()).collect();
            let hex = hex
                .strip_prefix("0x")
                .or_else(|| hex.strip_prefix("0X"))
                .unwrap_or(&hex);
            if hex.len() % 2 != 0 {
                return Err(format!("`{value}`: odd number of hex digits"));
            }
            (0..hex.len())
                .step_by(2)
                .map(|i| u8::from_str_radix(&hex[i..i + 2], 16))
                .collect::<Result<Vec<_>, _>>()
                .map_err(|_| format!("`{value}` is not hex digits"))
        }
        DataType::Real32 | DataType::Real64 => {
            let f: f64 = if value.is_empty() {
                0.0
            } else {
                value
                    .parse()
                    .map_err(|_| format!("`{value}` is not a number"))?
            };
            Ok(if t == DataType::Real32 {
                (f as f32).to_le_bytes().to_vec()
            } else {
                f.to_le_bytes().to_vec()
            })
        }
        _ => {
            let width = t.wire_size().unwrap_or(0);
            let v = if value.is_empty() {
                0
            } else {
                parse_int(value, node_id)?
            };
            let bits = 8 * width as u32;
            let (lo, hi) = if t.is_signed() {
                (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1)
            } else if t == DataType::Bool {
                (0, 1)
            } else {
                (0, (1i128 << bits) - 1)
            };
            if v < lo || v > hi {
                return Err(format!(
                    "{v} is out of range {lo}..={hi} for data type 0x{:04X}",
                    t.code()
                ));
            }
            Ok((v as u64).to_le_bytes()[..width].to_vec())
        }
    }
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
    (name.len() == 4)
        .then(|| u16::from_str_radix(name, 16).ok())
        .flatten()
}

fn is_sub_section(name: &str) -> Option<(u16, u8)> {
    let lower = name.to_ascii_lowercase();
    let (i, s) = lower.split_once("sub")?;
    if i.len() != 4 || s.is_empty() {
        return None;
    }
    Some((
        u16::from_str_radix(i, 16).ok()?,
        u8::from_str_radix(s, 16).ok()?,
    ))
}

/// Parses the text of a DCF/EDS (`file` names it in errors).
pub fn parse(text: &str, file: &Path, node_override: Option<u8>) -> Result<Dcf, Error> {
    let ctx = Ctx { file, text };
    let opt = ParseOption {
        enabled_quote: false,
        enabled_escape: false,
        enabled_indented_mutiline_value: false,
        enabled_preserve_key_leading_whitespace: false,
    };
    let ini = Ini::load_from_str_opt(text, opt).map_err(|e| Error {
        file: file.to_path_buf(),
        line: Some(e.line + 1),
        section: None,
        key: None,
        msg: e.msg.to_string(),
    })?;
    let node_id = match node_override {
        Some(n) => Some(n),
        None => match ini
            .section(Some("DeviceComissioning"))
            .and_then(|s| s.get("NodeID"))
        {
            Some(v) if !v.trim().is_empty() => {
                let n = parse_int(v, None)
                    .map_err(|m| ctx.err("DeviceComissioning", Some("NodeID"), m))?;
                Some(
                    u8::try_from(n)
                        .ok()
                        .filter(|n| (1..=127).contains(n))
                        .ok_or_else(|| {
                            ctx.err(
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
    let mut objects: BTreeMap<(u16, u8), Object> = BTreeMap::new();
    let get = |sec: &str, key: &str| {
        ini.section(Some(sec))
            .and_then(|s| s.get(key))
            .map(str::trim)
    };
    let variable = |sec: &str,
                    index: u16,
                    sub: u8,
                    fallback: Option<&str>|
     -> Result<Object, Error> {
        let dt_text = get(sec, "DataType").ok_or_else(|| ctx.err(sec, None, "no DataType"))?;
        let code = parse_int(dt_text, None).map_err(|m| ctx.err(sec, Some("DataType"), m))?;
        let t = u16::try_from(code)
            .ok()
            .and_then(DataType::from_code)
            .ok_or_else(|| {
                ctx.err(
                    sec,
                    Some("DataType"),
                    format!("data type {dt_text} is not supported"),
                )
            })?;
        if let Some(nv) = dcf::network_variable(index) {
            if sub != 0 && nv.typ != t {
                return Err(ctx.err(
                    sec,
                    Some("DataType"),
                    format!(
                        "0x{index:04X} holds data type 0x{:04X} (CiA 405 network variables, seed table 2), not {dt_text}",
                        nv.typ.code()
                    ),
                ));
            }
        }
        let access = get(sec, "AccessType")
            .ok_or_else(|| ctx.err(sec, None, "no AccessType"))?
            .to_ascii_lowercase();
        if !matches!(
            access.as_str(),
            "ro" | "wo" | "rw" | "rwr" | "rww" | "const"
        ) {
            return Err(ctx.err(
                sec,
                Some("AccessType"),
                format!("`{access}` is not an access type"),
            ));
        }
        let pdo_mapping = match get(sec, "PDOMapping") {
            Some(v) if !v.is_empty() => {
                parse_int(v, None).map_err(|m| ctx.err(sec, Some("PDOMapping"), m))? != 0
            }
            _ => false,
        };
        let (key, value) = match (get(sec, "ParameterValue"), get(sec, "DefaultValue")) {
            (Some(v), _) => ("ParameterValue", v),
            (None, Some(v)) => ("DefaultValue", v),
            (None, None) => ("DefaultValue", fallback.unwrap_or("")),
        };
        let data = encode_value(t, value, node_id).map_err(|m| ctx.err(sec, Some(key), m))?;
        Ok(Object {
            index,
            sub,
            data_type: t.code().into(),
            attr: attribute(t, &access, pdo_mapping),
            access,
            pdo_mapping,
            data,
        })
    };
    for name in ini.sections().flatten() {
        let Some(index) = is_object_section(name) else {
            continue;
        };
        let object_type = match get(name, "ObjectType") {
            Some(v) if !v.is_empty() => {
                parse_int(v, None).map_err(|m| ctx.err(name, Some("ObjectType"), m))?
            }
            _ => 7,
        };
        match object_type {
            2 | 7 => {
                let o = variable(name, index, 0, None)?;
                objects.insert((index, 0), o);
            }
            8 | 9 => {
                if let Some(n) = get(name, "CompactSubObj").filter(|v| !v.is_empty()) {
                    // CiA 306 compact array: subindices 1..n share the
                    // object's description; values may come from [XXXXValue].
                    let n =
                        parse_int(n, None).map_err(|m| ctx.err(name, Some("CompactSubObj"), m))?;
                    let n = u8::try_from(n)
                        .ok()
                        .filter(|n| *n >= 1 && *n < 255)
                        .ok_or_else(|| ctx.err(name, Some("CompactSubObj"), "must be 1..254"))?;
                    let values = format!("{index:04X}Value");
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
                        },
                    );
                    for s in 1..=n {
                        let v = get(&values, &s.to_string());
                        let mut o = variable(name, index, s, None)?;
                        if let Some(v) = v {
                            let t = DataType::from_code(o.data_type).unwrap_or(DataType::Domain);
                            o.data = encode_value(t, v, node_id)
                                .map_err(|m| ctx.err(&values, Some(&s.to_string()), m))?;
                        }
                        objects.insert((index, s), o);
                    }
                }
            }
            other => {
                return Err(ctx.err(
                    name,
                    Some("ObjectType"),
                    format!("object type {other} is not VAR, DOMAIN, ARRAY or RECORD"),
                ));
            }
        }
    }
    for name in ini.sections().flatten() {
        let Some((index, sub)) = is_sub_section(name) else {
            continue;
        };
        let parent = format!("{index:04X}");
        if ini.section(Some(parent.as_str())).is_none() {
            return Err(ctx.err(
                name,
                None,
                format!("subindex of [{parent}], which does not exist"),
            ));
        }
        let o = variable(name, index, sub, None)?;
        objects.insert((index, sub), o);
    }
    Ok(Dcf {
        file: file.to_path_buf(),
        node_id,
        objects: objects.into_values().collect(),
    })
}

/// Reads and parses a file.
pub fn load(path: &Path, node_override: Option<u8>) -> Result<(String, Dcf), Error> {
    let text = std::fs::read_to_string(path).map_err(|e| Error {
        file: path.to_path_buf(),
        line: None,
        section: None,
        key: None,
        msg: e.to_string(),
    })?;
    let d = parse(&text, path, node_override)?;
    Ok((text, d))
}

impl Dcf {
    /// The value of a subindex.
    pub fn get(&self, index: u16, sub: u8) -> Option<&Object> {
        self.objects
            .iter()
            .find(|o| o.index == index && o.sub == sub)
    }

    /// The process-image layout of the network variables (seed chapter 6).
    pub fn layout(&self) -> PiLayout {
        let mut l = PiLayout::default();
        for o in &self.objects {
            l.add(o.index, o.sub);
        }
        l
    }

    /// The entries of the index segment with their attributes.
    pub fn entries(&self) -> Vec<EntrySpec<'_>> {
        self.objects
            .iter()
            .map(|o| EntrySpec {
                index: o.index,
                sub: o.sub,
                data: &o.data,
                attr: o.attr,
            })
            .collect()
    }

    /// The address words, one per candidate (`cop::od::dcf::is_pi_candidate`).
    pub fn addresses(&self) -> Vec<u16> {
        let layout = self.layout();
        self.objects
            .iter()
            .filter(|o| {
                let others = self
                    .objects
                    .iter()
                    .any(|x| x.index == o.index && x.sub != o.sub);
                dcf::is_pi_candidate(o.index, o.sub, others)
            })
            .map(|o| match layout.place(o.index, o.sub) {
                Some((off, _)) => u16::try_from(off).unwrap_or(NOT_PLACED),
                None => NOT_PLACED,
            })
            .collect()
    }

    /// The process-image parameters, when there are network variables.
    pub fn pi_params(&self) -> Option<PiParams> {
        self.objects
            .iter()
            .any(|o| dcf::rule_offset(o.index, o.sub).is_some())
            .then(|| self.layout().params())
    }

    /// The binary container (all five segments where they have content).
    pub fn container(&self) -> Result<Vec<u8>, Error> {
        let entries = self.entries();
        let addresses = self.addresses();
        let addr = (!addresses.is_empty()).then_some(addresses.as_slice());
        let pi = self.pi_params();
        let whole = |msg: String| Error {
            file: self.file.clone(),
            line: None,
            section: None,
            key: None,
            msg,
        };
        let n = dcf::encoded_len(&entries, addr, true, pi.as_ref())
            .ok_or_else(|| whole("container larger than 4 GiB".into()))?;
        let mut out = vec![0u8; n];
        dcf::encode(&entries, addr, true, pi.as_ref(), &mut out)
            .map_err(|e| whole(format!("{e:?}")))?;
        // What the target will check, checked here first.
        dcf::Container::parse(&out)
            .map_err(|e| whole(format!("container does not validate: {e:?}")))?;
        Ok(out)
    }

    /// The SRDO configuration CRC (SAFETY_BEHAVIOUR.md section 3,
    /// CRC-16/XMODEM over direction, SCT, SRVT, COB-ID 1, COB-ID 2, mapping
    /// count, then subindex and entry of each mapping) of every SRDO the
    /// file configures: `(number, crc)`, number 1 for 0x1301.
    pub fn srdo_crcs(&self) -> Result<Vec<(u8, u16)>, Error> {
        let mut out = Vec::new();
        for n in 1..=64u8 {
            let commu = 0x1300 + u16::from(n);
            let mapp = 0x1380 + u16::from(n);
            if self.get(commu, 1).is_none() {
                continue;
            }
            let val = |index: u16, sub: u8| -> Result<&[u8], Error> {
                self.get(index, sub)
                    .map(|o| o.data.as_slice())
                    .ok_or_else(|| Error {
                        file: self.file.clone(),
                        line: None,
                        section: Some(format!("{index:04X}sub{sub}")),
                        key: None,
                        msg: format!("SRDO {n} needs 0x{index:04X} sub {sub} for its CRC"),
                    })
            };
            let mut stream = Vec::new();
            for (index, sub) in [
                (commu, 1),
                (commu, 2),
                (commu, 3),
                (commu, 5),
                (commu, 6),
                (mapp, 0),
            ] {
                stream.extend_from_slice(val(index, sub)?);
            }
            let count = *val(mapp, 0)?.first().unwrap_or(&0);
            for s in 1..=count {
                stream.push(s);
                stream.extend_from_slice(val(mapp, s)?);
            }
            out.push((n, cop::srdo::crc::crc16(&stream)));
        }
        Ok(out)
    }
}

/// Writes `crcs` into the DCF text as the values of 0x13FF sub n
/// (`ParameterValue` when the section has one or is a DCF, else
/// `DefaultValue`); every other line stays as it was. The sections must
/// exist.
pub fn write_crcs(text: &str, file: &Path, crcs: &[(u8, u16)]) -> Result<String, Error> {
    let newline = if text.contains("\r\n") { "\r\n" } else { "\n" };
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for (n, crc) in crcs {
        let section = format!("13FFsub{n:X}");
        let ctx = Ctx { file, text };
        let head = locate(text, &section, None).ok_or_else(|| {
            ctx.err(
                &section,
                None,
                "section missing: add 0x13FF sub n to the DCF",
            )
        })?;
        let value = format!("0x{crc:04X}");
        let key_line = ["ParameterValue", "DefaultValue"].iter().find_map(|k| {
            locate(text, &section, Some(k))
                .filter(|l| *l != head)
                .map(|l| (k, l))
        });
        match key_line {
            Some((k, l)) => lines[l - 1] = format!("{k}={value}"),
            None => lines[head - 1].push_str(&format!("{newline}ParameterValue={value}")),
        }
    }
    let mut out = lines.join(newline);
    if text.ends_with('\n') {
        out.push_str(newline);
    }
    Ok(out)
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
