//! Dictionaries built at run time for the scenarios (the tables are leaked:
//! the library wants `'static` tables and the process ends after one
//! scenario).
//!
//! SRDO dictionaries use the library's public SRDO object helpers
//! (`cop::srdo::objects`), i.e. exactly the layout the `obd_create_srdo_*`
//! macros and the C objdef.h produce.

use std::sync::atomic::AtomicU8;

use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
use cop::srdo::objects::{self, CommuDefaults, CommuVars, MappDefaults, MappVars};

fn leak<T>(v: T) -> &'static T {
    Box::leak(Box::new(v))
}

/// Data length of each frame (bytes) for `entries` mapping entries: each
/// normal/inverted pair maps one object of 2 bytes (4 entries = 4 bytes)
/// or, for 16 entries, of 1 byte (8 bytes, the longest SRDO).
fn entry_bytes(entries: usize) -> usize {
    if entries > 8 { 1 } else { 2 }
}

/// An SRDO dictionary: SRDOs 1..=`count`, each with direction
/// `direction` (1 transmit, 2 receive), refresh time / SCT `sct_ms`,
/// SRVT 20 ms, COB-IDs 0x101 + 2 (n - 1) and + 1, and `entries` mapping
/// entries (even) that alternate normal and inverted subindices of one
/// object 0x6000 + n - 1 per SRDO (sub 1 normal, sub 2 inverted, ...).
/// `count` must be one of the sizes this benchmark uses (1, 8, 32, 64):
/// 0x13FF is declared with the library's const-generic helper, one
/// instantiation per size.
pub fn srdo_dict(count: usize, direction: u8, sct_ms: u16, entries: usize) -> ObjectDictionary {
    assert!((1..=64).contains(&count) && entries.is_multiple_of(2) && (2..=16).contains(&entries));
    let bytes = entry_bytes(entries);
    let typ = if bytes == 1 {
        DataType::UInt8
    } else {
        DataType::UInt16
    };
    let mut generic: Vec<ObdEntry> = Vec::new();
    let mut device: Vec<ObdEntry> = Vec::new();

    let gfc: &'static [AtomicU8; 1] = leak(decl::zeroed());
    generic.push(ObdEntry::new(
        0x1300,
        leak(objects::gfc_param_subs(gfc)),
        None,
    ));
    for n in 1..=count as u16 {
        let cob1 = 0x101 + 2 * u32::from(n - 1);
        let commu = objects::commu_subs(
            leak(CommuVars::new()),
            leak(CommuDefaults::new(direction, sct_ms, 20, cob1, cob1 + 1)),
        );
        generic.push(ObdEntry::new(0x1300 + n, leak(commu), None));
    }
    for n in 1..=count as u16 {
        let object = 0x6000 + u32::from(n - 1);
        let map: Vec<u32> = (1..=entries as u32)
            .map(|sub| object << 16 | sub << 8 | (8 * bytes) as u32)
            .collect();
        let mapp = objects::mapp_subs(leak(MappVars::new()), leak(MappDefaults::new(&map)));
        generic.push(ObdEntry::new(0x1380 + n, leak(mapp), None));

        // The mapped object: sub 0 = number of entries, subs 1.. the
        // variables (PDO-mappable, readable and writable).
        let storage: &'static [AtomicU8] =
            Box::leak((0..entries * bytes).map(|_| AtomicU8::new(0)).collect());
        let zero: &'static [u8] = Box::leak(vec![0u8; bytes].into_boxed_slice());
        let count_value: &'static [u8] = Box::leak(vec![entries as u8].into_boxed_slice());
        let mut subs = vec![ObdSubEntry::rom(0, DataType::UInt8, Access::R, count_value)];
        for i in 0..entries {
            subs.push(ObdSubEntry::ram(
                (i + 1) as u8,
                typ,
                Access::PRW,
                storage.split_at(i * bytes).1.split_at(bytes).0,
                Some(zero),
            ));
        }
        device.push(ObdEntry::new(
            object as u16,
            Box::leak(subs.into_boxed_slice()),
            None,
        ));
    }
    let valid: &'static [AtomicU8; 1] = leak(decl::zeroed());
    generic.push(ObdEntry::new(
        0x13FE,
        leak(objects::cfg_valid_subs(valid)),
        None,
    ));
    generic.push(ObdEntry::new(0x13FF, crc_object(count), None));

    let generic: &'static [ObdEntry] = Box::leak(generic.into_boxed_slice());
    let device: &'static [ObdEntry] = Box::leak(device.into_boxed_slice());
    ObjectDictionary::new(generic, &[], device).expect("SRDO dictionary refused")
}

/// 0x13FF with one CRC entry per SRDO (`OBD_BEGIN_SRDO_CRC(count)`).
fn crc_object(count: usize) -> &'static [ObdSubEntry] {
    fn make<const S: usize>() -> &'static [ObdSubEntry] {
        let count_value: &'static [u8; 1] = leak([(S - 1) as u8]);
        let vars: &'static [AtomicU8] =
            Box::leak((0..2 * (S - 1)).map(|_| AtomicU8::new(0)).collect());
        let defaults: &'static [u8] = Box::leak(vec![0u8; 2 * (S - 1)].into_boxed_slice());
        leak(objects::crc_subs::<S>(count_value, vars, defaults))
    }
    match count {
        1 => make::<2>(),
        8 => make::<9>(),
        32 => make::<33>(),
        64 => make::<65>(),
        _ => panic!("SRDO count {count} not prepared (1, 8, 32, 64)"),
    }
}

/// A dictionary of `count` objects in the manufacturer part, spread evenly
/// over 0x2000..0x5FFF: every other object a plain variable (sub 0 only),
/// the others records of three subindices (sub 0 = 2, subs 1 and 2 U32).
/// Returns the dictionary and every (index, subindex) it holds.
pub fn lookup_dict(count: usize) -> (ObjectDictionary, Vec<(u16, u8)>) {
    assert!((1..=0x4000).contains(&count));
    let step = 0x4000 / count;
    let mut entries = Vec::with_capacity(count);
    let mut addresses = Vec::new();
    for i in 0..count {
        let index = (0x2000 + i * step) as u16;
        let var = |sub: u8| {
            let v: &'static [AtomicU8; 4] = leak(decl::zeroed());
            ObdSubEntry::ram(sub, DataType::UInt32, Access::RW, v, None)
        };
        let subs: Vec<ObdSubEntry> = if i % 2 == 0 {
            addresses.push((index, 0));
            vec![var(0)]
        } else {
            addresses.extend([(index, 0), (index, 1), (index, 2)]);
            vec![
                ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[2]),
                var(1),
                var(2),
            ]
        };
        entries.push(ObdEntry::new(
            index,
            Box::leak(subs.into_boxed_slice()),
            None,
        ));
    }
    let table: &'static [ObdEntry] = Box::leak(entries.into_boxed_slice());
    let od = ObjectDictionary::new(&[], table, &[]).expect("lookup dictionary refused");
    (od, addresses)
}
