//! `CcmSendSrdo` on the simulated bus: refusals and their codes, the
//! complement check before sending, the first-send delay, driver refusal.
//! Set-up: `tests/srdo_support.rs`.

#[path = "srdo_support.rs"]
mod support;

use cop::CopKernel;
use cop::ccm::NmtCommand;
use cop::event::{Event, ProgMonEvent};
use support::*;

const IDX: u16 = 0x1301;

// req: M-2.8.1-SEND
#[test]
fn refused_before_operational_with_nmt_error() {
    let mut net = Net::preoperational();
    net.set_values(1, 2);
    assert_eq!(net.p.send(IDX), (Err(CopKernel::SrdoNmtError), vec![]));
    assert!(net.bus.trace().is_empty());
    assert_eq!(
        net.p.status(IDX),
        0,
        "a refused call leaves the status alone"
    );
}

// req: M-2.5.1-FIRST-DELAY
#[test]
fn first_send_waits_half_a_millisecond_per_node_id() {
    // Manual 2.5.1: the first transmission after entering OPERATIONAL is
    // delayed by 0.5 ms x node-ID; the producer is node 1 (5 ticks).
    let mut net = Net::preoperational();
    net.p.command(NmtCommand::StartRemoteNode);
    net.bus.clear_trace();
    net.set_values(1, 2);
    net.wait_ticks(4);
    // A `CcmProcess` within the delay does not end it.
    net.p.cycle();
    assert_eq!(net.p.send(IDX).0, Err(CopKernel::SrdoNmtError));
    assert!(net.bus.trace().is_empty());
    net.wait_ticks(1);
    assert_eq!(net.p.send(IDX).0, Ok(()));
    assert_eq!(net.bus.trace().len(), 2);
}

// req: M-2.5.1-FIRST-DELAY
#[test]
fn the_first_send_delay_does_not_return_after_half_the_tick_range() {
    // The delay is once per entry into OPERATIONAL. A node that stays
    // OPERATIONAL longer than 2^31 ticks (59.65 h at 100 us) still sends:
    // with an early send, and without any send before (CcmProcess runs
    // meanwhile, here once every 2^28 ticks).
    for early_send in [true, false] {
        let mut net = Net::preoperational();
        net.p.command(NmtCommand::StartRemoteNode);
        net.set_values(1, 2);
        net.wait_ticks(5);
        if early_send {
            assert_eq!(net.p.send(IDX).0, Ok(()));
        }
        for _ in 0..9 {
            net.wait_ticks(1 << 28);
            net.p.cycle();
        }
        net.wait_ticks(10);
        net.bus.clear_trace();
        assert_eq!(net.p.send(IDX).0, Ok(()), "early send: {early_send}");
        assert_eq!(net.bus.trace().len(), 2);
        // After the next entry into OPERATIONAL the delay holds again.
        net.p.command(NmtCommand::EnterPreOperational);
        net.p.command(NmtCommand::StartRemoteNode);
        assert_eq!(net.p.send(IDX).0, Err(CopKernel::SrdoNmtError));
        net.wait_ticks(5);
        assert_eq!(net.p.send(IDX).0, Ok(()));
    }
}

// req: M-2.8.1-SEND, SB-2-RUN-ONLY-VALID
#[test]
fn refused_with_invalid_configuration() {
    let mut net = Net::preoperational();
    // Any accepted write to a safety parameter makes 0x13FE invalid.
    net.p.write(0x1301, 2, 30, 2).unwrap();
    assert_eq!(net.p.read(0x13FE, 0), 0);
    net.start_producer_only();
    net.wait_ms(1);
    net.set_values(1, 2);
    assert_eq!(net.p.send(IDX), (Err(CopKernel::SrdoInvalidCfg), vec![]));
    assert!(net.bus.trace().is_empty());
}

// req: M-2.8.1-SEND
#[test]
fn refused_for_a_receive_srdo_a_disabled_srdo_and_an_unknown_index() {
    let mut net = Net::operational();
    net.wait_ms(1);
    assert_eq!(net.c.send(IDX).0, Err(CopKernel::SrdoRxTxConflict));
    assert_eq!(net.p.send(0x1302).0, Err(CopKernel::SrdoInvalid));
    for bad in [0x1303, 0x1340, 0x1300, 0x1381, 0x2000] {
        assert_eq!(net.p.send(bad).0, Err(CopKernel::SrdoNotExist), "{bad:#x}");
    }
    assert!(net.bus.trace().is_empty());
}

// req: SB-4-COMPLEMENT
#[test]
fn data_not_inverted_is_not_sent() {
    // Manual 2.8.1: every bit is checked before sending; on a mismatch no
    // frame is sent and AppSrdoError reports kCopSrdoDataError.
    let mut net = Net::operational();
    net.wait_ms(1);
    net.set_values(0x1234, 0x5678);
    put(net.p.inverted, 2, !0x5678 ^ 0x0100);
    let (r, ev) = net.p.send(IDX);
    assert_eq!(r, Err(CopKernel::SrdoDataError));
    let mut expected = vec![Event::SrdoError(IDX, CopKernel::SrdoDataError)];
    expected.extend(pm(ProgMonEvent::SrdoError));
    assert_eq!(ev, expected);
    assert!(net.bus.trace().is_empty(), "nothing on the bus");
    assert_eq!(net.p.seen_in_error, vec![(CopKernel::SrdoDataError, 0x50)]);
    assert_eq!(net.p.status(IDX), 0xB0);
}

// req: SB-4-DRIVER
#[test]
fn driver_refusal_is_reported_with_the_driver_code() {
    let mut net = Net::operational();
    net.wait_ms(1);
    net.set_values(1, 2);
    net.bus.refuse_tx(net.p.port.node(), 1);
    let (r, ev) = net.p.send(IDX);
    assert_eq!(r, Err(CopKernel::CdrvTxBuffHighOverrun));
    assert_eq!(
        no_pm(&ev),
        vec![Event::SrdoError(IDX, CopKernel::CdrvTxBuffHighOverrun)]
    );
    assert!(net.bus.trace().is_empty());
    assert_eq!(
        net.p.seen_in_error,
        vec![(CopKernel::CdrvTxBuffHighOverrun, 0x50)]
    );
    // The next call goes through and reports success.
    let (r, ev) = net.p.send(IDX);
    assert_eq!(r, Ok(()));
    assert_eq!(no_pm(&ev), vec![Event::SrdoEvent(IDX)]);
    assert_eq!(net.p.status(IDX) & 0x30, 0x30);
}

// req: SB-4-ALL
#[test]
fn send_all_iterates_the_transmit_srdos() {
    let mut net = Net::operational();
    let od = *net.p.stack.od();
    let tx: Vec<u16> = net.p.stack.srdo().transmit_indices(&od).collect();
    assert_eq!(tx, vec![0x1301]);
    let od = *net.c.stack.od();
    assert_eq!(net.c.stack.srdo().transmit_indices(&od).count(), 0);
    net.wait_ms(1);
    net.set_values(3, 4);
    for idx in tx {
        assert_eq!(net.p.send(idx).0, Ok(()));
    }
    assert_eq!(net.bus.trace().len(), 2);
}

// req: SB-4-REFRESH
#[test]
fn missed_refresh_time_goes_to_the_program_monitor_once() {
    if !cop::config::SRDO_USE_PROGMONITOR {
        return;
    }
    let mut net = Net::operational();
    net.wait_ms(1);
    net.set_values(1, 2);
    assert_eq!(net.p.send(IDX).0, Ok(()));
    // Refresh time 25 ms: at the limit nothing, later one SrdoError.
    net.wait_ms(25);
    let ev = net.p.cycle();
    assert!(
        !ev.contains(&Event::ProgMon(ProgMonEvent::SrdoError)),
        "{ev:?}"
    );
    net.wait_ticks(1);
    let ev = srdo_only(&net.p.cycle());
    assert_eq!(
        ev,
        vec![
            Event::ProgMon(ProgMonEvent::SctNotCheckedItIsTx),
            Event::ProgMon(ProgMonEvent::SrdoError),
            Event::ProgMon(ProgMonEvent::SctNotCheckedItIsInvalid),
        ]
    );
    net.wait_ms(30);
    let ev = net.p.cycle();
    assert!(
        !ev.contains(&Event::ProgMon(ProgMonEvent::SrdoError)),
        "once per miss"
    );
    assert_eq!(net.p.send(IDX).0, Ok(()));
    net.wait_ms(26);
    assert!(
        net.p
            .cycle()
            .contains(&Event::ProgMon(ProgMonEvent::SrdoError))
    );
}
