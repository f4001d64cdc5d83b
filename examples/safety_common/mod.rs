//! What the two Rust safety examples share: a CAN driver as a HAL would
//! offer it (an `embedded_can::nb::Can` over a node of the simulated bus),
//! the dictionaries of the sensor and the actuator, and a node built from
//! them through the `cop::port::embedded` adapter.

use core::sync::atomic::{AtomicU8, Ordering};

use cop::CopKernel;
use cop::ccm::{NmtCommand, Stack};
use cop::event::Event;
use cop::od::{Access, ByteOrder, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
use cop::port::embedded::{NbPort, PlainFrame, TickFn};
use cop::port::{CanFrame, CanId, CanPort, Priority, Ticks};
use cop::sim::{SimBus, SimPort};
use embedded_can::{ExtendedId, Frame, Id, StandardId};

/// SRDO 1 of both nodes: COB-IDs of node 1 (CiA 304 predefined set).
pub const SRDO: u16 = 0x1301;
/// SCT of the actuator and refresh time of the sensor, ms.
pub const SCT_MS: u16 = 50;
/// SRVT, ms.
pub const SRVT_MS: u8 = 20;

// ---------------------------------------------------------------------
// The driver: a frame type and an nb::Can, as a HAL crate has them.

/// A classic CAN frame of the "HAL" (the adapter's plain frame type).
pub type HalFrame = PlainFrame;

/// The driver's error: only "mailbox full" happens on the simulated bus.
#[derive(Debug)]
pub struct HalError;

impl embedded_can::Error for HalError {
    fn kind(&self) -> embedded_can::ErrorKind {
        embedded_can::ErrorKind::Overrun
    }
}

/// One controller on the simulated bus, with the embedded-can interface.
pub struct HalCan(SimPort);

impl embedded_can::nb::Can for HalCan {
    type Frame = HalFrame;
    type Error = HalError;

    fn transmit(&mut self, frame: &HalFrame) -> nb::Result<Option<HalFrame>, HalError> {
        let id = match frame.id() {
            Id::Standard(s) => CanId::std_masked(s.as_raw()),
            Id::Extended(e) => CanId::ext(e.as_raw()).ok_or(nb::Error::Other(HalError))?,
        };
        let f = if frame.is_remote_frame() {
            CanFrame::remote(id, frame.dlc() as u8)
        } else {
            CanFrame::new(id, frame.data())
        };
        self.0
            .send(&f, Priority::High)
            .map_err(|_| nb::Error::WouldBlock)?;
        Ok(None)
    }

    fn receive(&mut self) -> nb::Result<HalFrame, HalError> {
        let rx = self.0.receive().ok_or(nb::Error::WouldBlock)?;
        let f = rx.frame;
        let id: Id = if f.id.is_extended() {
            ExtendedId::new(f.id.id())
                .ok_or(nb::Error::Other(HalError))?
                .into()
        } else {
            StandardId::new(f.id.id() as u16)
                .ok_or(nb::Error::Other(HalError))?
                .into()
        };
        let hal = if f.rtr {
            HalFrame::new_remote(id, f.len.into())
        } else {
            HalFrame::new(id, f.payload())
        };
        hal.ok_or(nb::Error::Other(HalError))
    }
}

// ---------------------------------------------------------------------
// The dictionaries: SRDO 1 maps two UNSIGNED16 process values, each with
// its inverted copy (0x6200/0x6300: E-stop, 1 = released; 0x6201/0x6301:
// safe speed limit in mm/s). DLC 4.

/// A part of a static byte array (const context).
const fn part(buf: &'static [AtomicU8], from: usize) -> &'static [AtomicU8] {
    buf.split_at(from).1.split_at(2).0
}

macro_rules! safety_od {
    ($m:ident, $dir:expr) => {
        pub mod $m {
            use super::*;

            /// The normal process values (E-stop, speed limit).
            pub static NORMAL: [AtomicU8; 4] = decl::zeroed();
            /// Their inverted copies.
            pub static INVERTED: [AtomicU8; 4] = decl::zeroed();

            const fn var(buf: &'static [AtomicU8], at: usize) -> [ObdSubEntry; 2] {
                [
                    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                    ObdSubEntry::ram(1, DataType::UInt16, Access::PRW, part(buf, at), Some(&[0, 0])),
                ]
            }
            cop::obd_create_srdo_gfc_param!(pub mod gfc);
            cop::obd_create_srdo_commu!(
                pub mod commu, 0x1301, $dir, crate::common::SCT_MS, crate::common::SRVT_MS, 0x101, 0x102
            );
            cop::obd_create_srdo_mapp!(
                pub mod mapp, 0x1381, [0x6200_0110, 0x6300_0110, 0x6201_0110, 0x6301_0110]
            );
            cop::obd_create_srdo_cfg_valid!(pub mod cfg_valid);
            cop::obd_create_srdo_crc!(pub mod crcs, [0]);

            static SAFETY: [ObdEntry; 5] = cop::srdo_obd_entries![gfc, commu, mapp, cfg_valid, crcs];
            static E_STOP: [ObdSubEntry; 2] = var(&NORMAL, 0);
            static SPEED: [ObdSubEntry; 2] = var(&NORMAL, 2);
            static E_STOP_INV: [ObdSubEntry; 2] = var(&INVERTED, 0);
            static SPEED_INV: [ObdSubEntry; 2] = var(&INVERTED, 2);
            static DEVICE: [ObdEntry; 4] = [
                ObdEntry::new(0x6200, &E_STOP, None),
                ObdEntry::new(0x6201, &SPEED, None),
                ObdEntry::new(0x6300, &E_STOP_INV, None),
                ObdEntry::new(0x6301, &SPEED_INV, None),
            ];

            /// The dictionary (communication part, manufacturer part,
            /// device part).
            pub fn od() -> Result<ObjectDictionary, CopKernel> {
                ObjectDictionary::new(&SAFETY, &[], &DEVICE).map_err(|e| e.code)
            }
        }
    };
}

safety_od!(sensor_od, 1);
safety_od!(actuator_od, 2);

/// The process values as frame bytes (little-endian UNSIGNED16, CiA 301).
pub fn values(field: &[AtomicU8; 4]) -> (u16, u16) {
    let b: Vec<u8> = field.iter().map(|v| v.load(Ordering::Relaxed)).collect();
    (
        u16::from_ne_bytes([b[0], b[1]]),
        u16::from_ne_bytes([b[2], b[3]]),
    )
}

/// Sets the process values and their complement (the application's job
/// before CcmSendSrdo, CiA 304).
pub fn set_values(normal: &[AtomicU8; 4], inverted: &[AtomicU8; 4], e_stop: u16, speed: u16) {
    let bytes = [e_stop.to_ne_bytes(), speed.to_ne_bytes()].concat();
    for ((n, i), b) in normal.iter().zip(inverted).zip(bytes) {
        n.store(b, Ordering::Relaxed);
        i.store(!b, Ordering::Relaxed);
    }
}

// ---------------------------------------------------------------------

/// The port type of a node: the adapter over the HAL driver, the bus time
/// as its tick function.
pub type Port = NbPort<HalCan, TickFn<Box<dyn Fn() -> u32>>>;

/// A node: the stack and its port.
pub struct Node {
    pub stack: Stack,
    pub port: Port,
    bus: SimBus,
}

impl Node {
    /// A node with `od` and `node_id` on `bus`, configured as a tool does
    /// (CRC into 0x13FF, 0xA5 into 0x13FE) and connected.
    pub fn new(bus: &SimBus, od: ObjectDictionary, node_id: u8) -> Result<Node, String> {
        let clock_bus = bus.clone();
        let clock: TickFn<Box<dyn Fn() -> u32>> =
            TickFn::ticks(Box::new(move || clock_bus.now().0));
        let mut node = Node {
            stack: Stack::new(od, node_id).map_err(|e| format!("{e:?}"))?,
            port: NbPort::new(HalCan(bus.attach(16)), clock),
            bus: bus.clone(),
        };
        node.stack.connect().map_err(|e| format!("{e:?}"))?;
        node.process(|_, _| {});
        node.write(0x1300, 0, &[1])?; // GFC on
        let crc = node
            .stack
            .srdo()
            .calc_crc(node.stack.od(), SRDO)
            .map_err(|e| format!("{e:?}"))?;
        node.write(0x13FF, 1, &crc.to_le_bytes())?;
        node.write(0x13FE, 0, &[0xA5])?;
        Ok(node)
    }

    fn now(&self) -> Ticks {
        self.bus.now()
    }

    /// CcmWriteObject in CANopen byte order.
    pub fn write(&mut self, index: u16, sub: u8, data: &[u8]) -> Result<(), String> {
        let now = self.now();
        self.stack
            .write_object(index, sub, ByteOrder::Wire, data, now)
            .map_err(|e| format!("write {index:04X}/{sub}: {e:?}"))
    }

    /// NMT start (as from an NMT master).
    pub fn start(&mut self) -> Result<(), String> {
        self.stack
            .exec_command(NmtCommand::StartRemoteNode)
            .map_err(|e| format!("{e:?}"))?;
        self.process(|_, _| {});
        Ok(())
    }

    /// One processing cycle (CcmProcess), each event to `handle`.
    pub fn process(&mut self, handle: impl FnMut(&mut Stack, Event)) {
        let now = self.now();
        self.stack.process(&mut self.port, now, handle);
    }

    /// CcmSendSrdo(0x1301); the events it queues go to `handle`.
    pub fn send_srdo(
        &mut self,
        mut handle: impl FnMut(&mut Stack, Event),
    ) -> Result<(), CopKernel> {
        let now = self.now();
        let r = self.stack.send_srdo(&mut self.port, SRDO, now);
        while let Some(e) = self.stack.drain(&mut self.port, now) {
            handle(&mut self.stack, e);
        }
        r
    }

    /// CcmSendGfc (the actuator example's sensor sends one).
    #[allow(dead_code)]
    pub fn send_gfc(&mut self) -> Result<(), CopKernel> {
        let state = self.stack.nmt_state();
        let Node { stack, port, .. } = self;
        stack.srdo_mut().send_gfc(port, state)
    }
}

/// The status handshake of manual 2.9.1 / 2.9.2 inside the callbacks: the
/// application marks a received pair or an error as processed.
pub fn acknowledge(stack: &mut Stack, e: &Event) {
    let idx = match *e {
        Event::SrdoEvent(idx) => idx,
        Event::SrdoError(idx, code) if code != CopKernel::SrdoNotHandledInApp => idx,
        _ => return,
    };
    if let Ok(st) = stack.srdo().get_state(idx) {
        let new = match *e {
            Event::SrdoError(..) if st & 0x30 == 0x10 => (st | 0x30) ^ 0xC0,
            _ => st | 0x30,
        };
        let _ = stack.srdo_mut().set_state(idx, new);
    }
}
