//! The LSS slave (CiA 305) of a stack on the simulated bus, driven by an
//! LSS master that is only a port: it sends requests on 0x7E5 and reads the
//! answers on 0x7E4.
//!
//! CiA 305 frames: 8 bytes, byte 0 the command specifier (0x04 switch
//! state global, 0x40..0x43 switch state selective with answer 0x44, 0x11
//! configure node-ID, 0x5A..0x5E inquire, 0x4C identify non-configured with
//! answer 0x50), numbers little-endian from byte 1.

#![cfg(feature = "lss-slave")]

use cop::ccm::{NmtCommand, Stack};
use cop::error::CopKernel;
use cop::event::{Event, NmtEvent, NmtState};
use cop::od::{DataType, ObdEntry, ObdSubEntry, ObjectDictionary};
use cop::port::{CanFrame, CanId, CanPort, Priority};
use cop::sim::{SimBus, SimPort};

/// LSS address: 0x1018 sub 1..=4.
const ADDRESS: [u32; 4] = [0x0000_0123, 0x0000_4567, 0x0002_0001, 0x1234_5678];

mod dictionary {
    use super::*;
    use cop::od::Access;

    static VENDOR: [u8; 4] = ADDRESS[0].to_ne_bytes();
    static PRODUCT: [u8; 4] = ADDRESS[1].to_ne_bytes();
    static REVISION: [u8; 4] = ADDRESS[2].to_ne_bytes();
    static SERIAL: [u8; 4] = ADDRESS[3].to_ne_bytes();
    static S1018: [ObdSubEntry; 5] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[4]),
        ObdSubEntry::rom(1, DataType::UInt32, Access::R, &VENDOR),
        ObdSubEntry::rom(2, DataType::UInt32, Access::R, &PRODUCT),
        ObdSubEntry::rom(3, DataType::UInt32, Access::R, &REVISION),
        ObdSubEntry::rom(4, DataType::UInt32, Access::R, &SERIAL),
    ];
    cop::od_ram!(static S1017, HB: u16 = 0 => UInt16, SRW);
    static GENERIC: [ObdEntry; 2] = [
        ObdEntry::new(0x1017, &S1017, None),
        ObdEntry::new(0x1018, &S1018, None),
    ];

    pub fn od() -> ObjectDictionary {
        ObjectDictionary::new(&GENERIC, &[], &[]).unwrap()
    }
}

/// A stack with the LSS slave and a master port on one bus.
struct Net {
    bus: SimBus,
    master: SimPort,
    port: SimPort,
    stack: Stack,
    events: Vec<Event>,
}

impl Net {
    fn new(node: u8) -> Net {
        let bus = SimBus::new();
        let master = bus.attach(16);
        let port = bus.attach(16);
        let stack = Stack::with_lss(dictionary::od(), node).unwrap();
        let mut net = Net {
            bus,
            master,
            port,
            stack,
            events: Vec::new(),
        };
        net.cycle();
        net
    }

    /// One `CcmProcess` cycle of the stack.
    fn cycle(&mut self) {
        let now = self.bus.now();
        let events = &mut self.events;
        self.stack
            .process(&mut self.port, now, |_, e| events.push(e));
    }

    /// Sends a request and returns the answers of one cycle.
    fn request(&mut self, data: [u8; 8]) -> Vec<[u8; 8]> {
        let f = CanFrame::new(CanId::std_masked(0x7E5), &data);
        self.master.send(&f, Priority::Low).unwrap();
        self.cycle();
        let mut answers = Vec::new();
        while let Some(rx) = self.master.receive() {
            if rx.frame.id != CanId::std_masked(0x7E4) {
                continue; // boot-up, heartbeat
            }
            assert_eq!(rx.frame.len, 8, "CiA 305: every LSS frame has 8 bytes");
            answers.push(rx.frame.data);
        }
        answers
    }

    fn switch_selective(&mut self) -> Vec<[u8; 8]> {
        let mut last = Vec::new();
        for (n, part) in ADDRESS.iter().enumerate() {
            let v = part.to_le_bytes();
            last = self.request([0x40 + n as u8, v[0], v[1], v[2], v[3], 0, 0, 0]);
        }
        last
    }

    fn frames(&self, id: u32) -> Vec<Vec<u8>> {
        let sent = self.bus.sent().into_iter();
        sent.filter(|(_, _, f)| f.id.id() == id)
            .map(|(_, _, f)| f.payload().to_vec())
            .collect()
    }
}

fn cmd(cs: u8, b1: u8) -> [u8; 8] {
    [cs, b1, 0, 0, 0, 0, 0, 0]
}

#[test]
fn a_node_without_node_id_answers_only_lss_until_a_master_gives_it_one() {
    let mut net = Net::new(0xFF);
    assert_eq!(
        net.stack.lss_init_state(),
        Err(CopKernel::LsssInvalidNodeId)
    );
    assert_eq!(net.stack.connect(), Err(CopKernel::LsssInvalidNodeId));
    // Identify non-configured remote slave: 0x50.
    assert_eq!(net.request(cmd(0x4C, 0)), vec![cmd(0x50, 0)]);
    // NMT and SDO are not answered.
    net.master
        .send(
            &CanFrame::new(CanId::std_masked(0x000), &[0x01, 0]),
            Priority::High,
        )
        .unwrap();
    net.cycle();
    assert_eq!(net.stack.nmt_state(), NmtState::Initialisation);

    assert_eq!(net.switch_selective(), vec![cmd(0x44, 0)]);
    assert!(net.stack.lss().unwrap().in_configuration());
    assert_eq!(net.request(cmd(0x5E, 0)), vec![cmd(0x5E, 0xFF)]);
    assert_eq!(net.request(cmd(0x11, 0x22)), vec![cmd(0x11, 0)]);
    assert_eq!(
        net.stack.lss_init_state(),
        Err(CopKernel::LsssInvalidNodeId)
    );

    // Back to waiting: the node takes 0x22 with a reset communication.
    net.events.clear();
    assert!(net.request(cmd(0x04, 0)).is_empty());
    for _ in 0..3 {
        net.cycle();
    }
    assert_eq!(net.stack.lss_init_state(), Ok(()));
    assert_eq!(net.stack.node_id(), 0x22);
    let nmt: Vec<Event> = net
        .events
        .iter()
        .filter(|e| matches!(e, Event::Nmt(_)))
        .copied()
        .collect();
    assert_eq!(
        nmt,
        vec![
            Event::Nmt(NmtEvent::PreResetCommunication),
            Event::Nmt(NmtEvent::ResetCommunication),
            Event::Nmt(NmtEvent::PostResetCommunication),
        ]
    );
    // CcmConnectToNet: boot-up with the new node-ID (CiA 301: 0x700 +
    // node-ID, one byte 0).
    net.stack.connect().unwrap();
    for _ in 0..3 {
        net.cycle();
    }
    assert_eq!(net.stack.nmt_state(), NmtState::PreOperational);
    assert_eq!(net.frames(0x722), vec![vec![0]]);
    // No longer non-configured.
    assert!(net.request(cmd(0x4C, 0)).is_empty());
}

#[test]
fn a_configured_node_takes_a_new_node_id_at_reset_communication() {
    let mut net = Net::new(5);
    net.stack.connect().unwrap();
    net.cycle();
    assert_eq!(net.stack.lss_init_state(), Ok(()));
    // Switch state global to configuration, then inquire everything.
    assert!(net.request(cmd(0x04, 1)).is_empty());
    for (n, part) in ADDRESS.iter().enumerate() {
        let v = part.to_le_bytes();
        let answer = [0x5A + n as u8, v[0], v[1], v[2], v[3], 0, 0, 0];
        assert_eq!(net.request(cmd(0x5A + n as u8, 0)), vec![answer]);
    }
    assert_eq!(net.request(cmd(0x5E, 0)), vec![cmd(0x5E, 5)]);
    assert_eq!(net.request(cmd(0x11, 9)), vec![cmd(0x11, 0)]);
    // Out of range: error 1, the pending node-ID stays 9.
    assert_eq!(net.request(cmd(0x11, 0)), vec![cmd(0x11, 1)]);
    // Bit timing and storage: error 1, not supported.
    assert_eq!(net.request([0x13, 0, 2, 0, 0, 0, 0, 0]), vec![cmd(0x13, 1)]);
    assert_eq!(net.request(cmd(0x17, 0)), vec![cmd(0x17, 1)]);
    assert!(net.request(cmd(0x04, 0)).is_empty());
    net.cycle();
    assert_eq!(
        net.stack.node_id(),
        5,
        "the node-ID changes at reset communication"
    );

    net.stack
        .exec_command(NmtCommand::ResetCommunication)
        .unwrap();
    net.bus.clear_trace();
    for _ in 0..5 {
        net.cycle();
    }
    assert_eq!(net.stack.node_id(), 9);
    assert_eq!(net.stack.nmt_state(), NmtState::PreOperational);
    assert_eq!(net.frames(0x709), vec![vec![0]]);
}

#[test]
fn switch_selective_with_another_address_selects_nothing() {
    let mut net = Net::new(5);
    let mut answers = Vec::new();
    for (n, part) in ADDRESS.iter().enumerate() {
        let v = (part ^ u32::from(n == 3)).to_le_bytes();
        answers = net.request([0x40 + n as u8, v[0], v[1], v[2], v[3], 0, 0, 0]);
    }
    assert!(answers.is_empty());
    assert!(!net.stack.lss().unwrap().in_configuration());
    // Configuration services are not answered in the waiting state.
    assert!(net.request(cmd(0x5E, 0)).is_empty());
    assert!(net.request(cmd(0x11, 9)).is_empty());
}

#[test]
fn a_stack_without_lss_keeps_0x7e5_unanswered_and_refuses_0xff() {
    assert_eq!(
        Stack::new(dictionary::od(), 0xFF).err(),
        Some(CopKernel::InvalidNodeId)
    );
    assert_eq!(
        Stack::with_lss(dictionary::od(), 0).err(),
        Some(CopKernel::InvalidNodeId)
    );
    assert_eq!(
        Stack::with_lss(dictionary::od(), 128).err(),
        Some(CopKernel::InvalidNodeId)
    );
    let bus = SimBus::new();
    let mut master = bus.attach(16);
    let mut port = bus.attach(16);
    let mut stack = Stack::new(dictionary::od(), 5).unwrap();
    stack.connect().unwrap();
    master
        .send(
            &CanFrame::new(CanId::std_masked(0x7E5), &cmd(0x4C, 0)),
            Priority::Low,
        )
        .unwrap();
    master
        .send(
            &CanFrame::new(CanId::std_masked(0x7E5), &cmd(0x04, 1)),
            Priority::Low,
        )
        .unwrap();
    master
        .send(
            &CanFrame::new(CanId::std_masked(0x7E5), &cmd(0x5E, 0)),
            Priority::Low,
        )
        .unwrap();
    stack.process(&mut port, bus.now(), |_, _| {});
    assert!(stack.lss().is_none());
    let lss_answers = bus
        .sent()
        .into_iter()
        .filter(|(_, _, f)| f.id.id() == 0x7E4)
        .count();
    assert_eq!(lss_answers, 0);
}
