//! Shared set-up of the SRDO scenarios (`tests/srdo_*.rs` include this
//! file as a module): two nodes on the simulated bus, a producer (node 1)
//! and a consumer (node 2), each with a Rust-declared dictionary.
//!
//! Each node has SRDO 1 (0x1301, predefined connection set of node 1:
//! COB-IDs 0x101/0x102, refresh time / SCT 25 ms, SRVT 20 ms) mapping
//! normal 0x6200 sub 1 and 0x6201 sub 1 (U16 each) and inverted 0x6300
//! sub 1 and 0x6301 sub 1, i.e. 4 data bytes per frame; and a disabled
//! SRDO 2 (0x1302). The mapped variables lie in two contiguous 4-byte
//! fields, so the same dictionary serves static mapping.
#![allow(dead_code)]

use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::{Mutex, MutexGuard};

use cop::ccm::{NmtCommand, Stack};
use cop::event::{Event, NmtState, ProgMonEvent};
use cop::od::{ByteOrder, ObjectDictionary};
use cop::port::{CanFrame, CanId, Ticks};
use cop::sim::{SimBus, SimPort};
use cop::{CopKernel, OdError};

/// A part of a static byte array (const context).
pub const fn part(buf: &'static [AtomicU8], from: usize, len: usize) -> &'static [AtomicU8] {
    buf.split_at(from).1.split_at(len).0
}

macro_rules! node_od {
    ($m:ident, $dir:expr) => {
        pub mod $m {
            use super::part;
            use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
            use std::sync::atomic::AtomicU8;

            /// Normal data: 0x6200 sub 1 at offset 0, 0x6201 sub 1 at 2.
            pub static NORMAL: [AtomicU8; 4] = decl::zeroed();
            /// Inverted data: 0x6300 sub 1 at offset 0, 0x6301 sub 1 at 2.
            pub static INVERTED: [AtomicU8; 4] = decl::zeroed();

            const fn var(sub: u8, buf: &'static [AtomicU8], at: usize) -> ObdSubEntry {
                ObdSubEntry::ram(
                    sub,
                    DataType::UInt16,
                    Access::PRW,
                    part(buf, at, 2),
                    Some(&[0, 0]),
                )
            }
            static S6200: [ObdSubEntry; 2] = [
                ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                var(1, &NORMAL, 0),
            ];
            static S6201: [ObdSubEntry; 2] = [
                ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                var(1, &NORMAL, 2),
            ];
            static S6300: [ObdSubEntry; 2] = [
                ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                var(1, &INVERTED, 0),
            ];
            static S6301: [ObdSubEntry; 2] = [
                ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                var(1, &INVERTED, 2),
            ];

            cop::obd_create_srdo_gfc_param!(pub mod gfc);
            cop::obd_create_srdo_commu!(pub mod c1, 0x1301, $dir, 25, 20, 0x101, 0x102);
            cop::obd_create_srdo_commu!(pub mod c2, 0x1302, 0, 25, 20, 0x103, 0x104);
            cop::obd_create_srdo_mapp!(
                pub mod m1,
                0x1381,
                [0x6200_0110, 0x6300_0110, 0x6201_0110, 0x6301_0110]
            );
            cop::obd_create_srdo_mapp!(pub mod m2, 0x1382, [0x6200_0110, 0x6300_0110]);
            cop::obd_create_srdo_cfg_valid!(pub mod cfg_valid);
            cop::obd_create_srdo_crc!(pub mod crcs, [0, 0]);

            static GENERIC: [ObdEntry; 7] = cop::srdo_obd_entries![gfc, c1, c2, m1, m2, cfg_valid, crcs];
            static DEVICE: [ObdEntry; 4] = [
                ObdEntry::new(0x6200, &S6200, None),
                ObdEntry::new(0x6201, &S6201, None),
                ObdEntry::new(0x6300, &S6300, None),
                ObdEntry::new(0x6301, &S6301, None),
            ];

            /// The dictionary.
            pub fn od() -> ObjectDictionary {
                ObjectDictionary::new(&GENERIC, &[], &DEVICE).unwrap()
            }
        }
    };
}

node_od!(producer, 1);
node_od!(consumer, 2);

/// How the simulated application answers `AppSrdoError`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum App {
    /// As in manual 2.9.1 / 2.9.2: bits 4-5 := 11 on every event; on an
    /// error (bits 4-5 = 01) also toggles bits 6-7 (01 -> 10).
    Manual,
    /// Never touches the status byte.
    Ignore,
}

/// One node: stack, port, and what its application does.
pub struct Node {
    pub stack: Stack,
    pub port: SimPort,
    pub app: App,
    pub normal: &'static [AtomicU8; 4],
    pub inverted: &'static [AtomicU8; 4],
    /// The status byte as the application saw it inside each
    /// `AppSrdoError` (code, status), for assertions.
    pub seen_in_error: Vec<(CopKernel, u8)>,
}

/// Both nodes; holds the lock over the shared statics.
pub struct Net {
    _guard: MutexGuard<'static, ()>,
    pub bus: SimBus,
    pub p: Node,
    pub c: Node,
}

static SERIAL: Mutex<()> = Mutex::new(());

/// Holds the lock over the shared statics (for tests that build their own
/// nodes instead of a [`Net`]).
pub fn serial_guard() -> MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

/// Writes a 16-bit value into a variable field: in CPU byte order (the
/// variable as the dictionary sees it) with dynamic mapping; in frame byte
/// order with static mapping, whose fields are copied to and from the
/// frames unchanged (manual 2.8.7).
pub fn put(field: &[AtomicU8; 4], offset: usize, v: u16) {
    let bytes = if cfg!(feature = "srdo-static-mapping") {
        v.to_le_bytes()
    } else {
        v.to_ne_bytes()
    };
    for (b, x) in field[offset..offset + 2].iter().zip(bytes) {
        b.store(x, Ordering::Relaxed);
    }
}

/// Reads a 16-bit value from a variable field (byte order as in [`put`]).
pub fn take(field: &[AtomicU8; 4], offset: usize) -> u16 {
    let bytes = [
        field[offset].load(Ordering::Relaxed),
        field[offset + 1].load(Ordering::Relaxed),
    ];
    if cfg!(feature = "srdo-static-mapping") {
        u16::from_le_bytes(bytes)
    } else {
        u16::from_ne_bytes(bytes)
    }
}

/// The program monitor event list when `SRDO_USE_PROGMONITOR` is on,
/// nothing otherwise.
pub fn pm(e: ProgMonEvent) -> Vec<Event> {
    if cop::config::SRDO_USE_PROGMONITOR {
        vec![Event::ProgMon(e)]
    } else {
        vec![]
    }
}

/// The events without program monitor events.
pub fn no_pm(v: &[Event]) -> Vec<Event> {
    v.iter()
        .copied()
        .filter(|e| !matches!(e, Event::ProgMon(_)))
        .collect()
}

/// The SRDO-related events (SRDO, GFC, program monitor).
pub fn srdo_only(v: &[Event]) -> Vec<Event> {
    v.iter()
        .copied()
        .filter(|e| {
            matches!(
                e,
                Event::SrdoEvent(_) | Event::SrdoError(..) | Event::Gfc | Event::ProgMon(_)
            )
        })
        .collect()
}

/// An 11-bit data frame.
pub fn frame(id: u16, data: &[u8]) -> CanFrame {
    CanFrame::new(CanId::std_masked(id), data)
}

fn answer(node_app: App, stack: &mut Stack, e: &Event, seen: &mut Vec<(CopKernel, u8)>) {
    match *e {
        Event::SrdoEvent(idx) if node_app == App::Manual => {
            let st = stack.srdo().get_state(idx).unwrap();
            stack.srdo_mut().set_state(idx, st | 0x30).unwrap();
        }
        Event::SrdoError(idx, code) if code != CopKernel::SrdoNotHandledInApp => {
            let st = stack.srdo().get_state(idx).unwrap();
            seen.push((code, st));
            if node_app == App::Manual && st & 0x30 == 0x10 {
                stack.srdo_mut().set_state(idx, (st | 0x30) ^ 0xC0).unwrap();
            }
        }
        _ => {}
    }
}

impl Node {
    fn new(bus: &SimBus, od: ObjectDictionary, node_id: u8, capacity: usize) -> Node {
        let (normal, inverted) = if node_id == 1 {
            (&producer::NORMAL, &producer::INVERTED)
        } else {
            (&consumer::NORMAL, &consumer::INVERTED)
        };
        Node {
            stack: Stack::new(od, node_id).unwrap(),
            port: bus.attach(capacity),
            app: App::Manual,
            normal,
            inverted,
            seen_in_error: Vec::new(),
        }
    }

    /// One `CcmProcess` at the bus time; returns every event.
    pub fn cycle(&mut self) -> Vec<Event> {
        let now = self.port.bus().now();
        let app = self.app;
        let mut out = Vec::new();
        let mut seen = Vec::new();
        self.stack.process(&mut self.port, now, |stack, e| {
            answer(app, stack, &e, &mut seen);
            out.push(e);
        });
        self.seen_in_error.extend(seen);
        out
    }

    /// Hands out events queued by an API call.
    pub fn drain(&mut self) -> Vec<Event> {
        let now = self.port.bus().now();
        let mut out = Vec::new();
        while let Some(e) = self.stack.drain(&mut self.port, now) {
            answer(self.app, &mut self.stack, &e, &mut self.seen_in_error);
            out.push(e);
        }
        out
    }

    /// `CcmSendSrdo(idx)` and the events it queued.
    pub fn send(&mut self, idx: u16) -> (Result<(), CopKernel>, Vec<Event>) {
        let now = self.port.bus().now();
        let r = self.stack.send_srdo(&mut self.port, idx, now);
        (r, self.drain())
    }

    /// `CcmWriteObject` of an unsigned value of `len` bytes (CANopen order).
    pub fn write(&mut self, index: u16, sub: u8, v: u32, len: usize) -> Result<(), OdError> {
        let now = self.port.bus().now();
        let bytes = v.to_le_bytes();
        self.stack
            .write_object(index, sub, ByteOrder::Wire, &bytes[..len], now)
    }

    /// Reads an unsigned value (CANopen order).
    pub fn read(&self, index: u16, sub: u8) -> u32 {
        let mut buf = [0u8; 8];
        let n = self
            .stack
            .read_object(index, sub, ByteOrder::Wire, &mut buf)
            .unwrap();
        let mut v = [0u8; 4];
        v[..n.min(4)].copy_from_slice(&buf[..n.min(4)]);
        u32::from_le_bytes(v)
    }

    /// Writes the CRC of every SRDO into 0x13FF and 0xA5 into 0x13FE (and
    /// defines the variable fields first with static mapping).
    pub fn seal(&mut self) -> Result<(), OdError> {
        #[cfg(feature = "srdo-static-mapping")]
        {
            let od = *self.stack.od();
            let (n, i): (&'static [AtomicU8], &'static [AtomicU8]) = (self.normal, self.inverted);
            self.stack
                .srdo_mut()
                .static_define_var_fields(&od, 0x1301, n, i)
                .unwrap();
        }
        for idx in [0x1301u16, 0x1302] {
            let crc = self.stack.srdo().calc_crc(self.stack.od(), idx).unwrap();
            self.write(0x13FF, (idx - 0x1300) as u8, u32::from(crc), 2)?;
        }
        self.write(0x13FE, 0, 0xA5, 1)
    }

    /// `CcmNmtsExecCommand` and one cycle to carry it out.
    pub fn command(&mut self, cmd: NmtCommand) -> Vec<Event> {
        self.stack.exec_command(cmd).unwrap();
        self.cycle()
    }

    pub fn state(&self) -> NmtState {
        self.stack.nmt_state()
    }

    pub fn status(&self, idx: u16) -> u8 {
        self.stack.srdo().get_state(idx).unwrap()
    }
}

impl Net {
    /// Both nodes booted to PRE-OPERATIONAL, configured (CRCs, 0x13FE =
    /// 0xA5), not yet OPERATIONAL. `capacity` is the consumer's receive
    /// queue length.
    pub fn preoperational_with(capacity: usize) -> Net {
        Self::preoperational_on(SimBus::new(), capacity)
    }

    /// [`Net::preoperational_with`] on `bus` (a physical bus gives every
    /// node its model's buffers instead of `capacity`).
    pub fn preoperational_on(bus: SimBus, capacity: usize) -> Net {
        let guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
        let mut p = Node::new(&bus, producer::od(), 1, 64);
        let mut c = Node::new(&bus, consumer::od(), 2, capacity);
        for n in [&mut p, &mut c] {
            n.stack.connect().unwrap();
            n.cycle();
            assert_eq!(n.state(), NmtState::PreOperational);
        }
        let mut net = Net {
            _guard: guard,
            bus,
            p,
            c,
        };
        net.p.seal().unwrap();
        net.c.seal().unwrap();
        net.settle();
        net
    }

    /// [`Net::preoperational_with`] and a receive queue of 64 frames.
    pub fn preoperational() -> Net {
        Self::preoperational_with(64)
    }

    /// Both nodes OPERATIONAL with the SRDOs running.
    pub fn operational() -> Net {
        let mut net = Self::preoperational();
        net.start();
        net
    }

    /// Starts both nodes (local NMT command) and discards the events.
    pub fn start(&mut self) {
        self.p.command(NmtCommand::StartRemoteNode);
        self.c.command(NmtCommand::StartRemoteNode);
        assert!(self.p.stack.srdo().is_running());
        assert!(self.c.stack.srdo().is_running());
        self.settle();
    }

    /// Starts only the producer, whatever its configuration.
    pub fn start_producer_only(&mut self) {
        self.p.command(NmtCommand::StartRemoteNode);
        assert_eq!(self.p.state(), NmtState::Operational);
        self.settle();
    }

    /// Lets the boot-up/NMT frames pass and forgets the trace.
    pub fn settle(&mut self) {
        self.p.cycle();
        self.c.cycle();
        self.bus.clear_trace();
    }

    /// Sets the producer's normal values and their complements.
    pub fn set_values(&mut self, a: u16, b: u16) {
        put(self.p.normal, 0, a);
        put(self.p.normal, 2, b);
        put(self.p.inverted, 0, !a);
        put(self.p.inverted, 2, !b);
    }

    /// The consumer's four mapped variables (0x6200, 0x6201, 0x6300, 0x6301).
    pub fn consumer_values(&self) -> [u16; 4] {
        [
            take(self.c.normal, 0),
            take(self.c.normal, 2),
            take(self.c.inverted, 0),
            take(self.c.inverted, 2),
        ]
    }

    /// Sets the consumer's mapped variables (to see that errors leave them).
    pub fn set_consumer_values(&mut self, v: [u16; 4]) {
        put(self.c.normal, 0, v[0]);
        put(self.c.normal, 2, v[1]);
        put(self.c.inverted, 0, v[2]);
        put(self.c.inverted, 2, v[3]);
    }

    /// Puts a frame on the bus from an outside node.
    pub fn inject(&self, id: u16, data: &[u8]) {
        self.bus.inject(frame(id, data));
    }

    /// Advances the bus time.
    pub fn wait_ms(&self, ms: u32) {
        self.bus.advance_ms(ms);
    }

    pub fn wait_ticks(&self, t: u32) {
        self.bus.advance_ticks(t);
    }

    pub fn now(&self) -> Ticks {
        self.bus.now()
    }

    /// Checks that the consumer reports nothing in this cycle and the SCT
    /// timeout of SRDO 1 in a cycle one tick later.
    #[track_caller]
    pub fn sct_times_out_one_tick_later(&mut self) {
        assert!(no_pm(&self.c.cycle()).is_empty());
        self.wait_ticks(1);
        assert_eq!(
            no_pm(&self.c.cycle()),
            vec![Event::SrdoError(0x1301, CopKernel::SrdoSctTimeout)]
        );
    }
}
