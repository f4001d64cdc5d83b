//! DCF -> dcf2bin -> container -> DynBuildOd -> reads: every value of the
//! sample DCF comes back, through the dictionary and over SDO (this
//! library's SDO client on a second node against the SDO server of the
//! node with the dynamic OD, on the simulated bus).

mod common;

use core::sync::atomic::AtomicU8;

use common::{hex, sample};
use cop::od::{ByteOrder, decl};
use cop::sdo::client::{ClientParam, Direction, SdocState};
use cop::sim::SimBus;
use cop::wire::sdo::Multiplexer;

node!(device);
node!(master);
static IMAGE: [AtomicU8; 64] = decl::zeroed();
static SDO_BUF: [AtomicU8; 64] = decl::zeroed();

/// Objects whose DCF value the device keeps its own value for: constants
/// of the static dictionary.
fn firmware_owned(index: u16, sub: u8) -> bool {
    matches!(
        (index, sub),
        (0x1000, 0) | (0x1018, _) | (0x1400, 0) | (0x1800, 0)
    )
}

#[test]
fn every_dcf_value_reads_back_locally_and_over_sdo() {
    let (_, dcf) = dcf2bin::load(&sample(), None).unwrap();
    let container = dcf.container().unwrap();
    let bus = SimBus::new();
    let (mut dev, mut dev_port) = common::node(&bus, device::od(), 1);
    let (mut cli, mut cli_port) = common::node(&bus, master::od(), 2);
    let need = dcf2bin::container::pool_need(&container, dev.od(), IMAGE.len()).unwrap();
    let info = device::POOL
        .build(&mut dev, &mut dev_port, bus.now(), &container, Some(&IMAGE))
        .unwrap();
    assert_eq!(Some(info.pi), dcf.pi_params());
    // The pool figure dcf2bin prints is the pool the build takes.
    assert_eq!(info.pool_used, need.host());
    assert_eq!(info.new_subs, need.new_subs);

    for o in &dcf.objects {
        if firmware_owned(o.index, o.sub) {
            continue;
        }
        let mut b = [0u8; 64];
        let n = dev
            .read_object(o.index, o.sub, ByteOrder::Wire, &mut b)
            .unwrap();
        assert_eq!(hex(&b[..n]), hex(&o.data), "{:04X}sub{:X}", o.index, o.sub);
    }
    // Network variables live in the process image at the offsets dcf2bin
    // computed (seed chapter 6): A4C0 sub 1..3 and A580 sub 3 are outputs.
    let out = info.pi.output_offset as usize;
    assert_eq!(
        decl::get::<3>(IMAGE[out..out + 3].try_into().unwrap()),
        [0x11, 0x22, 0x33]
    );

    let p = ClientParam {
        tx_cob: 0x601,
        rx_cob: 0x581,
        server_node: 1,
        timeout_ticks: 0,
    };
    cli.define_sdo_client(&mut cli_port, 0x1280, p).unwrap();
    for o in &dcf.objects {
        let now = bus.now();
        cli.sdo_client_start(
            &mut cli_port,
            now,
            0x1280,
            Direction::Upload,
            Multiplexer::new(o.index, o.sub),
            &SDO_BUF,
            SDO_BUF.len(),
            0,
        )
        .unwrap();
        for _ in 0..8 {
            let now = bus.now();
            dev.process(&mut dev_port, now, |_, _| {});
            cli.process(&mut cli_port, now, |_, _| {});
            bus.advance_ms(1);
        }
        let what = format!("{:04X}sub{:X}", o.index, o.sub);
        assert_eq!(
            cli.sdoc().state(0x1280).unwrap(),
            (SdocState::Finished, 0),
            "{what}"
        );
        if firmware_owned(o.index, o.sub) {
            continue;
        }
        let n = cli.sdoc().transferred(0x1280).unwrap() as usize;
        assert_eq!(hex(&decl::get(&SDO_BUF)[..n]), hex(&o.data), "{what}");
    }
}
