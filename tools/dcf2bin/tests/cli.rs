//! The command line: help, outputs, errors that name file, line, section
//! and key, nothing written on failure, SRDO CRCs (SAFETY_BEHAVIOUR.md
//! section 3 vectors) printed and written back.

mod common;

use std::path::Path;

use common::{dcf2bin, sample, temp_dir, text};

#[test]
fn help_and_usage_errors() {
    let o = dcf2bin(&["--help"]);
    assert!(o.status.success());
    assert!(text(&o.stdout).contains("USAGE:"));
    let o = dcf2bin(&[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("no input file"));
    let o = dcf2bin(&["--bogus", "x.dcf"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn writes_a_container_the_library_accepts() {
    let dir = temp_dir("out");
    let bin = dir.join("sample.bin");
    let o = dcf2bin(&[sample().to_str().unwrap(), "-o", bin.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let bytes = std::fs::read(&bin).unwrap();
    let c = cop::od::dcf::Container::parse(&bytes).unwrap();
    assert_eq!(c.len(), 43);
    assert!(c.has_attributes() && c.has_addresses());
    // The C form holds the same bytes.
    let src = dir.join("sample.c");
    let o = dcf2bin(&[
        sample().to_str().unwrap(),
        "--c-array",
        "abContainer",
        "-o",
        src.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let c_text = std::fs::read_to_string(&src).unwrap();
    assert!(c_text.contains(&format!("abContainer[{}]", bytes.len())));
    let listed = c_text.matches("0x").count();
    assert_eq!(listed, bytes.len());
    let _ = std::fs::remove_dir_all(dir);
}

/// Writes `content` as bad.dcf, runs dcf2bin on it and returns stderr;
/// checks that nothing was written.
fn refused(name: &str, content: &str) -> String {
    let dir = temp_dir(name);
    let input = dir.join("bad.dcf");
    std::fs::write(&input, content).unwrap();
    let o = dcf2bin(&[input.to_str().unwrap()]);
    assert!(!o.status.success());
    let entries: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(entries.len(), 1, "only the input is left");
    let _ = std::fs::remove_dir_all(dir);
    text(&o.stderr)
}

const HEAD: &str = "[DeviceInfo]\nVendorName=x\n\n";

#[test]
fn errors_name_file_line_section_and_key() {
    let e = refused(
        "value",
        &format!(
            "{HEAD}[2000]\nParameterName=x\nDataType=0x0005\nAccessType=rw\nDefaultValue=0\nParameterValue=256\n"
        ),
    );
    assert!(
        e.contains("bad.dcf:9: [2000] ParameterValue: 256 is out of range"),
        "{e}"
    );
    let e = refused(
        "netvar",
        &format!(
            "{HEAD}[A580]\nObjectType=0x8\nSubNumber=2\n\n[A580sub0]\nDataType=0x0005\nAccessType=ro\nDefaultValue=1\n\n[A580sub1]\nDataType=0x0005\nAccessType=rw\n"
        ),
    );
    assert!(
        e.contains(":14: [A580sub1] DataType: 0xA580 holds UNSIGNED16 (CiA 405 network variables, seed table 2), not UNSIGNED8"),
        "{e}"
    );
    let e = refused(
        "access",
        &format!("{HEAD}[2000]\nDataType=0x0005\nAccessType=readwrite\n"),
    );
    assert!(e.contains(":6: [2000] AccessType:"), "{e}");
    let e = refused(
        "nodeid",
        &format!(
            "{HEAD}[1800sub1]\nDataType=0x0007\nAccessType=rw\nDefaultValue=$NODEID+0x180\n[1800]\nObjectType=0x9\n"
        ),
    );
    assert!(e.contains("[1800sub1] DefaultValue: uses $NODEID"), "{e}");
    let e = refused(
        "orphan",
        &format!("{HEAD}[2000sub1]\nDataType=0x0005\nAccessType=rw\n"),
    );
    assert!(e.contains(":4: [2000sub1]: subindex of [2000]"), "{e}");
}

/// A DCF with the five SRDOs of SAFETY_BEHAVIOUR.md section 3 and 0x13FF.
fn srdo_dcf(with_crc_sections: bool) -> String {
    let rows: [(u8, &[u32]); 5] = [
        (1, &[0x6200_0108, 0x6200_0208]),
        (2, &[0x6200_0108, 0x6200_0208]),
        (1, &[0x6200_0108, 0x6200_0208, 0x6200_0308, 0x6200_0408]),
        (1, &[0x6300_0110, 0x6300_0210, 0x6200_0108, 0x6200_0208]),
        (2, &[0x6300_0110, 0x6300_0210, 0x6200_0108, 0x6200_0208]),
    ];
    let var = |sec: String, dt: u16, v: String| {
        format!(
            "[{sec}]\nParameterName=p\nObjectType=0x7\nDataType=0x{dt:04X}\nAccessType=rw\nDefaultValue={v}\nPDOMapping=0\n\n"
        )
    };
    let mut s = String::from(HEAD);
    for (n, (dir, map)) in rows.iter().enumerate() {
        let c = 0x1301 + n as u16;
        let m = 0x1381 + n as u16;
        s += &format!("[{c:04X}]\nObjectType=0x9\nSubNumber=7\n\n");
        s += &var(format!("{c:04X}sub0"), 5, "6".into());
        s += &var(format!("{c:04X}sub1"), 5, dir.to_string());
        s += &var(format!("{c:04X}sub2"), 6, "25".into());
        s += &var(format!("{c:04X}sub3"), 5, "20".into());
        s += &var(format!("{c:04X}sub4"), 5, "254".into());
        s += &var(format!("{c:04X}sub5"), 7, "0x101".into());
        s += &var(format!("{c:04X}sub6"), 7, "0x102".into());
        s += &format!("[{m:04X}]\nObjectType=0x8\nSubNumber={}\n\n", map.len() + 1);
        s += &var(format!("{m:04X}sub0"), 5, map.len().to_string());
        for (i, e) in map.iter().enumerate() {
            s += &var(format!("{m:04X}sub{:X}", i + 1), 7, format!("0x{e:08X}"));
        }
    }
    if with_crc_sections {
        s += "[13FF]\nObjectType=0x8\nSubNumber=6\n\n";
        s += &var("13FFsub0".into(), 5, "5".into());
        for n in 1..=5 {
            s += &var(format!("13FFsub{n}"), 6, "0".into());
        }
    }
    s
}

const VECTORS: [u16; 5] = [0xD879, 0x7764, 0xE57E, 0x25EA, 0xA3AF];

#[test]
fn srdo_crcs_of_the_public_vectors() {
    let d = dcf2bin::parse(&srdo_dcf(false), Path::new("srdo.dcf"), None).unwrap();
    let crcs: Vec<u16> = d.srdo_crcs().unwrap().iter().map(|c| c.1).collect();
    assert_eq!(crcs, VECTORS);
    // SAFETY_BEHAVIOUR.md section 3: CRC-16/XMODEM check value.
    assert_eq!(cop::srdo::crc::crc16(b"123456789"), 0x31C3);
}

/// `--srdo-crc` on a DCF that declares its SRDO configuration valid
/// (0x13FE = 0xA5, SAFETY_BEHAVIOUR.md section 2) with 0x13FF values that
/// are not the CRCs of the configuration: the node would refuse it at
/// start (`kCopSrdoCfgCrcError`), so the tool fails, and a CI step sees it.
#[test]
fn a_stored_crc_that_differs_fails_when_the_file_declares_it_valid() {
    let dir = temp_dir("crc-differs");
    let input = dir.join("srdo.dcf");
    let cfg_valid = |v: &str| {
        format!(
            "[13FE]\nParameterName=p\nObjectType=0x7\nDataType=0x0005\nAccessType=rw\nDefaultValue={v}\nPDOMapping=0\n\n"
        )
    };
    let run = |body: &str, extra: &[&str]| {
        std::fs::write(&input, body).unwrap();
        let mut args = vec!["--srdo-crc"];
        args.extend_from_slice(extra);
        args.push(input.to_str().unwrap());
        let o = dcf2bin(&args);
        (o.status.code(), text(&o.stdout), text(&o.stderr))
    };
    // 0x13FF sub 1..5 hold 0 in srdo_dcf: every one differs.
    let (code, out, err) = run(&(srdo_dcf(true) + &cfg_valid("0xA5")), &[]);
    assert_eq!(code, Some(1), "{out}{err}");
    assert!(out.contains("stored: 0x0000, differs"), "{out}");
    assert!(
        err.contains("0x13FE = 0xA5 declares the configuration valid, but 0x13FF sub 1 is 0x0000, not the CRC 0xD879"),
        "{err}"
    );
    // Not declared valid: the CRCs are information, no failure.
    let (code, out, err) = run(&(srdo_dcf(true) + &cfg_valid("0")), &[]);
    assert_eq!(code, Some(0), "{out}{err}");
    // With --write the file gets the CRCs, and then it agrees.
    let (code, out, err) = run(&(srdo_dcf(true) + &cfg_valid("0xA5")), &["--write"]);
    assert_eq!(code, Some(0), "{out}{err}");
    let written = std::fs::read_to_string(&input).unwrap();
    let (code, out, err) = run(&written, &[]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(!out.contains("differs"), "{out}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn srdo_crcs_are_printed_and_written_back() {
    let dir = temp_dir("crc");
    let input = dir.join("srdo.dcf");
    let original = srdo_dcf(true);
    std::fs::write(&input, &original).unwrap();
    let o = dcf2bin(&["--srdo-crc", input.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("SRDO 1 (0x1301): 0x13FF sub 1 = 0xD879"));
    // Without 0x13FE the library's check cannot run; the CRCs are printed.
    assert!(
        text(&o.stdout).contains(
            "(CcmCheckSrdoConfig, with these CRCs): not run: the file does not have every object"
        ),
        "{}",
        text(&o.stdout)
    );
    assert_eq!(
        std::fs::read_to_string(&input).unwrap(),
        original,
        "not written without --write"
    );
    let o = dcf2bin(&["--srdo-crc", "--write", input.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let updated = std::fs::read_to_string(&input).unwrap();
    let d = dcf2bin::parse(&updated, &input, None).unwrap();
    for (n, crc) in VECTORS.iter().enumerate() {
        let v = &d.get(0x13FF, n as u8 + 1).unwrap().data;
        assert_eq!(v, &crc.to_le_bytes());
    }
    // Only the CRC lines changed.
    let changed = original
        .lines()
        .zip(updated.lines())
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(changed, 5);
    // Without 0x13FF sections nothing is written and the error says why.
    std::fs::write(&input, srdo_dcf(false)).unwrap();
    let o = dcf2bin(&["--srdo-crc", "--write", input.to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(
        text(&o.stderr).contains("[13FFsub1]: section missing"),
        "{}",
        text(&o.stderr)
    );
    assert_eq!(std::fs::read_to_string(&input).unwrap(), srdo_dcf(false));
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn numbers_the_cia_306_way() {
    assert_eq!(dcf2bin::parse_int("0x1A", None), Ok(26));
    assert_eq!(dcf2bin::parse_int("017", None), Ok(15), "leading 0: octal");
    assert_eq!(dcf2bin::parse_int("-5", None), Ok(-5));
    assert_eq!(dcf2bin::parse_int("$NODEID+0x180", Some(3)), Ok(0x183));
    assert_eq!(dcf2bin::parse_int("0x200 + $NODEID", Some(3)), Ok(0x203));
    assert!(dcf2bin::parse_int("12a", None).is_err());
}
