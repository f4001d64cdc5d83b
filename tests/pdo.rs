//! Whole-stack tests of the PDO service and the SYNC consumer: two nodes
//! (`cop::ccm::Stack`) with Rust-declared dictionaries on the simulated
//! bus. Node A (ID 1) produces from its inputs 0x2000, node B (ID 2)
//! consumes into its outputs 0x2001. Payload layouts follow CiA 301 §7.2.2
//! (mapped objects in order, each little-endian, bit 0 of byte 0 first);
//! parameter rules follow CiA 301 §7.5.2.35–38; SYNC §7.2.5 and 0x1005–0x1007
//! §7.5.2.5–7; emergency codes CiA 301 table 21.

mod common;

use core::sync::atomic::AtomicU8;

use common::{Net, Node};
use cop::ccm::{NmtCommand, Stack};
use cop::error::{CopKernel, OdError};
use cop::event::{Event, NmtEvent, NmtState};
use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
use cop::pdo::{
    Direction, PDO_MAX_MAPPENTRIES, PDO_USE_BIT_MAPPING, PDO_USE_DUMMY_MAPPING, PdoParam,
    StaticPdoParam,
};
use cop::port::{CanFrame, CanId, Ticks};
use cop::sim::SimBus;
use cop::wire::pdo::encode_sync;

/// One node's dictionary: error register, SYNC objects, EMCY COB-ID, two
/// RPDOs and two TPDOs, inputs 0x2000 and outputs 0x2001 of the same shape
/// (1 U8, 2 U16, 3 U32, 4-6 BOOLEAN, 7 INTEGER16 in -100..=100, 8 U8 not
/// mappable, 9 U8 read-only mappable).
macro_rules! node_dictionary {
    ($name:ident) => {
        mod $name {
            use super::*;

            cop::od_ram!(static S1001, ERR_REG: u8 = 0 => UInt8, R);
            cop::od_ram!(static S1005, SYNC_COB: u32 = 0x80 => UInt32, SRW);
            cop::od_ram!(static S1006, CYCLE: u32 = 0 => UInt32, SRW);
            cop::od_ram!(static S1007, WINDOW: u32 = 0 => UInt32, SRW);
            cop::od_ram!(static S1014, EMCY_COB: u32 = 0x80 => UInt32, SRW);

            cop::pdo_commu!(static S1400, V1400 = 0x8000_0200, 255, 0, 0);
            cop::pdo_commu!(static S1401, V1401 = 0x8000_0300, 0, 0, 0);
            cop::pdo_mapp!(static S1600, V1600 = [0x2001_0108, 0x2001_0210, 0x2001_0320]);
            cop::pdo_mapp!(static S1601, V1601 = []);
            cop::pdo_commu!(static S1800, V1800 = 0x180, 255, 0, 0);
            cop::pdo_commu!(static S1801, V1801 = 0x8000_0280, 1, 0, 0);
            cop::pdo_mapp!(static S1A00, V1A00 = [0x2000_0108, 0x2000_0210, 0x2000_0320]);
            cop::pdo_mapp!(static S1A01, V1A01 = []);

            static IN: [[AtomicU8; 4]; 9] = [const { decl::zeroed() }; 9];
            static OUT: [[AtomicU8; 4]; 9] = [const { decl::zeroed() }; 9];
            static RANGE: [u8; 6] = decl::limits(0i16.to_ne_bytes(), (-100i16).to_ne_bytes(), 100i16.to_ne_bytes());

            const fn record(v: &'static [[AtomicU8; 4]; 9]) -> [ObdSubEntry; 10] {
                [
                    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[9]),
                    ObdSubEntry::ram(1, DataType::UInt8, Access::PRW, v[0].split_at(1).0, None),
                    ObdSubEntry::ram(2, DataType::UInt16, Access::PRW, v[1].split_at(2).0, None),
                    ObdSubEntry::ram(3, DataType::UInt32, Access::PRW, &v[2], None),
                    ObdSubEntry::ram(4, DataType::Bool, Access::PRW, v[3].split_at(1).0, None),
                    ObdSubEntry::ram(5, DataType::Bool, Access::PRW, v[4].split_at(1).0, None),
                    ObdSubEntry::ram(6, DataType::Bool, Access::PRW, v[5].split_at(1).0, None),
                    ObdSubEntry::ram_range(
                        7,
                        DataType::Int16,
                        Access::PRW,
                        v[6].split_at(2).0,
                        &RANGE,
                    ),
                    ObdSubEntry::ram(8, DataType::UInt8, Access::RW, v[7].split_at(1).0, None),
                    ObdSubEntry::ram(9, DataType::UInt8, Access::PR, v[8].split_at(1).0, None),
                ]
            }
            static S2000: [ObdSubEntry; 10] = record(&IN);
            static S2001: [ObdSubEntry; 10] = record(&OUT);

            static GENERIC: [ObdEntry; 13] = [
                ObdEntry::new(0x1001, &S1001, None),
                ObdEntry::new(0x1005, &S1005, None),
                ObdEntry::new(0x1006, &S1006, None),
                ObdEntry::new(0x1007, &S1007, None),
                ObdEntry::new(0x1014, &S1014, None),
                ObdEntry::new(0x1400, &S1400, None),
                ObdEntry::new(0x1401, &S1401, None),
                ObdEntry::new(0x1600, &S1600, None),
                ObdEntry::new(0x1601, &S1601, None),
                ObdEntry::new(0x1800, &S1800, None),
                ObdEntry::new(0x1801, &S1801, None),
                ObdEntry::new(0x1A00, &S1A00, None),
                ObdEntry::new(0x1A01, &S1A01, None),
            ];
            static MANUFACTURER: [ObdEntry; 2] = [
                ObdEntry::new(0x2000, &S2000, None),
                ObdEntry::new(0x2001, &S2001, None),
            ];

            pub fn od() -> ObjectDictionary {
                // Application objects are zeroed explicitly: they have no
                // defaults and the statics outlive a test.
                for v in IN.iter().chain(OUT.iter()) {
                    decl::set(v, [0; 4]);
                }
                ObjectDictionary::new(&GENERIC, &MANUFACTURER, &[]).unwrap()
            }
        }
    };
}

node_dictionary!(node_a);
node_dictionary!(node_b);

/// The dictionaries are statics shared by every test of this file.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

impl Node {
    fn define(&mut self, p: &PdoParam<'_>) -> Result<(), CopKernel> {
        let now = self.now();
        let r = self.stack.define_pdo(p, now);
        self.drain();
        r
    }

    /// Defines a PDO completely, with callback.
    fn pdo(&mut self, commu: u16, cob: u32, tx_type: u8, inhibit: u16, event: u16, map: &[u32]) {
        let dir = if commu >= 0x1800 {
            Direction::Tx
        } else {
            Direction::Rx
        };
        self.define(&PdoParam {
            cob_id: Some(cob),
            tx_type: Some(tx_type),
            inhibit_time: Some(inhibit),
            event_time: Some(event),
            entry_count: Some(map.len() as u8),
            entries: Some(map),
            notify: Some(true),
            ..PdoParam::new(commu, dir)
        })
        .unwrap();
    }

    fn pdo_events(&mut self) -> Vec<u16> {
        self.take(|e| match e {
            Event::Pdo(i) => Some(*i),
            _ => None,
        })
    }
}

impl Net {
    /// Both nodes PRE-OPERATIONAL, A's TPDO 1 (0x181, type 255, inputs
    /// 1..3) and B's RPDO 1 (0x181, outputs 1..3) linked, trace empty.
    fn new() -> Net {
        let mut net = Net::pair(&SERIAL, (node_a::od, 1), (node_b::od, 2));
        // Predefined connection set: TPDO 1 of node 1 is 0x181.
        assert_eq!(net.a.read(0x1800, 1), 0x181);
        net.b.write(0x1400, 1, 0x181, 4).unwrap();
        net.bus.clear_trace();
        net
    }

    fn start(&mut self) {
        self.a.command(NmtCommand::StartRemoteNode);
        self.b.command(NmtCommand::StartRemoteNode);
        assert_eq!(self.a.stack.nmt_state(), NmtState::Operational);
        self.a.events.clear();
        self.b.events.clear();
    }

    fn sync(&mut self) {
        self.bus.inject(encode_sync(CanId::std_masked(0x80), None));
        self.step();
    }

    /// 30 ms (the event timers), a SYNC and a frame of B's RPDO 1 (0x181).
    fn everything_a_pdo_acts_on(&mut self) {
        self.run(30);
        self.sync();
        self.bus.inject(CanFrame::new(
            CanId::std_masked(0x181),
            &[1, 2, 0, 3, 0, 0, 0],
        ));
        self.step();
    }
}

fn set_inputs(n: &mut Node, u8v: u8, u16v: u16, u32v: u32) {
    n.write(0x2000, 1, u64::from(u8v), 1).unwrap();
    n.write(0x2000, 2, u64::from(u16v), 2).unwrap();
    n.write(0x2000, 3, u64::from(u32v), 4).unwrap();
}

fn outputs(n: &Node) -> (u64, u64, u64) {
    (n.read(0x2001, 1), n.read(0x2001, 2), n.read(0x2001, 3))
}

#[test]
fn event_driven_tpdo_reaches_the_rpdo_variables() {
    let mut net = Net::new();
    net.a
        .define(&PdoParam {
            notify: Some(true),
            ..PdoParam::new(0x1800, Direction::Tx)
        })
        .unwrap();
    net.b
        .define(&PdoParam {
            notify: Some(true),
            ..PdoParam::new(0x1400, Direction::Rx)
        })
        .unwrap();
    net.start();
    set_inputs(&mut net.a, 0x12, 0x3456, 0x789A_BCDE);
    net.run(5);
    assert!(net.frames(0x181).is_empty(), "type 255 waits for an event");
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(1);
    // CiA 301 §7.2.2: U8, U16, U32 in mapping order, little-endian.
    assert_eq!(
        net.frames(0x181),
        vec![(60, vec![0x12, 0x56, 0x34, 0xDE, 0xBC, 0x9A, 0x78])]
    );
    assert_eq!(outputs(&net.b), (0x12, 0x3456, 0x789A_BCDE));
    assert_eq!(net.a.pdo_events(), vec![0x1800]);
    assert_eq!(net.b.pdo_events(), vec![0x1400]);
    net.run(5);
    assert_eq!(net.frames(0x181).len(), 1, "one event, one PDO");
}

#[test]
fn signal_by_object_and_check_var() {
    let mut net = Net::new();
    net.start();
    assert_eq!(
        net.a.stack.signal_object(0x2000, 8),
        Err(CopKernel::PdoVarNotFound)
    );
    set_inputs(&mut net.a, 1, 2, 3);
    net.a.stack.signal_object(0x2000, 2).unwrap();
    net.run(1);
    assert_eq!(net.frames(0x181).len(), 1);
    // Nothing changed: CcmSignalCheckVar sends nothing.
    net.a.stack.signal_check_var();
    net.run(2);
    assert_eq!(net.frames(0x181).len(), 1);
    // A changed input: sent once.
    net.a.write(0x2000, 3, 4, 4).unwrap();
    net.a.stack.signal_check_var();
    net.run(2);
    let f = net.frames(0x181);
    assert_eq!(f.len(), 2);
    assert_eq!(f[1].1, vec![1, 2, 0, 4, 0, 0, 0]);
    assert_eq!(outputs(&net.b), (1, 2, 4));
}

#[test]
fn signal_by_variable_address() {
    let mut net = Net::new();
    net.start();
    let obj = net.a.stack.od().find(0x2000, 2).unwrap();
    let addr = match obj.storage().unwrap() {
        cop::od::Storage::Ram(m) => m.as_ptr() as usize,
        _ => unreachable!(),
    };
    net.a.stack.signal_var_at(addr).unwrap();
    net.run(1);
    assert_eq!(net.frames(0x181).len(), 1);
    assert_eq!(
        net.a.stack.signal_var_at(addr + 1000),
        Err(CopKernel::PdoVarNotFound)
    );
}

#[test]
fn inhibit_time_spaces_event_driven_transmissions() {
    let mut net = Net::new();
    // 100 x 100 µs = 10 ms.
    net.a.pdo(0x1800, 0x181, 255, 100, 0, &[0x2000_0108]);
    net.start();
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(1);
    net.a.write(0x2000, 1, 7, 1).unwrap();
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(15);
    let f = net.frames(0x181);
    assert_eq!(f.len(), 2);
    assert_eq!(
        f[1].0 - f[0].0,
        100,
        "second PDO exactly one inhibit time later"
    );
    assert_eq!(f[1].1, vec![7], "with the data at the time of sending");
    // Several events during the inhibit time give one transmission, one
    // inhibit time after the previous one.
    for _ in 0..5 {
        net.a.stack.signal_pdo(0x1800).unwrap();
        net.run(1);
    }
    net.run(20);
    let f = net.frames(0x181);
    assert_eq!(f.len(), 3);
    assert_eq!(f[2].0 - f[1].0, 100);
}

#[test]
fn event_timer_sends_periodically_and_restarts_on_events() {
    let mut net = Net::new();
    net.a.pdo(0x1800, 0x181, 254, 0, 20, &[0x2000_0108]);
    net.start();
    net.run(100);
    let times: Vec<u32> = net.frames(0x181).iter().map(|f| f.0).collect();
    assert_eq!(times, vec![200, 400, 600, 800, 1000]);
    // Times are ticks of 100 µs. An event at 150 ms (sent in the cycle at
    // 151 ms) restarts the timer: the next PDO comes at 171 ms, not 160.
    net.run(50);
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(21);
    let times: Vec<u32> = net.frames(0x181).iter().map(|f| f.0).collect();
    assert_eq!(times[5..], [1200, 1400, 1510, 1710]);
}

#[test]
fn cyclic_sync_tpdo_and_synchronous_rpdo() {
    let mut net = Net::new();
    // A: TPDO 2 every 2nd SYNC. B: RPDO 2 synchronous (type 0).
    net.a.pdo(0x1801, 0x281, 2, 0, 0, &[0x2000_0108]);
    net.b.pdo(0x1401, 0x281, 0, 0, 0, &[0x2001_0108]);
    net.start();
    net.a.write(0x2000, 1, 5, 1).unwrap();
    net.run(10);
    net.sync(); // SYNC 1
    assert!(net.frames(0x281).is_empty());
    net.run(10);
    net.sync(); // SYNC 2: A sends, B keeps the data until the next SYNC
    assert_eq!(net.frames(0x281), vec![(200, vec![5])]);
    assert_eq!(net.b.read(0x2001, 1), 0);
    assert!(net.b.pdo_events().is_empty());
    net.a.write(0x2000, 1, 6, 1).unwrap();
    net.run(10);
    net.sync(); // SYNC 3: B actuates 5; A silent
    assert_eq!(net.b.read(0x2001, 1), 5);
    assert_eq!(net.b.pdo_events(), vec![0x1401]);
    assert_eq!(net.frames(0x281).len(), 1);
    net.run(10);
    net.sync(); // SYNC 4: A sends 6
    assert_eq!(net.frames(0x281)[1], (400, vec![6]));
    net.run(10);
    net.sync();
    assert_eq!(net.b.read(0x2001, 1), 6);
}

#[test]
fn acyclic_sync_tpdo_waits_for_sync_after_an_event() {
    let mut net = Net::new();
    net.a.pdo(0x1801, 0x281, 0, 0, 0, &[0x2000_0108]);
    net.start();
    net.sync();
    assert!(net.frames(0x281).is_empty(), "no event, nothing on SYNC");
    net.a.stack.signal_pdo(0x1801).unwrap();
    net.run(10);
    assert!(net.frames(0x281).is_empty(), "type 0 waits for the SYNC");
    net.sync();
    assert_eq!(net.frames(0x281).len(), 1);
    net.run(10);
    net.sync();
    assert_eq!(net.frames(0x281).len(), 1, "one event, one PDO");
}

#[test]
fn sync_window_discards_late_synchronous_pdos() {
    let mut net = Net::new();
    net.a.pdo(0x1801, 0x281, 1, 0, 0, &[0x2000_0108]);
    // 500 µs window (CiA 301 §7.5.2.7).
    net.a.write(0x1007, 0, 500, 4).unwrap();
    net.start();
    // The SYNC is processed 1 ms after it arrived: too late.
    net.bus.inject(encode_sync(CanId::std_masked(0x80), None));
    net.run(1);
    assert!(net.frames(0x281).is_empty());
    // In time.
    net.sync();
    assert_eq!(net.frames(0x281).len(), 1);
    // Without window the late SYNC still triggers the PDO.
    net.a.write(0x1007, 0, 0, 4).unwrap();
    net.bus
        .inject(encode_sync(CanId::std_masked(0x80), Some(3)));
    net.run(1);
    assert_eq!(net.frames(0x281).len(), 2);
}

#[test]
fn remote_requests() {
    let mut net = Net::new();
    net.a.pdo(0x1800, 0x181, 253, 0, 0, &[0x2000_0108]);
    net.start();
    net.a.write(0x2000, 1, 0x42, 1).unwrap();
    net.run(5);
    assert!(net.frames(0x181).is_empty(), "253 is sent on request only");
    net.bus
        .inject(CanFrame::remote(CanId::std_masked(0x181), 1));
    net.step();
    assert_eq!(net.frames(0x181), vec![(50, vec![0x42])]);
    // Type 252: sampled at the SYNC, sent on request.
    net.a.pdo(0x1800, 0x181, 252, 0, 0, &[0x2000_0108]);
    net.a.write(0x2000, 1, 1, 1).unwrap();
    net.sync();
    net.a.write(0x2000, 1, 2, 1).unwrap();
    net.run(1);
    assert_eq!(net.frames(0x181).len(), 1, "252 does not send on SYNC");
    net.bus
        .inject(CanFrame::remote(CanId::std_masked(0x181), 1));
    net.step();
    assert_eq!(net.frames(0x181)[1].1, vec![1], "the value of the SYNC");
    // Bit 30 set: no remote requests.
    net.a.pdo(0x1800, 0x4000_0181, 253, 0, 0, &[0x2000_0108]);
    net.bus
        .inject(CanFrame::remote(CanId::std_masked(0x181), 1));
    net.run(2);
    assert_eq!(net.frames(0x181).len(), 2);
    // Bit 30 alone may change while the PDO exists (CiA 301 7.5.2.37 fixes
    // bits 0-29 only): cleared, requests are answered again; set, not.
    net.a.write(0x1800, 1, 0x181, 4).unwrap();
    net.bus
        .inject(CanFrame::remote(CanId::std_masked(0x181), 1));
    net.run(2);
    assert_eq!(net.frames(0x181).len(), 3);
    net.a.write(0x1800, 1, 0x4000_0181, 4).unwrap();
    net.bus
        .inject(CanFrame::remote(CanId::std_masked(0x181), 1));
    net.run(2);
    assert_eq!(net.frames(0x181).len(), 3);
    // The identifier itself stays fixed while the PDO exists.
    assert!(net.a.write(0x1800, 1, 0x4000_0182, 4).is_err());
    assert!(net.a.write(0x1800, 1, 0x182, 4).is_err());
}

#[test]
fn short_rpdo_is_rejected_with_emcy_8210_and_long_one_accepted() {
    let mut net = Net::new();
    net.start();
    net.bus
        .inject(CanFrame::new(CanId::std_masked(0x181), &[1, 2, 3]));
    net.step();
    assert_eq!(outputs(&net.b), (0, 0, 0), "variables untouched");
    // CiA 301 table 21: 0x8210 "PDO not processed due to length error";
    // error register generic + communication; then RPDO 0x1400 and the DLC.
    assert_eq!(
        net.frames(0x82),
        vec![(0, vec![0x10, 0x82, 0x11, 0x00, 0x14, 3, 0, 0])]
    );
    assert_eq!(net.b.read(0x1001, 0), 0x11);
    assert!(net.b.pdo_events().is_empty());
    // Longer than the mapping (7 bytes): accepted, the surplus ignored.
    net.bus.inject(CanFrame::new(
        CanId::std_masked(0x181),
        &[1, 2, 0, 3, 0, 0, 0, 0xEE],
    ));
    net.step();
    assert_eq!(outputs(&net.b), (1, 2, 3));
    assert_eq!(net.frames(0x82).len(), 1);
}

#[test]
fn mapping_procedure_over_write_object() {
    let mut net = Net::new();
    net.start();
    let b = &mut net.b;
    let abort = |r: Result<(), OdError>| r.err().map(|e| e.abort);
    // RPDO 1 is valid: neither sub 0 nor an entry may change (0x08000022).
    assert_eq!(abort(b.write(0x1600, 0, 0, 1)), Some(0x0800_0022));
    assert_eq!(abort(b.write(0x1600, 1, 0x2001_0210, 4)), Some(0x0800_0022));
    // Nor its identifier (0x06090030).
    assert_eq!(abort(b.write(0x1400, 1, 0x182, 4)), Some(0x0609_0030));
    assert_eq!(b.read(0x1400, 1), 0x181);
    // Procedure: invalidate, sub 0 = 0, entries, sub 0 = n, validate.
    b.write(0x1400, 1, 0x8000_0181, 4).unwrap();
    assert_eq!(abort(b.write(0x1600, 1, 0x2001_0210, 4)), Some(0x0800_0022));
    b.write(0x1600, 0, 0, 1).unwrap();
    let refusals = [
        (0x2001_0808u64, 0x0604_0041u32), // not kObdAccPdo
        (0x2001_0908, 0x0604_0041),       // read-only into an RPDO
        (0x2001_0220, 0x0604_0041),       // U16 with 32 bits
        (0x2001_0148, 0x0604_0042),       // 72 bits
        (0x2005_0108, 0x0602_0000),       // no such index
        (0x2001_1F08, 0x0609_0011),       // no such subindex
    ];
    for (entry, code) in refusals {
        assert_eq!(
            abort(b.write(0x1600, 1, entry, 4)),
            Some(code),
            "{entry:#x}"
        );
        assert_eq!(b.read(0x1600, 1), 0x2001_0108, "refused entry left alone");
    }
    // Kernel codes for CcmWriteObject.
    let e = b.write(0x1600, 1, 0x2005_0108, 4).unwrap_err();
    assert_eq!(e.kernel, CopKernel::PdoVarNotFound);
    let e = b.write(0x1600, 1, 0x2001_0808, 4).unwrap_err();
    assert_eq!(e.kernel, CopKernel::PdoErrorMapp);
    // New layout: U32, U16, dummy U8, U8.
    b.write(0x1600, 1, 0x2001_0320, 4).unwrap();
    b.write(0x1600, 2, 0x2001_0210, 4).unwrap();
    if !PDO_USE_DUMMY_MAPPING {
        // Without PDO_USE_DUMMY_MAPPING a data type index is no mapping.
        assert_eq!(abort(b.write(0x1600, 3, 0x0005_0008, 4)), Some(0x0604_0041));
        return;
    }
    b.write(0x1600, 3, 0x0005_0008, 4).unwrap();
    b.write(0x1600, 4, 0x2001_0108, 4).unwrap();
    b.write(0x1600, 5, 0x2001_0320, 4).unwrap();
    // Five entries are 88 bits: sub 0 = 5 is refused, 4 accepted.
    assert_eq!(abort(b.write(0x1600, 0, 5, 1)), Some(0x0604_0042));
    assert_eq!(b.read(0x1600, 0), 0);
    b.write(0x1600, 0, 4, 1).unwrap();
    b.write(0x1400, 1, 0x181, 4).unwrap();
    net.bus.inject(CanFrame::new(
        CanId::std_masked(0x181),
        &[0x44, 0x33, 0x22, 0x11, 0xBB, 0xAA, 0xFF, 0x5A],
    ));
    net.step();
    assert_eq!(outputs(&net.b), (0x5A, 0xAABB, 0x1122_3344));
}

#[test]
fn sdo_download_is_judged_like_write_object() {
    let mut net = Net::new();
    net.start();
    // CiA 301 §7.2.4.3.3 expedited download of 4 bytes to 0x1400 sub 1
    // (identifier change of a valid RPDO).
    net.bus.inject(CanFrame::new(
        CanId::std_masked(0x602),
        &[0x23, 0x00, 0x14, 0x01, 0x82, 0x01, 0, 0],
    ));
    net.step();
    // Abort 0x06090030, little-endian (CiA 301 §7.2.4.3.17).
    assert_eq!(
        net.frames(0x582),
        vec![(0, vec![0x80, 0x00, 0x14, 0x01, 0x30, 0x00, 0x09, 0x06])]
    );
    assert_eq!(net.b.read(0x1400, 1), 0x181);
}

/// `PDO_USE_BIT_MAPPING` (seed 003 ch. 4): BOOLEANs as single bits. With
/// the switch on they share bytes with the next object; with it off
/// (copdef.h default) such a mapping is refused on both sides.
#[test]
fn boolean_bit_mapping() {
    let mut net = Net::new();
    let tx = [0x2000_0401, 0x2000_0501, 0x2000_0601, 0x2000_0108];
    let rx = [0x2001_0401, 0x2001_0501, 0x2001_0601, 0x2001_0108];
    if !PDO_USE_BIT_MAPPING {
        for (commu, dir, map) in [(0x1800, Direction::Tx, &tx), (0x1400, Direction::Rx, &rx)] {
            let r = net.a.define(&PdoParam {
                cob_id: Some(0x8000_0181),
                entry_count: Some(map.len() as u8),
                entries: Some(map),
                ..PdoParam::new(commu, dir)
            });
            assert_eq!(r, Err(CopKernel::PdoGranularityMismatch), "{commu:#x}");
        }
        return;
    }
    net.a.pdo(0x1800, 0x181, 255, 0, 0, &tx);
    net.b.pdo(0x1400, 0x181, 255, 0, 0, &rx);
    net.start();
    net.a.write(0x2000, 4, 1, 1).unwrap();
    net.a.write(0x2000, 6, 1, 1).unwrap();
    net.a.write(0x2000, 1, 0xFF, 1).unwrap();
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(1);
    // 11 bits: b0 = 1, b1 = 0, b2 = 1, then 0xFF from bit 3.
    assert_eq!(net.frames(0x181)[0].1, vec![0b1111_1101, 0b0000_0111]);
    assert_eq!(
        (
            net.b.read(0x2001, 4),
            net.b.read(0x2001, 5),
            net.b.read(0x2001, 6)
        ),
        (1, 0, 1)
    );
    assert_eq!(net.b.read(0x2001, 1), 0xFF);
}

/// `PDO_GRANULARITY` 64 with bit mapping (seed 003 ch. 4): 64 mapping
/// entries, so 64 BOOLEANs fill a whole PDO; with 8 entries a ninth is
/// refused.
#[test]
fn granularity_64_maps_64_booleans() {
    let mut net = Net::new();
    // b4 = 1, b5 = 0 alternating: 0x55 in every byte.
    let tx: Vec<u32> = (0..64)
        .map(|i| if i % 2 == 0 { 0x2000_0401 } else { 0x2000_0501 })
        .collect();
    let rx: Vec<u32> = (0..64)
        .map(|i| if i % 2 == 0 { 0x2001_0401 } else { 0x2001_0501 })
        .collect();
    if PDO_MAX_MAPPENTRIES < 64 {
        let nine = &tx[..9];
        let r = net.a.define(&PdoParam {
            cob_id: Some(0x8000_0181),
            entry_count: Some(9),
            entries: Some(nine),
            ..PdoParam::new(0x1800, Direction::Tx)
        });
        assert_eq!(r, Err(CopKernel::PdoLengthExceeded));
        return;
    }
    net.a.pdo(0x1800, 0x181, 255, 0, 0, &tx);
    net.b.pdo(0x1400, 0x181, 255, 0, 0, &rx);
    assert_eq!(net.a.read(0x1A00, 0), 64);
    assert_eq!(net.a.read(0x1A00, 64), 0x2000_0501);
    net.start();
    net.a.write(0x2000, 4, 1, 1).unwrap();
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(1);
    assert_eq!(net.frames(0x181)[0].1, vec![0x55; 8]);
    assert_eq!((net.b.read(0x2001, 4), net.b.read(0x2001, 5)), (1, 0));
}

#[test]
fn send_pdo_ignores_type_and_timers() {
    let mut net = Net::new();
    net.a.pdo(0x1800, 0x181, 1, 0, 0, &[0x2000_0108]);
    let now = net.a.now();
    assert_eq!(
        net.a.stack.send_pdo(&mut net.a.port, 0x1800, now),
        Err(CopKernel::NmtStateError),
        "not in PRE-OPERATIONAL"
    );
    net.start();
    net.a.write(0x2000, 1, 9, 1).unwrap();
    // Type 1 (cyclic synchronous), no SYNC: sent anyway.
    net.a.stack.send_pdo(&mut net.a.port, 0x1800, now).unwrap();
    net.a.drain();
    assert_eq!(net.frames(0x181), vec![(0, vec![9])]);
    assert_eq!(net.a.pdo_events(), vec![0x1800]);
    // Inhibit time does not hold it back either.
    net.a.pdo(0x1800, 0x181, 255, 10_000, 0, &[0x2000_0108]);
    net.a.stack.send_pdo(&mut net.a.port, 0x1800, now).unwrap();
    net.a.stack.send_pdo(&mut net.a.port, 0x1800, now).unwrap();
    assert_eq!(net.frames(0x181).len(), 3);
    // ... but it restarts it: an event now waits for the inhibit time.
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(5);
    assert_eq!(net.frames(0x181).len(), 3);
    let r = |n: &mut Node, i| {
        let now = n.now();
        n.stack.send_pdo(&mut n.port, i, now)
    };
    assert_eq!(r(&mut net.a, 0x1805), Err(CopKernel::PdoNotExist));
    assert_eq!(r(&mut net.a, 0x1400), Err(CopKernel::PdoNotExist));
    assert_eq!(r(&mut net.a, 0x1801), Err(CopKernel::PdoErrorSend));
    // A full driver buffer is reported.
    net.bus.refuse_tx(net.a.port.node(), 1);
    assert_eq!(r(&mut net.a, 0x1800), Err(CopKernel::CdrvTxBuffLowOverrun));
}

#[test]
fn pdos_are_silent_outside_operational() {
    let mut net = Net::new();
    net.a.pdo(0x1800, 0x181, 254, 0, 10, &[0x2000_0108]);
    net.a.pdo(0x1801, 0x281, 1, 0, 0, &[0x2000_0108]);
    // PRE-OPERATIONAL: events, event timer, SYNC and RPDOs do nothing.
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.everything_a_pdo_acts_on();
    assert!(net.frames(0x281).is_empty());
    assert_eq!(
        net.frames(0x181).len(),
        1,
        "only the injected frame is on the bus"
    );
    assert_eq!(outputs(&net.b), (0, 0, 0));
    // OPERATIONAL: the event timer runs.
    net.start();
    net.run(10);
    assert_eq!(net.frames(0x181).len(), 2);
    // STOPPED: silent again.
    net.a.command(NmtCommand::StopRemoteNode);
    net.b.command(NmtCommand::StopRemoteNode);
    net.everything_a_pdo_acts_on();
    assert_eq!(net.frames(0x181).len(), 3, "only the injected frame");
    assert!(net.frames(0x281).is_empty());
    assert_eq!(outputs(&net.b), (0, 0, 0));
}

#[test]
fn critical_section_defers_rpdo_data() {
    let mut net = Net::new();
    net.start();
    net.b.stack.enter_critical_pdo();
    net.b.stack.enter_critical_pdo();
    net.bus.inject(CanFrame::new(
        CanId::std_masked(0x181),
        &[1, 2, 0, 3, 0, 0, 0],
    ));
    net.bus.inject(CanFrame::new(
        CanId::std_masked(0x181),
        &[4, 5, 0, 6, 0, 0, 0],
    ));
    net.step();
    assert_eq!(outputs(&net.b), (0, 0, 0));
    net.b.stack.leave_critical_pdo();
    net.step();
    assert_eq!(outputs(&net.b), (0, 0, 0), "still one level inside");
    net.b.stack.leave_critical_pdo();
    net.step();
    assert_eq!(outputs(&net.b), (4, 5, 6), "the latest PDO");
}

#[test]
fn rpdo_deadline_monitoring_sends_emcy_8250_once() {
    let mut net = Net::new();
    net.b.pdo(
        0x1400,
        0x181,
        255,
        0,
        50,
        &[0x2001_0108, 0x2001_0210, 0x2001_0320],
    );
    net.start();
    net.run(100);
    assert!(net.frames(0x82).is_empty(), "armed by the first reception");
    net.bus.inject(CanFrame::new(
        CanId::std_masked(0x181),
        &[1, 2, 0, 3, 0, 0, 0],
    ));
    net.run(60);
    // CiA 301 table 21: 0x8250 "RPDO timeout".
    let e = net.frames(0x82);
    assert_eq!(e.len(), 1);
    assert_eq!(e[0].1[..2], [0x50, 0x82]);
    assert_eq!(e[0].0, 1000 + 510, "just after 50 ms");
    net.run(100);
    assert_eq!(net.frames(0x82).len(), 1, "once");
}

#[test]
fn reset_communication_restores_the_pdo_configuration() {
    let mut net = Net::new();
    net.a.pdo(0x1800, 0x185, 254, 5, 7, &[0x2000_0108]);
    assert_eq!(net.a.read(0x1800, 1), 0x185);
    net.a.command(NmtCommand::ResetCommunication);
    assert_eq!(net.a.read(0x1800, 1), 0x181);
    assert_eq!(net.a.read(0x1800, 2), 255);
    assert_eq!(net.a.read(0x1A00, 0), 3);
    assert_eq!(
        net.a.stack.pdo().cob_id(0x1800),
        Some(CanId::std_masked(0x181))
    );
    net.start();
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(1);
    assert_eq!(net.frames(0x181).len(), 1);
    assert!(net.frames(0x185).is_empty());
}

#[test]
fn define_pdo_tab_rules() {
    let mut net = Net::new();
    // m_bNodeID is added to the identifier; the PDO type must match.
    let wrong = PdoParam {
        cob_id: Some(0x200),
        ..PdoParam::new(0x1401, Direction::Tx)
    };
    assert_eq!(net.b.define(&wrong), Err(CopKernel::InvalidParam));
    assert_eq!(
        net.b.define(&PdoParam::new(0x1405, Direction::Rx)),
        Err(CopKernel::PdoNotExist)
    );
    let good = PdoParam {
        node_id: 1,
        cob_id: Some(0x280),
        tx_type: Some(254),
        entry_count: Some(1),
        entries: Some(&[0x2001_0210]),
        ..PdoParam::new(0x1401, Direction::Rx)
    };
    net.b.define(&good).unwrap();
    assert_eq!(net.b.read(0x1401, 1), 0x281);
    assert_eq!(net.b.read(0x1401, 2), 254);
    assert_eq!(
        (net.b.read(0x1601, 0), net.b.read(0x1601, 1)),
        (1, 0x2001_0210)
    );
    // A mapping error leaves the PDO invalid and returns the PDO code.
    let bad = PdoParam {
        entry_count: Some(1),
        entries: Some(&[0x2001_0208]),
        ..PdoParam::new(0x1401, Direction::Rx)
    };
    assert_eq!(net.b.define(&bad), Err(CopKernel::PdoErrorMapp));
    assert_eq!(net.b.read(0x1401, 1), 0x8000_0281);
    let missing = PdoParam {
        entry_count: Some(1),
        entries: Some(&[0x2009_0108]),
        cob_id: Some(0x281),
        ..PdoParam::new(0x1401, Direction::Rx)
    };
    assert_eq!(net.b.define(&missing), Err(CopKernel::PdoVarNotFound));
    let long = PdoParam {
        entry_count: Some(3),
        entries: Some(&[0x2001_0320, 0x2001_0320, 0x2001_0108]),
        ..PdoParam::new(0x1401, Direction::Rx)
    };
    assert_eq!(net.b.define(&long), Err(CopKernel::PdoLengthExceeded));
    let reserved = PdoParam {
        tx_type: Some(252),
        ..PdoParam::new(0x1401, Direction::Rx)
    };
    assert_eq!(net.b.define(&reserved), Err(CopKernel::InvalidParam));
    net.b.define(&good).unwrap();
    assert_eq!(net.b.read(0x1401, 1), 0x281);
}

static STATIC_TX: [AtomicU8; 3] = decl::zeroed();
static STATIC_RX: [AtomicU8; 3] = decl::zeroed();

#[test]
fn static_pdos_carry_a_byte_block() {
    let mut net = Net::new();
    decl::set(&STATIC_RX, [0; 3]);
    let now = net.a.now();
    let tx = StaticPdoParam {
        commu_index: 0x1801,
        cob_id: 0x301,
        tx_type: 255,
        inhibit_time: 0,
        event_time: 0,
        data: &STATIC_TX,
        notify: false,
    };
    net.a.stack.define_static_pdo(&tx, now).unwrap();
    let rx = StaticPdoParam {
        commu_index: 0x1401,
        cob_id: 0x301,
        tx_type: 254,
        data: &STATIC_RX,
        notify: true,
        ..tx
    };
    net.b.stack.define_static_pdo(&rx, now).unwrap();
    net.start();
    decl::set(&STATIC_TX, [0xA1, 0xB2, 0xC3]);
    net.a.stack.signal_pdo(0x1801).unwrap();
    net.run(1);
    assert_eq!(net.frames(0x301), vec![(10, vec![0xA1, 0xB2, 0xC3])]);
    assert_eq!(decl::get(&STATIC_RX), [0xA1, 0xB2, 0xC3]);
    assert_eq!(net.b.pdo_events(), vec![0x1401]);
    net.bus
        .inject(CanFrame::new(CanId::std_masked(0x301), &[1, 2]));
    net.step();
    assert_eq!(decl::get(&STATIC_RX), [0xA1, 0xB2, 0xC3]);
    assert_eq!(net.frames(0x82)[0].1[..2], [0x10, 0x82]);
}

#[test]
fn sync_consumer_configuration() {
    let mut net = Net::new();
    net.a.pdo(0x1801, 0x281, 1, 0, 0, &[0x2000_0108]);
    net.start();
    let now = net.a.now();
    net.a.stack.config_sync_consumer(0x81, 0, now).unwrap();
    assert_eq!(net.a.read(0x1005, 0), 0x81);
    net.sync(); // on 0x80: not a SYNC any more
    assert!(net.frames(0x281).is_empty());
    net.bus.inject(encode_sync(CanId::std_masked(0x81), None));
    net.step();
    assert_eq!(net.frames(0x281).len(), 1);
    // The consumer API does not make this node the SYNC producer.
    assert_eq!(
        net.a.stack.config_sync_consumer(0x4000_0080, 0, now),
        Err(CopKernel::InvalidParam)
    );
    assert_eq!(net.a.read(0x1005, 0), 0x81);
    net.a.stack.init_sync_consumer().unwrap();
    assert_eq!(
        net.a.stack.pdo().sync_cob_id(),
        Some(CanId::std_masked(0x81))
    );
    // A SYNC with a counter byte is a SYNC; with two bytes it is not.
    net.bus
        .inject(CanFrame::new(CanId::std_masked(0x81), &[1, 2]));
    net.step();
    assert_eq!(net.frames(0x281).len(), 1);
    net.bus
        .inject(encode_sync(CanId::std_masked(0x81), Some(9)));
    net.step();
    assert_eq!(net.frames(0x281).len(), 2);
}

#[test]
fn pdos_defined_in_the_reset_communication_callback() {
    // SYS TEC applications define their PDOs in the NMT callback at
    // kNmtEvResetCommunication (SYSTEC_API.md §10), before the stack has
    // taken over the communication parameters.
    let guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let bus = SimBus::new();
    let a = Node::new(&bus, node_a::od(), 1);
    let mut stack = Stack::new(node_b::od(), 2).unwrap();
    let mut port = bus.attach(64);
    let mut defined = 0;
    while let Some(e) = stack.drain(&mut port, Ticks(0)) {
        if e == Event::Nmt(NmtEvent::ResetCommunication) {
            // kPdoValidCallback alone, then the COB-ID.
            let cb = PdoParam {
                notify: Some(true),
                ..PdoParam::new(0x1400, Direction::Rx)
            };
            stack.define_pdo(&cb, Ticks(0)).unwrap();
            let cob = PdoParam {
                cob_id: Some(0x181),
                ..PdoParam::new(0x1400, Direction::Rx)
            };
            stack.define_pdo(&cob, Ticks(0)).unwrap();
            defined += 1;
        }
    }
    assert_eq!(defined, 1);
    stack.connect().unwrap();
    let b = Node {
        stack,
        port,
        events: Vec::new(),
    };
    let mut net = Net {
        bus,
        a,
        b,
        _guard: guard,
    };
    net.b.drain();
    net.start();
    set_inputs(&mut net.a, 3, 4, 5);
    net.a.stack.signal_pdo(0x1800).unwrap();
    net.run(1);
    assert_eq!(outputs(&net.b), (3, 4, 5));
    assert_eq!(net.b.pdo_events(), vec![0x1400]);
}

/// Stores `v` into the RAM of a mapped variable of node A directly, as an
/// application (or an interrupt) writing its variable does: no dictionary
/// write, no signal.
fn poke_input(net: &Net, sub: u8, v: u8) {
    let obj = net.a.stack.od().find(0x2000, sub).unwrap();
    match obj.storage().unwrap() {
        cop::od::Storage::Ram(m) => m[0].store(v, core::sync::atomic::Ordering::Relaxed),
        _ => unreachable!("0x2000 is RAM"),
    }
}

/// Both nodes OPERATIONAL for 3 ms (the first comparison has taken the
/// data as they are); `None` without `CCM_USE_PDO_CHECK_VAR`.
fn check_var_net() -> Option<Net> {
    if !cop::config::CCM_USE_PDO_CHECK_VAR {
        return None;
    }
    let mut net = Net::new();
    net.start();
    net.run(3);
    Some(net)
}

/// `CCM_USE_PDO_CHECK_VAR` (SYS TEC copdef.h default TRUE; pdo.h
/// `PdoProcessCheckVar`): an event-driven TPDO is sent in the cycle after
/// its mapped variable changed in memory, once per change, with the new
/// value, without `CcmSignalCheckVar`. Every change is seen, also the
/// second and third of the same variable and one back to an earlier value.
#[test]
fn check_var_sends_each_change_of_a_mapped_variable() {
    let Some(mut net) = check_var_net() else {
        return;
    };
    assert!(
        net.frames(0x181).is_empty(),
        "nothing changed, nothing sent"
    );
    for (n, v) in [0x11u8, 0x22, 0x11].into_iter().enumerate() {
        poke_input(&net, 1, v);
        let at = net.bus.now().0;
        net.step();
        let f = net.frames(0x181);
        assert_eq!(f.len(), n + 1, "change {n} sent in the next cycle");
        assert_eq!(f[n], (at, vec![v, 0, 0, 0, 0, 0, 0]));
        net.run(3);
        assert_eq!(net.frames(0x181).len(), n + 1, "once per change");
    }
}

/// A TPDO sent by the application (`CcmSendPdo`) with data the comparison
/// never saw is what it sent last: when the variable returns to the value
/// the comparison saw before, before the next cycle, that is a change
/// against the last transmission and is sent (pdo.h `PdoProcessCheckVar`
/// compares with the last transmitted data).
#[test]
fn check_var_compares_with_a_transmission_of_the_application() {
    let Some(mut net) = check_var_net() else {
        return;
    };
    poke_input(&net, 1, 0x66);
    let now = net.a.now();
    net.a.stack.send_pdo(&mut net.a.port, 0x1800, now).unwrap();
    net.a.drain();
    poke_input(&net, 1, 0);
    let at = net.bus.now().0;
    net.step();
    let f = net.frames(0x181);
    assert_eq!(f.len(), 2, "sent by the application, then the change back");
    assert_eq!(f[0].1, vec![0x66, 0, 0, 0, 0, 0, 0]);
    assert_eq!(f[1], (at, vec![0, 0, 0, 0, 0, 0, 0]));
    net.run(3);
    assert_eq!(net.frames(0x181).len(), 2, "no change since");
}

/// A TPDO remapped in OPERATIONAL (CiA 301 §7.5.2.38 procedure: invalidate,
/// sub 0 = 0, entry, sub 0 = 1, validate) is compared by its new mapping:
/// a change of the newly mapped variable (0x2000 sub 9, not mapped before)
/// is sent, a change of a variable mapped before is not.
#[test]
fn check_var_follows_a_remapped_tpdo() {
    let Some(mut net) = check_var_net() else {
        return;
    };
    poke_input(&net, 1, 0x33);
    net.step();
    assert_eq!(net.frames(0x181).len(), 1, "the old mapping is watched");
    let a = &mut net.a;
    a.write(0x1800, 1, 0x8000_0181, 4).unwrap();
    a.write(0x1A00, 0, 0, 1).unwrap();
    a.write(0x1A00, 1, 0x2000_0908, 4).unwrap();
    a.write(0x1A00, 0, 1, 1).unwrap();
    a.write(0x1800, 1, 0x181, 4).unwrap();
    net.run(3);
    assert_eq!(net.frames(0x181).len(), 1, "remapping sends nothing");
    poke_input(&net, 1, 0x44);
    net.run(3);
    assert_eq!(net.frames(0x181).len(), 1, "sub 1 is no longer mapped");
    poke_input(&net, 9, 0x55);
    let at = net.bus.now().0;
    net.step();
    let f = net.frames(0x181);
    assert_eq!(f.len(), 2, "the newly mapped sub 9 is watched");
    assert_eq!(f[1], (at, vec![0x55]));
}
