//! Plan-level rules (no stack): what a container creates, in which order,
//! with which types. Whole-stack behaviour is in tests/dynod.rs.

use super::*;
use crate::od::dcf::{EntrySpec, encode, encoded_len};

/// A container of `(index, sub, attribute, data)` entries, with or without
/// the attribute bytes.
fn container_of(entries: &[(u16, u8, u8, &[u8])], attributes: bool) -> Vec<u8> {
    let specs: Vec<EntrySpec<'_>> = entries
        .iter()
        .map(|(index, sub, attr, data)| EntrySpec {
            index: *index,
            sub: *sub,
            data,
            attr: *attr,
        })
        .collect();
    let n = encoded_len(&specs, None, attributes, None).unwrap();
    let mut out = vec![0u8; n];
    encode(&specs, None, attributes, None, &mut out).unwrap();
    out
}

/// A container with attribute bytes.
fn container(entries: &[(u16, u8, u8, &[u8])]) -> Vec<u8> {
    container_of(entries, true)
}

fn plan<'a>(bytes: &'a [u8]) -> Result<Plan<'a>, CopKernel> {
    let c = Container::parse(bytes).unwrap();
    Plan::new(c, &crate::testod::dictionary(), 0)
}

// req: D-2.1.2-INDEX
#[test]
fn new_objects_in_ascending_order_with_last_values() {
    // Unsorted, with a repeated entry and an array without subindex 0.
    let b = container(&[
        (0x2101, 2, 0x70, &[2]),
        (0x2100, 0, 0x70, &[0, 1]),
        (0x2101, 1, 0x70, &[1]),
        (0x2101, 2, 0x70, &[9]),
        (0x1017, 0, 0x70, &[5, 0]),
    ]);
    let p = plan(&b).unwrap();
    assert_eq!(p.new_index_list().collect::<Vec<_>>(), [0x2100, 0x2101]);
    assert_eq!(p.new_indices, 2);
    // 0x2100.0, 0x2101.0 (synthesised), .1, .2
    assert_eq!(p.new_subs, 4);
    let subs: Vec<_> = p.new_subs_of(0x2101).map(Result::unwrap).collect();
    assert_eq!(
        subs.iter().map(|s| s.sub).collect::<Vec<_>>(),
        [0, 1, 2],
        "subindex 0 added, subindices ascending"
    );
    assert_eq!(subs[0].initial, Initial::Count(2));
    assert_eq!(subs[0].access, Access::R);
    assert_eq!(subs[2].initial, Initial::Wire(&[9]), "the last entry wins");
    // Pool bytes: U16 (2) + count (1) + two U8 (2).
    assert_eq!(p.data_bytes, 5);
    // One write to 0x1017: 5-byte record header + 2 bytes.
    assert_eq!(p.snapshot_bytes, 7);
}

// req: D-2.1.2-NETVAR, D-2.1.4-ATTRIBUTES
#[test]
fn types_follow_the_attribute_or_seed_table_2() {
    let b = container(&[
        (0x2100, 0, 0x21, &[1]),
        (0x2101, 0, 0x28, b"abc"),
        (0x2102, 0, 0x30, &[1, 2, 3]),
        (0x2103, 0, 0x60, &[1, 2, 3, 4, 5]),
        (0x2104, 0, 0xF0, &[1, 2, 3, 4, 5, 6, 7, 8]),
        // Attribute says read-only string: network variables ignore it.
        (0xA000, 0, 0x28, &[0xFF]),
        (0xA240, 1, 0x30, &[0, 0, 0x80, 0x3F]),
        (0xA900, 1, 0x30, &[1, 2, 3]),
    ]);
    let p = plan(&b).unwrap();
    let first = |i| p.new_subs_of(i).next().unwrap().unwrap();
    let summary = |i| {
        let s = first(i);
        (s.typ, s.access.0, s.kind, s.size)
    };
    assert_eq!(summary(0x2100), (DataType::Bool, 0x01, kind::RAM, 1));
    assert_eq!(
        summary(0x2101),
        (DataType::VString, 0x01, kind::RAM_VSTRING, 3)
    );
    assert_eq!(summary(0x2102), (DataType::UInt24, 0x01, kind::RAM, 4));
    assert_eq!(summary(0x2103), (DataType::Domain, 0x03, kind::RAM, 5));
    assert_eq!(summary(0x2104), (DataType::UInt64, 0x0B, kind::RAM, 8));
    assert_eq!(summary(0xA000), (DataType::Int8, 0x0B, kind::RAM, 1));
    // 0xA240 has subindex 1 only: the count comes first.
    let a240: Vec<_> = p.new_subs_of(0xA240).map(Result::unwrap).collect();
    assert_eq!((a240[1].typ, a240[1].access.0), (DataType::Real32, 0x0B));
    let a900: Vec<_> = p.new_subs_of(0xA900).map(Result::unwrap).collect();
    assert_eq!(a900[1].typ, DataType::UInt24);
    let mut native = [0u8; 4];
    a240[1].initial_bytes(&mut native).unwrap();
    assert_eq!(f32::from_ne_bytes(native), 1.0);
}

#[test]
fn new_objects_without_attributes_are_refused() {
    let new = container_of(&[(0x2100, 0, 0x70, &[1])], false);
    assert_eq!(plan(&new).unwrap_err(), CopKernel::DynInvalidConfig);
    // Existing objects and network variables need none.
    let existing = container_of(&[(0x1017, 0, 0, &[1, 0]), (0xA4C0, 1, 0, &[1])], false);
    assert!(plan(&existing).is_ok());
}

#[test]
fn read_only_existing_objects_are_checked_not_written() {
    // 0x1000 is a constant: a different value is ignored, a missing
    // subindex is not.
    let b = container(&[(0x1000, 0, 0x30, &[1, 2, 3, 4])]);
    let p = plan(&b).unwrap();
    assert_eq!(p.snapshot_bytes, 0, "nothing will be written");
    let b = container(&[(0x1000, 1, 0x30, &[1, 2, 3, 4])]);
    assert_eq!(plan(&b).unwrap_err(), CopKernel::ObdSubindexNotExist);
}

// ---------------------------------------------------------------------
// With the container's index and the plan's notes, every decision is the
// one of the scanning plan.
// ---------------------------------------------------------------------

use crate::testod::Rng;

/// Entries that make sense for the reference dictionary, and some that
/// do not: existing objects (writable, read-only, constant, PDO
/// parameters of both directions, valid and invalid COB-IDs, mappings),
/// new objects of every attribute type, network variables with and
/// without their count, and impossible ones.
const TEMPLATES: &[(u16, u8, u8, &[u8])] = &[
    (0x1017, 0, 0x70, &[0xF4, 0x01]),
    (0x1017, 0, 0x70, &[0x0A, 0x00]),
    (0x1017, 0, 0x70, &[1, 2, 3]),
    (0x1017, 1, 0x70, &[1, 0]),
    (0x1000, 0, 0x30, &[1, 2, 3, 4]),
    (0x1018, 1, 0x30, &[0x99, 0x09, 0, 0]),
    (0x1400, 1, 0x70, &[0x01, 0x02, 0, 0x80]),
    (0x1400, 2, 0x70, &[0xFE]),
    (0x1600, 0, 0x70, &[0]),
    (0x1601, 0, 0x70, &[1]),
    (0x1601, 1, 0x70, &[0x08, 0x00, 0x00, 0x20]),
    (0x1800, 1, 0x70, &[0x81, 0x01, 0, 0]),
    (0x1800, 1, 0x70, &[0x81, 0x01, 0, 0x80]),
    (0x1800, 1, 0x70, &[0x01, 0, 0, 0]),
    (0x1800, 2, 0x70, &[0xFE]),
    (0x1801, 1, 0x70, &[0x81, 0x01, 0, 0]),
    (0x1A00, 0, 0x70, &[0]),
    (0x1A00, 0, 0x70, &[1]),
    (0x1A00, 1, 0x70, &[0x08, 0x00, 0x00, 0x20]),
    (0x1A00, 1, 0x70, &[0x08, 0x00, 0xC0, 0xA4]),
    (0x1A01, 0, 0x70, &[0]),
    (0x1A05, 0, 0x70, &[0]),
    (0x2000, 0, 0x70, &[7]),
    (0x2002, 0, 0x70, &[1, 2, 3, 4]),
    (0x2002, 0, 0x70, &[9, 9, 9, 9]),
    (0x2004, 0, 0x70, b"x"),
    (0x2100, 0, 0x28, b"dynamic"),
    (0x2101, 0, 0x60, &[1, 2, 3]),
    (0x2102, 0, 0x70, &[0x78, 0x56, 0x34, 0x12]),
    (0x2102, 0, 0x70, &[0x78, 0x56]),
    (0x2103, 0, 0xE1, &[1]),
    (0x2103, 0, 0xE1, &[2]),
    (0x2104, 0, 0x30, &[1, 2, 3]),
    (0x2105, 0, 0x00, &[5]),
    (0x3000, 1, 0x70, &[1, 2, 3, 4]),
    (0x3000, 2, 0x70, &[1, 2]),
    (0x3000, 3, 0x70, &[1]),
    (0x3000, 0, 0x70, &[3]),
    (0x3001, 1, 0x70, &[1, 2, 3, 4, 5, 6, 7, 8]),
    (0xA000, 0, 0x30, &[0xFF]),
    (0xA040, 0, 0x30, &[1]),
    (0xA040, 1, 0x70, &[0]),
    (0xA4C0, 0, 0x30, &[3]),
    (0xA4C0, 1, 0xF0, &[0x11]),
    (0xA4C0, 2, 0xF0, &[0x22]),
    (0xA4C0, 3, 0xF0, &[0x33]),
    (0xA580, 0, 0x30, &[3]),
    (0xA580, 3, 0xF0, &[0x34, 0x12]),
    (0xA580, 1, 0xF0, &[0x34]),
    (0xA900, 1, 0x30, &[1, 2, 3]),
    (0x0005, 0, 0x70, &[0]),
];

/// A random container of template entries (repeats and any order), with
/// an address segment and a parameter segment now and then.
fn random_container(rng: &mut Rng) -> Vec<u8> {
    let n = match rng.below(4) {
        0 => rng.below(4),
        1 => rng.below(12),
        _ => rng.below(40),
    } as usize;
    // Mostly from a few templates, so that objects repeat.
    let pick = 1 + rng.below(TEMPLATES.len() as u64);
    let start = rng.below(TEMPLATES.len() as u64);
    let specs: Vec<EntrySpec<'static>> = (0..n)
        .map(|_| {
            let t = TEMPLATES[((start + rng.below(pick)) % TEMPLATES.len() as u64) as usize];
            EntrySpec {
                index: t.0,
                sub: t.1,
                data: t.3,
                attr: t.2,
            }
        })
        .collect();
    let pi = (rng.below(3) == 0).then_some(crate::od::dcf::PiParams {
        total: 24,
        input_offset: 0,
        input_size: 8,
        output_offset: 8,
        output_size: 16,
    });
    let probe_len = encoded_len(&specs, None, true, None).unwrap();
    let mut probe = vec![0u8; probe_len];
    encode(&specs, None, true, None, &mut probe).unwrap();
    let candidates = Container::parse(&probe).unwrap().candidate_count();
    let words: Vec<u16> = (0..candidates)
        .map(|_| match rng.below(4) {
            0 => crate::od::dcf::NOT_PLACED,
            _ => rng.below(24) as u16,
        })
        .collect();
    let addresses = (rng.below(3) == 0).then_some(&words[..]);
    let len = encoded_len(&specs, addresses, true, pi.as_ref()).unwrap();
    let mut out = vec![0u8; len];
    encode(&specs, addresses, true, pi.as_ref(), &mut out).unwrap();
    out
}

/// Everything a plan decides, as the build uses it.
#[derive(Debug, PartialEq)]
struct Decisions<'a> {
    counts: (usize, usize, usize, usize),
    pi: PiParams,
    new_indices: Vec<u16>,
    new_subs: Vec<(u16, Vec<Result<NewSub<'a>, CopKernel>>)>,
    objects: Vec<(u16, Vec<Result<NewSub<'a>, CopKernel>>)>,
    pdo_check: Result<(), CopKernel>,
    writes: Vec<(u16, u8, String)>,
}

fn decisions<'a>(p: &Plan<'a>, od: &ObjectDictionary) -> Decisions<'a> {
    let mut writes = Vec::new();
    let mut seq = Sequence::new(p);
    let mut seen = Vec::new();
    while let Some(w) = seq.next(p, od) {
        // A write marked as a repeat writes an object written before.
        assert!(!w.repeat || seen.contains(&(w.index, w.sub)), "{w:?}");
        seen.push((w.index, w.sub));
        writes.push((w.index, w.sub, format!("{:?}", w.op)));
    }
    Decisions {
        counts: (p.new_indices, p.new_subs, p.data_bytes, p.snapshot_bytes),
        pi: p.pi,
        new_indices: p.new_index_list().collect(),
        new_subs: p
            .new_index_list()
            .map(|i| (i, p.new_subs_of(i).collect()))
            .collect(),
        objects: p
            .new_objects()
            .map(|(i, subs)| (i, subs.collect()))
            .collect(),
        pdo_check: p.check_pdos(od),
        writes,
    }
}

/// A dictionary of this test's own (nobody else writes its variables):
/// heartbeat, identity, RPDO 1 and TPDO 1 invalid, TPDO 2 valid (so the
/// sequence invalidates it first), a mappable U8 and a U32.
mod pdo_od {
    use crate::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary};
    use crate::pdo::PDO_MAX_MAPPENTRIES;
    use crate::pdo::decl::{
        CommuDefaults, CommuVars, MappDefaults, MappVars, commu_subs, mapp_subs,
    };

    static DEVICE: [u8; 4] = 0x0001_0191u32.to_ne_bytes();
    static S1000: [ObdSubEntry; 1] = [ObdSubEntry::rom(0, DataType::UInt32, Access::R, &DEVICE)];
    crate::od_ram!(static S1017, HB: u16 = 0 => UInt16, SRW);
    static VENDOR: [u8; 4] = 0x0000_0123u32.to_ne_bytes();
    static S1018: [ObdSubEntry; 2] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
        ObdSubEntry::rom(1, DataType::UInt32, Access::R, &VENDOR),
    ];
    static V1400: CommuVars = CommuVars::new();
    static D1400: CommuDefaults = CommuDefaults::new(0x8000_0200, 255, 0, 0);
    static S1400: [ObdSubEntry; 5] = commu_subs(&V1400, &D1400);
    static V1600: MappVars = MappVars::new();
    static D1600: MappDefaults = MappDefaults::new(&[]);
    static S1600: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1600, &D1600);
    static V1800: CommuVars = CommuVars::new();
    static D1800: CommuDefaults = CommuDefaults::new(0x8000_0180, 255, 0, 0);
    static S1800: [ObdSubEntry; 5] = commu_subs(&V1800, &D1800);
    static V1801: CommuVars = CommuVars::new();
    static D1801: CommuDefaults = CommuDefaults::new(0x0000_0281, 255, 0, 0);
    static S1801: [ObdSubEntry; 5] = commu_subs(&V1801, &D1801);
    static V1A00: MappVars = MappVars::new();
    static D1A00: MappDefaults = MappDefaults::new(&[]);
    static S1A00: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1A00, &D1A00);
    static V1A01: MappVars = MappVars::new();
    static D1A01: MappDefaults = MappDefaults::new(&[0x2000_0008]);
    static S1A01: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1A01, &D1A01);
    crate::od_ram!(static S2000, V2000: u8 = 0 => UInt8, PRW);
    crate::od_ram!(static S2002, V2002: u32 = 0 => UInt32, RW);
    static GENERIC: [ObdEntry; 9] = [
        ObdEntry::new(0x1000, &S1000, None),
        ObdEntry::new(0x1017, &S1017, None),
        ObdEntry::new(0x1018, &S1018, None),
        ObdEntry::new(0x1400, &S1400, None),
        ObdEntry::new(0x1600, &S1600, None),
        ObdEntry::new(0x1800, &S1800, None),
        ObdEntry::new(0x1801, &S1801, None),
        ObdEntry::new(0x1A00, &S1A00, None),
        ObdEntry::new(0x1A01, &S1A01, None),
    ];
    static MANUFACTURER: [ObdEntry; 2] = [
        ObdEntry::new(0x2000, &S2000, None),
        ObdEntry::new(0x2002, &S2002, None),
    ];

    pub fn od() -> ObjectDictionary {
        let od = ObjectDictionary::new(&GENERIC, &MANUFACTURER, &[]).unwrap();
        od.restore_defaults(0x1000, 0xFFFF);
        od
    }
}

#[test]
fn index_and_notes_decide_as_the_scanning_plan() {
    let od = pdo_od::od();
    let mut rng = Rng(0x005E_ED0F_C0DE);
    let rounds = if cfg!(miri) { 15 } else { 1500 };
    let mut accepted = 0;
    for _ in 0..rounds {
        let bytes = random_container(&mut rng);
        let image_len = [0usize, 8, 24][rng.below(3) as usize];
        let c = Container::parse(&bytes).unwrap();
        let scan = Plan::new(c, &od, image_len);
        let mut index_scratch = vec![0u8; 4096];
        let mut notes_scratch = vec![0u8; 512];
        let indexed = Container::parse_indexed(&bytes, &mut index_scratch).unwrap();
        assert!(indexed.is_indexed());
        let fast = Plan::new_with_notes(indexed, &od, image_len, &mut notes_scratch);
        let mut index_scratch2 = vec![0u8; 4096];
        let indexed2 = Container::parse_indexed(&bytes, &mut index_scratch2).unwrap();
        let no_notes = Plan::new(indexed2, &od, image_len);
        match (&scan, &fast, &no_notes) {
            (Ok(s), Ok(f), Ok(n)) => {
                accepted += 1;
                assert_eq!(f.notes_len(), c.len());
                let expect = decisions(s, &od);
                assert_eq!(decisions(f, &od), expect, "{bytes:02X?}");
                assert_eq!(decisions(n, &od), expect, "{bytes:02X?}");
                assert_eq!(decisions(&f.without_index(), &od), expect);
            }
            (Err(s), Err(f), Err(n)) => {
                assert_eq!((f, n), (s, s), "{bytes:02X?}");
            }
            _ => panic!(
                "{:?} / {:?} / {:?} for {bytes:02X?}",
                scan.map(|_| ()),
                fast.map(|_| ()),
                no_notes.map(|_| ())
            ),
        }
    }
    // Both outcomes are well represented.
    assert!(accepted > rounds / 10, "{accepted} of {rounds} accepted");
    assert!(
        accepted < rounds * 9 / 10,
        "{accepted} of {rounds} accepted"
    );
}

#[test]
fn the_bitmap_finds_the_overlaps_the_pairs_find() {
    use crate::od::ObdSubEntry;
    let image: [AtomicU8; 40] = core::array::from_fn(|_| AtomicU8::new(0));
    let outside: [AtomicU8; 8] = core::array::from_fn(|_| AtomicU8::new(0));
    let mut rng = Rng(77);
    let mut overlapping = 0;
    for round in 0..400 {
        let subs: Vec<ObdSubEntry> = (0..rng.below(8))
            .map(|i| {
                let size = [0u32, 1, 2, 4, 8][rng.below(5) as usize];
                let at = rng.below(40 - u64::from(size.max(1)) + 1) as usize;
                let current = if rng.below(6) == 0 {
                    outside.as_ptr()
                } else {
                    image[at..].as_ptr()
                };
                ObdSubEntry {
                    m_bSubIndex: i as u8,
                    m_bType: DataType::Domain.code(),
                    m_bAccess: Access::RW.0,
                    m_bKind: kind::RAM,
                    m_dwSize: size,
                    m_pDefault: core::ptr::null(),
                    m_pCurrent: current as *mut core::ffi::c_void,
                }
            })
            .collect();
        let expect = image_overlaps(&image, &subs);
        overlapping += usize::from(expect);
        let mut room = [0xFFu8; 5];
        assert_eq!(
            image_overlaps_in(&image, &subs, &mut room),
            expect,
            "{round}"
        );
        // Without room for the bitmap: the pairs.
        assert_eq!(image_overlaps_in(&image, &subs, &mut [0u8; 4]), expect);
    }
    assert!(
        (50..350).contains(&overlapping),
        "{overlapping} of 400 overlap"
    );
}

/// The pool regions of `DynBuildOd`: the RPDO channels after the subindex
/// entries, the TPDO channels after them, each region aligned for its own
/// channel type and ending before the next one starts (the claims the
/// pool's `unsafe` block rests on), for channel types of different size and
/// alignment; without channels the data follow the subindex entries.
#[test]
fn pool_layout_keeps_the_channel_regions_apart_and_aligned() {
    use super::pool::Layout;
    use core::mem::{align_of, size_of};
    #[allow(dead_code)]
    struct Small(u8, u8, u8);
    #[allow(dead_code)]
    #[repr(align(8))]
    struct Wide([u8; 20]);
    let b = container(&[(0x2100, 0, 0x70, &[0, 1]), (0x2101, 1, 0x70, &[1])]);
    for (rx, tx) in [(0, 0), (1, 0), (0, 2), (3, 2)] {
        let mut p = plan(&b).unwrap();
        p.rx_channels = rx;
        p.tx_channels = tx;
        for user in [0, 1, 5] {
            let l = Layout::of::<Small, Wide>(&p, user).unwrap();
            let subs_end = l.subs_at + l.subs * size_of::<crate::od::ObdSubEntry>();
            if rx + tx == 0 {
                assert_eq!(l.data_at, subs_end, "{rx} {tx} {user}");
                continue;
            }
            assert!(l.rx_at >= subs_end, "{rx} {tx} {user}");
            assert_eq!(l.rx_at % align_of::<Small>(), 0);
            assert_eq!(l.tx_at % align_of::<Wide>(), 0, "{rx} {tx} {user}");
            assert!(
                l.rx_at + rx * size_of::<Small>() <= l.tx_at,
                "{rx} {tx} {user}"
            );
            assert_eq!(
                l.data_at,
                l.tx_at + tx * size_of::<Wide>(),
                "{rx} {tx} {user}"
            );
            assert_eq!((l.rx_channels, l.tx_channels), (rx, tx));
        }
    }
    // Reversed alignments: the TPDO region is aligned up after small RPDO
    // channels.
    let mut p = plan(&b).unwrap();
    p.rx_channels = 1;
    p.tx_channels = 1;
    let l = Layout::of::<Wide, Small>(&p, 1).unwrap();
    assert_eq!(l.rx_at % align_of::<Wide>(), 0);
    assert_eq!(l.tx_at, l.rx_at + size_of::<Wide>());
}
