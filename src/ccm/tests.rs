//! Stack-level tests: start-up sequence, NMT commands, heartbeat, node
//! guarding, object access through the stack.

use super::*;
use crate::od::{ObdEntry, decl};
use crate::port::{CanFrame, CanId};
use crate::sim::SimBus;

crate::od_rom!(static S1000: u32 = 0x0001_0191 => UInt32, R);

crate::od_ram!(static S1001, ERR_REG: u8 = 0 => UInt8, R);

crate::od_ram!(static S1017, HB_TIME: u16 = 100 => UInt16, SRW);

crate::od_ram!(static S2000, APP_VAR: u8 = 7 => UInt8, RW);

static GENERIC: [ObdEntry; 3] = [
    ObdEntry::new(0x1000, &S1000, None),
    ObdEntry::new(0x1001, &S1001, None),
    ObdEntry::new(0x1017, &S1017, None),
];
static MANUFACTURER: [ObdEntry; 1] = [ObdEntry::new(0x2000, &S2000, None)];

/// The dictionary's variables are statics shared by all tests of this
/// file; each test holds this lock so they do not run into each other.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

fn od() -> ObjectDictionary {
    ObjectDictionary::new(&GENERIC, &MANUFACTURER, &[]).unwrap()
}

fn events(stack: &mut Stack, port: &mut crate::sim::SimPort, now: Ticks) -> Vec<Event> {
    let mut v = Vec::new();
    while let Some(e) = stack.drain(port, now) {
        v.push(e);
    }
    v
}

fn cycle(stack: &mut Stack, port: &mut crate::sim::SimPort) -> Vec<Event> {
    let now = port.bus().now();
    let mut v = Vec::new();
    stack.process(port, now, |_, e| v.push(e));
    v
}

#[test]
fn node_id_must_be_1_to_127() {
    let _guard = serial();
    assert_eq!(Stack::new(od(), 0).err(), Some(CopKernel::InvalidNodeId));
    assert_eq!(Stack::new(od(), 128).err(), Some(CopKernel::InvalidNodeId));
    assert!(Stack::new(od(), 127).is_ok());
}

#[test]
fn startup_sequence_and_bootup() {
    let _guard = serial();
    let bus = SimBus::new();
    let mut port = bus.attach(16);
    let mut stack = Stack::new(od(), 2).unwrap();
    // CcmInitCANopen: the NMT callback sees these, in this order.
    assert_eq!(
        events(&mut stack, &mut port, Ticks(0)),
        vec![
            Event::Nmt(NmtEvent::EnterInitialising),
            Event::Nmt(NmtEvent::ResetNode),
            Event::Nmt(NmtEvent::PreResetCommunication),
            Event::Nmt(NmtEvent::ResetCommunication),
            Event::Nmt(NmtEvent::PostResetCommunication),
        ]
    );
    assert_eq!(stack.nmt_state(), NmtState::Initialisation);
    assert!(
        bus.trace().is_empty(),
        "nothing is sent before CcmConnectToNet"
    );
    // Reset node restored the defaults.
    assert_eq!(decl::get(&APP_VAR), [7]);
    stack.connect().unwrap();
    assert_eq!(stack.connect(), Err(CopKernel::NmtStateError));
    assert_eq!(
        events(&mut stack, &mut port, Ticks(0)),
        vec![Event::Nmt(NmtEvent::EnterPreOperational)]
    );
    assert_eq!(stack.nmt_state(), NmtState::PreOperational);
    // CiA 301 boot-up: 0x700 + node-ID, one byte 0x00.
    assert_eq!(bus.trace(), vec!["  can0  702   [1]  00"]);
}

fn started(node: u8) -> (SimBus, crate::sim::SimPort, Stack) {
    let bus = SimBus::new();
    let mut port = bus.attach(64);
    let mut stack = Stack::new(od(), node).unwrap();
    events(&mut stack, &mut port, Ticks(0));
    stack.connect().unwrap();
    events(&mut stack, &mut port, Ticks(0));
    bus.clear_trace();
    (bus, port, stack)
}

#[test]
fn nmt_commands_for_this_node_and_broadcast() {
    let _guard = serial();
    let (bus, mut port, mut stack) = started(2);
    bus.inject(nmt::encode_command(NmtCs::Start, 0));
    assert_eq!(
        cycle(&mut stack, &mut port),
        vec![Event::Nmt(NmtEvent::EnterOperational)]
    );
    assert_eq!(stack.nmt_state(), NmtState::Operational);
    // Addressed to another node: ignored.
    bus.inject(nmt::encode_command(NmtCs::Stop, 3));
    assert!(cycle(&mut stack, &mut port).is_empty());
    bus.inject(nmt::encode_command(NmtCs::Stop, 2));
    assert_eq!(
        cycle(&mut stack, &mut port),
        vec![Event::Nmt(NmtEvent::EnterStopped)]
    );
    // Start again while stopped, then the same command twice: one event.
    bus.inject(nmt::encode_command(NmtCs::EnterPreOperational, 2));
    bus.inject(nmt::encode_command(NmtCs::EnterPreOperational, 2));
    assert_eq!(
        cycle(&mut stack, &mut port),
        vec![Event::Nmt(NmtEvent::EnterPreOperational)]
    );
    // A frame with the wrong DLC is not an NMT command.
    bus.inject(CanFrame::new(CanId::std_masked(0), &[0x01, 0x00, 0x00]));
    assert!(cycle(&mut stack, &mut port).is_empty());
    assert_eq!(stack.nmt_state(), NmtState::PreOperational);
}

#[test]
fn reset_communication_restores_comm_objects_and_boots_again() {
    let _guard = serial();
    let (bus, mut port, mut stack) = started(5);
    stack
        .write_object(0x1017, 0, ByteOrder::Wire, &[0xF4, 0x01], Ticks(0))
        .unwrap();
    stack
        .write_object(0x2000, 0, ByteOrder::Wire, &[0x55], Ticks(0))
        .unwrap();
    bus.inject(nmt::encode_command(NmtCs::ResetCommunication, 5));
    assert_eq!(
        cycle(&mut stack, &mut port),
        vec![
            Event::Nmt(NmtEvent::PreResetCommunication),
            Event::Nmt(NmtEvent::ResetCommunication),
            Event::Nmt(NmtEvent::PostResetCommunication),
            Event::Nmt(NmtEvent::EnterPreOperational),
        ]
    );
    assert_eq!(
        decl::get(&HB_TIME),
        100u16.to_ne_bytes(),
        "0x1017 back to default"
    );
    assert_eq!(decl::get(&APP_VAR), [0x55], "application object kept");
    assert_eq!(
        bus.trace(),
        vec!["  can0  000   [2]  82 05", "  can0  705   [1]  00"]
    );
    bus.inject(nmt::encode_command(NmtCs::ResetNode, 0));
    let ev = cycle(&mut stack, &mut port);
    assert_eq!(ev.first(), Some(&Event::Nmt(NmtEvent::ResetNode)));
    assert_eq!(
        decl::get(&APP_VAR),
        [7],
        "application object back to default"
    );
}

#[test]
fn heartbeat_follows_0x1017() {
    let _guard = serial();
    let (bus, mut port, mut stack) = started(4);
    // Default 100 ms from the dictionary; the first heartbeat one period
    // after the boot-up.
    bus.advance_ms(99);
    cycle(&mut stack, &mut port);
    assert!(bus.trace().is_empty());
    bus.advance_ms(1);
    cycle(&mut stack, &mut port);
    assert_eq!(bus.trace(), vec!["  can0  704   [1]  7F"]);
    // 0 switches it off.
    stack
        .write_object(0x1017, 0, ByteOrder::Wire, &[0, 0], bus.now())
        .unwrap();
    bus.advance_ms(1000);
    cycle(&mut stack, &mut port);
    assert_eq!(bus.trace().len(), 1);
}

#[test]
fn node_guarding_answers_with_toggle() {
    let _guard = serial();
    let (bus, mut port, mut stack) = started(3);
    stack
        .write_object(0x1017, 0, ByteOrder::Wire, &[0, 0], bus.now())
        .unwrap();
    bus.inject(CanFrame::remote(CanId::std_masked(0x703), 1));
    cycle(&mut stack, &mut port);
    bus.inject(CanFrame::remote(CanId::std_masked(0x703), 1));
    cycle(&mut stack, &mut port);
    let t = bus.trace();
    // CiA 301 7.2.8.3.2.1: state 0x7F, toggle bit 7 alternating from 0.
    assert_eq!(t[1], "  can0  703   [1]  7F");
    assert_eq!(t[3], "  can0  703   [1]  FF");
}

#[test]
fn stopped_node_ignores_everything_but_nmt() {
    let _guard = serial();
    let (bus, mut port, mut stack) = started(6);
    bus.inject(nmt::encode_command(NmtCs::Stop, 6));
    cycle(&mut stack, &mut port);
    bus.clear_trace();
    // An SDO upload request gets no answer in STOPPED.
    bus.inject(CanFrame::new(
        CanId::std_masked(0x606),
        &[0x40, 0x00, 0x10, 0, 0, 0, 0, 0],
    ));
    cycle(&mut stack, &mut port);
    assert_eq!(
        bus.trace().len(),
        1,
        "only the request itself is on the bus"
    );
}

#[test]
fn write_refusals_change_nothing() {
    let _guard = serial();
    let (_bus, _port, mut stack) = started(7);
    assert_eq!(
        stack.write_object(0x1000, 0, ByteOrder::Wire, &[0, 0, 0, 0], Ticks(0)),
        Err(OdError::WRITE)
    );
    assert_eq!(
        stack.write_object(0x1017, 0, ByteOrder::Wire, &[1], Ticks(0)),
        Err(OdError::TOO_SHORT)
    );
    assert_eq!(
        stack.write_object(0x1017, 1, ByteOrder::Wire, &[1, 0], Ticks(0)),
        Err(OdError::SUBINDEX)
    );
    assert_eq!(
        stack.write_object(0x1999, 0, ByteOrder::Wire, &[1], Ticks(0)),
        Err(OdError::INDEX)
    );
    let mut out = [0u8; 4];
    assert_eq!(
        stack.read_object(0x1017, 0, ByteOrder::Wire, &mut out),
        Ok(2)
    );
    assert_eq!(&out[..2], &[100, 0]);
}

#[test]
fn emergency_records_and_sends() {
    let _guard = serial();
    let (bus, mut port, mut stack) = started(9);
    let e = Emergency {
        code: 0x8130,
        register: 0x11,
        manufacturer: [1, 2, 3, 4, 5],
    };
    stack.send_emergency(&mut port, bus.now(), e).unwrap();
    // No 0x1014 in this dictionary: predefined 0x80 + node-ID.
    assert_eq!(
        bus.trace(),
        vec!["  can0  089   [8]  30 81 11 01 02 03 04 05"]
    );
    assert_eq!(decl::get(&ERR_REG), [0x11]);
}

/// Emergency 0x5000 (CiA 301 table 21: device hardware), error register
/// bit 0.
const HARDWARE_ERROR: Emergency = Emergency {
    code: 0x5000,
    register: 0x01,
    manufacturer: [0; 5],
};

/// Without 0x1014, `CcmConfigEmcp`'s COB-ID is the producer's own: it
/// holds through a communication reset when the NMT callback gives it
/// again at `kNmtEvResetCommunication` (where SYS TEC applications call
/// it), and a reset without that call goes back to 0x80 + node-ID.
#[test]
fn emcy_cob_id_without_0x1014_holds_until_reset_communication() {
    let _guard = serial();
    let (bus, mut port, mut stack) = started(9);
    let e = HARDWARE_ERROR;
    assert_eq!(
        stack.config_emcp(0x0101, Ticks(0)),
        Err(CopKernel::InvalidParam)
    );
    stack.config_emcp(0xA0, Ticks(0)).unwrap();
    stack.send_emergency(&mut port, bus.now(), e).unwrap();

    bus.inject(nmt::encode_command(NmtCs::ResetCommunication, 9));
    stack.process(&mut port, bus.now(), |s, ev| {
        if ev == Event::Nmt(NmtEvent::ResetCommunication) {
            s.config_emcp(0xA1, Ticks(0)).unwrap();
        }
    });
    stack.send_emergency(&mut port, bus.now(), e).unwrap();

    bus.inject(nmt::encode_command(NmtCs::ResetCommunication, 9));
    cycle(&mut stack, &mut port);
    stack.send_emergency(&mut port, bus.now(), e).unwrap();
    // CiA 301 7.2.7.3.1: code LSB first, register, 5 bytes.
    let emcy: Vec<_> = bus
        .trace()
        .into_iter()
        .filter(|l| l.contains("[8]  00 50 01"))
        .collect();
    assert_eq!(
        emcy,
        vec![
            "  can0  0A0   [8]  00 50 01 00 00 00 00 00",
            "  can0  0A1   [8]  00 50 01 00 00 00 00 00",
            "  can0  089   [8]  00 50 01 00 00 00 00 00",
        ]
    );
}

#[test]
fn srdo_dispatch_range_is_what_the_srdo_module_takes() {
    // The range test of `on_frame` agrees with the GFC and SRDO identifier
    // decoding of the wire module for every 11-bit identifier and never
    // matches an extended one.
    use crate::wire::srdo as w;
    for raw in 0..=0x7FFu16 {
        let id = CanId::std_masked(raw);
        let frame = CanFrame::new(id, &[]);
        let srdo = w::is_gfc_id(&frame) || w::classify(id).is_some();
        assert_eq!(srdo_or_gfc_id(id), srdo, "id {raw:#05x}");
    }
    for raw in [0x001u32, 0x101, 0x180, 0x1FFF_FFFF] {
        assert!(!srdo_or_gfc_id(CanId::ext(raw).unwrap()));
    }
}
