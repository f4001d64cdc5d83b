//! The static dictionary of a node, for `--check`: read from the node's
//! C folder (its `copcfg.h`, `obdcfg.h` and `objdict.h`, turned into tables
//! by the library's own `include/objdef.h` and the host C compiler), or
//! from the node's EDS; then built as a `cop` dictionary in this process.
//!
//! # The C folder
//! A small C program includes `objdef.h` (which expands `objdict.h` into
//! the very tables the library runs on), calls the generated
//! `ObdInitRam`, and prints every subindex: type, access, storage kind,
//! size, value, limits, and the configuration values `copdef.h` settles.
//! It is linked with unresolved symbols allowed, because the application's
//! callbacks and `OBD_SUBINDEX_RAM_EXTVAR` variables live in the
//! application, not in `objdict.h`: the check runs without the callbacks,
//! and an application variable starts at 0 (its value is the
//! application's). The host C compiler is `$CC`, else `cc`; the library's
//! headers come from `$COP_INCLUDE_DIR`, else the source tree this tool
//! was built from.
//!
//! # An EDS as node description
//! Every object of the EDS becomes a variable with its value: `const` and
//! `ro` objects constant, the others RAM; ranges from `LowLimit` and
//! `HighLimit`. An EDS does not give string capacities: strings and
//! domains take up to [`eds_string_capacity`] bytes.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::AtomicU8;

use cop::od::{
    Access, DataType, ObdEntry, ObdSize, ObdSubEntry, ObdVarEntry, ObjectDictionary, value,
};

use crate::Dcf;

/// Capacity of strings and domains of a node described by an EDS: the
/// largest object the library's `tObdSize` (`OBD_SUPPORTED_OBJ_SIZE`)
/// allows, at most 4096 bytes.
pub fn eds_string_capacity() -> usize {
    // tObdSize is u8, u16 or u32 depending on the configuration.
    #[allow(clippy::unnecessary_fallible_conversions)]
    usize::try_from(ObdSize::MAX)
        .unwrap_or(usize::MAX)
        .min(4096)
}

/// How a subindex stores its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A variable.
    Ram,
    /// A constant.
    Rom,
    /// A visible string in RAM (capacity in `size`).
    RamString,
    /// A constant visible string.
    RomString,
    /// A variable the application attaches (DOMAIN, USERDEF).
    Var,
}

/// One subindex of the node's static dictionary.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NodeObject {
    /// Index.
    pub index: u16,
    /// Subindex.
    pub sub: u8,
    /// Data type.
    pub typ: DataType,
    /// `tObdAccess` bits.
    pub access: u8,
    /// Storage.
    pub kind: Kind,
    /// C width of a variable, capacity of a string or domain.
    pub size: usize,
    /// The value in CANopen byte order; `None` for an application variable
    /// whose value the tables do not hold.
    pub value: Option<Vec<u8>>,
    /// Low and high limit in CANopen byte order.
    pub limits: Option<(Vec<u8>, Vec<u8>)>,
    /// The index has an OBD callback (not run by the check).
    pub callback: bool,
}

/// A node: its objects and, from a C folder, its configuration.
#[derive(Debug, Clone, Default)]
pub struct Node {
    /// Where it was read from.
    pub source: PathBuf,
    /// Every subindex, ascending.
    pub objects: Vec<NodeObject>,
    /// The configuration values (`OBD_DYNAMIC_POOL_SIZE`, ...) as the C
    /// compiler sees them; empty for an EDS.
    pub config: BTreeMap<String, i64>,
}

fn leak_bytes(b: &[u8]) -> &'static [u8] {
    Box::leak(b.to_vec().into_boxed_slice())
}

fn leak_ram(n: usize) -> &'static [AtomicU8] {
    Box::leak(
        (0..n)
            .map(|_| AtomicU8::new(0))
            .collect::<Vec<_>>()
            .into_boxed_slice(),
    )
}

/// Native bytes of a wire value in a variable of `size` bytes.
fn native(typ: DataType, wire: &[u8], size: usize) -> Result<Vec<u8>, String> {
    if typ.wire_size().is_none() {
        return Ok(wire.to_vec());
    }
    let mut out = vec![0u8; size];
    value::wire_to_native(typ, wire, size, &mut out)
        .map_err(|e| format!("value of {} bytes: {:?}", wire.len(), e.kernel))?;
    Ok(out)
}

impl Node {
    /// The node as a `cop` dictionary (tables allocated for the rest of the
    /// process, as a firmware's are static).
    pub fn dictionary(&self) -> Result<ObjectDictionary, String> {
        let mut parts: [Vec<ObdEntry>; 3] = Default::default();
        let mut i = 0;
        while i < self.objects.len() {
            let index = self.objects[i].index;
            let mut subs = Vec::new();
            while let Some(o) = self.objects.get(i).filter(|o| o.index == index) {
                subs.push(
                    sub_entry(o).map_err(|m| format!("0x{:04X} sub {}: {m}", o.index, o.sub))?,
                );
                i += 1;
            }
            let subs: &'static [ObdSubEntry] = Box::leak(subs.into_boxed_slice());
            let part = match index {
                0x1000..=0x1FFF => 0,
                0x2000..=0x5FFF => 1,
                0x6000..=0x9FFF => 2,
                _ => {
                    return Err(format!(
                        "0x{index:04X}: a static dictionary holds 0x1000..0x9FFF (the rest is the user part)"
                    ));
                }
            };
            parts[part].push(ObdEntry::new(index, subs, None));
        }
        let [g, m, d] = parts;
        let leak = |v: Vec<ObdEntry>| -> &'static [ObdEntry] { Box::leak(v.into_boxed_slice()) };
        ObjectDictionary::new(leak(g), leak(m), leak(d))
            .map_err(|e| format!("the node's tables are refused: {e:?}"))
    }
}

fn sub_entry(o: &NodeObject) -> Result<ObdSubEntry, String> {
    let access = Access(o.access & !(Access::ARRAY | Access::RANGE | Access::VAR));
    let wire = o.value.clone().unwrap_or_default();
    let fixed = o.typ.wire_size().is_some();
    let wire = if fixed && o.value.is_none() {
        vec![0; o.typ.wire_size().unwrap_or(0)]
    } else {
        wire
    };
    Ok(match o.kind {
        Kind::Rom => {
            let v = native(o.typ, &wire, o.size)?;
            ObdSubEntry::rom(o.sub, o.typ, access, leak_bytes(&v))
        }
        Kind::RomString => ObdSubEntry::rom_string(o.sub, access, leak_bytes(&wire)),
        Kind::RamString => {
            let cap = o.size.max(wire.len());
            let buf = leak_ram(cap + 1);
            value::store(&buf[..wire.len()], &wire);
            let mut c = wire.clone();
            c.push(0);
            let cstr = std::ffi::CString::from_vec_with_nul(c)
                .map_err(|_| "a string with a NUL inside".to_string())?;
            ObdSubEntry::ram_string(o.sub, access, buf, Box::leak(cstr.into_boxed_c_str()))
        }
        Kind::Ram | Kind::Var if fixed => {
            let v = native(o.typ, &wire, o.size)?;
            let cur = leak_ram(o.size);
            value::store(cur, &v);
            match &o.limits {
                Some((lo, hi)) => {
                    let mut l = v.clone();
                    l.extend(native(o.typ, lo, o.size)?);
                    l.extend(native(o.typ, hi, o.size)?);
                    ObdSubEntry::ram_range(o.sub, o.typ, access, cur, leak_bytes(&l))
                }
                None => ObdSubEntry::ram(o.sub, o.typ, access, cur, Some(leak_bytes(&v))),
            }
        }
        Kind::Ram | Kind::Var => {
            // A domain or string the application attaches: attached here to
            // a buffer of its capacity holding its value.
            let cap = o.size.max(wire.len());
            let var: &'static ObdVarEntry = Box::leak(Box::new(ObdVarEntry::new()));
            let buf = leak_ram(cap);
            value::store(&buf[..wire.len()], &wire);
            if !var.attach(buf) {
                return Err(format!("{cap} bytes do not fit tObdSize"));
            }
            ObdSubEntry::var(o.sub, o.typ, access, var, cap as u32, None)
        }
    })
}

/// The node an EDS describes (see the module documentation).
pub fn from_eds(d: &Dcf) -> Node {
    let objects = d
        .objects
        .iter()
        .map(|o| {
            let typ = o.typ();
            let constant = matches!(o.access.as_str(), "ro" | "const");
            let mut access = match o.access.as_str() {
                "wo" => Access::WRITE,
                "ro" | "const" => Access::READ,
                _ => Access::READ | Access::WRITE,
            };
            if o.pdo_mapping {
                access |= Access::PDO;
            }
            let (kind, size) = match (typ, constant) {
                (DataType::VString, true) => (Kind::RomString, o.data.len()),
                (DataType::VString, false) => (Kind::RamString, eds_string_capacity()),
                (t, true) if t.wire_size().is_none() => (Kind::Rom, o.data.len()),
                (t, _) if t.wire_size().is_none() => (Kind::Var, eds_string_capacity()),
                (t, true) => (Kind::Rom, cop::od::dcf::element_size(t)),
                (t, false) => (Kind::Ram, cop::od::dcf::element_size(t)),
            };
            let limits = match o.limits {
                (Some(lo), Some(hi)) if kind == Kind::Ram => {
                    let enc = |n: crate::value::Number| match n {
                        crate::value::Number::Int(i) => {
                            (i as u64).to_le_bytes()[..typ.wire_size().unwrap_or(0)].to_vec()
                        }
                        crate::value::Number::Real(r) if typ == DataType::Real32 => {
                            (r as f32).to_le_bytes().to_vec()
                        }
                        crate::value::Number::Real(r) => r.to_le_bytes().to_vec(),
                    };
                    Some((enc(lo), enc(hi)))
                }
                _ => None,
            };
            NodeObject {
                index: o.index,
                sub: o.sub,
                typ,
                access,
                kind,
                size,
                value: Some(o.data.clone()),
                limits,
                callback: false,
            }
        })
        .collect();
    Node {
        source: d.file.clone(),
        objects,
        config: BTreeMap::new(),
    }
}

/// The configuration keys the dump prints (those `build.rs` reads).
pub const CONFIG_KEYS: &[&str] = &[
    "OBD_SUPPORTED_OBJ_SIZE",
    "SRDO_GRANULARITY",
    "SRDO_USE_STATIC_MAPPING",
    "SRDO_USE_DUMMY_MAPPING",
    "SRDO_ALLOW_GAPS_IN_OD",
    "SRDO_USE_GFC",
    "SRDO_USE_PROGMONITOR",
    "SRDO_MAX_SRDO_IN_OBD",
    "PDO_GRANULARITY",
    "PDO_USE_BIT_MAPPING",
    "PDO_USE_DUMMY_MAPPING",
    "PDO_MAX_MAPPENTRIES",
    "PDO_MAX_RXPDO_IN_OBD",
    "PDO_MAX_TXPDO_IN_OBD",
    "SDO_MAX_CLIENT_IN_OBD",
    "HBC_MAX_CONSUMER_IN_OBD",
    "NMTS_USE_LIFEGUARDING",
    "OBD_DYNAMIC_POOL_SIZE",
    "OBD_USE_DYNAMIC_OD",
];

/// The dump program (see the module documentation).
const DUMP_C: &str = include_str!("od_dump.c");

/// The library's C headers.
pub fn include_dir() -> PathBuf {
    std::env::var_os("COP_INCLUDE_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../include"))
}

/// Reads the node of C folder `dir` (its `objdict.h`, or `objdict`).
pub fn from_c_folder(dir: &Path, objdict: Option<&Path>) -> Result<Node, String> {
    if !dir.join("copcfg.h").is_file() {
        return Err(format!("{}: no copcfg.h in this folder", dir.display()));
    }
    let objdict = match objdict {
        Some(p) => p.to_path_buf(),
        None => dir.join("objdict.h"),
    };
    if !objdict.is_file() {
        return Err(format!(
            "{}: not found (give the node's dictionary with --objdict)",
            objdict.display()
        ));
    }
    let objdict = objdict.canonicalize().map_err(|e| e.to_string())?;
    let include = include_dir();
    let work = std::env::temp_dir().join(format!("dcf2bin-node-{}", std::process::id()));
    std::fs::create_dir_all(&work).map_err(|e| format!("{}: {e}", work.display()))?;
    let result = (|| {
        let mut keys = String::new();
        for k in CONFIG_KEYS {
            keys.push_str(&format!("    COP_DUMP_KEY({k});\n"));
        }
        let src = work.join("od_dump.c");
        std::fs::write(&src, DUMP_C.replace("    /* COP_DUMP_KEYS */\n", &keys))
            .map_err(|e| e.to_string())?;
        let exe = work.join("od_dump");
        let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
        let mut cmd = Command::new(&cc);
        cmd.arg("-w")
            .arg(format!("-I{}", dir.display()))
            .arg(format!(
                "-I{}",
                objdict.parent().unwrap_or(Path::new(".")).display()
            ))
            .arg(format!("-I{}", include.display()))
            .arg(format!("-I{}", include.join("default_cfg").display()))
            .arg(format!("-DOBD_OBJDICT_FILE=\"{}\"", objdict.display()))
            .arg(&src)
            .arg("-o")
            .arg(&exe)
            .arg("-Wl,--unresolved-symbols=ignore-all");
        let out = cmd
            .output()
            .map_err(|e| format!("{cc}: {e} (the C compiler turns objdict.h into tables)"))?;
        if !out.status.success() {
            return Err(format!(
                "{cc} could not compile {} with the library's objdef.h:\n{}",
                objdict.display(),
                String::from_utf8_lossy(&out.stderr)
            ));
        }
        let run = Command::new(&exe).output().map_err(|e| e.to_string())?;
        if !run.status.success() {
            return Err(format!(
                "the tables of {} could not be read: {}",
                objdict.display(),
                String::from_utf8_lossy(&run.stdout)
            ));
        }
        parse_dump(&String::from_utf8_lossy(&run.stdout))
    })();
    let _ = std::fs::remove_dir_all(&work);
    let mut node = result?;
    node.source = dir.to_path_buf();
    Ok(node)
}

fn hex(s: &str) -> Result<Option<Vec<u8>>, String> {
    if s == "-" {
        return Ok(None);
    }
    if s == "." {
        return Ok(Some(Vec::new()));
    }
    (0..s.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(s.get(i..i + 2).unwrap_or("x"), 16))
        .collect::<Result<Vec<_>, _>>()
        .map(Some)
        .map_err(|_| format!("bad hex `{s}`"))
}

/// Reads the dump program's output.
fn parse_dump(text: &str) -> Result<Node, String> {
    let mut node = Node::default();
    let mut callback = false;
    let mut index = 0u16;
    for line in text.lines() {
        let f: Vec<&str> = line.split(' ').collect();
        let bad = || format!("dump line `{line}`");
        let num = |s: &str, radix| u64::from_str_radix(s, radix).map_err(|_| bad());
        match f.as_slice() {
            ["cfg", key, v] => {
                node.config
                    .insert((*key).to_string(), v.parse().map_err(|_| bad())?);
            }
            ["index", i, cb] => {
                index = num(i, 16)? as u16;
                callback = *cb == "1";
            }
            ["sub", sub, typ, acc, kind, size, count, val, low, high] => {
                let typ = DataType::from_code(num(typ, 16)? as u16)
                    .ok_or_else(|| format!("0x{index:04X}: data type {typ} unknown"))?;
                let access = num(acc, 16)? as u8;
                let size = num(size, 10)? as usize;
                let count = num(count, 10)? as usize;
                let kind = match *kind {
                    "0" => Kind::Ram,
                    "1" => Kind::Rom,
                    "2" => Kind::RamString,
                    "3" => Kind::RomString,
                    "4" => Kind::Var,
                    _ => return Err(bad()),
                };
                let raw = hex(val)?;
                let limits = match (hex(low)?, hex(high)?) {
                    (Some(l), Some(h)) => Some((l, h)),
                    _ => None,
                };
                let first = num(sub, 16)? as u8;
                // An array entry stands for `count` subindices.
                for n in 0..count.max(1) {
                    let element = raw
                        .as_ref()
                        .map(|r| r.get(n * size..(n + 1) * size).unwrap_or(&[]).to_vec());
                    let wire = |b: &[u8]| -> Result<Vec<u8>, String> {
                        if typ.wire_size().is_none() {
                            return Ok(b.to_vec());
                        }
                        let mut out = [0u8; 8];
                        let len = value::native_to_wire(typ, b, &mut out)
                            .map_err(|e| format!("0x{index:04X}: {:?}", e.kernel))?;
                        Ok(out[..len].to_vec())
                    };
                    let value = match element {
                        Some(e) if typ.wire_size().is_some() && e.len() < size => None,
                        Some(e) => Some(wire(&e)?),
                        None => None,
                    };
                    let limits = match &limits {
                        Some((l, h)) => Some((wire(l)?, wire(h)?)),
                        None => None,
                    };
                    node.objects.push(NodeObject {
                        index,
                        sub: first.wrapping_add(n as u8),
                        typ,
                        access: access & !Access::ARRAY,
                        kind,
                        size,
                        value,
                        limits,
                        callback,
                    });
                }
            }
            [] | [""] => {}
            _ => return Err(bad()),
        }
    }
    node.objects.sort_by_key(|o| (o.index, o.sub));
    Ok(node)
}
