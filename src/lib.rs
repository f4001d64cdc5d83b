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
