use super::*;

/// A small container with every segment: two network variables of seed
/// Bild 8 (0xA4C0 sub 1..3 UNSIGNED8, 0xA580 sub 3 UNSIGNED16), their
/// counts, and a communication object.
fn sample_specs() -> [EntrySpec<'static>; 7] {
    [
        EntrySpec {
            index: 0x1017,
            sub: 0,
            data: &[0xE8, 0x03],
            attr: 0x70,
        },
        EntrySpec {
            index: 0xA4C0,
            sub: 0,
            data: &[3],
            attr: 0x30,
        },
        EntrySpec {
            index: 0xA4C0,
            sub: 1,
            data: &[0x11],
            attr: 0xF0,
        },
        EntrySpec {
            index: 0xA4C0,
            sub: 2,
            data: &[0x22],
            attr: 0xF0,
        },
        EntrySpec {
            index: 0xA4C0,
            sub: 3,
            data: &[0x33],
            attr: 0xF0,
        },
        EntrySpec {
            index: 0xA580,
            sub: 0,
            data: &[3],
            attr: 0x30,
        },
        EntrySpec {
            index: 0xA580,
            sub: 3,
            data: &[0x34, 0x12],
            attr: 0xF0,
        },
    ]
}

fn build(specs: &[EntrySpec<'_>], addr: Option<&[u16]>, pi: Option<&PiParams>) -> Vec<u8> {
    let n = encoded_len(specs, addr, true, pi).unwrap();
    let mut out = vec![0u8; n];
    assert_eq!(encode(specs, addr, true, pi, &mut out), Ok(n));
    out
}

fn sample() -> Vec<u8> {
    let pi = PiParams {
        total: 6,
        input_offset: 0,
        input_size: 0,
        output_offset: 0,
        output_size: 6,
    };
    build(&sample_specs(), Some(&[0, 1, 2, 4]), Some(&pi))
}

fn put32(b: &mut [u8], at: usize, v: u32) {
    b[at..at + 4].copy_from_slice(&v.to_le_bytes());
}

#[test]
fn round_trip_with_all_segments() {
    let bytes = sample();
    let c = Container::parse(&bytes).unwrap();
    assert_eq!(c.len(), 7);
    assert_eq!(c.header().total as usize, bytes.len());
    assert_eq!(
        c.header().index.offset,
        40,
        "index segment follows the header"
    );
    let got: Vec<_> = c
        .entries()
        .map(|e| (e.index, e.sub, e.data.to_vec(), e.attr))
        .collect();
    for (g, s) in got.iter().zip(sample_specs()) {
        assert_eq!(*g, (s.index, s.sub, s.data.to_vec(), Some(s.attr)));
    }
    let addr: Vec<_> = c.addressed().map(|(e, a)| ((e.index, e.sub), a)).collect();
    assert_eq!(
        addr[0],
        ((0x1017, 0), None),
        "communication objects are never candidates"
    );
    assert_eq!(
        addr[1],
        ((0xA4C0, 0), None),
        "the count of an array is no candidate"
    );
    assert_eq!(addr[2].1, Some(0));
    assert_eq!(addr[6], ((0xA580, 3), Some(4)));
    assert_eq!(c.pi_params().unwrap().output_size, 6);
}

#[test]
fn segment_count_field_is_not_relied_upon() {
    // SYSTEC_API.md section 8: a real container carries 0 segments.
    let mut bytes = sample();
    bytes[6] = 0;
    bytes[7] = 0;
    assert!(Container::parse(&bytes).is_ok());
}

#[test]
fn optional_segments_may_be_absent() {
    let specs = sample_specs();
    let n = encoded_len(&specs, None, false, None).unwrap();
    let mut out = vec![0u8; n];
    encode(&specs, None, false, None, &mut out).unwrap();
    let c = Container::parse(&out).unwrap();
    assert!(!c.has_attributes() && !c.has_addresses());
    assert!(c.pi_params().is_none());
    assert!(c.entries().all(|e| e.attr.is_none()));
}

#[test]
fn truncation_at_every_byte_is_refused() {
    let bytes = sample();
    for n in 0..bytes.len() {
        assert!(Container::parse(&bytes[..n]).is_err(), "{n} bytes accepted");
    }
}

#[test]
fn a_changed_header_field_is_refused() {
    let bytes = sample();
    // Every DWORD of the header except the reserved segment count, one up
    // and one down: nothing adds up any more.
    for at in [0usize, 8, 12, 16, 20, 24, 28, 32, 36] {
        for delta in [1i64, -1] {
            let mut b = bytes.clone();
            let v = u32::from_le_bytes(b[at..at + 4].try_into().unwrap());
            put32(&mut b, at, (i64::from(v) + delta) as u32);
            assert!(Container::parse(&b).is_err(), "field at {at} {delta:+}");
        }
    }
}

#[test]
fn version_must_be_one() {
    let mut b = sample();
    b[4] = 2;
    assert_eq!(
        Container::parse(&b).unwrap_err(),
        ContainerError::Version(2)
    );
}

#[test]
fn overlapping_segments_are_refused() {
    let mut b = sample();
    let h = Container::parse(&b).unwrap().header().to_owned();
    // The parameter segment moved onto the attributes, the sizes still add
    // up to the total.
    put32(&mut b, 32, h.ext_info.offset);
    assert!(matches!(
        Container::parse(&b),
        Err(ContainerError::Overlap(..))
    ));
}

#[test]
fn segment_inside_header_or_half_described_is_refused() {
    let mut b = sample();
    put32(&mut b, 8, 4);
    assert_eq!(
        Container::parse(&b).unwrap_err(),
        ContainerError::Segment(SegmentId::Index)
    );
    let mut b = sample();
    put32(&mut b, 36, 0); // parameter segment: offset without size
    assert_eq!(
        Container::parse(&b).unwrap_err(),
        ContainerError::Segment(SegmentId::PiParam)
    );
}

#[test]
fn entry_sizes_must_add_up() {
    let bytes = sample();
    let c = Container::parse(&bytes).unwrap();
    let idx = c.header().index.offset as usize;
    // Count one too high: the walk runs off the segment.
    let mut b = bytes.clone();
    put32(&mut b, idx, 8);
    assert_eq!(
        Container::parse(&b).unwrap_err(),
        ContainerError::IndexSegment
    );
    // Count one too low: a whole entry is left over.
    let mut b = bytes.clone();
    put32(&mut b, idx, 6);
    assert!(Container::parse(&b).is_err());
    // First entry's size one byte larger / smaller.
    for size in [1u32, 3] {
        let mut b = bytes.clone();
        put32(&mut b, idx + 4 + 3, size);
        assert!(Container::parse(&b).is_err(), "size {size}");
    }
}

#[test]
fn attribute_rules_of_seed_table_1() {
    let ok = |a: u8, data: &'static [u8]| {
        let specs = [EntrySpec {
            index: 0x2000,
            sub: 0,
            data,
            attr: a,
        }];
        Container::parse(&build(&specs, None, None)).is_ok()
    };
    // Seed 2.1.4 examples.
    assert!(ok(0x70, &[1, 2]));
    assert!(ok(0x60, &[1, 2, 3]));
    assert!(ok(0xF0, &[1]));
    assert!(ok(0x30, &[1, 2, 3, 4]));
    assert!(ok(0x28, b"name"), "read-only string of the real container");
    assert!(ok(0x21, &[1]));
    assert!(!ok(0x22, &[1]), "0x02 is reserved");
    assert!(!ok(0x24, &[1]), "0x04 is reserved");
    assert!(!ok(0x31, &[1]), "two type bits");
    assert!(!ok(0x21, &[1, 0]), "BOOLEAN with two bytes");
    assert!(!ok(0x30, &[0; 9]), "number of nine bytes");
    assert!(!ok(0x30, &[]), "number without bytes");
}

#[test]
fn attribute_segment_needs_one_byte_per_entry() {
    let mut b = sample();
    let h = *Container::parse(&b).unwrap().header();
    // Shrink the attribute segment by one and grow the parameter
    // segment's offset accordingly is not possible without a gap, so
    // claim one byte less and one byte more of total: still refused.
    put32(&mut b, 28, h.ext_info.size - 1);
    assert!(Container::parse(&b).is_err());
}

#[test]
fn address_segment_must_match_the_candidates() {
    let specs = sample_specs();
    for words in [&[0u16, 1, 2][..], &[0, 1, 2, 4, 6]] {
        let b = build(&specs, Some(words), None);
        assert_eq!(
            Container::parse(&b).unwrap_err(),
            ContainerError::AddressCount
        );
    }
}

#[test]
fn pi_windows_must_lie_inside_the_image() {
    let specs = sample_specs();
    let pi = PiParams {
        total: 4,
        input_offset: 0,
        input_size: 0,
        output_offset: 0,
        output_size: 6,
    };
    let b = build(&specs, None, Some(&pi));
    assert_eq!(Container::parse(&b).unwrap_err(), ContainerError::PiParams);
}

#[test]
fn simple_variable_from_0x2000_is_a_candidate() {
    let specs = [
        EntrySpec {
            index: 0x2000,
            sub: 0,
            data: &[5],
            attr: 0x70,
        },
        EntrySpec {
            index: 0x2001,
            sub: 0,
            data: &[1],
            attr: 0x30,
        },
        EntrySpec {
            index: 0x2001,
            sub: 1,
            data: &[7],
            attr: 0x70,
        },
    ];
    let b = build(&specs, Some(&[8, NOT_PLACED]), None);
    let c = Container::parse(&b).unwrap();
    let a: Vec<_> = c.addressed().map(|(_, a)| a).collect();
    assert_eq!(a, [Some(8), None, None]);
}

#[test]
fn seed_table_2_types_and_areas() {
    let nv = |i| network_variable(i).map(|n| (n.area, n.typ, n.range_start));
    assert_eq!(nv(0xA000), Some((PiArea::Input, DataType::Int8, 0xA000)));
    assert_eq!(nv(0xA080), Some((PiArea::Input, DataType::Bool, 0xA080)));
    assert_eq!(nv(0xA27F), Some((PiArea::Input, DataType::Real32, 0xA240)));
    assert_eq!(nv(0xA440), Some((PiArea::Input, DataType::UInt64, 0xA440)));
    assert_eq!(nv(0xA4C1), Some((PiArea::Output, DataType::UInt8, 0xA4C0)));
    assert_eq!(nv(0xA580), Some((PiArea::Output, DataType::UInt16, 0xA580)));
    assert_eq!(nv(0xA6C0), Some((PiArea::Output, DataType::Real32, 0xA6C0)));
    assert_eq!(nv(0xA880), Some((PiArea::Output, DataType::Int64, 0xA880)));
    assert_eq!(nv(0xA8FF), Some((PiArea::Output, DataType::UInt64, 0xA8C0)));
    assert_eq!(nv(0xA900), None);
    assert_eq!(nv(0x9FFF), None);
    assert!(is_network_variable(0xAFFF) && !is_network_variable(0xB000));
}

#[test]
fn offset_rule_of_seed_chapter_6() {
    // Seed Bild 8: three BYTEs at +0..+2, the WORD with subindex 3 at +4.
    assert_eq!(rule_offset(0xA4C0, 1), Some((PiArea::Output, 0, 1)));
    assert_eq!(rule_offset(0xA4C0, 3), Some((PiArea::Output, 2, 1)));
    assert_eq!(rule_offset(0xA580, 3), Some((PiArea::Output, 4, 2)));
    // Seed text: subindex 6 of a BYTE is offset 5, subindex 3 of a DWORD 8.
    assert_eq!(rule_offset(0xA4C0, 6).map(|r| r.1), Some(5));
    assert_eq!(rule_offset(0xA680, 3).map(|r| r.1), Some(8));
    // The 255th BYTE variable is 0xA4C1 sub 1.
    assert_eq!(rule_offset(0xA4C1, 1).map(|r| r.1), Some(254));
    assert_eq!(rule_offset(0xA4C0, 0), None);
    assert_eq!(rule_offset(0xA4C0, 255), None);
    // 24-bit variables take the width of their C type.
    assert_eq!(rule_offset(0xA5C0, 2), Some((PiArea::Output, 4, 4)));
}

#[test]
fn layout_puts_outputs_after_inputs_aligned() {
    let mut l = PiLayout::default();
    for (i, s) in [(0xA040u16, 3u8), (0xA4C0, 1), (0xA4C0, 2), (0xA580, 3)] {
        l.add(i, s);
    }
    assert_eq!(l.input_size, 3);
    assert_eq!(l.output_offset(), 8);
    assert_eq!(l.params().total, 14);
    assert_eq!(l.place(0xA580, 3), Some((12, 2)));
    assert_eq!(l.place(0xA040, 3), Some((2, 1)));
}
