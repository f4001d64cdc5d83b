//! SRDO transmission and reception between two nodes on the simulated bus:
//! the valid pair, every reception error code, the boundaries of SRVT and
//! SCT, overrun, the application handshake of the status byte, tick wrap.
//! Set-up: `tests/srdo_support.rs`.

#[path = "srdo_support.rs"]
mod support;

use cop::CopKernel;
use cop::event::{Event, ProgMonEvent};
use cop::port::Ticks;
use support::*;

const IDX: u16 = 0x1301;

/// The events of one error report for SRDO 1 when the application handles
/// it as the manual does.
fn handled_error(code: CopKernel) -> Vec<Event> {
    let mut v = vec![Event::SrdoError(IDX, code)];
    v.extend(pm(ProgMonEvent::SrdoError));
    v
}

/// The producer sends SRDO 1 with `a`, `b` (after the first-send delay).
fn send_pair(net: &mut Net, a: u16, b: u16) {
    net.set_values(a, b);
    let (r, _) = net.p.send(IDX);
    assert_eq!(r, Ok(()));
}

// req: M-2.5.2-RECEIVE
#[test]
fn valid_pair_end_to_end() {
    let mut net = Net::operational();
    net.wait_ms(1);
    net.set_values(0x1234, 0xBEEF);
    let (r, ev) = net.p.send(IDX);
    assert_eq!(r, Ok(()));
    let mut expected = vec![Event::SrdoEvent(IDX)];
    expected.extend(pm(ProgMonEvent::SrdoTransmitted));
    assert_eq!(ev, expected);
    assert_eq!(net.p.status(IDX), 0x30, "ok, then processed by the app");
    // CiA 304 / manual 1.1: frame 1 normal data (little-endian), frame 2
    // every bit inverted, same DLC (4 = two UNSIGNED16).
    assert_eq!(
        net.bus.trace(),
        vec![
            "  can0  101   [4]  34 12 EF BE",
            "  can0  102   [4]  CB ED 10 41"
        ]
    );
    let ev = net.c.cycle();
    let mut expected = vec![Event::SrdoEvent(IDX)];
    expected.extend(pm(ProgMonEvent::SrdoReceived));
    assert_eq!(&ev[..expected.len()], &expected[..]);
    assert_eq!(net.consumer_values(), [0x1234, 0xBEEF, 0xEDCB, 0x4110]);
    assert_eq!(net.c.status(IDX), 0x30);
}

/// Injects frames one cycle apart or all at once and returns the SRDO
/// events of the consumer without program monitor events.
fn check_error(frames: &[(u16, &[u8])], gap_ticks: u32, code: CopKernel) {
    let mut net = Net::operational();
    net.set_consumer_values([1, 2, 3, 4]);
    let mut events = Vec::new();
    for (i, (id, data)) in frames.iter().enumerate() {
        if i > 0 {
            net.wait_ticks(gap_ticks);
        }
        net.inject(*id, data);
    }
    events.extend(srdo_only(&net.c.cycle()));
    assert_eq!(
        no_pm(&events),
        vec![Event::SrdoError(IDX, code)],
        "frames {frames:x?}"
    );
    assert_eq!(
        net.c.seen_in_error,
        vec![(code, 0x50)],
        "inside AppSrdoError bits 4-5 = 01 and bits 6-7 = 01"
    );
    assert_eq!(net.c.status(IDX), 0xB0, "the application answered 11/10");
    assert_eq!(net.consumer_values(), [1, 2, 3, 4], "variables untouched");
}

// req: SB-5-DLC
#[test]
fn dlc_of_first_frame_not_valid() {
    check_error(&[(0x101, &[1, 2, 3])], 1, CopKernel::SrdoDlcNotValid);
}

// req: SB-5-DLC
#[test]
fn dlc_of_second_frame_not_valid() {
    check_error(
        &[(0x101, &[1, 0, 2, 0]), (0x102, &[0xFE, 0xFF, 0xFD])],
        1,
        CopKernel::SrdoDlcNotValid,
    );
}

// req: M-1.1-ORDER
#[test]
fn inverted_frame_without_normal_frame_is_not_in_order() {
    check_error(
        &[(0x102, &[0xFE, 0xFF, 0xFD, 0xFF])],
        1,
        CopKernel::SrdoNotInOrder,
    );
}

// req: M-1.1-ORDER
#[test]
fn two_normal_frames_in_a_row_are_not_in_order() {
    check_error(
        &[(0x101, &[1, 0, 2, 0]), (0x101, &[1, 0, 2, 0])],
        1,
        CopKernel::SrdoNotInOrder,
    );
}

// req: M-1.1-INVERTED
#[test]
fn bit_not_inverted_is_a_data_error() {
    check_error(
        &[(0x101, &[1, 0, 2, 0]), (0x102, &[0xFE, 0xFF, 0xFD, 0xFE])],
        1,
        CopKernel::SrdoDataError,
    );
}

// req: M-1.1-SRVT
#[test]
fn second_frame_after_srvt_is_a_timeout() {
    // SRVT 20 ms = 200 ticks; 201 ticks between the frames, one cycle for
    // both (the late frame finds the error whatever SRDO_CHECK_SRVT_BEFORE_1STRX).
    check_error(
        &[(0x101, &[1, 0, 2, 0]), (0x102, &[0xFE, 0xFF, 0xFD, 0xFF])],
        201,
        CopKernel::SrdoSrvtTimeout,
    );
}

// req: M-1.1-SRVT
#[test]
fn second_frame_exactly_at_srvt_is_valid() {
    let mut net = Net::operational();
    net.inject(0x101, &[1, 0, 2, 0]);
    net.wait_ticks(200);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    let ev = no_pm(&net.c.cycle());
    assert_eq!(ev, vec![Event::SrdoEvent(IDX)]);
    assert_eq!(net.consumer_values(), [1, 2, 0xFFFE, 0xFFFD]);
}

// req: M-1.1-SRVT
#[test]
fn a_first_frame_held_for_the_whole_tick_range_completes_no_pair() {
    // The producer falls silent after a first frame; the consumer runs on
    // (one cycle every 2^28 ticks). 2^32 + 100 ticks later a lone inverted
    // frame arrives: 100 ticks after the held frame when the 32-bit tick
    // count is taken modulo 2^32, 4.97 days in fact. It must not complete
    // a pair with the stale data.
    let mut net = Net::operational();
    net.inject(0x101, &[1, 0, 2, 0]);
    assert!(no_pm(&net.c.cycle()).is_empty());
    for _ in 0..16 {
        net.wait_ticks(1 << 28);
        net.c.cycle();
    }
    net.wait_ticks(100);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    let ev = no_pm(&net.c.cycle());
    let expected = if cop::config::SRDO_CHECK_SRVT_BEFORE_1STRX {
        CopKernel::SrdoNotInOrder
    } else {
        CopKernel::SrdoSrvtTimeout
    };
    assert!(ev.contains(&Event::SrdoError(IDX, expected)), "{ev:?}");
    assert!(!ev.contains(&Event::SrdoEvent(IDX)), "{ev:?}");
    assert_eq!(net.consumer_values(), [0, 0, 0, 0]);
}

// req: SB-5-SRVT-SWITCH
#[test]
fn srvt_with_a_cycle_between_the_frames_follows_the_switch() {
    // SRDO_CHECK_SRVT_BEFORE_1STRX (manual 2.4): FALSE (default) finds the
    // error when the late second frame arrives; TRUE in the cycle in which
    // SRVT has passed, and the late frame is then out of order.
    let mut net = Net::operational();
    net.inject(0x101, &[1, 0, 2, 0]);
    assert!(no_pm(&net.c.cycle()).is_empty());
    net.wait_ticks(201);
    let middle = no_pm(&net.c.cycle());
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    let late = no_pm(&net.c.cycle());
    if cop::config::SRDO_CHECK_SRVT_BEFORE_1STRX {
        assert_eq!(
            middle,
            vec![Event::SrdoError(IDX, CopKernel::SrdoSrvtTimeout)]
        );
        assert_eq!(late, vec![Event::SrdoError(IDX, CopKernel::SrdoNotInOrder)]);
    } else {
        assert!(middle.is_empty(), "{middle:?}");
        assert_eq!(
            late,
            vec![Event::SrdoError(IDX, CopKernel::SrdoSrvtTimeout)]
        );
    }
    assert_eq!(net.consumer_values(), [0, 0, 0, 0]);
}

// req: M-1.1-SCT
#[test]
fn sct_runs_from_entering_operational_and_reports_once() {
    let mut net = Net::operational();
    // SCT 25 ms: at the limit nothing, one tick later the timeout, once.
    net.wait_ms(25);
    assert!(no_pm(&net.c.cycle()).is_empty());
    net.wait_ticks(1);
    let ev = srdo_only(&net.c.cycle());
    let mut expected = handled_error(CopKernel::SrdoSctTimeout);
    expected.extend(pm(ProgMonEvent::SctChecked));
    expected.extend(pm(ProgMonEvent::SctNotCheckedItIsInvalid));
    assert_eq!(ev, expected);
    assert_eq!(net.c.status(IDX), 0xB0);
    net.wait_ms(100);
    assert!(no_pm(&net.c.cycle()).is_empty(), "reported once per expiry");
    // The next valid pair re-arms it.
    net.wait_ms(1);
    send_pair(&mut net, 7, 8);
    assert_eq!(no_pm(&net.c.cycle()), vec![Event::SrdoEvent(IDX)]);
    net.wait_ms(25);
    net.sct_times_out_one_tick_later();
}

// req: M-1.1-SCT
#[test]
fn sct_boundary_between_pairs() {
    let mut net = Net::operational();
    net.wait_ms(1);
    send_pair(&mut net, 1, 1);
    assert_eq!(no_pm(&net.c.cycle()), vec![Event::SrdoEvent(IDX)]);
    // Exactly SCT after the previous first frame: in time.
    net.wait_ms(25);
    send_pair(&mut net, 2, 2);
    assert_eq!(no_pm(&net.c.cycle()), vec![Event::SrdoEvent(IDX)]);
    // 100 µs later than SCT, no cycle in between: the first frame reports
    // the SCT timeout before it is processed; the pair itself is valid.
    net.wait_ms(25);
    net.wait_ticks(1);
    send_pair(&mut net, 3, 3);
    assert_eq!(
        no_pm(&net.c.cycle()),
        vec![
            Event::SrdoError(IDX, CopKernel::SrdoSctTimeout),
            Event::SrdoEvent(IDX)
        ]
    );
    assert_eq!(net.consumer_values(), [3, 3, !3, !3]);
}

// req: SB-5-OVERRUN
#[test]
fn receive_overrun_is_reported_before_the_frames() {
    // The consumer's driver holds two frames; a third is lost.
    let mut net = Net::preoperational_with(2);
    net.start();
    net.set_consumer_values([9, 9, 9, 9]);
    net.inject(0x101, &[1, 0, 2, 0]);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    net.inject(0x101, &[1, 0, 2, 0]);
    let ev = no_pm(&net.c.cycle());
    assert_eq!(
        ev,
        vec![
            Event::SrdoError(IDX, CopKernel::SrdoOverrun),
            Event::SrdoEvent(IDX)
        ]
    );
    assert_eq!(net.c.seen_in_error, vec![(CopKernel::SrdoOverrun, 0x50)]);
}

/// Both nodes OPERATIONAL on a physical bus at 1 Mbit/s with the buffers
/// of a SYS TEC driver configuration (high 16, low 10), their start-up
/// frames taken.
fn operational_on_the_physical_bus() -> Net {
    let bus = cop::sim::SimBus::with_bit_rate(1_000_000).unwrap();
    let mut net = Net::preoperational_on(bus, 0);
    net.start();
    net.wait_ms(2);
    net.p.cycle();
    net.c.cycle();
    net
}

/// On the physical bus with the buffers of a SYS TEC driver configuration
/// (high 16, low 10): 17 SDO requests to the consumer (node 2) overflow its
/// low buffer while the SRDO pair behind them waits in the high one, where
/// the consumer subscribed its COB-IDs. A CAN overrun, not an SRDO error.
#[test]
fn physical_bus_low_buffer_overrun_is_no_srdo_alarm() {
    let mut net = operational_on_the_physical_bus();
    net.bus.clear_trace();
    for i in 0..17 {
        net.inject(0x602, &[0x40, 0x00, 0x10, 0x00, 0, 0, 0, i]);
    }
    net.inject(0x101, &[1, 0, 2, 0]);
    net.inject(0x102, &[0xFE, 0xFF, 0xFD, 0xFF]);
    net.wait_ms(5);
    let ev = no_pm(&net.c.cycle());
    assert_eq!(srdo_only(&ev), vec![Event::SrdoEvent(IDX)]);
    assert_eq!(net.consumer_values(), [1, 2, 0xFFFE, 0xFFFD]);
    // The consumer kept 10 of the 17; the producer's identifier filter
    // let none of them in.
    assert_eq!(net.bus.stats().unwrap().rx_lost_low, 7);
    assert_eq!(net.bus.stats().unwrap().rx_lost_high, 0);
}

/// The same with 17 frames on the SRDO's COB-ID 1: the high buffer
/// overflows and the consumer reports the overrun as an SRDO error.
#[test]
fn physical_bus_high_buffer_overrun_is_an_srdo_overrun() {
    let mut net = operational_on_the_physical_bus();
    for _ in 0..17 {
        net.inject(0x101, &[1, 0, 2, 0]);
    }
    net.wait_ms(5);
    let ev = no_pm(&net.c.cycle());
    assert_eq!(
        ev.first(),
        Some(&Event::SrdoError(IDX, CopKernel::SrdoOverrun))
    );
    // Each node kept 16 of the 17 (the producer subscribes its SRDO's
    // COB-IDs in the high buffer as well).
    assert_eq!(net.bus.stats().unwrap().rx_lost_high, 2);
    assert_eq!(net.bus.stats().unwrap().rx_lost_low, 0);
}

// req: M-2.9.2-APPERROR, M-2.5.3-STATUS
#[test]
fn error_not_handled_by_the_application() {
    let mut net = Net::operational();
    net.c.app = App::Ignore;
    net.inject(0x102, &[0, 0, 0, 0]);
    let ev = srdo_only(&net.c.cycle());
    let mut expected = vec![
        Event::SrdoError(IDX, CopKernel::SrdoNotInOrder),
        Event::SrdoError(IDX, CopKernel::SrdoNotHandledInApp),
    ];
    expected.extend(pm(ProgMonEvent::SrdoError));
    assert_eq!(&ev[..expected.len()], &expected[..]);
    assert_eq!(net.c.status(IDX), 0x50, "bits 6-7 still 01");
}

// req: M-2.9.2-APPERROR
#[test]
fn two_errors_in_one_frame_each_see_the_prepared_status() {
    // A late first frame while another is held: SCT timeout, then not in
    // order; the application sees 01/01 inside both AppSrdoError calls.
    let mut net = Net::operational();
    net.inject(0x101, &[1, 0, 2, 0]);
    net.c.cycle();
    net.wait_ms(26);
    net.inject(0x101, &[1, 0, 2, 0]);
    let ev = no_pm(&net.c.cycle());
    assert_eq!(
        ev,
        vec![
            Event::SrdoError(IDX, CopKernel::SrdoSctTimeout),
            Event::SrdoError(IDX, CopKernel::SrdoNotInOrder)
        ]
    );
    assert_eq!(
        net.c.seen_in_error,
        vec![
            (CopKernel::SrdoSctTimeout, 0x50),
            (CopKernel::SrdoNotInOrder, 0x50)
        ]
    );
    assert_eq!(net.c.status(IDX), 0xB0);
}

// req: SB-5-WRAP
#[test]
fn pair_across_the_tick_counter_wrap() {
    let mut net = Net::preoperational();
    net.bus.set_time(Ticks(u32::MAX - 100));
    net.start();
    // A pair whose frames lie on both sides of the wrap.
    net.wait_ticks(90);
    net.inject(0x101, &[5, 0, 6, 0]);
    net.wait_ticks(20);
    assert!(net.now().0 < 100, "the counter wrapped");
    net.inject(0x102, &[0xFA, 0xFF, 0xF9, 0xFF]);
    assert_eq!(no_pm(&net.c.cycle()), vec![Event::SrdoEvent(IDX)]);
    assert_eq!(net.consumer_values(), [5, 6, 0xFFFA, 0xFFF9]);
    // SCT across the wrap: 25 ms after the first frame is still in time.
    net.wait_ticks(230);
    assert!(net.now().0 < 1000);
    net.sct_times_out_one_tick_later();
}

// req: SB-5-FOREIGN
#[test]
fn remote_frames_and_foreign_ids_are_ignored() {
    let mut net = Net::operational();
    net.bus.inject(cop::port::CanFrame::remote(
        cop::port::CanId::std_masked(0x101),
        4,
    ));
    net.inject(0x103, &[1, 2, 3, 4]);
    net.inject(0x181, &[1, 2, 3, 4]);
    assert!(no_pm(&net.c.cycle()).is_empty());
    assert_eq!(net.consumer_values(), [0, 0, 0, 0]);
}

// req: M-2.4-DUMMY
#[cfg(feature = "srdo-dummy-mapping")]
#[test]
fn dummy_entries_of_a_receive_srdo_skip_their_bytes() {
    let mut net = Net::preoperational();
    // The consumer's second pair becomes two dummy entries (0x0006 =
    // UNSIGNED16, CiA 301 7.4.7.1): the frames keep 4 bytes, bytes 2-3 go
    // nowhere. The mapping is written while the SRDO is disabled.
    net.c.write(0x1301, 1, 0, 1).unwrap();
    net.c.write(0x1381, 0, 0, 1).unwrap();
    net.c.write(0x1381, 3, 0x0006_0010, 4).unwrap();
    net.c.write(0x1381, 4, 0x0006_0010, 4).unwrap();
    net.c.write(0x1381, 0, 4, 1).unwrap();
    net.c.write(0x1301, 1, 2, 1).unwrap();
    net.c.seal().unwrap();
    net.start();
    net.set_consumer_values([0, 0x5555, 0, 0xAAAA]);
    net.wait_ms(1);
    send_pair(&mut net, 0x1234, 0xBEEF);
    let ev = net.c.cycle();
    assert_eq!(ev[0], Event::SrdoEvent(IDX));
    assert_eq!(net.consumer_values(), [0x1234, 0x5555, 0xEDCB, 0xAAAA]);
    assert_eq!(net.c.status(IDX), 0x30);
    // SrdoGetMappParam: no variable behind the dummy entries.
    let m = net
        .c
        .stack
        .srdo()
        .mapp_param(net.c.stack.od(), IDX)
        .unwrap();
    assert_eq!(m.count, 4);
    assert!(std::ptr::eq(
        m.vars[0].unwrap().as_ptr(),
        net.c.normal.as_ptr()
    ));
    assert!(std::ptr::eq(
        m.vars[1].unwrap().as_ptr(),
        net.c.inverted.as_ptr()
    ));
    assert!(m.vars[2].is_none() && m.vars[3].is_none());
    // The dummy bytes are still checked: a second frame whose bytes 2-3
    // are not the complement is a data error, and nothing is written.
    net.wait_ms(20);
    net.inject(0x101, &[0x11, 0x11, 0x22, 0x22]);
    net.inject(0x102, &[0xEE, 0xEE, 0x22, 0x22]);
    assert_eq!(
        no_pm(&net.c.cycle()),
        vec![Event::SrdoError(IDX, CopKernel::SrdoDataError)]
    );
    assert_eq!(net.consumer_values(), [0x1234, 0x5555, 0xEDCB, 0xAAAA]);
}
