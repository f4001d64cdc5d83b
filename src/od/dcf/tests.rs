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

// ---------------------------------------------------------------------
// The index of the entries (parse_indexed): every answer as without it
// ---------------------------------------------------------------------

use crate::testod::Rng;

/// A valid container of `n` random entries: indices from a few objects
/// (communication, PDO, manufacturer, network variables), repeated
/// subindices, subindex 0 alone or with others, data sizes 0..=8 (the
/// attribute matching), entries in random order; with an address segment
/// when `addresses`.
fn random_container(rng: &mut Rng, n: usize, addresses: bool) -> Vec<u8> {
    const INDICES: [u16; 12] = [
        0x1017, 0x1400, 0x1600, 0x1801, 0x1A01, 0x2000, 0x2001, 0x2100, 0x3000, 0xA000, 0xA4C0,
        0xA580,
    ];
    const DATA: [u8; 8] = [1, 2, 3, 4, 5, 6, 7, 8];
    let objects = 1 + rng.below(INDICES.len() as u64) as usize;
    let specs: Vec<EntrySpec<'static>> = (0..n)
        .map(|_| {
            let index = INDICES[rng.below(objects as u64) as usize];
            let sub = match rng.below(4) {
                0 => 0,
                _ => rng.below(6) as u8,
            };
            let len = rng.below(9) as usize;
            let attr = match len {
                0 => 0x60,
                1 if rng.below(2) == 0 => 0x61,
                _ => 0x70,
            };
            EntrySpec {
                index,
                sub,
                data: &DATA[..len],
                attr,
            }
        })
        .collect();
    // Count the candidates with the scanning parser to size the address
    // segment.
    let probe = build(&specs, None, None);
    let candidates = Container::parse(&probe).unwrap().candidate_count();
    let words: Vec<u16> = (0..candidates)
        .map(|i| if i % 3 == 2 { NOT_PLACED } else { i as u16 * 2 })
        .collect();
    build(&specs, addresses.then_some(&words[..]), None)
}

/// What `objects()` tells about one index.
type ObjectAnswers<'a> = ((u16, Option<u8>, Subindices), Vec<(Entry<'a>, Entry<'a>)>);

/// Compares every answer of the indexed container with the scanning one
/// (under Miri, which is slow, for some of the indices and entries).
fn same_answers(bytes: &[u8]) {
    let scan = Container::parse(bytes).unwrap();
    let len =
        index_scratch_len(scan.len(), scan.index_segment().len(), scan.has_addresses()).unwrap();
    let mut scratch = vec![0xA5u8; len + 3];
    let fast = Container::parse_indexed(bytes, &mut scratch).unwrap();
    assert!(fast.is_indexed());
    assert_eq!(fast.index_len(), len);
    assert_eq!(fast.candidate_count(), scan.candidate_count());
    assert_eq!(
        fast.addressed().collect::<Vec<_>>(),
        scan.addressed().collect::<Vec<_>>()
    );
    assert_eq!(
        fast.indices().collect::<Vec<_>>(),
        scan.indices().collect::<Vec<_>>()
    );
    let sample = |n: usize| if cfg!(miri) { n.div_ceil(8).max(1) } else { 1 };
    if !cfg!(miri) || scan.len() <= 64 {
        fn objects<'a>(c: &Container<'a>) -> Vec<ObjectAnswers<'a>> {
            c.objects()
                .map(|o| {
                    let head = (o.index(), o.missing_count(), o.subindices());
                    (head, o.collect())
                })
                .collect()
        }
        assert_eq!(objects(&fast), objects(&scan));
    }
    let mut indices: Vec<u16> = scan.entries().map(|e| e.index).collect();
    indices.sort_unstable();
    indices.dedup();
    let step = sample(indices.len());
    let mut indices: Vec<u16> = indices.into_iter().step_by(step).collect();
    indices.extend([0x0000, 0x1000, 0x1FFF, 0x2002, 0xA001, 0xFFFF]);
    for &index in &indices {
        assert_eq!(
            fast.subindices(index),
            scan.subindices(index),
            "{index:#06x}"
        );
        assert_eq!(fast.first_position(index), scan.first_position(index));
        assert_eq!(
            fast.subs_of(index).collect::<Vec<_>>(),
            scan.subs_of(index).collect::<Vec<_>>(),
            "{index:#06x}"
        );
        for sub in [0u8, 1, 2, 3, 4, 5, 9, 0xFF] {
            assert_eq!(
                fast.has_other_subs(index, sub),
                scan.has_other_subs(index, sub),
                "{index:#06x}/{sub}"
            );
            assert_eq!(
                fast.last_occurrence(index, sub),
                scan.last_occurrence(index, sub),
                "{index:#06x}/{sub}"
            );
        }
    }
    for (first, last) in [
        (0x0000, 0xFFFF),
        (0x1400, 0x1BFF),
        (0xA000, 0xA8FF),
        (0x1017, 0x1017),
        (0x5000, 0x9FFF),
    ] {
        assert_eq!(
            fast.entries_in(first, last).collect::<Vec<_>>(),
            scan.entries_in(first, last).collect::<Vec<_>>(),
            "{first:#06x}..={last:#06x}"
        );
    }
    for e in scan.entries().step_by(sample(scan.len())) {
        assert_eq!(fast.entry(e.position as usize), Some(e));
        assert_eq!(
            fast.is_first_occurrence_at(e.position as usize),
            fast.is_first_occurrence(&e)
        );
        assert_eq!(fast.is_first_occurrence(&e), scan.is_first_occurrence(&e));
        assert_eq!(fast.has_sub_zero(&e), scan.has_sub_zero(&e));
        assert_eq!(fast.entry_has_other_subs(&e), scan.entry_has_other_subs(&e));
        assert_eq!(fast.is_candidate(&e), scan.is_candidate(&e));
        // (Without address segment the scan asks every subindex 0 before
        // `e` whether it is a candidate: too slow for Miri.)
        if !cfg!(miri) || scan.has_addresses() {
            assert_eq!(fast.address_word(&e), scan.address_word(&e));
        }
        assert_eq!(fast.first_occurrence(&e), scan.first_occurrence(&e));
        assert_eq!(fast.is_last_occurrence(&e), scan.is_last_occurrence(&e));
        assert_eq!(fast.is_first_of_index(&e), scan.is_first_of_index(&e));
    }
    // The bytes before the index are not touched.
    let start = scratch.len() - len;
    assert!(scratch[..start].iter().all(|b| *b == 0xA5));
}

#[test]
fn the_index_gives_the_answers_of_a_scan() {
    same_answers(&sample());
    same_answers(&build(&[], None, None));
    let mut rng = Rng(0x0123_4567_89AB_CDEF);
    // Under Miri one round of each kind: the four sizes and address
    // segment with and without (round % 4, round % 2).
    let (rounds, most) = if cfg!(miri) { (4, 24) } else { (400, 150) };
    for round in 0..rounds {
        let n = match round % 4 {
            0 => rng.below(4) as usize,
            1 => rng.below(20) as usize,
            _ => rng.below(most) as usize,
        };
        same_answers(&random_container(&mut rng, n, round % 2 == 1));
    }
}

#[test]
fn the_index_of_a_large_container_uses_wide_positions() {
    // An index segment beyond 64 KiB: 4-byte positions and offsets.
    // Under Miri fewer, larger entries (each scanning answer it is
    // compared with walks the entries) over fewer indices, so that
    // subindices still repeat.
    let (n, size, spread, indices) = if cfg!(miri) {
        (60u32, 1100, 50, 20)
    } else {
        (500, 0, 300, 50)
    };
    let mut rng = Rng(42);
    let data = [0x5Au8; 1150];
    let specs: Vec<EntrySpec<'_>> = (0..n)
        .map(|i| EntrySpec {
            index: 0x2000 + (rng.below(indices) as u16),
            sub: (i % 7) as u8,
            data: &data[..size + rng.below(spread) as usize],
            attr: 0x60,
        })
        .collect();
    let bytes = build(&specs, None, None);
    assert!(Container::parse(&bytes).unwrap().index_segment().len() > 0xFFFF);
    same_answers(&bytes);
}

#[test]
fn a_scratch_too_small_means_no_index_and_the_same_answers() {
    let bytes = sample();
    let c = Container::parse(&bytes).unwrap();
    let need = index_scratch_len(c.len(), c.index_segment().len(), c.has_addresses()).unwrap();
    let mut scratch = vec![0u8; need - 1];
    let small = Container::parse_indexed(&bytes, &mut scratch).unwrap();
    assert!(!small.is_indexed());
    assert_eq!(small.index_len(), 0);
    assert_eq!(small.candidate_count(), c.candidate_count());
    // Refusals are the same with and without index.
    let mut bad = bytes.clone();
    let addr = u32::from_le_bytes(bad[16..20].try_into().unwrap()) as usize;
    bad[addr] ^= 0; // unchanged, then one word too few:
    put32(&mut bad, 20, 6);
    let mut scratch = vec![0u8; 4096];
    assert_eq!(
        Container::parse_indexed(&bad, &mut scratch).unwrap_err(),
        Container::parse(&bad).unwrap_err()
    );
}
