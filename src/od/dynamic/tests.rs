//! Plan-level rules (no stack): what a container creates, in which order,
//! with which types. Whole-stack behaviour is in tests/dynod.rs.

use super::*;
use crate::od::dcf::{EntrySpec, encode, encoded_len};

fn container(entries: &[(u16, u8, u8, &[u8])]) -> Vec<u8> {
    let specs: Vec<EntrySpec<'_>> = entries
        .iter()
        .map(|(index, sub, attr, data)| EntrySpec {
            index: *index,
            sub: *sub,
            data,
            attr: *attr,
        })
        .collect();
    let n = encoded_len(&specs, None, true, None).unwrap();
    let mut out = vec![0u8; n];
    encode(&specs, None, true, None, &mut out).unwrap();
    out
}

fn plan<'a>(bytes: &'a [u8]) -> Result<Plan<'a>, CopKernel> {
    let c = Container::parse(bytes).unwrap();
    Plan::new(c, &crate::testod::dictionary(), 0)
}

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
    let specs = [EntrySpec {
        index: 0x2100,
        sub: 0,
        data: &[1],
        attr: 0x70,
    }];
    let n = encoded_len(&specs, None, false, None).unwrap();
    let mut out = vec![0u8; n];
    encode(&specs, None, false, None, &mut out).unwrap();
    assert_eq!(plan(&out).unwrap_err(), CopKernel::DynInvalidConfig);
    // Existing objects and network variables need none.
    let specs = [
        EntrySpec {
            index: 0x1017,
            sub: 0,
            data: &[1, 0],
            attr: 0,
        },
        EntrySpec {
            index: 0xA4C0,
            sub: 1,
            data: &[1],
            attr: 0,
        },
    ];
    let n = encoded_len(&specs, None, false, None).unwrap();
    let mut out = vec![0u8; n];
    encode(&specs, None, false, None, &mut out).unwrap();
    assert!(plan(&out).is_ok());
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
