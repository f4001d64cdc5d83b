//! SRDOs and the NMT state machine, the GFC, and the order of the program
//! monitor events within one cycle. Set-up: `tests/srdo_support.rs`.

#[path = "srdo_support.rs"]
mod support;

use cop::CopKernel;
use cop::ccm::NmtCommand;
use cop::event::{Event, NmtState, ProgMonEvent};
use support::*;

const IDX: u16 = 0x1301;

// req: SB-9-LEAVE
#[test]
fn leaving_operational_stops_everything_at_once() {
    let mut net = Net::operational();
    // A first frame is held when the node leaves OPERATIONAL.
    net.inject(0x101, &[1, 0, 2, 0]);
    net.c.cycle();
    net.c.command(NmtCommand::EnterPreOperational);
    assert_eq!(net.c.state(), NmtState::PreOperational);
    assert!(!net.c.stack.srdo().is_running());
    // No timeouts and no reception while not OPERATIONAL.
    net.wait_ms(500);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    assert!(no_pm(&net.c.cycle()).is_empty());
    assert_eq!(net.consumer_values(), [0, 0, 0, 0]);
    // Re-entering: the held half is gone, its inverted frame is out of
    // order; the SCT starts again at entry.
    net.c.command(NmtCommand::StartRemoteNode);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    assert_eq!(
        no_pm(&net.c.cycle()),
        vec![Event::SrdoError(IDX, CopKernel::SrdoNotInOrder)]
    );
    // A fresh SCT: nothing at its end, the timeout a tick later.
    net.wait_ms(25);
    net.sct_times_out_one_tick_later();
}

// req: SB-8-RESET
#[test]
fn entering_operational_resets_every_status_byte() {
    let mut net = Net::operational();
    net.c.app = App::Ignore;
    net.inject(0x102, &[0, 0, 0, 0]);
    net.c.cycle();
    assert_eq!(net.c.status(IDX), 0x50);
    net.c.stack.srdo_mut().set_state(0x1302, 0xF0).unwrap();
    net.c.command(NmtCommand::EnterPreOperational);
    assert_eq!(net.c.status(IDX), 0x50, "kept while not OPERATIONAL");
    net.c.command(NmtCommand::StartRemoteNode);
    assert_eq!(net.c.status(IDX), 0);
    assert_eq!(net.c.status(0x1302), 0);
}

// req: SB-9-LEAVE
#[test]
fn stopped_node_ignores_srdos() {
    let mut net = Net::operational();
    net.c.command(NmtCommand::StopRemoteNode);
    net.inject(0x102, &[0, 0, 0, 0]);
    net.wait_ms(100);
    assert!(no_pm(&net.c.cycle()).is_empty());
    net.wait_ms(1);
    net.set_values(1, 2);
    net.p.command(NmtCommand::StopRemoteNode);
    assert_eq!(net.p.send(IDX).0, Err(CopKernel::SrdoNmtError));
}

// req: SB-9-RESETCOMM
#[test]
fn reset_communication_reloads_the_defaults() {
    let mut net = Net::preoperational();
    net.p.write(0x1301, 2, 40, 2).unwrap();
    net.p.command(NmtCommand::ResetCommunication);
    assert_eq!(net.p.state(), NmtState::PreOperational);
    assert_eq!(
        net.p.read(0x1301, 2),
        25,
        "default of OBD_CREATE_SRDO_COMMU"
    );
    assert_eq!(net.p.read(0x13FE, 0), 0, "0x13FE default: invalid");
}

// req: M-2.5.4-PROGMON
#[test]
fn program_monitor_order_in_one_cycle() {
    if !cop::config::SRDO_USE_PROGMONITOR {
        return;
    }
    let mut net = Net::preoperational();
    // Not OPERATIONAL: exactly one event per cycle for all SRDOs.
    assert_eq!(
        srdo_only(&net.c.cycle()),
        vec![Event::ProgMon(ProgMonEvent::SctNotCheckedNotOperational)]
    );
    assert_eq!(
        srdo_only(&net.c.cycle()),
        vec![Event::ProgMon(ProgMonEvent::SctNotCheckedNotOperational)]
    );
    net.start();
    // Receive phase in frame order, then the timer phase per SRDO in index
    // order (0x1301 receive: SctChecked; 0x1302 disabled: ItIsInvalid).
    net.inject(0x102, &[0, 0, 0, 0]);
    net.inject(0x101, &[1, 0, 2, 0]);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    assert_eq!(
        srdo_only(&net.c.cycle()),
        vec![
            Event::SrdoError(IDX, CopKernel::SrdoNotInOrder),
            Event::ProgMon(ProgMonEvent::SrdoError),
            Event::SrdoEvent(IDX),
            Event::ProgMon(ProgMonEvent::SrdoReceived),
            Event::ProgMon(ProgMonEvent::SctChecked),
            Event::ProgMon(ProgMonEvent::SctNotCheckedItIsInvalid),
        ]
    );
    // The SCT error belongs to the timer step of its SRDO.
    net.wait_ms(26);
    assert_eq!(
        srdo_only(&net.c.cycle()),
        vec![
            Event::SrdoError(IDX, CopKernel::SrdoSctTimeout),
            Event::ProgMon(ProgMonEvent::SrdoError),
            Event::ProgMon(ProgMonEvent::SctChecked),
            Event::ProgMon(ProgMonEvent::SctNotCheckedItIsInvalid),
        ]
    );
    // The producer's transmit SRDO.
    assert_eq!(
        srdo_only(&net.p.cycle()),
        vec![
            Event::ProgMon(ProgMonEvent::SctNotCheckedItIsTx),
            Event::ProgMon(ProgMonEvent::SrdoError),
            Event::ProgMon(ProgMonEvent::SctNotCheckedItIsInvalid),
        ],
        "refresh time missed since entering OPERATIONAL"
    );
}

#[cfg(feature = "srdo-gfc")]
mod gfc {
    use super::*;

    // req: M-1.3-GFC
    #[test]
    fn send_gfc_only_when_enabled_and_operational() {
        let mut net = Net::preoperational();
        let st = net.p.state();
        assert_eq!(
            net.p.stack.srdo_mut().send_gfc(&mut net.p.port, st),
            Err(CopKernel::SrdoNmtError)
        );
        net.p.write(0x1300, 0, 1, 1).unwrap();
        net.c.write(0x1300, 0, 1, 1).unwrap();
        net.start();
        net.p.write(0x1300, 0, 0, 1).unwrap_err();
        let st = net.p.state();
        assert_eq!(net.p.stack.srdo_mut().send_gfc(&mut net.p.port, st), Ok(()));
        // Manual 1.3 / table 7: CAN id 1 without data.
        assert_eq!(net.bus.trace(), vec!["  can0  001   [0]  "]);
        assert_eq!(srdo_only(&net.c.cycle())[0], Event::Gfc);
    }

    // req: SB-6-GFC-OFF, M-1.3-GFC
    #[test]
    fn gfc_off_refuses_sending_and_ignores_reception() {
        let mut net = Net::operational();
        let st = net.p.state();
        assert_eq!(
            net.p.stack.srdo_mut().send_gfc(&mut net.p.port, st),
            Err(CopKernel::SrdoInvalid)
        );
        assert!(net.bus.trace().is_empty());
        net.inject(0x001, &[]);
        assert!(!net.c.cycle().contains(&Event::Gfc));
        assert_eq!(net.c.stack.srdo().gfc_ignored(), 1);
    }

    // req: M-1.3-GFC
    #[test]
    fn gfc_received_in_pre_operational_and_wrong_dlc_ignored() {
        let mut net = Net::preoperational();
        net.c.write(0x1300, 0, 1, 1).unwrap();
        net.inject(0x001, &[]);
        assert_eq!(srdo_only(&net.c.cycle())[0], Event::Gfc);
        net.inject(0x001, &[0]);
        assert!(!net.c.cycle().contains(&Event::Gfc));
        assert_eq!(net.c.stack.srdo().gfc_ignored(), 1);
        net.c.command(NmtCommand::StopRemoteNode);
        net.inject(0x001, &[]);
        assert!(!net.c.cycle().contains(&Event::Gfc), "not in STOPPED");
    }
}
