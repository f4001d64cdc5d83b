//! A CANopen device with the CiA 304 / EN 50325-5 safety extension (SRDO,
//! GFC, safety configuration), written in Rust and exported with the C API
//! of the SYS TEC CANopen stack (CCM layer) so that an existing C
//! application links it instead of the original.
//!
//! Layers, from the bottom (ARCHITECTURE.md has the rules and the path of
//! a frame through them):
//! * [`wire`]: frame encoding and decoding per protocol, no state;
//! * [`od`]: the object dictionary, with its table format shared with C
//!   ([`od::table`]);
//! * the services, each driven with the current time and received frames:
//!   [`nmt`] (slave, master, life guarding), [`heartbeat`] (producer,
//!   consumer), [`emcy`] (producer, consumer), [`sync`] (producer), [`sdo`]
//!   (server, client), [`pdo`] (with the SYNC consumer), [`srdo`] (SRDO and
//!   GFC), [`store`];
//! * [`ccm`]: the stack that ties them together (the CCM layer);
//! * [`port`]: the CAN driver and clock contract; [`event`]: what the stack
//!   reports and the queue that orders it;
//! * `ffi`: the C edge, the only module with exported functions and C
//!   names; nothing below it imports it.
//!
//! The library has no heap; capacities are build-time constants
//! ([`config`]).
//!
//! # A safety sensor in a few lines
//!
//! A dictionary declared in Rust (SRDO 1 maps one UNSIGNED16 value and its
//! inverted copy), a [`ccm::Stack`] on the simulated bus (host builds,
//! feature `std`; on a target the port is your CAN driver, for example
//! through [`port`]`::embedded` with the feature `embedded-can`), the
//! configuration a tool would write, NMT start and one SRDO:
//!
//! ```
//! # #[cfg(feature = "std")] {
//! use core::sync::atomic::{AtomicU8, Ordering};
//! use cop::ccm::{NmtCommand, Stack};
//! use cop::od::{Access, ByteOrder, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
//! use cop::sim::SimBus;
//!
//! static VALUE: [AtomicU8; 2] = decl::zeroed();
//! static VALUE_INV: [AtomicU8; 2] = decl::zeroed();
//! mod srdo {
//!     cop::obd_create_srdo_gfc_param!(pub mod gfc);
//!     // SRDO 1: transmit, refresh time 50 ms, SRVT 20 ms, COB-IDs 0x101/0x102
//!     cop::obd_create_srdo_commu!(pub mod commu, 0x1301, 1, 50, 20, 0x101, 0x102);
//!     cop::obd_create_srdo_mapp!(pub mod mapp, 0x1381, [0x6200_0110, 0x6300_0110]);
//!     cop::obd_create_srdo_cfg_valid!(pub mod valid);
//!     cop::obd_create_srdo_crc!(pub mod crc, [0]);
//! }
//! static SAFETY: [ObdEntry; 5] =
//!     cop::srdo_obd_entries![srdo::gfc, srdo::commu, srdo::mapp, srdo::valid, srdo::crc];
//! static V: [ObdSubEntry; 2] = [
//!     ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
//!     ObdSubEntry::ram(1, DataType::UInt16, Access::PRW, &VALUE, Some(&[0, 0])),
//! ];
//! static V_INV: [ObdSubEntry; 2] = [
//!     ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
//!     ObdSubEntry::ram(1, DataType::UInt16, Access::PRW, &VALUE_INV, Some(&[0, 0])),
//! ];
//! static DEVICE: [ObdEntry; 2] = [ObdEntry::new(0x6200, &V, None), ObdEntry::new(0x6300, &V_INV, None)];
//!
//! let bus = SimBus::new();
//! let mut port = bus.attach(8);
//! let od = ObjectDictionary::new(&SAFETY, &[], &DEVICE).map_err(|e| e.code)?;
//! let mut stack = Stack::new(od, 1)?; // CcmInitCANopen, node-ID 1
//! stack.connect()?; // CcmConnectToNet: boot-up, PRE-OPERATIONAL
//! stack.process(&mut port, bus.now(), |_, event| println!("{event:?}"));
//!
//! // with static mapping (SRDO_USE_STATIC_MAPPING) the variables are one field each
//! #[cfg(feature = "srdo-static-mapping")]
//! {
//!     let od = *stack.od();
//!     stack.srdo_mut().static_define_var_fields(&od, 0x1301, &VALUE, &VALUE_INV)?;
//! }
//! // the configuration of manual 2.9.5: CRC into 0x13FF, 0xA5 into 0x13FE
//! let crc = stack.srdo().calc_crc(stack.od(), 0x1301)?;
//! stack.write_object(0x13FF, 1, ByteOrder::Wire, &crc.to_le_bytes(), bus.now()).map_err(|e| e.kernel)?;
//! stack.write_object(0x13FE, 0, ByteOrder::Wire, &[0xA5], bus.now()).map_err(|e| e.kernel)?;
//! stack.exec_command(NmtCommand::StartRemoteNode)?;
//! stack.process(&mut port, bus.now(), |_, _| {});
//!
//! bus.advance_ms(1); // past the first-send delay (0.5 ms per node-ID)
//! for (v, inv) in VALUE.iter().zip(&VALUE_INV) {
//!     v.store(0x5A, Ordering::Relaxed); // 0x5A5A in either byte order
//!     inv.store(!0x5A, Ordering::Relaxed);
//! }
//! stack.send_srdo(&mut port, 0x1301, bus.now())?; // CcmSendSrdo
//! let trace = bus.trace();
//! assert_eq!(&trace[trace.len() - 2..], ["  can0  101   [2]  5A 5A", "  can0  102   [2]  A5 A5"]);
//! # }
//! # Ok::<(), cop::CopKernel>(())
//! ```

#![cfg_attr(not(any(test, feature = "std")), no_std)]
// `unsafe` is allowed in two places only, each block with a `SAFETY`
// comment: `ffi` (the C edge) and `od::table` (the dictionary's table
// format, whose pointers are the C application's statics). scripts/layers.sh
// (lint stage) checks which layer imports which.
#![deny(unsafe_code)]
#![warn(missing_docs)]
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::indexing_slicing
    )
)]

#[macro_use]
mod cenum;

pub mod ccm;
pub mod config;
pub mod emcy;
pub mod error;
pub mod event;
pub mod heartbeat;
pub mod nmt;
pub mod od;
pub mod pdo;
pub mod port;
pub mod sdo;
pub mod srdo;
pub mod store;
pub mod sync;
pub mod wire;

#[cfg(any(test, feature = "std"))]
pub mod sim;
#[cfg(any(test, feature = "std"))]
pub mod testod;

#[allow(unsafe_code)]
pub mod ffi;

pub use error::{CopKernel, CopResult, OdError, OdResult, SdoAbort};
