//! Pointer parameters of the exported functions: every conversion of a C
//! pointer into a Rust reference or slice, in one place.
//!
//! Each helper returns `Err(kCopInvalidParam)` for NULL, the code the SYS
//! TEC API gives for a missing parameter, so an exported function checks a
//! pointer and converts it in one step, and the `?`-style macro
//! [`c_try`] returns the code to the caller. The helpers are `unsafe`: the
//! exported function passes on its own contract (its `# Safety` section),
//! once per call, with a `SAFETY` comment.

use core::ffi::c_void;
use core::ptr::NonNull;
use core::sync::atomic::AtomicU8;

use crate::error::{CopKernel, CopResult};
use crate::od::ObdEntry;

/// Evaluates a `Result<T, CopKernel>`; on `Err` returns its `tCopKernel`
/// from the exported function.
macro_rules! c_try {
    ($e:expr) => {
        match $e {
            Ok(v) => v,
            Err(e) => return crate::error::CopKernel::code(e),
        }
    };
}
pub(crate) use c_try;

/// A copy of the structure `p` points to.
///
/// # Safety
/// `p` must be NULL or point to a valid, initialised `T`.
#[inline]
pub(crate) unsafe fn read<T: Copy>(p: *const T) -> Result<T, CopKernel> {
    if p.is_null() {
        return Err(CopKernel::InvalidParam);
    }
    // SAFETY: not NULL; valid by the caller's contract.
    Ok(unsafe { *p })
}

/// A result parameter: a pointer checked for NULL, written when the call
/// has its result (and read, for in-out parameters such as `pSize_p`).
/// It keeps the raw pointer instead of a reference, because the
/// application may look at the same variable from a callback that runs
/// during the call.
pub(crate) struct Out<T: Copy>(NonNull<T>);

impl<T: Copy> Out<T> {
    /// The value the caller put there (in-out parameters).
    #[inline]
    pub(crate) fn get(&self) -> T {
        // SAFETY: `out`'s contract: valid for reads and writes of a T for
        // the duration of the exported call that made this.
        unsafe { self.0.as_ptr().read() }
    }

    /// Writes the result.
    #[inline]
    pub(crate) fn set(self, v: T) {
        // SAFETY: as in `get`.
        unsafe { self.0.as_ptr().write(v) }
    }

    /// The code of a call that gives a value: on success the value is
    /// stored here and kCopSuccessful returned; otherwise the call's code,
    /// with nothing stored.
    #[inline]
    pub(crate) fn give(self, r: Result<CopResult<T>, CopKernel>) -> u32 {
        match r {
            Ok(Ok(v)) => {
                self.set(v);
                CopKernel::Successful.code()
            }
            Ok(Err(e)) | Err(e) => e.code(),
        }
    }
}

/// A result parameter ([`Out`]).
///
/// # Safety
/// `p` must be NULL or valid for reads and writes of a `T` until the
/// exported function that calls this returns.
#[inline]
pub(crate) unsafe fn out<T: Copy>(p: *mut T) -> Result<Out<T>, CopKernel> {
    NonNull::new(p).map(Out).ok_or(CopKernel::InvalidParam)
}

/// `n` elements at `p`; NULL is refused whatever `n` is.
///
/// # Safety
/// `p` must be NULL or valid for reads of `n` elements for `'a`.
#[inline]
pub(crate) unsafe fn slice<'a, T>(p: *const T, n: usize) -> Result<&'a [T], CopKernel> {
    if p.is_null() {
        return Err(CopKernel::InvalidParam);
    }
    // SAFETY: not NULL; valid for n elements by the caller's contract.
    Ok(unsafe { core::slice::from_raw_parts(p, n) })
}

/// `n` elements at `p`; NULL stands for an empty table when `n` is 0.
///
/// # Safety
/// As [`slice`] when `n` is not 0.
#[inline]
pub(crate) unsafe fn slice_or_empty<'a, T>(p: *const T, n: usize) -> Result<&'a [T], CopKernel> {
    if n == 0 {
        return Ok(&[]);
    }
    // SAFETY: the caller's contract, passed on.
    unsafe { slice(p, n) }
}

/// `n` bytes at `p`, for writing into; NULL is refused.
///
/// # Safety
/// `p` must be NULL or valid for writes of `n` bytes that nothing else
/// accesses while the slice lives.
#[inline]
pub(crate) unsafe fn bytes_mut<'a>(p: *mut c_void, n: usize) -> Result<&'a mut [u8], CopKernel> {
    if p.is_null() {
        return Err(CopKernel::InvalidParam);
    }
    // SAFETY: not NULL; valid for n bytes by the caller's contract.
    Ok(unsafe { core::slice::from_raw_parts_mut(p as *mut u8, n) })
}

/// The address of a variable the call only compares, never dereferences
/// (`CcmSignalVar`); NULL is refused.
#[inline]
pub(crate) fn address(p: *mut c_void) -> Result<usize, CopKernel> {
    if p.is_null() {
        return Err(CopKernel::InvalidParam);
    }
    Ok(p as usize)
}

/// An application variable the stack keeps using after the call (SRDO
/// variable fields, static PDO data, SDO client buffers), as a shared byte
/// view; NULL is refused.
///
/// # Safety
/// `p` must be NULL or valid for `len` bytes for as long as the stack
/// uses them (the rest of the program, or the transfer).
#[inline]
pub(crate) unsafe fn lent_bytes(
    p: *mut c_void,
    len: usize,
) -> Result<&'static [AtomicU8], CopKernel> {
    if p.is_null() {
        return Err(CopKernel::InvalidParam);
    }
    // SAFETY: not NULL; the caller's contract, passed on.
    Ok(unsafe { static_bytes(p, len) })
}

/// [`lent_bytes`] for a pointer the caller has checked (the dynamic OD's
/// process image).
///
/// # Safety
/// `p` must be valid for `len` bytes for as long as the stack uses them.
pub(crate) unsafe fn static_bytes(p: *mut c_void, len: usize) -> &'static [AtomicU8] {
    // SAFETY: guaranteed by the caller; AtomicU8 has the layout of u8.
    unsafe { core::slice::from_raw_parts(p as *const AtomicU8, len) }
}

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
