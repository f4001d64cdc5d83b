//! Writes the dictionary (static parts and dynamic OD alike) as an
//! electronic data sheet (CiA 306 EDS) into any [`core::fmt::Write`] sink,
//! so it works without heap on the target too (into a buffer, a UART, an
//! SDO domain) and on the host into a `String`.
//!
//! What is written:
//! * `[FileInfo]`, `[DeviceInfo]` from [`EdsInfo`] and the dictionary
//!   (number of RPDOs/TPDOs), `[DummyUsage]`, the three object lists;
//! * one section per object: a single subindex 0 is a VAR (0x7); more
//!   subindices of one type an ARRAY (0x8), of several types a RECORD
//!   (0x9), each subindex in its own `[xxxxsubN]` section (array elements
//!   of `kObdAccArray` entries included);
//! * `DefaultValue` is the **current** value (the EDS describes the device
//!   as it is, e.g. after `DynBuildOd`): unsigned numbers in hex, signed in
//!   decimal, REAL32/64 as decimal fractions, BOOLEAN 0/1, VISIBLE_STRING
//!   and UNICODE_STRING as text (characters an INI line cannot carry, i.e.
//!   control characters and `;`, become `_`), OCTET_STRING and DOMAIN as
//!   hex digits (CiA 306 4.3, the form python-canopen reads),
//!   TIME_OF_DAY/TIME_DIFFERENCE as the 48-bit number; objects without readable value (an unattached USERDEF
//!   variable) have none;
//! * `AccessType` `const`, `ro`, `wo` or `rw`; `PDOMapping`; `LowLimit` and
//!   `HighLimit` for objects with a value range;
//! * `DataType` is the type the dictionary has. A numeric object the
//!   dynamic OD created is UNSIGNEDn of its size (the container carries no
//!   data type, seed 2.1.4); the type the device description gave it can be
//!   handed in [`EdsInfo::types`] and is then written, with the value in its
//!   form (INTEGER24 −1 as `-1`, not UNSIGNED24 `0xFFFFFF`);
//! * CANopen safety (CiA 304) with the keys of CiA 306: `[DeviceInfo]
//!   CANopenSafetySupported=1` when the dictionary has SRDOs (0x1301 ..
//!   0x1340); on every object an SRDO mapping (0x1381 .. 0x13C0) maps,
//!   `SRDOMapping=1`, and on the normal data of each pair (mapping entries
//!   2k−1 and 2k) `InvertedSRAD=0xIIIISS`, index (four hex digits) and
//!   subindex (two) of its inverted data;
//! * parameter names: the CiA 301/304 name for communication objects,
//!   "Network variables ..." for 0xA000-0xAFFF, otherwise
//!   "Object 0xXXXX"; subindices "Highest sub-index supported" (subindex 0
//!   of arrays and records) or "Sub-index N". The dictionary carries no
//!   names, so these are what a tool shows.

use core::fmt::{self, Write};

use super::{Access, ByteOrder, DataType, ObdEntry, Object, ObjectDictionary, Part, value};
use crate::wire::srdo::{
    COMMU_FIRST as SRDO_COMMU_FIRST, COMMU_LAST as SRDO_COMMU_LAST, MAPP_FIRST as SRDO_MAPP_FIRST,
    MAPP_LAST as SRDO_MAPP_LAST,
};

/// CiA 301 name of a data type (`INTEGER24`, `VISIBLE_STRING`, ...).
pub const fn type_name(t: DataType) -> &'static str {
    use DataType::*;
    match t {
        Bool => "BOOLEAN",
        Int8 => "INTEGER8",
        Int16 => "INTEGER16",
        Int24 => "INTEGER24",
        Int32 => "INTEGER32",
        Int40 => "INTEGER40",
        Int48 => "INTEGER48",
        Int56 => "INTEGER56",
        Int64 => "INTEGER64",
        UInt8 => "UNSIGNED8",
        UInt16 => "UNSIGNED16",
        UInt24 => "UNSIGNED24",
        UInt32 => "UNSIGNED32",
        UInt40 => "UNSIGNED40",
        UInt48 => "UNSIGNED48",
        UInt56 => "UNSIGNED56",
        UInt64 => "UNSIGNED64",
        Real32 => "REAL32",
        Real64 => "REAL64",
        VString => "VISIBLE_STRING",
        OString => "OCTET_STRING",
        UString => "UNICODE_STRING",
        TimeOfDay => "TIME_OF_DAY",
        TimeDiff => "TIME_DIFFERENCE",
        Domain => "DOMAIN",
    }
}

/// Device data for `[DeviceInfo]` and `[FileInfo]`.
#[derive(Clone, Copy, Debug)]
pub struct EdsInfo<'a> {
    /// `FileName`.
    pub file_name: &'a str,
    /// `VendorName`.
    pub vendor_name: &'a str,
    /// `VendorNumber` (0x1018 sub 1).
    pub vendor_number: u32,
    /// `ProductName`.
    pub product_name: &'a str,
    /// `ProductNumber` (0x1018 sub 2).
    pub product_number: u32,
    /// `RevisionNumber` (0x1018 sub 3).
    pub revision_number: u32,
    /// `Description` in `[FileInfo]`.
    pub description: &'a str,
    /// Data types the device description gave objects of the user part
    /// (index, subindex, type): used for an object the dictionary holds as
    /// UNSIGNEDn when the given type is numeric of the same size (the
    /// dynamic OD's NUMERIC objects), and for one it holds as DOMAIN when
    /// the given type is OCTET_STRING, UNICODE_STRING, TIME_OF_DAY or
    /// TIME_DIFFERENCE (kept bytewise); otherwise the dictionary's type.
    pub types: &'a [(u16, u8, DataType)],
}

impl Default for EdsInfo<'_> {
    fn default() -> Self {
        EdsInfo {
            file_name: "device.eds",
            vendor_name: "",
            vendor_number: 0,
            product_name: "",
            product_number: 0,
            revision_number: 0,
            description: "Object dictionary of a cop device",
            types: &[],
        }
    }
}

/// CiA 306 object types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ObjectType {
    /// 0x7.
    Var = 0x7,
    /// 0x8.
    Array = 0x8,
    /// 0x9.
    Record = 0x9,
}

/// How an entry is described.
pub fn object_type(od: &ObjectDictionary, entry: &'static ObdEntry) -> ObjectType {
    let subs = entry.subs();
    let only_sub0 = subs.len() == 1 && subs.first().is_some_and(|s| s.sub() == 0);
    if only_sub0
        && subs
            .first()
            .is_some_and(|s| s.access().0 & Access::ARRAY == 0)
    {
        return ObjectType::Var;
    }
    // CiA 301/304 define these as records (identity, SDO, PDO and SRDO
    // parameters) even where every subindex has one type.
    if matches!(entry.index(), 0x1018 | 0x1200..=0x12FF | 0x1301..=0x13C0 | 0x1400..=0x1BFF) {
        return ObjectType::Record;
    }
    let mut first: Option<DataType> = None;
    for sub in 1..od.sub_count(entry).min(256) {
        if let Ok(o) = od.find(entry.index(), sub as u8) {
            match first {
                None => first = Some(o.data_type()),
                Some(t) if t != o.data_type() => return ObjectType::Record,
                Some(_) => {}
            }
        }
    }
    ObjectType::Array
}

/// Writes `od` as an EDS.
pub fn write_eds(od: &ObjectDictionary, info: &EdsInfo<'_>, out: &mut impl Write) -> fmt::Result {
    writeln!(out, "[FileInfo]")?;
    writeln!(out, "FileName={}", info.file_name)?;
    writeln!(out, "FileVersion=1")?;
    writeln!(out, "FileRevision=0")?;
    writeln!(out, "EDSVersion=4.0")?;
    writeln!(out, "Description={}", Text(info.description))?;
    writeln!(out, "CreatedBy=cop")?;
    writeln!(out)?;
    let count = |lo: u16, hi: u16| {
        od.entries()
            .filter(|e| (lo..=hi).contains(&e.index()))
            .count()
    };
    writeln!(out, "[DeviceInfo]")?;
    writeln!(out, "VendorName={}", Text(info.vendor_name))?;
    writeln!(out, "VendorNumber=0x{:08X}", info.vendor_number)?;
    writeln!(out, "ProductName={}", Text(info.product_name))?;
    writeln!(out, "ProductNumber=0x{:08X}", info.product_number)?;
    writeln!(out, "RevisionNumber=0x{:08X}", info.revision_number)?;
    for rate in [10, 20, 50, 125, 250, 500, 800, 1000] {
        writeln!(out, "BaudRate_{rate}=1")?;
    }
    writeln!(out, "SimpleBootUpMaster=0")?;
    writeln!(out, "SimpleBootUpSlave=1")?;
    writeln!(out, "Granularity=8")?;
    writeln!(out, "DynamicChannelsSupported=0")?;
    writeln!(out, "GroupMessaging=0")?;
    writeln!(out, "NrOfRXPDO={}", count(0x1400, 0x15FF))?;
    writeln!(out, "NrOfTXPDO={}", count(0x1800, 0x19FF))?;
    writeln!(out, "LSS_Supported=0")?;
    if count(SRDO_COMMU_FIRST, SRDO_COMMU_LAST) > 0 {
        writeln!(out, "CANopenSafetySupported=1")?;
    }
    writeln!(out)?;
    writeln!(out, "[DummyUsage]")?;
    for t in 1..=7 {
        writeln!(out, "Dummy{t:04}=0")?;
    }
    writeln!(out)?;
    let mandatory = |i: u16| matches!(i, 0x1000 | 0x1001 | 0x1018);
    let manufacturer = |i: u16| Part::of(i) == Part::Manufacturer;
    let lists: [(&str, &dyn Fn(u16) -> bool); 3] = [
        ("MandatoryObjects", &mandatory),
        ("OptionalObjects", &|i| !mandatory(i) && !manufacturer(i)),
        ("ManufacturerObjects", &manufacturer),
    ];
    for (name, pick) in lists {
        writeln!(out, "[{name}]")?;
        let indices = sorted(od).filter(|e| pick(e.index()));
        writeln!(out, "SupportedObjects={}", indices.clone().count())?;
        for (n, e) in (1..).zip(indices) {
            writeln!(out, "{n}=0x{:04X}", e.index())?;
        }
        writeln!(out)?;
    }
    for e in sorted(od) {
        write_object(od, info, e, out)?;
    }
    Ok(())
}

/// The entries in ascending index order (the user part may hold indices
/// of every range).
fn sorted(od: &ObjectDictionary) -> impl Iterator<Item = &'static ObdEntry> + Clone + '_ {
    let mut last: Option<u16> = None;
    core::iter::from_fn(move || {
        let next = od
            .entries()
            .filter(|e| last.is_none_or(|l| e.index() > l))
            .min_by_key(|e| e.index())?;
        last = Some(next.index());
        Some(next)
    })
}

fn write_object(
    od: &ObjectDictionary,
    info: &EdsInfo<'_>,
    e: &'static ObdEntry,
    out: &mut impl Write,
) -> fmt::Result {
    let index = e.index();
    let ot = object_type(od, e);
    writeln!(out, "[{index:04X}]")?;
    writeln!(out, "ParameterName={}", ObjectName(index))?;
    writeln!(out, "ObjectType=0x{:X}", ot as u8)?;
    if ot == ObjectType::Var {
        if let Ok(o) = od.find(index, 0) {
            write_value_keys(od, info, &o, out)?;
        }
        return writeln!(out);
    }
    let subs = (0..od.sub_count(e).min(256)).filter(|s| od.find(index, *s as u8).is_ok());
    writeln!(out, "SubNumber={}", subs.clone().count())?;
    writeln!(out)?;
    for sub in subs {
        let sub = sub as u8;
        let Ok(o) = od.find(index, sub) else {
            continue;
        };
        writeln!(out, "[{index:04X}sub{sub:X}]")?;
        writeln!(out, "ParameterName={}", SubName(index, sub))?;
        writeln!(out, "ObjectType=0x7")?;
        write_value_keys(od, info, &o, out)?;
        writeln!(out)?;
    }
    Ok(())
}

/// The type to write for `o`: the dictionary's, or the one `info` gives
/// an object of the user part that the dictionary holds as UNSIGNEDn or
/// DOMAIN (see [`EdsInfo::types`]).
fn exported_type(od: &ObjectDictionary, info: &EdsInfo<'_>, o: &Object) -> DataType {
    let t = o.data_type();
    let unsigned = matches!(
        t,
        DataType::UInt8
            | DataType::UInt16
            | DataType::UInt24
            | DataType::UInt32
            | DataType::UInt40
            | DataType::UInt48
            | DataType::UInt56
            | DataType::UInt64
    );
    let user = od.part(Part::User).iter().any(|e| e.index() == o.index());
    if !(unsigned || t == DataType::Domain) || !user {
        return t;
    }
    info.types
        .iter()
        .find(|(i, s, _)| (*i, *s) == (o.index(), o.sub()))
        .map(|(_, _, d)| *d)
        .filter(|d| {
            if unsigned {
                d.is_numeric() && d.wire_size() == t.wire_size()
            } else {
                // Bytes the dynamic OD keeps as DOMAIN (no attribute).
                matches!(
                    d,
                    DataType::OString
                        | DataType::UString
                        | DataType::TimeOfDay
                        | DataType::TimeDiff
                )
            }
        })
        .unwrap_or(t)
}

/// What an object is to the SRDOs of the dictionary (CiA 304).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SrdoRole {
    /// Mapped by no SRDO.
    None,
    /// Normal data of a pair, with the index and subindex of its inverted
    /// data.
    Normal(u16, u8),
    /// Inverted data of a pair.
    Inverted,
}

/// An object's value as a number (up to 8 bytes, CANopen byte order).
fn read_number(od: &ObjectDictionary, index: u16, sub: u8) -> Option<u64> {
    let o = od.find(index, sub).ok()?;
    let mut b = [0u8; 8];
    let n = od.peek(&o, ByteOrder::Wire, &mut b).ok()?;
    Some(value::le_to_u64(b.get(..n)?))
}

/// Index and subindex a mapping entry names.
fn srdo_entry(od: &ObjectDictionary, mapp: u16, sub: u8) -> Option<(u16, u8)> {
    let v = read_number(od, mapp, sub)?;
    Some(((v >> 16) as u16, (v >> 8) as u8))
}

/// The role of `index`/`sub` in the SRDO mappings (the first pair that
/// maps it).
fn srdo_role(od: &ObjectDictionary, index: u16, sub: u8) -> SrdoRole {
    for mapp in SRDO_MAPP_FIRST..=SRDO_MAPP_LAST {
        let Some(count) = read_number(od, mapp, 0) else {
            continue;
        };
        for pair in 0..(count.min(u64::from(u8::MAX)) as u8) / 2 {
            let normal = srdo_entry(od, mapp, 2 * pair + 1);
            let inverted = srdo_entry(od, mapp, 2 * pair + 2);
            match (normal, inverted) {
                (Some(n), Some(i)) if n == (index, sub) => return SrdoRole::Normal(i.0, i.1),
                (Some(_), Some(i)) if i == (index, sub) => return SrdoRole::Inverted,
                _ => {}
            }
        }
    }
    SrdoRole::None
}

fn write_value_keys(
    od: &ObjectDictionary,
    info: &EdsInfo<'_>,
    o: &Object,
    out: &mut impl Write,
) -> fmt::Result {
    let a = o.access();
    let access = if a.0 & Access::CONST != 0 {
        "const"
    } else {
        match (a.readable(), a.writable()) {
            (true, true) => "rw",
            (false, true) => "wo",
            _ => "ro",
        }
    };
    let typ = exported_type(od, info, o);
    writeln!(out, "DataType=0x{:04X}", typ.code())?;
    writeln!(out, "AccessType={access}")?;
    if let Some((low, high)) = o.desc().limits() {
        writeln!(out, "LowLimit={}", Native(o.data_type(), low))?;
        writeln!(out, "HighLimit={}", Native(o.data_type(), high))?;
    }
    let mut buf = [0u8; 256];
    if let Ok(n) = od.peek(o, ByteOrder::Wire, &mut buf) {
        writeln!(
            out,
            "DefaultValue={}",
            Wire(typ, buf.get(..n).unwrap_or(&[]))
        )?;
    }
    writeln!(out, "PDOMapping={}", u8::from(a.mappable()))?;
    // Only mappable objects can be in an SRDO (the configuration check).
    if a.mappable() {
        match srdo_role(od, o.index(), o.sub()) {
            SrdoRole::None => {}
            SrdoRole::Normal(i, s) => {
                writeln!(out, "SRDOMapping=1")?;
                writeln!(out, "InvertedSRAD=0x{i:04X}{s:02X}")?;
            }
            SrdoRole::Inverted => writeln!(out, "SRDOMapping=1")?,
        }
    }
    Ok(())
}

/// A value in CANopen byte order, formatted for an EDS.
struct Wire<'a>(DataType, &'a [u8]);

impl fmt::Display for Wire<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Wire(t, b) = *self;
        let v = value::le_to_u64(b);
        match t {
            DataType::VString => Text(core::str::from_utf8(b).unwrap_or("")).fmt(f),
            DataType::UString => {
                // CiA 301: 16-bit characters, little-endian.
                let units = b.chunks_exact(2).map(|c| match c {
                    [lo, hi] => u16::from_le_bytes([*lo, *hi]),
                    _ => 0,
                });
                for c in char::decode_utf16(units) {
                    let c = c.unwrap_or(char::REPLACEMENT_CHARACTER);
                    f.write_char(if c.is_control() || c == ';' { '_' } else { c })?;
                }
                Ok(())
            }
            DataType::OString | DataType::Domain => b.iter().try_for_each(|x| write!(f, "{x:02X}")),
            DataType::Real32 => write!(f, "{:?}", f32::from_bits(v as u32)),
            DataType::Real64 => write!(f, "{:?}", f64::from_bits(v)),
            DataType::Bool => write!(f, "{}", v & 1),
            t if t.is_signed() => {
                write!(f, "{}", value::sign_extend(v, b.len()) as i64)
            }
            _ => write!(f, "0x{v:X}"),
        }
    }
}

/// A limit in the CPU's byte order and C width.
struct Native<'a>(DataType, &'a [u8]);

impl fmt::Display for Native<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut wire = [0u8; 8];
        match value::native_to_wire(self.0, self.1, &mut wire) {
            Ok(n) => Wire(self.0, wire.get(..n).unwrap_or(&[])).fmt(f),
            Err(_) => Ok(()),
        }
    }
}

/// Text on one INI line: control characters and `;` (which starts a
/// comment for many readers) become `_`.
struct Text<'a>(&'a str);

impl fmt::Display for Text<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for c in self.0.chars() {
            f.write_char(if c.is_control() || c == ';' { '_' } else { c })?;
        }
        Ok(())
    }
}

struct ObjectName(u16);

impl fmt::Display for ObjectName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let i = self.0;
        let fixed = match i {
            0x1000 => "Device type",
            0x1001 => "Error register",
            0x1002 => "Manufacturer status register",
            0x1003 => "Pre-defined error field",
            0x1005 => "COB-ID SYNC",
            0x1006 => "Communication cycle period",
            0x1007 => "Synchronous window length",
            0x1008 => "Manufacturer device name",
            0x1009 => "Manufacturer hardware version",
            0x100A => "Manufacturer software version",
            0x100C => "Guard time",
            0x100D => "Life time factor",
            0x1010 => "Store parameters",
            0x1011 => "Restore default parameters",
            0x1014 => "COB-ID EMCY",
            0x1015 => "Inhibit time EMCY",
            0x1016 => "Consumer heartbeat time",
            0x1017 => "Producer heartbeat time",
            0x1018 => "Identity object",
            0x1300 => "Global fail-safe command parameter",
            0x13FE => "Configuration valid",
            0x13FF => "Safety configuration checksum",
            _ => "",
        };
        if !fixed.is_empty() {
            return f.write_str(fixed);
        }
        let numbered = |f: &mut fmt::Formatter<'_>, what: &str, base: u16| {
            write!(f, "{what} {}", i - base + 1)
        };
        match i {
            0x1200..=0x127F => numbered(f, "SDO server parameter", 0x1200),
            0x1280..=0x12FF => numbered(f, "SDO client parameter", 0x1280),
            0x1301..=0x1340 => numbered(f, "SRDO communication parameter", 0x1301),
            0x1381..=0x13C0 => numbered(f, "SRDO mapping parameter", 0x1381),
            0x1400..=0x15FF => numbered(f, "RPDO communication parameter", 0x1400),
            0x1600..=0x17FF => numbered(f, "RPDO mapping parameter", 0x1600),
            0x1800..=0x19FF => numbered(f, "TPDO communication parameter", 0x1800),
            0x1A00..=0x1BFF => numbered(f, "TPDO mapping parameter", 0x1A00),
            _ => match super::dcf::network_variable(i) {
                Some(nv) => write!(
                    f,
                    "Network variables {} {} 0x{i:04X}",
                    type_name(nv.typ),
                    match nv.area {
                        super::dcf::PiArea::Input => "in",
                        super::dcf::PiArea::Output => "out",
                    }
                ),
                None => write!(f, "Object 0x{i:04X}"),
            },
        }
    }
}

struct SubName(u16, u8);

impl fmt::Display for SubName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let SubName(i, s) = *self;
        if s == 0 {
            return f.write_str("Highest sub-index supported");
        }
        let pdo_commu = matches!(i, 0x1400..=0x15FF | 0x1800..=0x19FF);
        let pdo_mapp = matches!(i, 0x1600..=0x17FF | 0x1A00..=0x1BFF);
        match (pdo_commu, pdo_mapp, s) {
            (true, _, 1) => f.write_str("COB-ID used by PDO"),
            (true, _, 2) => f.write_str("Transmission type"),
            (true, _, 3) => f.write_str("Inhibit time"),
            (true, _, 4) => f.write_str("Compatibility entry"),
            (true, _, 5) => f.write_str("Event timer"),
            (true, _, 6) => f.write_str("SYNC start value"),
            (_, true, n) => write!(f, "Application object {n}"),
            _ => write!(f, "Sub-index {s}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_dictionary_as_eds() {
        let od = crate::testod::dictionary();
        let mut s = String::new();
        write_eds(&od, &EdsInfo::default(), &mut s).unwrap();
        assert!(s.contains("[1000]\nParameterName=Device type\nObjectType=0x7\nDataType=0x0007\nAccessType=const\nDefaultValue=0x10191\nPDOMapping=0\n"));
        assert!(s.contains("[1018]\nParameterName=Identity object\nObjectType=0x9\nSubNumber=5\n"));
        assert!(s.contains("[1018sub1]\nParameterName=Sub-index 1\n"));
        assert!(
            s.contains("[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n")
        );
    }

    use crate::od::{ObdSubEntry, decl};
    use core::sync::atomic::AtomicU8;

    static I24: [AtomicU8; 4] = decl::init(0x00FF_FFFFu32.to_ne_bytes());
    static R32: [AtomicU8; 4] = decl::init(1.5f32.to_bits().to_ne_bytes());
    static U16: [AtomicU8; 2] = decl::init(7u16.to_ne_bytes());
    static TEXT: [AtomicU8; 4] = decl::init([0x61, 0, 0x62, 0]);
    static S2010: [ObdSubEntry; 1] = decl::ram_object(DataType::UInt24, Access::RW, &I24);
    static S2011: [ObdSubEntry; 1] = decl::ram_object(DataType::UInt32, Access::RW, &R32);
    static S2012: [ObdSubEntry; 1] = decl::ram_object(DataType::UInt16, Access::RW, &U16);
    static S2013: [ObdSubEntry; 1] = decl::ram_object(DataType::Domain, Access::RW, &TEXT);
    static USER: [ObdEntry; 4] = [
        ObdEntry::new(0x2010, &S2010, None),
        ObdEntry::new(0x2011, &S2011, None),
        ObdEntry::new(0x2012, &S2012, None),
        ObdEntry::new(0x2013, &S2013, None),
    ];

    fn section<'s>(eds: &'s str, name: &str) -> &'s str {
        let head = format!("[{name}]\n");
        let at = eds.find(&head).unwrap();
        let rest = &eds[at..];
        &rest[..rest.find("\n\n").unwrap_or(rest.len())]
    }

    #[test]
    fn dynamic_objects_with_the_types_the_description_gave() {
        // The dynamic OD holds NUMERIC entries as UNSIGNEDn (seed 2.1.4):
        // INTEGER24 -1 is UNSIGNED24 0xFFFFFF, REAL32 1.5 UNSIGNED32.
        let mut od = crate::testod::dictionary();
        od.set_user_part(&USER).unwrap();
        let mut plain = String::new();
        write_eds(&od, &EdsInfo::default(), &mut plain).unwrap();
        assert!(
            section(&plain, "2010")
                .contains("DataType=0x0016\nAccessType=rw\nDefaultValue=0xFFFFFF")
        );
        let types = [
            (0x2010, 0, DataType::Int24),
            (0x2011, 0, DataType::Real32),
            // Another size than the object's: not taken.
            (0x2012, 0, DataType::Int32),
            (0x2013, 0, DataType::UString),
            // Not a user-part object: the static dictionary's type stays.
            (0x2000, 0, DataType::Int16),
        ];
        let info = EdsInfo {
            types: &types,
            ..EdsInfo::default()
        };
        let mut s = String::new();
        write_eds(&od, &info, &mut s).unwrap();
        assert!(
            section(&s, "2010").contains("DataType=0x0010\nAccessType=rw\nDefaultValue=-1\n"),
            "{}",
            section(&s, "2010")
        );
        assert!(section(&s, "2011").contains("DataType=0x0008\nAccessType=rw\nDefaultValue=1.5\n"));
        assert!(section(&s, "2012").contains("DataType=0x0006\nAccessType=rw\nDefaultValue=0x7\n"));
        assert!(section(&s, "2013").contains("DataType=0x000B\nAccessType=rw\nDefaultValue=ab\n"));
        assert!(
            section(&plain, "2013")
                .contains("DataType=0x000F\nAccessType=rw\nDefaultValue=61006200\n")
        );
        assert_eq!(section(&s, "2000"), section(&plain, "2000"));
    }

    crate::obd_create_srdo_commu!(mod c1, 0x1301, 1, 25, 20, 0x101, 0x102);
    crate::obd_create_srdo_mapp!(mod m1, 0x1381, [0x6200_0108, 0x6200_0208, 0x6200_0308, 0x6201_0008]);
    static SAFE: [AtomicU8; 4] = decl::zeroed();
    static S6200: [ObdSubEntry; 4] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[3]),
        ObdSubEntry::ram(1, DataType::UInt8, Access::PRW, &SAFE_1, None),
        ObdSubEntry::ram(2, DataType::UInt8, Access::PRW, &SAFE_2, None),
        ObdSubEntry::ram(3, DataType::UInt8, Access::PRW, &SAFE_3, None),
    ];
    static SAFE_1: [AtomicU8; 1] = decl::zeroed();
    static SAFE_2: [AtomicU8; 1] = decl::zeroed();
    static SAFE_3: [AtomicU8; 1] = decl::zeroed();
    static S6201: [ObdSubEntry; 1] = decl::ram_object(DataType::UInt8, Access::PRW, &SAFE);
    static S6202: [ObdSubEntry; 1] = decl::ram_object(DataType::UInt8, Access::PRW, &SAFE);
    crate::obd_create_srdo_cfg_valid!(mod cfg_valid);
    crate::obd_create_srdo_crc!(mod crcs, [0]);
    static GEN: [ObdEntry; 4] = crate::srdo_obd_entries![c1, m1, cfg_valid, crcs];
    static DEV: [ObdEntry; 3] = [
        ObdEntry::new(0x6200, &S6200, None),
        ObdEntry::new(0x6201, &S6201, None),
        ObdEntry::new(0x6202, &S6202, None),
    ];

    #[test]
    fn srdo_objects_carry_the_cia_306_safety_keys() {
        let od = ObjectDictionary::new(&GEN, &[], &DEV).unwrap();
        od.restore_defaults(0x1000, 0x9FFF);
        let mut s = String::new();
        write_eds(&od, &EdsInfo::default(), &mut s).unwrap();
        assert!(section(&s, "DeviceInfo").ends_with("LSS_Supported=0\nCANopenSafetySupported=1"));
        // CiA 304: entry 1 normal data, entry 2 its inverted data, ...
        assert!(
            section(&s, "6200sub1").ends_with("PDOMapping=1\nSRDOMapping=1\nInvertedSRAD=0x620002")
        );
        assert!(section(&s, "6200sub2").ends_with("PDOMapping=1\nSRDOMapping=1"));
        assert!(
            section(&s, "6200sub3").ends_with("PDOMapping=1\nSRDOMapping=1\nInvertedSRAD=0x620100")
        );
        assert!(section(&s, "6201").ends_with("PDOMapping=1\nSRDOMapping=1"));
        // Mapped by no SRDO: no key.
        assert!(section(&s, "6202").ends_with("PDOMapping=1"));
        // Without SRDOs no safety at all.
        let mut plain = String::new();
        write_eds(
            &crate::testod::dictionary(),
            &EdsInfo::default(),
            &mut plain,
        )
        .unwrap();
        assert!(!plain.contains("CANopenSafetySupported") && !plain.contains("SRDOMapping"));
    }

    #[test]
    fn values_in_eds_form() {
        assert_eq!(
            Wire(DataType::Int16, &(-5i16).to_le_bytes()).to_string(),
            "-5"
        );
        assert_eq!(
            Wire(DataType::UInt32, &[0x81, 1, 0, 0]).to_string(),
            "0x181"
        );
        assert_eq!(
            Wire(DataType::Real32, &1.5f32.to_le_bytes()).to_string(),
            "1.5"
        );
        assert_eq!(Wire(DataType::Domain, &[1, 0xAB]).to_string(), "01AB");
        assert_eq!(Wire(DataType::VString, b"a;b\n").to_string(), "a_b_");
        assert_eq!(Wire(DataType::Int24, &[0xFE, 0xFF, 0xFF]).to_string(), "-2");
        // CiA 301 UNICODE_STRING: 16-bit characters, written as text.
        assert_eq!(
            Wire(DataType::UString, &[0x61, 0, 0x13, 0x27, b';', 0]).to_string(),
            "a\u{2713}_"
        );
    }
}
