//! The C ABI: every `extern "C"` item, every raw pointer and every `unsafe`
//! block of the library lives below this module.

#![allow(non_snake_case, non_camel_case_types, non_upper_case_globals)]

pub mod ccm;
pub mod driver;
pub mod dynod;
pub mod global;
pub mod master;

#[cfg(test)]
mod od_callback_tests;
pub mod pdo;
mod ptr;
pub mod services;
pub mod srdo;
pub mod stack_callbacks;
pub mod types;

include!(concat!(env!("OUT_DIR"), "/abi_symbol.rs"));

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
