//! Device descriptions of the kinds configuration tools write (our own
//! files in tests/data, each with the shapes of one tool: a CANopenNode
//! editor DS301 profile, its older editor's IO example, a CANopenDemo
//! device, a python-canopen test sample, a file of every data type, a
//! CanFestival master), and what dcf2bin makes of them: the container, the
//! warnings with file and line, and what DynBuildOd does with the container
//! on a node whose static dictionary fits.

mod common;

use std::path::Path;

use common::{data, dcf2bin, hex, temp_dir, text};
use dcf2bin::node::{self, Node};
use dcf2bin::{Dcf, Options, WarningKind, check};

fn load(name: &str, strict: bool) -> Result<Dcf, dcf2bin::Error> {
    dcf2bin::load_with(
        &data(name),
        Options {
            node_id: Some(3),
            strict,
        },
    )
    .map(|(_, d)| d)
}

/// The warnings of a file as (kind, line, message start).
fn warnings(d: &Dcf) -> Vec<(WarningKind, usize, String)> {
    d.warnings
        .iter()
        .map(|w| (w.kind, w.at.line.unwrap_or(0), w.at.to_string()))
        .collect()
}

fn has(d: &Dcf, kind: WarningKind, line: usize, part: &str) -> bool {
    warnings(d)
        .iter()
        .any(|(k, l, m)| *k == kind && *l == line && m.contains(part))
}

/// The node whose static dictionary is the communication part (0x1000 ..
/// 0x1FFF) the file itself describes: the manufacturer objects are what the
/// container adds.
fn communication_node(d: &Dcf) -> Node {
    let mut part = d.clone();
    part.objects.retain(|o| o.index < 0x2000);
    node::from_eds(&part)
}

#[test]
fn every_kind_of_file_converts_with_its_warnings() {
    // CANopenNode editor profile: 0x1003, 0x1010 and 0x1011 describe the
    // device (DynBuildOd checks them, writes nothing): those with values
    // go into the container, the 9 subindices of 0x1003 without value
    // stay out (notes).
    let d = load("profile301.eds", false).unwrap();
    for line in [151, 160, 223] {
        assert!(
            has(&d, WarningKind::LeftOut, line, "0x1003"),
            "{:?}",
            warnings(&d)
        );
    }
    assert!(d.objects.iter().all(|o| o.index != 0x1003));
    assert!(d.get(0x1010, 1).is_some() && d.get(0x1011, 1).is_some());
    assert_eq!(d.warnings.len(), 9, "{:?}", warnings(&d));
    assert_eq!(
        hex(&d.get(0x1014, 0).unwrap().data),
        "83000000",
        "$NODEID+0x80 with node-ID 3"
    );
    // Notes are no warnings: --strict converts it too.
    assert!(load("profile301.eds", true).is_ok());

    // The older editor: C integer suffixes and `0` for an empty domain.
    let d = load("io_editor.eds", false).unwrap();
    assert!(has(&d, WarningKind::Tolerated, 119, "suffix `LL`"));
    assert!(has(&d, WarningKind::Tolerated, 127, "suffix `ULL`"));
    assert!(has(&d, WarningKind::Tolerated, 143, "suffix `UL`"));
    assert!(has(&d, WarningKind::Tolerated, 151, "DOMAIN value `0`"));
    assert_eq!(
        hex(&d.get(0x2110, 1).unwrap().data),
        "8877665544332211",
        "0x1122334455667788LL"
    );
    assert_eq!(d.get(0x2110, 3).unwrap().access, "rwr");
    assert!(d.get(0x2110, 5).unwrap().data.is_empty());
    let e = load("io_editor.eds", true).unwrap_err().to_string();
    assert!(
        e.contains("io_editor.eds:119: [2110sub1] DefaultValue:")
            && e.contains("(refused: --strict)"),
        "{e}"
    );

    // CANopenDemo: a VISIBLE_STRING with characters outside 0x20..0x7E,
    // written as UTF-8; an empty number is 0, an empty string empty.
    let d = load("demo_device.eds", false).unwrap();
    assert!(has(&d, WarningKind::Tolerated, 150, "VISIBLE_STRING"));
    assert_eq!(
        d.get(0x2120, 3).unwrap().data,
        "caf\u{e9} \u{20ac}5".as_bytes()
    );
    assert_eq!(
        hex(&d.get(0x2120, 2).unwrap().data),
        "00000000004029C0",
        "-12.625"
    );
    assert_eq!(hex(&d.get(0x2120, 5).unwrap().data), "0000");
    assert!(d.get(0x2120, 6).unwrap().data.is_empty());

    // python-canopen's sample: CRLF, decimal data types, a type the
    // container cannot carry, a compact array with [XXXXValue], a comment
    // after a value.
    let d = load("sample_tool.eds", false).unwrap();
    assert!(has(&d, WarningKind::Skipped, 111, "data type 0x0041"));
    assert!(d.get(0x2020, 0).is_none());
    assert!(has(
        &d,
        WarningKind::Tolerated,
        68,
        "4 subindices announced, 3"
    ));
    assert_eq!(
        d.node_id,
        Some(3),
        "--node-id wins over [DeviceComissioning]"
    );
    assert_eq!(
        hex(&d.get(0x2010, 0).unwrap().data),
        "ECFF",
        "ParameterValue -20"
    );
    assert_eq!(hex(&d.get(0x2030, 0).unwrap().data), "0000C840", "6.25");
    let compact: Vec<String> = (0..=3)
        .map(|s| hex(&d.get(0x2040, s).unwrap().data))
        .collect();
    assert_eq!(
        compact,
        ["03", "0101", "0700", "0303"],
        "[2040Value] 1 and 3"
    );
    assert_eq!(
        hex(&d.get(0x2050, 0).unwrap().data),
        "10000000",
        "`0x10 ; sixteen`"
    );
    let e = load("sample_tool.eds", true).unwrap_err().to_string();
    assert!(
        e.contains("sample_tool.eds:111: [2020] DataType: data type 0x0041")
            && e.contains("--strict"),
        "{e}"
    );

    // CanFestival master: BOOLEAN written as False, a concise DCF domain.
    let d = load("master_festival.eds", false).unwrap();
    assert!(has(
        &d,
        WarningKind::Tolerated,
        213,
        "BOOLEAN values as 0 or 1"
    ));
    assert_eq!(d.get(0x2000, 0).unwrap().data, [0]);
    assert_eq!(d.get(0x1F22, 2).unwrap().data.len(), 15);

    // Every basic type (the encodings are compared with python-canopen in
    // python.rs).
    let d = load("all_types.eds", false).unwrap();
    assert!(d.warnings.is_empty(), "{:?}", warnings(&d));
    assert_eq!(d.objects.len(), 3 + 25);
}

#[test]
fn each_container_builds_on_a_node_that_fits() {
    for name in [
        "profile301.eds",
        "io_editor.eds",
        "demo_device.eds",
        "sample_tool.eds",
        "all_types.eds",
        "master_festival.eds",
    ] {
        let d = load(name, false).unwrap();
        let c = d.container().unwrap();
        let node = communication_node(&d);
        let r = check::check(&d, &c, &node, None, usize::MAX).unwrap();
        assert!(r.builds, "{name}: {:#?}", r.lines);
        let made: std::collections::BTreeSet<u16> = d
            .objects
            .iter()
            .filter(|o| o.index >= 0x2000)
            .map(|o| o.index)
            .collect();
        assert!(
            r.lines[0].contains(&format!("{} objects", made.len())),
            "{name}: {:?}",
            r.lines
        );
    }
}

/// The node of tests/common as an EDS: identity with the vendor-ID only,
/// heartbeat, RPDO 1 and TPDO 1.
const SMALL_NODE: &str = "[DeviceInfo]\nVendorName=x\n\
[1000]\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x00010191\n\
[1001]\nDataType=0x0005\nAccessType=ro\nDefaultValue=0\n\
[1017]\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\n\
[1018]\nObjectType=0x9\n[1018sub0]\nDataType=0x0005\nAccessType=ro\nDefaultValue=1\n\
[1018sub1]\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x123\n";

#[test]
fn subindices_the_node_lacks_are_named_line_by_line() {
    let dir = temp_dir("small-node");
    let node = dir.join("node.eds");
    std::fs::write(&node, SMALL_NODE).unwrap();
    let o = dcf2bin(&[
        "--node-id",
        "3",
        "--check",
        node.to_str().unwrap(),
        data("profile301.eds").to_str().unwrap(),
    ]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(
        out.contains("DynBuildOd refuses the container: kCopObdSubindexNotExist (0x0032)"),
        "{out}"
    );
    for (line, sub) in [(99, 2), (108, 3), (117, 4)] {
        assert!(
            out.contains(&format!(
                "profile301.eds:{line}: [1018sub{sub}] the node's object 0x1018 has no subindex {sub}"
            )),
            "{out}"
        );
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn the_check_reports_what_the_build_creates_and_changes() {
    // The node of tests/data/node_c (objdict.h through the library's
    // objdef.h): 0x2100 sub 1 has the range -50..50.
    let dir = temp_dir("node-c");
    let dcf = dir.join("app.dcf");
    let body = "[DeviceInfo]\nVendorName=x\n[DeviceComissioning]\nNodeID=4\n\
[1000]\nDataType=0x0007\nAccessType=ro\nParameterValue=0x00020192\n\
[1017]\nDataType=0x0006\nAccessType=rw\nParameterValue=250\n\
[2100]\nObjectType=0x8\n[2100sub1]\nDataType=0x0003\nAccessType=rw\nParameterValue=VALUE\n\
[2200]\nDataType=0x0008\nAccessType=rw\nDefaultValue=1.5\n";
    let node = data("node_c");
    let run = |v: &str| {
        std::fs::write(&dcf, body.replace("VALUE", v)).unwrap();
        dcf2bin(&["--check", node.to_str().unwrap(), dcf.to_str().unwrap()])
    };
    let o = run("-6");
    let out = text(&o.stdout);
    assert!(o.status.success(), "{out}{}", text(&o.stderr));
    assert!(
        !text(&o.stderr).contains("building dcf2bin"),
        "the test node has this build's configuration"
    );
    for part in [
        "DynBuildOd builds the container: 1 objects (1 subindices) created",
        "created 0x2200 (1 subindex from the file)",
        "changed 0x1017 sub 0: 0x0000 -> 0x00FA (",
        "app.dcf:12)",
        "changed 0x2100 sub 1: 0 -> -6 (",
        "app.dcf:18)",
        "kept 0x1000 sub 0: the node's 0x00000191 (read-only there), the file says 0x00020192",
        "OBD_DYNAMIC_POOL_SIZE 2048: fits",
    ] {
        assert!(out.contains(part), "{part}\n{out}");
    }
    // The node's range refuses 60; the line of the value is named.
    let o = run("60");
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        out.contains("app.dcf:18: [2100sub1] the node's 0x2100 sub 1 (INTEGER16) refuses the value 60: kCopObdValueToHigh (0x0039)"),
        "{out}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_pdo_the_node_cannot_map_is_named() {
    // python-canopen's sample maps objects of a drive profile the file
    // does not describe; the check names the mapping entry.
    let dir = temp_dir("pdo-blame");
    let f = dir.join("pdo.dcf");
    let mut s = String::from("[DeviceInfo]\nVendorName=x\n");
    s += "[1800]\nObjectType=0x9\n[1800sub1]\nDataType=0x0007\nAccessType=rw\nDefaultValue=$NODEID+0x180\n";
    s += "[1800sub2]\nDataType=0x0005\nAccessType=rw\nDefaultValue=255\n";
    s += "[1A00]\nObjectType=0x9\n[1A00sub0]\nDataType=0x0005\nAccessType=rw\nDefaultValue=2\n";
    s += "[1A00sub1]\nDataType=0x0007\nAccessType=rw\nDefaultValue=0x20000010\n";
    s += "[1A00sub2]\nDataType=0x0007\nAccessType=rw\nDefaultValue=0x60410010\n";
    s += "[2000]\nDataType=0x0006\nAccessType=ro\nPDOMapping=1\nDefaultValue=7\n";
    std::fs::write(&f, s).unwrap();
    let o = dcf2bin(&[
        "--node-id",
        "2",
        "--check",
        data("node_c").to_str().unwrap(),
        f.to_str().unwrap(),
    ]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(out.contains("kCopPdoErrorMapp (0x0078)"), "{out}");
    assert!(
        out.contains("TPDO 1: ")
            && out.contains(
                "pdo.dcf:26: [1A00sub2] maps 0x6041 sub 0, which neither the node nor the file has"
            ),
        "{out}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_refusal_outside_the_pdos_is_not_laid_on_them() {
    // The node has 0x1029 and TPDO 1; the file keeps TPDO 1 valid and sets
    // 0x1029 sub 1 to 0x80, which the error behaviour rule refuses (CiA
    // 301 7.5.2.32 defines 0x00..=0x02; abort 0x06090030). The refusal is
    // the object's, not the PDO's.
    let dir = temp_dir("plain-blame");
    let tpdo = "[1800]\nObjectType=0x9\n[1800sub0]\nDataType=0x0005\nAccessType=ro\nDefaultValue=2\n\
[1800sub1]\nDataType=0x0007\nAccessType=rw\nDefaultValue=$NODEID+0x180\n\
[1800sub2]\nDataType=0x0005\nAccessType=rw\nDefaultValue=255\n\
[1A00]\nObjectType=0x9\n[1A00sub0]\nDataType=0x0005\nAccessType=rw\nDefaultValue=1\n\
[1A00sub1]\nDataType=0x0007\nAccessType=rw\nDefaultValue=0x20000010\n\
[2000]\nDataType=0x0006\nAccessType=rw\nPDOMapping=1\nDefaultValue=7\n";
    let behaviour = |v: &str| {
        format!(
            "[1029]\nObjectType=0x8\n[1029sub0]\nDataType=0x0005\nAccessType=ro\nDefaultValue=1\n\
[1029sub1]\nDataType=0x0005\nAccessType=rw\nDefaultValue={v}\n"
        )
    };
    let node = dir.join("node.eds");
    std::fs::write(&node, format!("{SMALL_NODE}{}{tpdo}", behaviour("0"))).unwrap();
    let f = dir.join("app.dcf");
    let check = |v: &str| {
        let body = format!("[DeviceInfo]\nVendorName=x\n{}{tpdo}", behaviour(v));
        std::fs::write(&f, body).unwrap();
        let o = dcf2bin(&[
            "--node-id",
            "2",
            "--check",
            node.to_str().unwrap(),
            f.to_str().unwrap(),
        ]);
        (o.status.code(), text(&o.stdout))
    };
    let (code, out) = check("2");
    assert_eq!(code, Some(0), "{out}");
    let (code, out) = check("0x80");
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("DynBuildOd refuses the container: kCopInvalidParam (0x0009)"),
        "{out}"
    );
    assert!(
        out.contains("0x1029 is refused on its own: kCopInvalidParam"),
        "{out}"
    );
    assert!(!out.contains("TPDO 1"), "{out}");
    // On a node without 0x1029 the file creates it: the build takes 0x80
    // as the default, and the check says that a write of it is refused.
    std::fs::write(&node, format!("{SMALL_NODE}{tpdo}")).unwrap();
    let (code, out) = check("0x80");
    assert_eq!(code, Some(0), "{out}");
    assert!(
        out.contains("created 0x1029 (2 subindices from the file)"),
        "{out}"
    );
    assert!(
        out.contains("[1029sub1] 0x1029 sub 1 is created with 0x80, which the stack refuses on a write (kCopInvalidParam (0x0009))"),
        "{out}"
    );
    let (_, out) = check("1");
    assert!(!out.contains("note: "), "{out}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_pdo_the_file_creates_gets_no_false_note() {
    // The node has no TPDO; the file creates TPDO 1 (valid COB-ID) and the
    // variable it maps. The build applies the CiA 301 procedure (PDO
    // invalid, count 0, entries, count, COB-ID: 7.5.2.36), so the PDO runs
    // with the file's mapping; a write of a mapping entry or of the count
    // into the valid PDO is refused by that procedure (0x08000022), not by
    // the values, and is no reason for a note.
    let dir = temp_dir("created-pdo");
    let node = dir.join("node.eds");
    std::fs::write(&node, SMALL_NODE).unwrap();
    let f = dir.join("app.dcf");
    let body = format!(
        "{SMALL_NODE}\
[1800]\nObjectType=0x9\n[1800sub0]\nDataType=0x0005\nAccessType=ro\nDefaultValue=2\n\
[1800sub1]\nDataType=0x0007\nAccessType=rw\nDefaultValue=$NODEID+0x180\n\
[1800sub2]\nDataType=0x0005\nAccessType=rw\nDefaultValue=255\n\
[1A00]\nObjectType=0x9\n[1A00sub0]\nDataType=0x0005\nAccessType=rw\nDefaultValue=2\n\
[1A00sub1]\nDataType=0x0007\nAccessType=rw\nDefaultValue=0x20000010\n\
[1A00sub2]\nDataType=0x0007\nAccessType=rw\nDefaultValue=0x20010008\n\
[2000]\nDataType=0x0006\nAccessType=rw\nPDOMapping=1\nDefaultValue=7\n\
[2001]\nDataType=0x0005\nAccessType=rw\nPDOMapping=1\nDefaultValue=1\n"
    );
    std::fs::write(&f, body).unwrap();
    let o = dcf2bin(&[
        "--node-id",
        "2",
        "--check",
        node.to_str().unwrap(),
        f.to_str().unwrap(),
    ]);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.contains("DynBuildOd builds the container"), "{out}");
    assert!(out.contains("created 0x1A00 (3 subindices"), "{out}");
    assert!(!out.contains("note: "), "{out}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_node_of_another_configuration_gets_its_own_build() {
    // examples_c/dynod has 2 RPDOs, 2 TPDOs, no SDO client, no bit
    // mapping: the check builds a dcf2bin for that configuration once
    // (COP_CONFIG_DIR) and answers with it.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let folder = root.join("examples_c/dynod");
    let o = dcf2bin(&[
        "--check",
        folder.to_str().unwrap(),
        folder.join("node1.dcf").to_str().unwrap(),
    ]);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert!(o.status.success(), "{out}{err}");
    assert!(
        err.contains("PDO_MAX_RXPDO_IN_OBD 2 (this dcf2bin: 8)")
            && err.contains("building dcf2bin"),
        "{err}"
    );
    assert!(
        out.contains("DynBuildOd builds the container: 5 objects"),
        "{out}"
    );
    assert!(out.contains("reconfigured TPDO 1 (0x1800/0x1A00)"), "{out}");
    assert!(out.contains("OBD_DYNAMIC_POOL_SIZE 4096: fits"), "{out}");
}

#[test]
fn values_tools_write_and_what_is_refused() {
    let parse = |body: &str| {
        dcf2bin::parse(
            &format!("[DeviceInfo]\nVendorName=x\n{body}"),
            Path::new("v.eds"),
            Some(1),
        )
    };
    // `@ABCD` is no CiA 306 form; the message says so (not "odd digits").
    let e = parse("[200F]\nDataType=0x000F\nAccessType=rw\nDefaultValue=@ABCD\n")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("v.eds:6: [200F] DefaultValue: `@ABCD`: CiA 306 (4.3)"),
        "{e}"
    );
    assert!(!e.contains("odd"), "{e}");
    // UNICODE_STRING: 16-bit characters (CiA 301 7.1.6.4).
    let d = parse("[200B]\nDataType=0x000B\nAccessType=rw\nDefaultValue=abc\n").unwrap();
    assert_eq!(hex(&d.get(0x200B, 0).unwrap().data), "610062006300");
    // A comment after a value is no part of it; a glued `;` is.
    let d = parse("[2001]\nDataType=0x0009\nAccessType=rw\nDefaultValue=a;b ; note\n").unwrap();
    assert_eq!(d.get(0x2001, 0).unwrap().data, b"a;b");
}

#[test]
fn limits_are_checked() {
    let parse = |body: &str| {
        dcf2bin::parse(
            &format!("[DeviceInfo]\nVendorName=x\n[2000]\nDataType=0x0006\nAccessType=rw\n{body}"),
            Path::new("l.dcf"),
            Some(1),
        )
    };
    let e = parse("DefaultValue=5\nParameterValue=25\nLowLimit=0\nHighLimit=20\n")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("l.dcf:7: [2000] ParameterValue: `25` (25) is above HighLimit 20"),
        "{e}"
    );
    let e = parse("ParameterValue=0x02\nLowLimit=3\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("`0x02` (2) is below LowLimit 3"), "{e}");
    let e = parse("DefaultValue=5\nLowLimit=9\nHighLimit=4\n")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("[2000] HighLimit: HighLimit 4 is below LowLimit 9"),
        "{e}"
    );
    let e = parse("DefaultValue=5\nHighLimit=0x10000\n")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("[2000] HighLimit: 65536 is out of range 0..=65535"),
        "{e}"
    );
    assert!(parse("DefaultValue=20\nLowLimit=20\nHighLimit=20\n").is_ok());
    // A value the file does not give: left out when 0 is outside the
    // range (a skipped warning, refused with --strict).
    let d = parse("LowLimit=1000\nHighLimit=2000\n").unwrap();
    assert!(d.get(0x2000, 0).is_none());
    assert_eq!(d.warnings[0].kind, WarningKind::Skipped);
    assert!(
        d.warnings[0]
            .to_string()
            .contains("no value (0) is below LowLimit 1000")
    );
    // Signed and REAL limits in their own domain.
    let d = dcf2bin::parse(
        "[2000]\nDataType=0x0002\nAccessType=rw\nDefaultValue=-100\nLowLimit=0x80\nHighLimit=-1\n\
         [2001]\nDataType=0x0008\nAccessType=rw\nDefaultValue=4.75\nLowLimit=4.5\nHighLimit=5\n",
        Path::new("l.dcf"),
        None,
    )
    .unwrap();
    assert_eq!(d.objects.len(), 2);
    let e = dcf2bin::parse(
        "[2001]\nDataType=0x0008\nAccessType=rw\nDefaultValue=4.25\nLowLimit=4.5\n",
        Path::new("l.dcf"),
        None,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("`4.25` (4.25) is below LowLimit 4.5"), "{e}");
}

#[test]
fn a_subindex_described_twice_is_refused() {
    let refused = |body: &str| {
        dcf2bin::parse(body, Path::new("d.dcf"), Some(1))
            .unwrap_err()
            .to_string()
    };
    let e =
        refused("[2000]\nDataType=7\nAccessType=rw\n[2001]\nDataType=7\nAccessType=rw\n[2000]\n");
    assert!(
        e.contains("d.dcf:7: [2000]: section [2000] already opened at line 1"),
        "{e}"
    );
    let e = refused("[2000]\nDataType=7\nAccessType=rw\nDefaultValue=1\nDefaultValue=2\n");
    assert!(
        e.contains("d.dcf:5: [2000] DefaultValue: DefaultValue already given at line 4 (`1`)"),
        "{e}"
    );
    let e = refused(
        "[2000]\nObjectType=8\n[2000sub1]\nDataType=7\nAccessType=rw\n[2000sub01]\nDataType=7\nAccessType=rw\n",
    );
    assert!(
        e.contains(
            "d.dcf:6: [2000sub01]: 0x2000 sub 1 is already described by [2000sub1] at line 3"
        ),
        "{e}"
    );
    let e = refused(
        "[2000]\nObjectType=8\nCompactSubObj=2\nDataType=7\nAccessType=rw\n[2000sub2]\nDataType=7\nAccessType=rw\n",
    );
    assert!(
        e.contains("[2000sub2]: 0x2000 sub 2 is already described by [2000]"),
        "{e}"
    );
    let e = refused("[2000]\nDataType=7\nAccessType=rw\n[2000sub1]\nDataType=7\nAccessType=rw\n");
    assert!(e.contains("[2000sub1]: [2000] is a VAR"), "{e}");
}

/// An EDS with `n` UNSIGNED32 variables in records of 100 (the size of
/// python-canopen's e35.eds, 995 variables).
fn big_eds(n: usize) -> String {
    let mut s = String::from("[DeviceInfo]\nVendorName=x\n");
    let mut left = n;
    let mut index = 0x2000u16;
    while left > 0 {
        let k = left.min(100);
        s += &format!("[{index:04X}]\nObjectType=0x9\nSubNumber={}\n", k + 1);
        s += &format!("[{index:04X}sub0]\nDataType=0x0005\nAccessType=ro\nDefaultValue={k}\n");
        for sub in 1..=k {
            s += &format!(
                "[{index:04X}sub{sub:X}]\nDataType=0x0007\nAccessType=rw\nDefaultValue={sub}\nPDOMapping=1\n"
            );
        }
        left -= k;
        index += 1;
    }
    s
}

#[test]
fn the_pool_a_container_needs_is_printed() {
    let dir = temp_dir("pool");
    let f = dir.join("big.eds");
    std::fs::write(&f, big_eds(995)).unwrap();
    let o = dcf2bin(&[f.to_str().unwrap()]);
    let out = text(&o.stdout);
    assert!(o.status.success(), "{}", text(&o.stderr));
    // 10 new objects, 1005 subindices (16 bytes each on 32-bit targets),
    // 4 bytes per variable, the copy of the index segment (7 + 4 bytes per
    // UNSIGNED32 entry, 8 per count, 4 for the count of entries).
    let tables = 10 * 16 + 1005 * 16;
    let data = 995 * 4 + 10;
    let copy = 4 + 995 * 11 + 10 * 8;
    assert!(
        out.contains(&format!(
            "pool (OBD_DYNAMIC_POOL_SIZE) on a node without any of these objects: {} bytes on 32-bit targets",
            tables + data + copy
        )),
        "{out}"
    );
    let _ = std::fs::remove_dir_all(dir);
}
