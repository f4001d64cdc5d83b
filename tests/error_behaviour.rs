//! The error behaviour object 0x1029 (CiA 301 7.5.2.32) on the simulated
//! bus: the NMT state a node enters after a communication error (heartbeat
//! producer lost, life guarding event, bus-off).
//!
//! Node A (ID 2) has 0x1029 (sub 1 default 0x00), supervises node B's
//! heartbeat with 50 ms in 0x1016 and sends its own every 20 ms; node B
//! (ID 3) has no 0x1029, supervises A the same way and beats every 20 ms.
//! Heartbeat frame: CiA 301 7.2.8.3.2.2 (0x700 + node-ID, one byte of
//! state: 0x04 STOPPED, 0x05 OPERATIONAL, 0x7F PRE-OPERATIONAL).

mod common;

use core::sync::atomic::AtomicU8;

use common::{Net, Node};
use cop::ccm::NmtCommand;
use cop::error::OdError;
use cop::event::{ErrCtrlEvent, Event, NmtEvent, NmtState};
use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
use cop::port::{CanFrame, CanId};

const ID_A: u8 = 2;
const ID_B: u8 = 3;

/// 0x1016 with one entry: `node` supervised with 50 ms (CiA 301 7.5.2.40:
/// node-ID in bits 16..23, time in ms in bits 0..15), and 0x1017 = 20 ms.
macro_rules! heartbeats {
    ($node:expr) => {
        static CONSUMED: [AtomicU8; 4] = decl::zeroed();
        static CONSUMED_DEFAULT: [u8; 4] = ((($node as u32) << 16) | 50).to_ne_bytes();
        static S1016: [ObdSubEntry; 2] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
            ObdSubEntry::ram(
                1,
                DataType::UInt32,
                Access::RW,
                &CONSUMED,
                Some(&CONSUMED_DEFAULT),
            ),
        ];
        cop::od_ram!(static S1017, HB: u16 = 20 => UInt16, SRW);
        cop::od_ram!(static S1001, ERR_REG: u8 = 0 => UInt8, R);
        cop::od_ram!(static S2000, V2000: u8 = 0 => UInt8, PRW);
        static MANUFACTURER: [ObdEntry; 1] = [ObdEntry::new(0x2000, &S2000, None)];

        pub fn od() -> ObjectDictionary {
            ObjectDictionary::new(&GENERIC, &MANUFACTURER, &[]).unwrap()
        }
    };
}

mod node_a {
    use super::*;

    heartbeats!(ID_B);
    cop::od_ram!(static S100C, GUARD: u16 = 0 => UInt16, SRW);
    cop::od_ram!(static S100D, FACTOR: u8 = 0 => UInt8, SRW);
    static BEHAVIOUR: [AtomicU8; 1] = decl::zeroed();
    static S1029: [ObdSubEntry; 2] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
        ObdSubEntry::ram(1, DataType::UInt8, Access::RW, &BEHAVIOUR, Some(&[0])),
    ];

    static GENERIC: [ObdEntry; 6] = [
        ObdEntry::new(0x1001, &S1001, None),
        ObdEntry::new(0x100C, &S100C, None),
        ObdEntry::new(0x100D, &S100D, None),
        ObdEntry::new(0x1016, &S1016, None),
        ObdEntry::new(0x1017, &S1017, None),
        ObdEntry::new(0x1029, &S1029, None),
    ];
}

mod node_b {
    use super::*;

    heartbeats!(ID_A);

    static GENERIC: [ObdEntry; 3] = [
        ObdEntry::new(0x1001, &S1001, None),
        ObdEntry::new(0x1016, &S1016, None),
        ObdEntry::new(0x1017, &S1017, None),
    ];
}

/// The dictionaries are statics shared by every test of this file.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

impl Net {
    /// Both nodes in `state` (reached by local NMT commands), each
    /// supervising the other's heartbeat, A with 0x1029 sub 1 = `reaction`;
    /// events cleared.
    fn supervising(reaction: u8, state: NmtState) -> Net {
        let mut net = Net::pair(&SERIAL, (node_a::od, ID_A), (node_b::od, ID_B));
        net.a.write(0x1029, 1, reaction.into(), 1).unwrap();
        net.run(30);
        for n in [&mut net.a, &mut net.b] {
            match state {
                NmtState::Operational => n.command(NmtCommand::StartRemoteNode),
                NmtState::Stopped => n.command(NmtCommand::StopRemoteNode),
                _ => {}
            }
            assert_eq!(n.stack.nmt_state(), state);
            n.events.clear();
        }
        net
    }

    /// `ms` milliseconds in which only node A runs (B falls silent).
    fn run_a_only(&mut self, ms: u32) {
        for _ in 0..ms {
            self.bus.advance_ms(1);
            self.a.cycle();
        }
    }

    /// The state byte of A's last heartbeat.
    fn last_heartbeat_of_a(&self) -> u8 {
        let beats = self.frames(0x700 + u32::from(ID_A));
        beats.last().expect("A beats").1[0]
    }
}

impl Node {
    /// The heartbeat consumer's and the NMT events, in their order.
    fn supervision_events(&mut self) -> Vec<Event> {
        self.take(|e| matches!(e, Event::Hbc(..) | Event::Nmt(_)).then_some(*e))
    }
}

#[test]
fn a_lost_heartbeat_producer_leads_to_the_state_0x1029_asks_for() {
    use NmtState::*;
    let lost = Event::Hbc(ID_B, ErrCtrlEvent::HbcConnectionLost);
    // (sub 1, state before, state after, NMT event of the change)
    let cases = [
        (
            0,
            Operational,
            PreOperational,
            Some(NmtEvent::EnterPreOperational),
        ),
        (0, PreOperational, PreOperational, None),
        (0, Stopped, Stopped, None),
        (1, Operational, Operational, None),
        (1, PreOperational, PreOperational, None),
        (2, Operational, Stopped, Some(NmtEvent::EnterStopped)),
        (2, PreOperational, Stopped, Some(NmtEvent::EnterStopped)),
        (2, Stopped, Stopped, None),
    ];
    for (reaction, before, after, event) in cases {
        let what = format!("0x1029 = {reaction}, {before:?}");
        let mut net = Net::supervising(reaction, before);
        // B's last heartbeat came at most 20 ms ago; 50 ms later it is lost.
        net.run_a_only(80);
        let mut expected = vec![lost];
        expected.extend(event.map(Event::Nmt));
        assert_eq!(net.a.supervision_events(), expected, "{what}");
        assert_eq!(net.a.stack.nmt_state(), after, "{what}");
        // The heartbeat goes on in the new state (in STOPPED too).
        net.run_a_only(40);
        assert_eq!(net.last_heartbeat_of_a(), after as u8, "{what}");
        assert!(
            net.a.supervision_events().is_empty(),
            "{what}: once per loss"
        );
    }
}

#[test]
fn without_0x1029_a_lost_producer_changes_no_state() {
    let mut net = Net::supervising(0, NmtState::Operational);
    // A falls silent; B, which has no 0x1029, reports it and stays.
    for _ in 0..80 {
        net.bus.advance_ms(1);
        net.b.cycle();
    }
    assert_eq!(
        net.b.supervision_events(),
        vec![Event::Hbc(ID_A, ErrCtrlEvent::HbcConnectionLost)]
    );
    assert_eq!(net.b.stack.nmt_state(), NmtState::Operational);
}

#[test]
fn only_values_with_a_defined_reaction_are_written() {
    let mut net = Net::supervising(1, NmtState::PreOperational);
    for v in [0u64, 1, 2] {
        assert_eq!(net.a.write(0x1029, 1, v, 1), Ok(()));
        assert_eq!(net.a.read(0x1029, 1), v);
    }
    // CiA 301 7.5.2.32: 0x03..=0x7F reserved, 0x80..=0xFF manufacturer
    // specific (none defined here): refused, the value stays.
    for v in [3u64, 0x7F, 0x80, 0xFF] {
        assert_eq!(
            net.a.write(0x1029, 1, v, 1),
            Err(OdError::VALUE_RANGE),
            "{v:#x}"
        );
        assert_eq!(net.a.read(0x1029, 1), 2, "{v:#x}");
    }
}

#[test]
fn an_sdo_write_without_a_defined_reaction_is_aborted_with_0x06090030() {
    let mut net = Net::supervising(1, NmtState::PreOperational);
    // Expedited download of one byte 0x03 to 0x1029 sub 1 (CiA 301
    // 7.2.4.3.3), answered by an abort with 0x06090030 (CiA 301 table 22).
    net.bus.inject(CanFrame::new(
        CanId::std_masked(0x600 + u16::from(ID_A)),
        &[0x2F, 0x29, 0x10, 0x01, 0x03, 0, 0, 0],
    ));
    net.step();
    assert_eq!(
        net.frames(0x580 + u32::from(ID_A)),
        vec![(
            net.a.now().0,
            vec![0x80, 0x29, 0x10, 0x01, 0x30, 0x00, 0x09, 0x06]
        )]
    );
    assert_eq!(net.a.read(0x1029, 1), 1);
}

#[test]
fn bus_off_counts_when_the_driver_raises_it() {
    let mut net = Net::supervising(0, NmtState::Operational);
    let a = net.a.port.node();
    net.bus.set_bus_off(a, true);
    net.step();
    assert_eq!(
        net.a.supervision_events(),
        vec![Event::Nmt(NmtEvent::EnterPreOperational)]
    );
    assert_eq!(net.a.stack.nmt_state(), NmtState::PreOperational);

    // Started again while the flag stays: no second reaction.
    net.a.command(NmtCommand::StartRemoteNode);
    net.a.events.clear();
    net.run(10);
    assert_eq!(net.a.stack.nmt_state(), NmtState::Operational);
    assert!(net.a.supervision_events().is_empty());

    // Cleared, then raised again: a new bus-off.
    net.bus.set_bus_off(a, false);
    net.run(10);
    assert_eq!(net.a.stack.nmt_state(), NmtState::Operational);
    net.bus.set_bus_off(a, true);
    net.run(1);
    assert_eq!(net.a.stack.nmt_state(), NmtState::PreOperational);
}

#[test]
fn bus_off_of_a_node_without_0x1029_changes_no_state() {
    let mut net = Net::supervising(0, NmtState::Operational);
    let b = net.b.port.node();
    net.bus.set_bus_off(b, true);
    net.run(5);
    assert_eq!(net.b.stack.nmt_state(), NmtState::Operational);
    assert!(net.b.supervision_events().is_empty());
}

#[test]
fn a_life_guarding_event_leads_to_the_state_0x1029_asks_for() {
    let mut net = Net::supervising(2, NmtState::Operational);
    // B beats, A does not consume heartbeats here: 0x1016 sub 1 = 0.
    net.a.write(0x1016, 1, 0, 4).unwrap();
    net.a.write(0x1017, 0, 0, 2).unwrap();
    net.a.stack.init_lgs();
    let now = net.a.now();
    net.a.stack.config_lgs(100, 3, now).unwrap();
    if !cop::config::NMTS_USE_LIFEGUARDING {
        // Without the module the node never supervises its master.
        net.run(1000);
        assert_eq!(net.a.stack.nmt_state(), NmtState::Operational);
        return;
    }
    let guard = CanFrame::remote(CanId::std_masked(0x700 + u16::from(ID_A)), 1);
    net.bus.inject(guard);
    net.step();
    net.a.events.clear();
    // The life time is 300 ms: exactly at it still in time, then lost.
    net.run(300);
    assert_eq!(net.a.stack.nmt_state(), NmtState::Operational);
    net.bus.advance_ticks(1);
    net.step();
    assert_eq!(net.a.stack.nmt_state(), NmtState::Stopped);
    assert_eq!(
        net.a.supervision_events(),
        vec![Event::Nmt(NmtEvent::EnterStopped)]
    );
}

#[test]
fn a_controller_bus_off_before_the_node_connects_counts_at_its_first_cycle() {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let bus = cop::sim::SimBus::new();
    let mut port = bus.attach(64);
    bus.set_bus_off(port.node(), true);
    let mut stack = cop::ccm::Stack::new(node_a::od(), ID_A).unwrap();
    while stack.drain(&mut port, bus.now()).is_some() {}
    stack
        .write_object(0x1029, 1, cop::od::ByteOrder::Wire, &[2], bus.now())
        .unwrap();
    // Cycles before the connection do not take the flag.
    stack.process(&mut port, bus.now(), |_, _| {});
    stack.connect().unwrap();
    while stack.drain(&mut port, bus.now()).is_some() {}
    assert_eq!(stack.nmt_state(), NmtState::PreOperational);
    let mut events = Vec::new();
    stack.process(&mut port, bus.now(), |_, e| events.push(e));
    assert_eq!(stack.nmt_state(), NmtState::Stopped);
    assert_eq!(events, vec![Event::Nmt(NmtEvent::EnterStopped)]);
}

/// A loss of frames that no SRDO or GFC uses (the driver's low buffer) is a
/// CAN overrun of the communication: emergency 0x8110 with the error
/// register's generic and communication bits (CiA 301 table 21, 7.5.2.2),
/// no SRDO error and no state change.
#[test]
fn a_low_buffer_overrun_is_a_can_overrun_emergency() {
    let mut net = Net::supervising(0, NmtState::Operational);
    let a = net.a.port.node();
    net.bus.raise_other_overrun(a);
    net.step();
    let emcy = net.frames(0x80 + u32::from(ID_A));
    assert_eq!(
        emcy,
        vec![(emcy[0].0, vec![0x10, 0x81, 0x11, 0, 0, 0, 0, 0])]
    );
    assert_eq!(net.a.stack.nmt_state(), NmtState::Operational);
    assert!(net.a.supervision_events().is_empty());
    // Taken once: the next cycles send nothing more.
    net.run(5);
    assert_eq!(net.frames(0x80 + u32::from(ID_A)).len(), 1);
}
