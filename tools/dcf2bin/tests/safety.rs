//! The CiA 306 safety keys between the library's EDS export and dcf2bin:
//! the export of a dictionary with SRDOs carries `CANopenSafetySupported`,
//! `SRDOMapping` and `InvertedSRAD`; dcf2bin reads them back, checks them
//! against each other and the SRDO mappings, and computes the same 0x13FF
//! CRCs as the library; python-canopen still loads the export. Files with
//! inconsistent keys are refused with the line.

mod common;

use std::path::Path;
use std::process::Command;

use common::{python_dump, temp_dir};
use cop::od::eds::{EdsInfo, write_eds};
use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
use cop::srdo::Srdo;
use core::sync::atomic::AtomicU8;

// SRDO 1 (transmit) maps 0x6200 sub 1 with its inverted data 0x6300 sub 1
// and 0x6200 sub 2 with 0x6300 sub 2; SRDO 2 (receive) 0x6201 / 0x6301.
cop::obd_create_srdo_gfc_param!(mod gfc);
cop::obd_create_srdo_commu!(mod c1, 0x1301, 1, 25, 20, 0x101, 0x102);
cop::obd_create_srdo_commu!(mod c2, 0x1302, 2, 50, 40, 0x103, 0x104);
cop::obd_create_srdo_mapp!(mod m1, 0x1381, [0x6200_0108, 0x6300_0108, 0x6200_0208, 0x6300_0208]);
cop::obd_create_srdo_mapp!(mod m2, 0x1382, [0x6201_0010, 0x6301_0010]);
cop::obd_create_srdo_cfg_valid!(mod cfg_valid);
cop::obd_create_srdo_crc!(mod crcs, [0, 0]);

static N1: [AtomicU8; 1] = decl::zeroed();
static N2: [AtomicU8; 1] = decl::zeroed();
static I1: [AtomicU8; 1] = decl::init([0xFF]);
static I2: [AtomicU8; 1] = decl::init([0xFF]);
static W: [AtomicU8; 2] = decl::zeroed();
static WI: [AtomicU8; 2] = decl::init([0xFF, 0xFF]);
static S6200: [ObdSubEntry; 3] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[2]),
    ObdSubEntry::ram(1, DataType::UInt8, Access::PRW, &N1, None),
    ObdSubEntry::ram(2, DataType::UInt8, Access::PRW, &N2, None),
];
static S6300: [ObdSubEntry; 3] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[2]),
    ObdSubEntry::ram(1, DataType::UInt8, Access::PRW, &I1, None),
    ObdSubEntry::ram(2, DataType::UInt8, Access::PRW, &I2, None),
];
static S6201: [ObdSubEntry; 1] = [ObdSubEntry::ram(0, DataType::UInt16, Access::PRW, &W, None)];
static S6301: [ObdSubEntry; 1] = [ObdSubEntry::ram(
    0,
    DataType::UInt16,
    Access::PRW,
    &WI,
    None,
)];
static GENERIC: [ObdEntry; 7] = [
    cop::srdo_obd_entry!(gfc),
    cop::srdo_obd_entry!(c1),
    cop::srdo_obd_entry!(c2),
    cop::srdo_obd_entry!(m1),
    cop::srdo_obd_entry!(m2),
    cop::srdo_obd_entry!(cfg_valid),
    cop::srdo_obd_entry!(crcs),
];
static DEVICE: [ObdEntry; 4] = [
    ObdEntry::new(0x6200, &S6200, None),
    ObdEntry::new(0x6201, &S6201, None),
    ObdEntry::new(0x6300, &S6300, None),
    ObdEntry::new(0x6301, &S6301, None),
];

fn dictionary() -> ObjectDictionary {
    let od = ObjectDictionary::new(&GENERIC, &[], &DEVICE).unwrap();
    od.restore_defaults(0x1000, 0x9FFF);
    od
}

#[test]
fn safety_keys_round_trip_between_the_export_and_dcf2bin() {
    let od = dictionary();
    let mut eds = String::new();
    write_eds(&od, &EdsInfo::default(), &mut eds).unwrap();
    let d = dcf2bin::parse(&eds, Path::new("safety.eds"), Some(1)).unwrap();
    assert_eq!(d.safety_supported, Some(true));
    assert!(d.warnings.is_empty(), "{:?}", d.warnings);
    let keys = |i, s| {
        let o = d.get(i, s).unwrap();
        (o.srdo_mapping, o.inverted_srad.map(|(i, s, _)| (i, s)))
    };
    assert_eq!(keys(0x6200, 1), (true, Some((0x6300, 1))));
    assert_eq!(keys(0x6200, 2), (true, Some((0x6300, 2))));
    assert_eq!(keys(0x6201, 0), (true, Some((0x6301, 0))));
    assert_eq!(keys(0x6300, 1), (true, None));
    assert_eq!(keys(0x6301, 0), (true, None));
    // The CRCs dcf2bin computes from the export are the library's.
    let mut srdo = Srdo::new();
    srdo.init(&od).unwrap();
    let ours: Vec<(u8, u16)> = d.srdo_crcs().unwrap();
    let library: Vec<(u8, u16)> = [1u8, 2]
        .iter()
        .map(|n| (*n, srdo.calc_crc(&od, 0x1300 + u16::from(*n)).unwrap()))
        .collect();
    assert_eq!(ours, library);
    // python-canopen loads the export with every object.
    let dir = temp_dir("safety-export");
    let path = dir.join("safety.eds");
    std::fs::write(&path, &eds).unwrap();
    let py = python_dump(&path);
    assert_eq!(py.len(), d.objects.len());
    // --srdo-crc names the pairs and compares the stored CRCs.
    let o = Command::new(env!("CARGO_BIN_EXE_dcf2bin"))
        .args(["--srdo-crc", path.to_str().unwrap()])
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        out.contains(&format!(
            "SRDO 1 (0x1301): 0x13FF sub 1 = 0x{:04X} (stored: 0x0000, differs)",
            library[0].1
        )),
        "{out}"
    );
    assert!(
        out.contains("    0x6200 sub 2 / inverted 0x6300 sub 2\n"),
        "{out}"
    );
    assert!(
        out.contains("SRDO configuration check (CcmCheckSrdoConfig, with these CRCs): passes"),
        "{out}"
    );
    // The library's check on a configuration it refuses: SRDO 2 with the
    // COB-ID 1 of SRDO 1.
    let clash = eds.replacen("DefaultValue=0x103\n", "DefaultValue=0x101\n", 1);
    assert_ne!(clash, eds);
    std::fs::write(&path, &clash).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_dcf2bin"))
        .args(["--srdo-crc", path.to_str().unwrap()])
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.contains("(CcmCheckSrdoConfig, with these CRCs): kCopSrdoCfgIdError"),
        "{out}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

/// The export with one line replaced (`from` must occur once).
fn edited(from: &str, to: &str) -> String {
    let mut eds = String::new();
    write_eds(&dictionary(), &EdsInfo::default(), &mut eds).unwrap();
    assert_eq!(eds.matches(from).count(), 1, "{from}");
    eds.replacen(from, to, 1)
}

fn refused(text: &str) -> String {
    dcf2bin::parse(text, Path::new("s.eds"), Some(1))
        .unwrap_err()
        .to_string()
}

#[test]
fn inconsistent_safety_keys_are_refused() {
    for (from, to, expect) in [
        (
            "InvertedSRAD=0x630001",
            "InvertedSRAD=0x63001",
            "InvertedSRAD: `0x63001`: CiA 306 writes the inverted object as 0x, four hex digits of the index, two of the subindex",
        ),
        (
            "InvertedSRAD=0x630001",
            "InvertedSRAD=0x640001",
            "InvertedSRAD: the inverted object 0x6400 sub 1 is not in the file",
        ),
        (
            "InvertedSRAD=0x630001",
            "InvertedSRAD=0x630100",
            "is UNSIGNED8 and its inverted object 0x6301 sub 0 UNSIGNED16",
        ),
        (
            "InvertedSRAD=0x630002",
            "InvertedSRAD=0x630001",
            "0x6300 sub 1 is already the inverted data of 0x6200 sub 1",
        ),
        (
            "InvertedSRAD=0x630001",
            "InvertedSRAD=0x620002",
            "0x6200 sub 2 is the inverted data of 0x6200 sub 1 and names inverted data itself",
        ),
    ] {
        let e = refused(&edited(from, to));
        assert!(e.contains(expect), "{to}: {e}");
        assert!(e.starts_with("s.eds:"), "{e}");
    }
    // A mapped object not marked for SRDOs.
    let text = edited(
        "PDOMapping=1\nSRDOMapping=1\nInvertedSRAD=0x630100",
        "PDOMapping=1",
    );
    let e = refused(&text.replacen(
        "PDOMapping=1\nSRDOMapping=1\n\n[6302",
        "PDOMapping=1\n\n[6302",
        1,
    ));
    assert!(
        e.contains("SRDO 2 maps 0x6201 sub 0, which is not marked SRDOMapping=1"),
        "{e}"
    );
    // A pair the mapping holds against the object's InvertedSRAD: swap the
    // inverted objects of SRDO 1 in its mapping.
    let e = refused(
        &edited("DefaultValue=0x63000108", "DefaultValue=0x63000208").replacen(
            "DefaultValue=0x63000208\nPDOMapping=0\n\n[1381sub4]",
            "DefaultValue=0x63000108\nPDOMapping=0\n\n[1381sub4]",
            1,
        ),
    );
    assert!(
        e.contains(
            "SRDO 1 pairs 0x6200 sub 1 with 0x6300 sub 2, but its InvertedSRAD names 0x6300 sub 1"
        ),
        "{e}"
    );
    // Keys without CANopenSafetySupported=1: tolerated, refused with --strict.
    let text = edited("CANopenSafetySupported=1\n", "");
    let d = dcf2bin::parse(&text, Path::new("s.eds"), Some(1)).unwrap();
    assert!(
        d.warnings[0]
            .to_string()
            .contains("safety keys without [DeviceInfo] CANopenSafetySupported=1")
    );
    let strict = dcf2bin::parse_with(
        &text,
        Path::new("s.eds"),
        dcf2bin::Options {
            node_id: Some(1),
            strict: true,
        },
    );
    assert!(strict.is_err());
}
