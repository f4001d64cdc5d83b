//! Helpers for declaring a dictionary in Rust: variables as `static`
//! arrays of `AtomicU8` (so the stack and the application can share them
//! without `unsafe`), default values in CPU byte order.
//!
//! ```
//! use core::sync::atomic::AtomicU8;
//! use cop::od::{decl, Access, DataType, ObdEntry, ObdSubEntry};
//!
//! static PRODUCER_HB: [AtomicU8; 2] = decl::zeroed();
//! static PRODUCER_HB_DEF: [u8; 2] = 100u16.to_ne_bytes();
//! static SUBS_1017: [ObdSubEntry; 1] =
//!     [ObdSubEntry::ram(0, DataType::UInt16, Access::SRW, &PRODUCER_HB, Some(&PRODUCER_HB_DEF))];
//! static GENERIC: [ObdEntry; 1] = [ObdEntry::new(0x1017, &SUBS_1017, None)];
//! ```

use core::sync::atomic::{AtomicU8, Ordering};

/// A variable of `N` bytes, all zero.
pub const fn zeroed<const N: usize>() -> [AtomicU8; N] {
    [const { AtomicU8::new(0) }; N]
}

/// A variable of `N` bytes with an initial content.
// Indexing is bounded by the loop condition; `get_mut` is not usable in a
// const fn.
#[allow(clippy::indexing_slicing)]
pub const fn init<const N: usize>(v: [u8; N]) -> [AtomicU8; N] {
    let mut a = zeroed::<N>();
    let mut i = 0;
    while i < N {
        a[i] = AtomicU8::new(v[i]);
        i += 1;
    }
    a
}

/// Reads a variable's bytes (native order) into an array.
pub fn get<const N: usize>(v: &[AtomicU8; N]) -> [u8; N] {
    let mut out = [0u8; N];
    for (o, b) in out.iter_mut().zip(v.iter()) {
        *o = b.load(Ordering::Relaxed);
    }
    out
}

/// Sets a variable's bytes (native order).
pub fn set<const N: usize>(v: &[AtomicU8; N], bytes: [u8; N]) {
    for (b, x) in v.iter().zip(bytes) {
        b.store(x, Ordering::Relaxed);
    }
}
