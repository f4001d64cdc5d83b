//! The C ABI: every exported function, every C name and every conversion
//! of a C pointer lives below this module (the dictionary's table format,
//! which C and Rust share, is [`crate::od::table`]).
//!
//! Inside, the imports go one way: the exported functions ([`ccm`],
//! [`master`], [`pdo`], [`services`], [`srdo`], [`dynod`]) use the instance
//! registry ([`global`]), the callback adapter ([`callbacks`]), the pointer
//! helpers (`ptr`) and the driver ([`driver`]); the registry hands events
//! to the callback adapter; neither imports an exported function.

#![allow(non_snake_case, non_camel_case_types, non_upper_case_globals)]
// In a multi-instance build every module function (`SrdoSend`, ...) reads
// the handle its instance pointer points to (`instance::mco_enter!`), the
// C contract of `MCO_DECL_INSTANCE_PTR_`; the functions keep the safe
// Rust signature they have in a single-instance build.
#![cfg_attr(multi_instance, allow(clippy::not_unsafe_ptr_arg_deref))]

pub mod ami;
pub mod callbacks;
pub mod ccm;
pub mod cob;
pub mod driver;
pub mod dynod;
pub mod global;
pub mod instance;
pub mod master;

#[cfg(test)]
mod od_callback_tests;
pub mod pdo;
mod ptr;
pub mod services;
pub mod srdo;
#[cfg(test)]
mod srdo_tests;
pub mod stack_callbacks;
pub mod tables;
pub mod types;

include!(concat!(env!("OUT_DIR"), "/abi_symbol.rs"));

/// Instances: `COP_MAX_INSTANCES` of `copcfg.h` in a multi-instance build
/// (each `Ccm*` call names its instance, [`instance`]).
#[cfg(multi_instance)]
pub const MAX_INSTANCES: usize = crate::config::COP_MAX_INSTANCES;
/// Instances of a single-instance build: one on a target. Simulation builds
/// (`sim-instances`, part of `std`) keep several so that a simulation can
/// run more than one node in one program; the harness selects the node the
/// next `Ccm*` calls address with `CopSimSelectInstance`.
#[cfg(all(not(multi_instance), feature = "sim-instances"))]
pub const MAX_INSTANCES: usize = 8;
/// Instances of a single-instance build: one on a target.
#[cfg(all(not(multi_instance), not(feature = "sim-instances")))]
pub const MAX_INSTANCES: usize = 1;

#[cfg(not(any(test, feature = "std")))]
#[panic_handler]
fn panic(_info: &core::panic::PanicInfo) -> ! {
    // No code path of the library panics (clippy denies unwrap, expect,
    // panic and unchecked indexing); this handler exists because a no_std
    // staticlib needs one. It parks the CPU so that a watchdog resets it.
    loop {
        core::hint::spin_loop();
    }
}
