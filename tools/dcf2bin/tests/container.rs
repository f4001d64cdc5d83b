//! What `verify` (every container dcf2bin writes, and `--verify` for
//! containers of other tools) finds beyond `Container::parse`: process-image
//! windows that do not cover the variables the address segment places,
//! variables sharing bytes; and subindices written twice, which a concise
//! DCF may do (DynBuildOd keeps the last value).

mod common;

use std::process::Command;

use cop::od::ByteOrder;
use cop::od::dcf::{self, EntrySpec, PiParams, attr};
use cop::pdo::Direction;
use cop::sim::SimBus;
use dcf2bin::container::verify;

fn container(entries: &[EntrySpec<'_>], addr: Option<&[u16]>, pi: Option<&PiParams>) -> Vec<u8> {
    let n = dcf::encoded_len(entries, addr, true, pi).unwrap();
    let mut out = vec![0u8; n];
    dcf::encode(entries, addr, true, pi, &mut out).unwrap();
    out
}

const NV: u8 = attr::NETWORK_VARIABLE;

fn netvars() -> [EntrySpec<'static>; 4] {
    [
        EntrySpec {
            index: 0xA040,
            sub: 0,
            data: &[1],
            attr: attr::NUMERIC | attr::READ,
        },
        EntrySpec {
            index: 0xA040,
            sub: 1,
            data: &[0],
            attr: NV,
        },
        EntrySpec {
            index: 0xA580,
            sub: 0,
            data: &[3],
            attr: attr::NUMERIC | attr::READ,
        },
        EntrySpec {
            index: 0xA580,
            sub: 3,
            data: &[0, 0],
            attr: NV,
        },
    ]
}

#[test]
fn process_image_windows_must_cover_the_variables() {
    let e = netvars();
    // The layout of the offset rule (seed chapter 6): A040/1 input at 0,
    // A580/3 output at 8 + 2 * 2 = 12 (outputs start at the next multiple
    // of 8), 14 bytes in all.
    let good = PiParams {
        total: 14,
        input_offset: 0,
        input_size: 1,
        output_offset: 8,
        output_size: 6,
    };
    let v = verify(&container(&e, Some(&[0, 12]), Some(&good))).unwrap();
    assert_eq!((v.entries, v.placed, v.pi), (4, 2, Some(good)));

    // A parameter segment smaller than the image the variables take.
    let short = PiParams {
        total: 12,
        input_offset: 0,
        input_size: 1,
        output_offset: 8,
        output_size: 4,
    };
    let err = verify(&container(&e, Some(&[0, 12]), Some(&short))).unwrap_err();
    assert!(
        err.contains(
            "0xA580 sub 3 at offset 12 (2 bytes) ends after the process image of 12 bytes"
        ),
        "{err}"
    );
    // A WORD on the 1-byte input area: in neither area.
    let err = verify(&container(&e, Some(&[0, 0]), Some(&good))).unwrap_err();
    assert!(
        err.contains(
            "0xA580 sub 3 at offset 0 (2 bytes) lies in neither the input area 0..1 nor the output area 8..14"
        ),
        "{err}"
    );
    // Without parameter segment the rule's layout is what DynBuildOd
    // reports: an address beyond it is outside too.
    let err = verify(&container(&e, Some(&[0, 20]), None)).unwrap_err();
    assert!(
        err.contains("ends after the process image of 14 bytes"),
        "{err}"
    );
    // Two variables on the same bytes.
    let two = [
        EntrySpec {
            index: 0x2000,
            sub: 0,
            data: &[0, 0],
            attr: attr::NUMERIC | attr::READ,
        },
        EntrySpec {
            index: 0x2001,
            sub: 0,
            data: &[0, 0],
            attr: attr::NUMERIC | attr::READ,
        },
    ];
    let wide = PiParams {
        total: 8,
        input_offset: 0,
        input_size: 8,
        output_offset: 8,
        output_size: 0,
    };
    let err = verify(&container(&two, Some(&[2, 3]), Some(&wide))).unwrap_err();
    assert!(
        err.contains("0x2000 sub 0 and 0x2001 sub 0 share bytes"),
        "{err}"
    );
    // What dcf2bin writes always verifies (it is checked before writing).
    let (_, d) = dcf2bin::load(&common::sample(), None).unwrap();
    assert!(verify(&d.container().unwrap()).is_ok());
}

node!(node);

#[test]
fn a_subindex_written_twice_keeps_the_last_value() {
    // CiA 302 concise DCFs are sequences of writes; the second value of
    // 0x1017 is the one the node keeps.
    let e = [
        EntrySpec {
            index: 0x1017,
            sub: 0,
            data: &[0x10, 0],
            attr: attr::NUMERIC | attr::READ | attr::WRITE,
        },
        EntrySpec {
            index: 0x1017,
            sub: 0,
            data: &[0xF4, 0x01],
            attr: attr::NUMERIC | attr::READ | attr::WRITE,
        },
    ];
    let c = container(&e, None, None);
    let v = verify(&c).unwrap();
    assert_eq!(v.repeated, [(0x1017, 0, 2)]);
    let bus = SimBus::new();
    let (mut stack, mut port) = common::node(&bus, node::od(), 1);
    node::POOL
        .build(&mut stack, &mut port, bus.now(), &c, None)
        .unwrap();
    let mut b = [0u8; 2];
    stack
        .read_object(0x1017, 0, ByteOrder::Wire, &mut b)
        .unwrap();
    assert_eq!(u16::from_le_bytes(b), 500);

    let dir = common::temp_dir("verify");
    let f = dir.join("twice.bin");
    std::fs::write(&f, &c).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_dcf2bin"))
        .args(["--verify", f.to_str().unwrap()])
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success());
    assert!(out.contains("2 entries, 0 variables placed"), "{out}");
    assert!(
        out.contains("0x1017 sub 0 written 2 times: DynBuildOd keeps the last value"),
        "{out}"
    );
    // A truncated container is what DynBuildOd refuses.
    std::fs::write(&f, &c[..c.len() - 1]).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_dcf2bin"))
        .args(["--verify", f.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("(kCopDynInvalidConfig)"));
    let _ = std::fs::remove_dir_all(dir);
}

/// The pool figure for a node whose obdcfg.h counts 0 PDOs: the PDOs of
/// the container (here RPDO 1 and TPDO 2: 1 + 2 channels) add their state
/// to the tables, after the subindex tables aligned to 8 bytes.
#[test]
fn pool_figure_counts_the_pdo_channels_of_the_container() {
    let spec = |index, sub, data: &'static [u8]| EntrySpec {
        index,
        sub,
        data,
        attr: attr::READ | attr::WRITE | attr::NUMERIC,
    };
    let e = [
        spec(0x1400, 1, &[0x01, 0x02, 0, 0x80]),
        spec(0x1600, 0, &[0]),
        spec(0x1801, 1, &[0x82, 0x02, 0, 0x80]),
        spec(0x1A01, 0, &[0]),
    ];
    let c = container(&e, None, None);
    let n = dcf2bin::container::pool_need_alone(&c, 0).unwrap();
    assert_eq!((n.container_channels.rx, n.container_channels.tx), (1, 2));
    assert_eq!(n.channel_bytes.rx, cop::pdo::channel_size(Direction::Rx));
    assert_eq!(n.channel_bytes.tx, cop::pdo::channel_size(Direction::Tx));
    // This library's own build counts 8 PDOs: none from the pool.
    assert_eq!(n.pooled_channels.total(), 0);
    let without = n.target32();
    let with = n.target32_pdos_from_pool();
    let channels = n.channel_bytes.rx + 2 * n.channel_bytes.tx;
    assert!(with >= without + channels, "{with} {without}");
    assert!(with < without + channels + 8, "{with} {without}");
}
