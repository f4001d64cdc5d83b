//! CANopen safety (CiA 304) in a device description: the CiA 306 keys
//! `[DeviceInfo] CANopenSafetySupported`, per object `SRDOMapping` and
//! `InvertedSRAD`, checked against each other and against the SRDO
//! mapping parameters (0x1381..0x13C0), and the SRDO configuration CRCs of
//! 0x13FF.
//!
//! # What is checked when a file is read
//! * `InvertedSRAD` names an object of the file, of the same size, that is
//!   itself marked `SRDOMapping=1` and names no inverted object of its own;
//!   the object carrying the key is marked `SRDOMapping=1`; no inverted
//!   object serves two objects.
//! * With `CANopenSafetySupported=1`, every pair an SRDO mapping holds
//!   (entries 2k−1 and 2k: normal and inverted data, CiA 304) maps objects
//!   the file describes, marked `SRDOMapping=1`, with the mapped length
//!   their size, both entries of a pair the same length, and the normal
//!   object's `InvertedSRAD` (when given) naming the inverted one.
//! * Safety keys without `CANopenSafetySupported=1` are tolerated with a
//!   warning.

use cop::od::DataType;

use crate::value::type_name;
use crate::{Dcf, Error, Object, Reader, WarningKind};

/// Communication parameter of SRDO `n` (1..=64).
pub fn commu_index(n: u8) -> u16 {
    0x1300 + u16::from(n)
}

/// Mapping parameter of SRDO `n` (1..=64).
pub fn mapp_index(n: u8) -> u16 {
    0x1380 + u16::from(n)
}

fn size_of(o: &Object) -> Option<usize> {
    DataType::from_code(o.data_type).and_then(DataType::wire_size)
}

fn u32_of(o: &Object) -> u32 {
    let mut b = [0u8; 4];
    for (d, s) in b.iter_mut().zip(&o.data) {
        *d = *s;
    }
    u32::from_le_bytes(b)
}

/// The mapping entries of SRDO `n` as (subindex, index, sub, bits).
pub fn mapping(d: &Dcf, n: u8) -> Vec<(u8, u16, u8, u8)> {
    let m = mapp_index(n);
    let count = d
        .get(m, 0)
        .and_then(|o| o.data.first().copied())
        .unwrap_or(0);
    (1..=count)
        .filter_map(|s| {
            let v = u32_of(d.get(m, s)?);
            Some((s, (v >> 16) as u16, (v >> 8) as u8, v as u8))
        })
        .collect()
}

pub(crate) fn check_keys(d: &Dcf, r: &mut Reader<'_>) -> Result<(), Error> {
    let supported = d.safety_supported == Some(true);
    let err = |o: &Object, key: &str, msg: String| r.err(&o.section, Some(key), msg);
    let mut served: std::collections::BTreeMap<(u16, u8), (u16, u8)> = Default::default();
    let mut keyed = None;
    for o in &d.objects {
        if o.srdo_mapping || o.inverted_srad.is_some() {
            keyed.get_or_insert(o);
        }
        let Some((i, s, _)) = o.inverted_srad else {
            continue;
        };
        let here = format!("0x{:04X} sub {}", o.index, o.sub);
        let there = format!("0x{i:04X} sub {s}");
        if !o.srdo_mapping {
            return Err(err(
                o,
                "InvertedSRAD",
                format!("{here} names its inverted data but is not marked SRDOMapping=1"),
            ));
        }
        let Some(inv) = d.get(i, s) else {
            return Err(err(
                o,
                "InvertedSRAD",
                format!("the inverted object {there} is not in the file"),
            ));
        };
        if (i, s) == (o.index, o.sub) {
            return Err(err(o, "InvertedSRAD", format!("{here} names itself")));
        }
        if size_of(inv) != size_of(o) || size_of(o).is_none() {
            return Err(err(
                o,
                "InvertedSRAD",
                format!(
                    "{here} is {} and its inverted object {there} {}: the inverted data has the size of the data (CiA 304)",
                    type_name(o.typ()),
                    type_name(inv.typ())
                ),
            ));
        }
        if !inv.srdo_mapping {
            return Err(err(
                o,
                "InvertedSRAD",
                format!("the inverted object {there} is not marked SRDOMapping=1"),
            ));
        }
        if inv.inverted_srad.is_some() {
            return Err(err(
                o,
                "InvertedSRAD",
                format!("{there} is the inverted data of {here} and names inverted data itself"),
            ));
        }
        if let Some((pi, ps)) = served.insert((i, s), (o.index, o.sub)) {
            return Err(err(
                o,
                "InvertedSRAD",
                format!("{there} is already the inverted data of 0x{pi:04X} sub {ps}"),
            ));
        }
    }
    if !supported {
        if let Some(o) = keyed {
            let (sec, key) = (o.section.clone(), "SRDOMapping");
            r.warn(
                WarningKind::Tolerated,
                &sec,
                Some(key),
                "safety keys without [DeviceInfo] CANopenSafetySupported=1",
            )?;
        }
        return Ok(());
    }
    for n in 1..=64u8 {
        let m = mapp_index(n);
        let entries = mapping(d, n);
        for pair in entries.chunks(2) {
            let [a, b] = pair else {
                let (s, ..) = pair[0];
                let o = d.get(m, s).unwrap_or(&d.objects[0]);
                return Err(err(
                    o,
                    "DefaultValue",
                    format!(
                        "SRDO {n}: an odd number of mapping entries (CiA 304 maps pairs of normal and inverted data)"
                    ),
                ));
            };
            let entry_obj = |s: u8| d.get(m, s).unwrap_or(&d.objects[0]);
            let target = |e: &(u8, u16, u8, u8)| -> Result<&Object, Error> {
                let (s, i, si, bits) = *e;
                let Some(t) = d.get(i, si) else {
                    return Err(err(
                        entry_obj(s),
                        "DefaultValue",
                        format!(
                            "SRDO {n} maps 0x{i:04X} sub {si}, which the file does not describe"
                        ),
                    ));
                };
                if !t.srdo_mapping {
                    return Err(err(
                        entry_obj(s),
                        "DefaultValue",
                        format!(
                            "SRDO {n} maps 0x{i:04X} sub {si}, which is not marked SRDOMapping=1 (line {})",
                            t.line
                        ),
                    ));
                }
                if size_of(t).map(|z| z * 8) != Some(usize::from(bits)) {
                    return Err(err(
                        entry_obj(s),
                        "DefaultValue",
                        format!(
                            "SRDO {n} maps 0x{i:04X} sub {si} with {bits} bits; it is {}",
                            type_name(t.typ())
                        ),
                    ));
                }
                Ok(t)
            };
            let normal = target(a)?;
            let inverted = target(b)?;
            if a.3 != b.3 {
                return Err(err(
                    entry_obj(b.0),
                    "DefaultValue",
                    format!(
                        "SRDO {n}: normal data {} bits, inverted data {} bits",
                        a.3, b.3
                    ),
                ));
            }
            if let Some((i, s, _)) = normal.inverted_srad {
                if (i, s) != (inverted.index, inverted.sub) {
                    return Err(err(
                        entry_obj(b.0),
                        "DefaultValue",
                        format!(
                            "SRDO {n} pairs 0x{:04X} sub {} with 0x{:04X} sub {}, but its InvertedSRAD names 0x{i:04X} sub {s}",
                            normal.index, normal.sub, inverted.index, inverted.sub
                        ),
                    ));
                }
            }
        }
    }
    Ok(())
}

/// One SRDO as `--srdo-crc` reports it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SrdoReport {
    /// Number, 1 for 0x1301.
    pub n: u8,
    /// Direction (0x1301+n sub 1): 0 off, 1 transmit, 2 receive.
    pub direction: u8,
    /// The CRC of the configuration.
    pub crc: u16,
    /// 0x13FF sub n as the file has it.
    pub stored: Option<u16>,
    /// Pairs (normal, inverted) the mapping holds.
    pub pairs: Vec<((u16, u8), (u16, u8))>,
}

impl Dcf {
    /// The SRDO configuration CRC (SAFETY_BEHAVIOUR.md section 3,
    /// CRC-16/XMODEM over direction, SCT, SRVT, COB-ID 1, COB-ID 2, mapping
    /// count, then subindex and entry of each mapping) of every SRDO the
    /// file configures: `(number, crc)`, number 1 for 0x1301.
    pub fn srdo_crcs(&self) -> Result<Vec<(u8, u16)>, Error> {
        Ok(self.srdo_reports()?.iter().map(|r| (r.n, r.crc)).collect())
    }

    /// Every SRDO the file configures, with its CRC, the stored 0x13FF
    /// value and its pairs.
    pub fn srdo_reports(&self) -> Result<Vec<SrdoReport>, Error> {
        let mut out = Vec::new();
        for n in 1..=64u8 {
            let commu = commu_index(n);
            let mapp = mapp_index(n);
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
            let pairs = mapping(self, n)
                .chunks(2)
                .filter_map(|p| match p {
                    [a, b] => Some(((a.1, a.2), (b.1, b.2))),
                    _ => None,
                })
                .collect();
            out.push(SrdoReport {
                n,
                direction: *val(commu, 1)?.first().unwrap_or(&0),
                crc: cop::srdo::crc::crc16(&stream),
                stored: self
                    .get(0x13FF, n)
                    .filter(|o| o.data.len() == 2)
                    .map(|o| u16::from_le_bytes([o.data[0], o.data[1]])),
                pairs,
            });
        }
        Ok(out)
    }
}

/// The library's own SRDO configuration check (`CcmCheckSrdoConfig`,
/// SAFETY_BEHAVIOUR.md section 2: timing, COB-IDs, mapping, length,
/// granularity) on the configuration the file describes, the file's
/// objects taken as the node's dictionary ([`crate::node::from_eds`]) and
/// 0x13FF holding the CRCs computed here (a stored CRC that differs is
/// reported by [`SrdoReport::stored`]). `Ok(None)` when it passes,
/// `Ok(Some((code, index)))` for the first SRDO it refuses.
pub fn library_check(d: &Dcf) -> Result<Option<(cop::CopKernel, u16)>, String> {
    let mut with_crcs = d.clone();
    for r in d.srdo_reports().map_err(|e| e.to_string())? {
        if let Some(o) = with_crcs
            .objects
            .iter_mut()
            .find(|o| (o.index, o.sub) == (0x13FF, r.n))
        {
            o.data = r.crc.to_le_bytes().to_vec();
        }
    }
    let od = crate::node::from_eds(&with_crcs).dictionary()?;
    let mut srdo = cop::srdo::Srdo::new();
    srdo.init(&od).map_err(|k| {
        format!(
            "the file does not have every object an SRDO needs (0x1301+n sub 1, 2, 3, 5, 6, 0x1381+n, 0x13FE, 0x13FF sub n): {}",
            crate::check::kernel_name(k)
        )
    })?;
    Ok(srdo.check_config(&od).err())
}

/// Writes `crcs` into the DCF text as the values of 0x13FF sub n
/// (`ParameterValue` when the section has one or is a DCF, else
/// `DefaultValue`); every other line stays as it was. The sections must
/// exist.
pub fn write_crcs(text: &str, file: &std::path::Path, crcs: &[(u8, u16)]) -> Result<String, Error> {
    let ini = crate::ini::Ini::parse(text).map_err(|e| e.in_file(file))?;
    let newline = if text.contains("\r\n") { "\r\n" } else { "\n" };
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    // Lines to insert after (line number, text), applied from the bottom.
    let mut inserts = Vec::new();
    for (n, crc) in crcs {
        let name = format!("13FFsub{n:X}");
        let Some(s) = ini.section(&name) else {
            return Err(Error {
                file: file.to_path_buf(),
                line: None,
                section: Some(name),
                key: None,
                msg: "section missing: add 0x13FF sub n to the DCF".into(),
            });
        };
        let value = format!("0x{crc:04X}");
        match ["ParameterValue", "DefaultValue"]
            .iter()
            .find_map(|k| s.key(k))
        {
            Some(k) => {
                if let Some(l) = lines.get_mut(k.line - 1) {
                    *l = format!("{}={value}", k.name);
                }
            }
            None => inserts.push((s.line, format!("ParameterValue={value}"))),
        }
    }
    inserts.sort_by_key(|i| std::cmp::Reverse(i.0));
    for (after, l) in inserts {
        lines.insert(after.min(lines.len()), l);
    }
    let mut out = lines.join(newline);
    if text.ends_with('\n') {
        out.push_str(newline);
    }
    Ok(out)
}
