//! A CANopen device with the CiA 304 / EN 50325-5 safety extension (SRDO,
//! GFC, safety configuration), written in Rust and exported with the C API
//! of the SYS TEC CANopen stack (CCM layer) so that an existing C
//! application links it instead of the original.
//!
//! Layout:
//! * [`wire`]: frame encoding and decoding per protocol, no state;
//! * [`od`]: the object dictionary;
//! * [`nmt`], [`heartbeat`], [`emcy`], [`sdo`], [`srdo`], [`pdo`], [`hbc`],
//!   [`nmtm`], [`emcc`], [`lgs`], [`syncp`], [`store`]: protocol state
//!   machines, each driven with the current time and received frames;
//! * [`ccm`]: the stack that ties them together (the CCM layer);
//! * [`port`]: the CAN driver and clock contract;
//! * `ffi`: the only module with `extern "C"`, C names and `unsafe`.
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

pub mod ccm;
pub mod config;
pub mod emcc;
pub mod emcy;
pub mod error;
pub mod event;
pub mod hbc;
pub mod heartbeat;
pub mod lgs;
pub mod nmtm;
pub mod od;
pub mod pdo;
pub mod port;
pub mod sdo;
pub mod srdo;
pub mod store;
pub mod syncp;
pub mod wire;

#[cfg(any(test, feature = "std"))]
pub mod sim;
#[cfg(any(test, feature = "std"))]
pub mod testod;

#[allow(unsafe_code)]
pub mod ffi;

pub use error::{CopKernel, CopResult, OdError, SdoAbort};
