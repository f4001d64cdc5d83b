//! dcf2bin and the library's EDS export against python-canopen 2.4, a
//! CANopen implementation nobody here wrote: the same DCF read by both
//! gives the same objects, and the EDS the library writes of its
//! dictionary (static part plus dynamic OD) loads there with every object,
//! type, access and value.

mod common;

use common::{hex, python_dump, sample, temp_dir};
use cop::od::eds::{EdsInfo, write_eds};
use cop::od::{Access, ByteOrder};
use cop::sim::SimBus;

#[test]
fn python_canopen_and_dcf2bin_read_the_same_dcf() {
    let (_, dcf) = dcf2bin::load(&sample(), None).unwrap();
    let py = python_dump(&sample());
    assert_eq!(py.len(), dcf.objects.len());
    for (p, o) in py.iter().zip(&dcf.objects) {
        let what = format!("{:04X}sub{:X}", o.index, o.sub);
        assert_eq!((p.index, p.sub), (o.index, o.sub), "{what}");
        assert_eq!(p.data_type, o.data_type, "{what}");
        assert_eq!(p.access, o.access, "{what}");
        assert_eq!(p.pdo, o.pdo_mapping, "{what}");
        assert_eq!(p.hex.as_deref(), Some(hex(&o.data).as_str()), "{what}");
    }
}

/// Every test file read by both: the same objects, types, access, PDO
/// mapping and, where python-canopen has a value, the same bytes. Where
/// they differ, dcf2bin said why (a warning at that line) or the
/// difference is python-canopen's (listed).
#[test]
fn python_canopen_and_dcf2bin_read_every_test_file_alike() {
    for name in [
        "all_types.eds",
        "io_editor.eds",
        "demo_device.eds",
        "sample_tool.eds",
        "master_festival.eds",
    ] {
        let path = common::data(name);
        let (_, dcf) = dcf2bin::load(&path, Some(3)).unwrap();
        let py: Vec<_> = python_dump(&path)
            .into_iter()
            // python-canopen adds the [DummyUsage] types as objects.
            .filter(|p| p.index >= 0x1000)
            .collect();
        let warned = |line: usize| dcf.warnings.iter().any(|w| w.at.line == Some(line));
        let mut compared = 0;
        for p in &py {
            let what = format!("{name} {:04X}sub{:X}", p.index, p.sub);
            let Some(o) = dcf.get(p.index, p.sub) else {
                // Only what dcf2bin skipped with a warning is missing.
                let sec = if p.sub == 0 {
                    format!("{:04X}", p.index)
                } else {
                    format!("{:04X}sub{:X}", p.index, p.sub)
                };
                assert!(
                    dcf.warnings
                        .iter()
                        .any(|w| w.kind == dcf2bin::WarningKind::Skipped
                            && w.at.section.as_deref() == Some(sec.as_str())),
                    "{what}: missing without warning"
                );
                continue;
            };
            // python-canopen reads compact arrays without [XXXXValue] and
            // gives their subindex 0 neither access type nor value (CiA 306
            // compact storage: the number of subindices, read-only).
            let compact = (name, p.index) == ("sample_tool.eds", 0x2040);
            if compact && p.sub == 0 {
                assert_eq!((o.access.as_str(), o.data.as_slice()), ("ro", &[3u8][..]));
                continue;
            }
            assert_eq!(p.data_type, o.data_type, "{what}");
            assert_eq!(p.access, o.access, "{what}");
            assert_eq!(p.pdo, o.pdo_mapping, "{what}");
            match p.hex.as_deref() {
                Some("ERR") | None => assert!(
                    warned(o.value_line),
                    "{what}: python-canopen has no value, dcf2bin {} without warning",
                    hex(&o.data)
                ),
                Some(h) if compact && h != hex(&o.data) => {}
                Some(h) => {
                    assert_eq!(h, hex(&o.data), "{what}");
                    compared += 1;
                }
            }
        }
        assert!(compared >= 5, "{name}: {compared} values compared");
        // And the other way round: nothing only dcf2bin has.
        for o in &dcf.objects {
            assert!(
                py.iter().any(|p| (p.index, p.sub) == (o.index, o.sub)),
                "{name}: {:04X}sub{:X} only in dcf2bin",
                o.index,
                o.sub
            );
        }
    }
}

/// The node after the build of every type's container, exported as EDS
/// (`--check ... --eds`): python-canopen reads each object with the type
/// the input gave it (INTEGER24 -1 as INTEGER24, not UNSIGNED24 0xFFFFFF)
/// and the input's value.
#[test]
fn the_node_after_the_build_exports_the_types_of_the_input() {
    let (_, dcf) = dcf2bin::load(&common::data("all_types.eds"), Some(3)).unwrap();
    let mut part = dcf.clone();
    part.objects.retain(|o| o.index < 0x2000);
    let node = dcf2bin::node::from_eds(&part);
    let dir = temp_dir("export-types");
    let eds = dir.join("after.eds");
    let c = dcf.container().unwrap();
    let r =
        dcf2bin::check::check_and_export(&dcf, &c, &node, None, usize::MAX, Some(&eds)).unwrap();
    assert!(r.builds, "{:?}", r.lines);
    let py = python_dump(&eds);
    let mut seen = 0;
    for o in dcf.objects.iter().filter(|o| o.index >= 0x2000) {
        let p = py
            .iter()
            .find(|p| (p.index, p.sub) == (o.index, o.sub))
            .unwrap();
        let what = format!("{:04X}", o.index);
        assert_eq!(p.data_type, o.data_type, "{what}");
        assert_eq!(p.hex.as_deref(), Some(hex(&o.data).as_str()), "{what}");
        seen += 1;
    }
    assert_eq!(seen, 25);
    let _ = std::fs::remove_dir_all(dir);
}

node!(eds_node);

#[test]
fn exported_eds_loads_in_python_canopen_object_by_object() {
    let bus = SimBus::new();
    let (mut stack, mut port) = common::node(&bus, eds_node::od(), 1);
    let (_, dcf) = dcf2bin::load(&sample(), None).unwrap();
    let c = dcf.container().unwrap();
    eds_node::POOL
        .build(&mut stack, &mut port, bus.now(), &c, None)
        .unwrap();
    let mut text = String::new();
    let info = EdsInfo {
        file_name: "dynod.eds",
        vendor_name: "cop",
        vendor_number: 0x123,
        product_name: "dynod; sample",
        ..EdsInfo::default()
    };
    write_eds(stack.od(), &info, &mut text).unwrap();
    let dir = temp_dir("eds");
    let path = dir.join("dynod.eds");
    std::fs::write(&path, &text).unwrap();
    let py = python_dump(&path);

    let od = stack.od();
    let mut ours = Vec::new();
    for e in od.entries() {
        for sub in 0..od.sub_count(e).min(256) {
            let Ok(o) = od.find(e.index(), sub as u8) else {
                continue;
            };
            let mut b = [0u8; 256];
            let n = od.peek(&o, ByteOrder::Wire, &mut b).unwrap();
            let a = o.access();
            let access = if a.0 & Access::CONST != 0 {
                "const"
            } else if a.readable() && a.writable() {
                "rw"
            } else if a.writable() {
                "wo"
            } else {
                "ro"
            };
            ours.push((
                e.index(),
                sub as u8,
                u16::from(o.data_type().code()),
                access.to_string(),
                a.mappable(),
                hex(&b[..n]),
            ));
        }
    }
    ours.sort();
    let theirs: Vec<_> = py
        .iter()
        .map(|p| {
            (
                p.index,
                p.sub,
                p.data_type,
                p.access.clone(),
                p.pdo,
                p.hex.clone().unwrap_or_default(),
            )
        })
        .collect();
    for (a, b) in ours.iter().zip(&theirs) {
        assert_eq!(a, b);
    }
    assert_eq!(ours.len(), theirs.len());
    // The dynamic objects are there, with the DCF's values.
    assert!(
        theirs
            .iter()
            .any(|t| (t.0, t.1, t.5.as_str()) == (0xA580, 3, "3412"))
    );
    assert!(
        theirs
            .iter()
            .any(|t| (t.0, t.1, t.5.as_str()) == (0x2003, 0, "0000C03F"))
    );
    let _ = std::fs::remove_dir_all(dir);
}
