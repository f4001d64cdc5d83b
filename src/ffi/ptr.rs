//! Pointer parameters of the exported functions: every conversion of a C
//! pointer into a Rust reference or slice, in one place.
//!
//! Each helper returns `Err(kCopInvalidParam)` for NULL, the code the SYS
//! TEC API gives for a missing parameter, so an exported function checks a
//! pointer and converts it in one step, and the `?`-style macro
//! [`c_try`] returns the code to the caller. The helpers are `unsafe`: the
//! exported function passes on its own contract (its `# Safety` section),
//! once per call, with a `SAFETY` comment.

use crate::od::ObdEntry;

/// Reads a C table that ends with an index of 0xFFFF (as objdef.h emits
/// them) into a slice without the end marker.
///
/// # Safety
/// `table` must point to a static array of `ObdEntry` terminated by an entry
/// whose index is 0xFFFF.
pub(crate) unsafe fn c_table(table: *const ObdEntry) -> &'static [ObdEntry] {
    if table.is_null() {
        return &[];
    }
    let mut n = 0usize;
    // SAFETY: the caller guarantees an end marker; we stop there.
    while unsafe { (*table.add(n)).m_wIndex } != 0xFFFF {
        n += 1;
    }
    // SAFETY: the first n entries were just read and are valid statics.
    unsafe { core::slice::from_raw_parts(table, n) }
}
