//! The synchronous counter (object 0x1019, CiA 301 7.5.2.22) of the SYNC
//! producer on the simulated bus.
//!
//! CiA 301 7.2.5.2.1: a SYNC without counter has no data; with 0x1019 =
//! 2..=240 it has one byte, a counter that starts at 1, goes up by one with
//! every SYNC and after the overflow value starts at 1 again. 0x1019 = 1 and
//! 241..=255 are reserved; 0x1019 may change only while the communication
//! cycle period 0x1006 is 0 (SDO abort 0x08000022 otherwise).

mod common;

use cop::ccm::NmtCommand;
use cop::error::{CopKernel, OdError, SdoAbort};
use cop::od::{ObdEntry, ObjectDictionary};
use cop::sim::SimBus;
use cop::sync::producer::COUNTER_OVERFLOW_INDEX;

use common::Node;

const ID: u8 = 4;

/// The SYNC objects as an objdict.h declares them, 0x1019 = 0.
mod dictionary {
    use super::*;

    cop::od_ram!(static S1005, SYNC_COB: u32 = 0x4000_0080 => UInt32, SRW);
    cop::od_ram!(static S1006, CYCLE: u32 = 0 => UInt32, SRW);
    cop::od_ram!(static S1019, OVERFLOW: u8 = 0 => UInt8, SRW);
    static GENERIC: [ObdEntry; 3] = [
        ObdEntry::new(0x1005, &S1005, None),
        ObdEntry::new(0x1006, &S1006, None),
        ObdEntry::new(0x1019, &S1019, None),
    ];

    pub fn od() -> ObjectDictionary {
        ObjectDictionary::new(&GENERIC, &[], &[]).unwrap()
    }
}

/// The dictionary is a static shared by every test of this file.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

struct Producer {
    bus: SimBus,
    node: Node,
    _guard: std::sync::MutexGuard<'static, ()>,
}

impl Producer {
    /// A PRE-OPERATIONAL node whose 0x1019 is `overflow`, producing SYNC on
    /// 0x80 every millisecond (0x1006 = 1 000 µs).
    fn with_overflow(overflow: u8) -> Producer {
        let guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
        let bus = SimBus::new();
        let mut node = Node::new(&bus, dictionary::od(), ID);
        node.write(COUNTER_OVERFLOW_INDEX, 0, overflow.into(), 1)
            .unwrap();
        node.write(0x1006, 0, 1_000, 4).unwrap();
        bus.clear_trace();
        Producer {
            bus,
            node,
            _guard: guard,
        }
    }

    /// The payloads of the SYNC frames of `ms` milliseconds.
    fn syncs(&mut self, ms: u32) -> Vec<Vec<u8>> {
        self.bus.clear_trace();
        for _ in 0..ms {
            self.bus.advance_ms(1);
            self.node.cycle();
        }
        let sent = self.bus.sent().into_iter();
        sent.filter(|(_, _, f)| f.id.id() == 0x80)
            .map(|(_, _, f)| f.payload().to_vec())
            .collect()
    }
}

fn counting(from: u8, to: u8) -> Vec<Vec<u8>> {
    (from..=to).map(|c| vec![c]).collect()
}

#[test]
fn without_counter_a_sync_has_no_data() {
    let mut p = Producer::with_overflow(0);
    assert_eq!(p.syncs(3), vec![Vec::<u8>::new(); 3]);
}

#[test]
fn the_counter_runs_from_1_to_the_overflow_value_and_starts_at_1_again() {
    let mut p = Producer::with_overflow(3);
    assert_eq!(p.node.stack.syncp().counter_overflow(), 3);
    let expected: Vec<Vec<u8>> = [1, 2, 3, 1, 2, 3, 1].iter().map(|&c| vec![c]).collect();
    assert_eq!(p.syncs(7), expected);

    // The highest value, 240, is reached and followed by 1.
    drop(p);
    let mut p = Producer::with_overflow(240);
    let mut all = p.syncs(241);
    assert_eq!(all.pop(), Some(vec![1]));
    assert_eq!(all, counting(1, 240));
}

#[test]
fn reserved_values_are_refused_and_change_nothing() {
    let mut p = Producer::with_overflow(0);
    p.node.write(0x1006, 0, 0, 4).unwrap();
    for v in [1u64, 241, 255] {
        let refused = p.node.write(COUNTER_OVERFLOW_INDEX, 0, v, 1);
        // 0x06090030: value range of parameter exceeded.
        assert_eq!(
            refused,
            Err(OdError::new(CopKernel::InvalidParam, SdoAbort::ValueRange)),
            "{v}"
        );
        assert_eq!(p.node.read(COUNTER_OVERFLOW_INDEX, 0), 0);
    }
    for v in [0u64, 2, 240] {
        assert_eq!(p.node.write(COUNTER_OVERFLOW_INDEX, 0, v, 1), Ok(()), "{v}");
    }
}

#[test]
fn the_counter_changes_only_while_the_cycle_period_is_0() {
    let mut p = Producer::with_overflow(5);
    // 0x08000022: not in the present device state; the old value stays in
    // force and on the bus.
    let refused = p.node.write(COUNTER_OVERFLOW_INDEX, 0, 0, 1);
    assert_eq!(
        refused,
        Err(OdError::new(CopKernel::InvalidParam, SdoAbort::DeviceState))
    );
    assert_eq!(p.node.read(COUNTER_OVERFLOW_INDEX, 0), 5);
    assert_eq!(p.syncs(2), counting(1, 2));

    // Period 0, then a new overflow value and the period again: the
    // counter starts at 1 with the new value.
    p.node.write(0x1006, 0, 0, 4).unwrap();
    assert!(p.syncs(3).is_empty());
    p.node.write(COUNTER_OVERFLOW_INDEX, 0, 2, 1).unwrap();
    p.node.write(0x1006, 0, 1_000, 4).unwrap();
    assert_eq!(p.syncs(3), vec![vec![1], vec![2], vec![1]]);
}

#[test]
fn production_restarted_starts_at_1_and_the_nmt_state_keeps_the_count() {
    let mut p = Producer::with_overflow(10);
    assert_eq!(p.syncs(3), counting(1, 3));
    // STOPPED sends nothing; back in OPERATIONAL the count goes on.
    p.node.command(NmtCommand::StopRemoteNode);
    assert!(p.syncs(5).is_empty());
    p.node.command(NmtCommand::StartRemoteNode);
    assert_eq!(p.syncs(2), counting(4, 5));
    // Bit 30 cleared and set again: production restarts, and so does the
    // counter.
    p.node.write(0x1005, 0, 0x80, 4).unwrap();
    assert!(p.syncs(2).is_empty());
    p.node.write(0x1005, 0, 0x4000_0080, 4).unwrap();
    assert_eq!(p.syncs(2), counting(1, 2));
    // Reset communication: the dictionary's defaults (0x1006 = 0) stop
    // production; the period written again starts at 1 with 0x1019 back at
    // its default 0.
    p.node.command(NmtCommand::ResetCommunication);
    assert!(p.syncs(3).is_empty());
    p.node.write(0x1006, 0, 1_000, 4).unwrap();
    assert_eq!(p.syncs(2), vec![Vec::<u8>::new(); 2]);
}
