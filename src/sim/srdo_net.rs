//! Safety devices for the simulated bus: an SRDO producer, an SRDO consumer
//! and a masquerading producer, each a complete [`Stack`] with a Rust
//! dictionary. The fault-injection campaign ([`super::faults`]), the
//! `srdo_rx` fuzz target and the timing tests build on them.
//!
//! Every device has SRDO 1 (0x1301) on COB-IDs 0x101/0x102 and a disabled
//! SRDO 2 (0x1302, COB-IDs 0x103/0x104), GFC on, and its mapped variables
//! in two contiguous fields (so the same dictionaries serve static
//! mapping); every mapped object is an UNSIGNED16.
//!
//! | device | node | SRDO 1 | refresh / SCT | SRVT | mapping (normal, inverted) | DLC |
//! |---|---|---|---|---|---|---|
//! | producer | 1 | transmit | [`SCT_MS`] | [`SRVT_MS`] | 0x6200.1 0x6300.1 0x6201.1 0x6301.1 | 4 |
//! | consumer | 2 | receive | [`SCT_MS`] | [`SRVT_MS`] | 0x6200.1 0x6300.1 0x6201.1 0x6301.1 | 4 |
//! | rogue | 3 | transmit | [`SCT_MS`] | [`SRVT_MS`] | 0x6200.1 0x6300.1 | 2 |
//!
//! The rogue is "another producer whose configuration differs": it uses the
//! consumer's COB-IDs with a mapping of one pair instead of two.
//!
//! The variables are process-wide statics: hold [`lock`] while devices
//! exist (tests run in parallel threads).

use core::sync::atomic::{AtomicU8, Ordering};
use std::sync::{Mutex, MutexGuard};

use crate::ccm::{NmtCommand, Stack};
use crate::error::{CopKernel, CopResult, OdError};
use crate::event::Event;
use crate::od::{ByteOrder, ObjectDictionary};
use crate::port::Ticks;
use crate::sim::{SimBus, SimPort};

/// SCT of the consumer and refresh time of the producers, in ms.
pub const SCT_MS: u16 = 50;
/// SRVT of every device, in ms.
pub const SRVT_MS: u8 = 20;
/// Communication index of the SRDO every device runs.
pub const SRDO: u16 = 0x1301;
/// COB-ID 1 (normal data) of that SRDO.
pub const COB_NORMAL: u16 = 0x101;
/// COB-ID 2 (inverted data) of that SRDO.
pub const COB_INVERTED: u16 = 0x102;
/// Data bytes per frame of the producer and the consumer.
pub const DATA_LEN: usize = 4;
/// Data bytes per frame of the rogue.
pub const ROGUE_DATA_LEN: usize = 2;

/// A part of a static byte array (const context).
const fn part(buf: &'static [AtomicU8], from: usize, len: usize) -> &'static [AtomicU8] {
    buf.split_at(from).1.split_at(len).0
}

macro_rules! device_od {
    ($m:ident, $doc:literal, $dir:expr, $len:expr, [$($entry:expr),*], [$(($idx:expr, $field:ident, $at:expr)),*]) => {
        #[doc = $doc]
        pub mod $m {
            use super::part;
            use crate::od::{Access, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
            use core::sync::atomic::AtomicU8;

            /// The normal variables, in mapping order.
            pub static NORMAL: [AtomicU8; $len] = decl::zeroed();
            /// The inverted variables, in mapping order.
            pub static INVERTED: [AtomicU8; $len] = decl::zeroed();

            const fn var(buf: &'static [AtomicU8], at: usize) -> [ObdSubEntry; 2] {
                [
                    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                    ObdSubEntry::ram(1, DataType::UInt16, Access::PRW, part(buf, at, 2), Some(&[0, 0])),
                ]
            }
            crate::obd_create_srdo_gfc_param!(pub mod gfc);
            crate::obd_create_srdo_commu!(
                pub mod c1, 0x1301, $dir, crate::sim::srdo_net::SCT_MS, crate::sim::srdo_net::SRVT_MS, 0x101, 0x102
            );
            crate::obd_create_srdo_commu!(
                pub mod c2, 0x1302, 0, crate::sim::srdo_net::SCT_MS, crate::sim::srdo_net::SRVT_MS, 0x103, 0x104
            );
            crate::obd_create_srdo_mapp!(pub mod m1, 0x1381, [$($entry),*]);
            crate::obd_create_srdo_mapp!(pub mod m2, 0x1382, [0x6200_0110, 0x6300_0110]);
            crate::obd_create_srdo_cfg_valid!(pub mod cfg_valid);
            crate::obd_create_srdo_crc!(pub mod crcs, [0, 0]);

            static GENERIC: [ObdEntry; 7] = crate::srdo_obd_entries![gfc, c1, c2, m1, m2, cfg_valid, crcs];
            static DEVICE: [ObdEntry; [$($idx),*].len()] = [
                $(ObdEntry::new($idx, {
                    static S: [ObdSubEntry; 2] = var(&$field, $at);
                    &S
                }, None)),*
            ];

            /// The dictionary (the tables above are sorted and well formed).
            pub fn od() -> Result<ObjectDictionary, crate::CopKernel> {
                ObjectDictionary::new(&GENERIC, &[], &DEVICE).map_err(|e| e.code)
            }
        }
    };
}

/// A device with the two UNSIGNED16 pairs (0x6200/0x6300 sub 0 and
/// 0x6201/0x6301) in SRDO 1, direction `$direction`.
macro_rules! two_pair_od {
    ($name:ident, $doc:literal, $direction:expr) => {
        device_od!(
            $name,
            $doc,
            $direction,
            4,
            [0x6200_0110, 0x6300_0110, 0x6201_0110, 0x6301_0110],
            [
                (0x6200, NORMAL, 0),
                (0x6201, NORMAL, 2),
                (0x6300, INVERTED, 0),
                (0x6301, INVERTED, 2)
            ]
        );
    };
}

two_pair_od!(producer, "Dictionary of the producer (node 1).", 1);
two_pair_od!(consumer, "Dictionary of the consumer (node 2).", 2);
device_od!(
    rogue,
    "Dictionary of the rogue producer (node 3): same COB-IDs, one pair.",
    1,
    2,
    [0x6200_0110, 0x6300_0110],
    [(0x6200, NORMAL, 0), (0x6300, INVERTED, 0)]
);

static LOCK: Mutex<()> = Mutex::new(());

/// Serialises the users of the devices' static variables. A panic in an
/// earlier holder does not poison the devices (each user seals afresh).
pub fn lock() -> MutexGuard<'static, ()> {
    LOCK.lock().unwrap_or_else(|e| e.into_inner())
}

/// Which device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Node 1, transmits SRDO 1.
    Producer,
    /// Node 2, receives SRDO 1.
    Consumer,
    /// Node 3, transmits on the consumer's COB-IDs with another mapping.
    Rogue,
}

impl Role {
    /// The node-ID.
    pub const fn node_id(self) -> u8 {
        match self {
            Role::Producer => 1,
            Role::Consumer => 2,
            Role::Rogue => 3,
        }
    }

    /// Data bytes per frame.
    pub const fn data_len(self) -> usize {
        match self {
            Role::Producer | Role::Consumer => DATA_LEN,
            Role::Rogue => ROGUE_DATA_LEN,
        }
    }
}

/// One safety device on the simulated bus.
pub struct Device {
    /// The stack.
    pub stack: Stack,
    /// Its connection to the bus.
    pub port: SimPort,
    /// Which device.
    pub role: Role,
    normal: &'static [AtomicU8],
    inverted: &'static [AtomicU8],
}

/// Copies frame bytes into a field of UNSIGNED16 variables. With dynamic
/// mapping each variable holds its value in CPU byte order (the library
/// converts); with static mapping the field is copied to and from the
/// frames unchanged, so it holds frame (little-endian) order.
fn store(field: &[AtomicU8], frame_bytes: &[u8]) {
    for (var, wire) in field.chunks(2).zip(frame_bytes.chunks(2)) {
        let (Some(&lo), Some(&hi)) = (wire.first(), wire.get(1)) else {
            continue;
        };
        let bytes = if cfg!(srdo_static_mapping) {
            [lo, hi]
        } else {
            u16::from_le_bytes([lo, hi]).to_ne_bytes()
        };
        for (b, v) in var.iter().zip(bytes) {
            b.store(v, Ordering::Relaxed);
        }
    }
}

/// The frame bytes a field of UNSIGNED16 variables stands for (inverse of
/// [`store`]).
fn load<const N: usize>(field: &[AtomicU8]) -> [u8; N] {
    let mut out = [0u8; N];
    for (var, wire) in field.chunks(2).zip(out.chunks_mut(2)) {
        let (Some(a), Some(b)) = (var.first(), var.get(1)) else {
            continue;
        };
        let raw = [a.load(Ordering::Relaxed), b.load(Ordering::Relaxed)];
        let bytes = if cfg!(srdo_static_mapping) {
            raw
        } else {
            u16::from_ne_bytes(raw).to_le_bytes()
        };
        for (w, v) in wire.iter_mut().zip(bytes) {
            *w = v;
        }
    }
    out
}

impl Device {
    /// Creates the device, attaches it with a receive queue of
    /// `rx_capacity` frames (0: it hears nothing) and connects it; it is
    /// PRE-OPERATIONAL with the default parameters (0x13FE not yet valid).
    pub fn new(bus: &SimBus, role: Role, rx_capacity: usize) -> CopResult<Device> {
        let (od, normal, inverted): (_, &'static [AtomicU8], &'static [AtomicU8]) = match role {
            Role::Producer => (producer::od()?, &producer::NORMAL, &producer::INVERTED),
            Role::Consumer => (consumer::od()?, &consumer::NORMAL, &consumer::INVERTED),
            Role::Rogue => (rogue::od()?, &rogue::NORMAL, &rogue::INVERTED),
        };
        let mut d = Device {
            stack: Stack::new(od, role.node_id())?,
            port: bus.attach(rx_capacity),
            role,
            normal,
            inverted,
        };
        d.stack.connect()?;
        d.process(|_, _| {});
        Ok(d)
    }

    /// One `CcmProcess` at the bus time, each event handed to `handle`.
    pub fn process(&mut self, handle: impl FnMut(&mut Stack, Event)) {
        let now = self.port.bus().now();
        self.stack.process(&mut self.port, now, handle);
    }

    /// Hands the events queued by an API call to `handle`.
    pub fn drain(&mut self, mut handle: impl FnMut(&mut Stack, Event)) {
        let now = self.port.bus().now();
        while let Some(e) = self.stack.drain(&mut self.port, now) {
            handle(&mut self.stack, e);
        }
    }

    /// A local NMT command (`CcmNmtsExecCommand`) and the cycle that carries
    /// it out.
    pub fn command(&mut self, cmd: NmtCommand) -> CopResult {
        self.stack.exec_command(cmd)?;
        self.process(|_, _| {});
        Ok(())
    }

    /// `CcmWriteObject` of an unsigned value of `len` bytes.
    pub fn write(&mut self, index: u16, sub: u8, value: u32, len: usize) -> Result<(), OdError> {
        let now = self.port.bus().now();
        let bytes = value.to_le_bytes();
        let data = bytes.get(..len).unwrap_or(&bytes);
        self.stack
            .write_object(index, sub, ByteOrder::Wire, data, now)
    }

    /// Reads an unsigned value of at most 4 bytes (0 when unreadable).
    pub fn read(&self, index: u16, sub: u8) -> u32 {
        let mut buf = [0u8; 8];
        let n = self
            .stack
            .read_object(index, sub, ByteOrder::Wire, &mut buf)
            .unwrap_or(0);
        let mut v = [0u8; 4];
        for (d, s) in v.iter_mut().zip(buf.iter().take(n)) {
            *d = *s;
        }
        u32::from_le_bytes(v)
    }

    /// Makes the configuration valid the way a configuration tool does:
    /// the CRC of every SRDO into 0x13FF, then 0xA5 into 0x13FE (which runs
    /// the configuration check). With static mapping the variable fields
    /// are handed over first.
    pub fn seal(&mut self) -> Result<(), OdError> {
        #[cfg(srdo_static_mapping)]
        {
            let od = *self.stack.od();
            let (n, i) = (self.normal, self.inverted);
            self.stack
                .srdo_mut()
                .static_define_var_fields(&od, SRDO, n, i)
                .map_err(|k| OdError::new(k, crate::error::SdoAbort::General))?;
        }
        for idx in [SRDO, SRDO + 1] {
            let crc = self
                .stack
                .srdo()
                .calc_crc(self.stack.od(), idx)
                .map_err(|k| OdError::new(k, crate::error::SdoAbort::General))?;
            self.write(
                crate::srdo::CRC_INDEX,
                (idx - 0x1300) as u8,
                u32::from(crc),
                2,
            )?;
        }
        self.write(crate::srdo::CONFIG_VALID_INDEX, 0, 0xA5, 1)
    }

    /// Sets the mapped variables: `normal` (frame bytes) and, for the
    /// inverted variables, `inverted`.
    pub fn set_fields(&self, normal: &[u8], inverted: &[u8]) {
        store(self.normal, normal);
        store(self.inverted, inverted);
    }

    /// Sets the normal variables to `normal` and the inverted ones to its
    /// complement, ready for `CcmSendSrdo`.
    pub fn set_data(&self, normal: &[u8]) {
        let mut inv = [0u8; 8];
        for (i, b) in inv.iter_mut().zip(normal) {
            *i = !b;
        }
        self.set_fields(normal, inv.get(..normal.len()).unwrap_or(&[]));
    }

    /// The normal variables as frame bytes.
    pub fn normal_data(&self) -> [u8; DATA_LEN] {
        self.fields().normal()
    }

    /// The inverted variables as frame bytes.
    pub fn inverted_data(&self) -> [u8; DATA_LEN] {
        self.fields().inverted()
    }

    /// The mapped variables, readable while the stack is borrowed (inside
    /// the callbacks of [`Device::process`]).
    pub fn fields(&self) -> Fields {
        Fields {
            normal: self.normal,
            inverted: self.inverted,
        }
    }

    /// `CcmSendSrdo(0x1301)` at the bus time; the queued events go to
    /// `handle`.
    pub fn send(&mut self, handle: impl FnMut(&mut Stack, Event)) -> CopResult {
        let now: Ticks = self.port.bus().now();
        let r = self.stack.send_srdo(&mut self.port, SRDO, now);
        self.drain(handle);
        r
    }

    /// The status byte of SRDO 1 (`CcmGetSrdoState`).
    pub fn status(&self) -> u8 {
        self.stack.srdo().get_state(SRDO).unwrap_or(0xFF)
    }

    /// `CcmSetSrdoState` for SRDO 1.
    pub fn set_status(&mut self, v: u8) -> CopResult {
        self.stack.srdo_mut().set_state(SRDO, v)
    }
}

/// The mapped variables of a device (see [`Device::fields`]).
#[derive(Clone, Copy, Debug)]
pub struct Fields {
    normal: &'static [AtomicU8],
    inverted: &'static [AtomicU8],
}

impl Fields {
    /// The normal variables as frame bytes (the rogue's fill 2 of them).
    pub fn normal(&self) -> [u8; DATA_LEN] {
        load(self.normal)
    }

    /// The inverted variables as frame bytes.
    pub fn inverted(&self) -> [u8; DATA_LEN] {
        load(self.inverted)
    }
}

/// The answer of an application written as manual 2.9.1 / 2.9.2 ask:
/// inside `AppSrdoEvent` bits 4-5 := 11; inside `AppSrdoError` bits 4-5 :=
/// 11 and bits 6-7 toggled from 01 to 10. Returns the status byte the
/// application found when the callback started.
pub fn answer_as_manual(stack: &mut Stack, e: &Event) -> Option<u8> {
    let idx = match *e {
        Event::SrdoEvent(idx) => idx,
        Event::SrdoError(idx, code) if code != CopKernel::SrdoNotHandledInApp => idx,
        _ => return None,
    };
    let st = stack.srdo().get_state(idx).ok()?;
    let new = match *e {
        Event::SrdoError(..) if st & 0x30 == 0x10 => (st | 0x30) ^ 0xC0,
        _ => st | 0x30,
    };
    let _ = stack.srdo_mut().set_state(idx, new);
    Some(st)
}

/// The dictionary of a role (for callers that build their own stack).
pub fn dictionary(role: Role) -> Result<ObjectDictionary, CopKernel> {
    match role {
        Role::Producer => producer::od(),
        Role::Consumer => consumer::od(),
        Role::Rogue => rogue::od(),
    }
}
