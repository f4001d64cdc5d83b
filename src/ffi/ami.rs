//! `ami.h`: reading and writing values of a given width at any address,
//! in CANopen byte order (little-endian, CiA 301 7.1.2), whatever the
//! target's byte order and alignment. `AmiSetByte` / `AmiGetByte` are
//! macros in `include/ami.h`.

use core::ffi::c_void;

use super::types::{DWORD, QWORD, WORD};

/// Writes `b` to `n` bytes at `p`.
///
/// # Safety
/// `p` must be valid for writes of `N` bytes.
#[inline]
unsafe fn put<const N: usize>(p: *mut c_void, b: [u8; N]) {
    if p.is_null() {
        return;
    }
    // SAFETY: the caller's contract; byte copies need no alignment.
    unsafe { core::ptr::copy_nonoverlapping(b.as_ptr(), p as *mut u8, N) }
}

/// Reads `N` bytes at `p` (zeros for NULL).
///
/// # Safety
/// `p` must be valid for reads of `N` bytes.
#[inline]
unsafe fn get<const N: usize>(p: *const c_void) -> [u8; N] {
    let mut b = [0u8; N];
    if !p.is_null() {
        // SAFETY: the caller's contract; byte copies need no alignment.
        unsafe { core::ptr::copy_nonoverlapping(p as *const u8, b.as_mut_ptr(), N) }
    }
    b
}

/// Takes the low `N` bytes of a little-endian 8-byte array.
fn low<const N: usize>(v: u64) -> [u8; N] {
    let all = v.to_le_bytes();
    let mut b = [0u8; N];
    for (d, s) in b.iter_mut().zip(all.iter()) {
        *d = *s;
    }
    b
}

/// Little-endian bytes to a value.
fn value<const N: usize>(b: [u8; N]) -> u64 {
    let mut all = [0u8; 8];
    for (d, s) in all.iter_mut().zip(b.iter()) {
        *d = *s;
    }
    u64::from_le_bytes(all)
}

macro_rules! ami_pair {
    ($set:ident, $get:ident, $ty:ty, $n:literal, $doc:literal) => {
        #[doc = concat!("`", stringify!($set), "`: stores the low ", $doc, " at `pAddr_p` (little-endian; NULL is ignored).")]
        ///
        /// # Safety
        #[doc = concat!("`pAddr_p` must be NULL or valid for writes of ", stringify!($n), " bytes.")]
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $set(pAddr_p: *mut c_void, Val_p: $ty) {
            // SAFETY: the caller's contract, passed on.
            unsafe { put::<$n>(pAddr_p, low::<$n>(u64::from(Val_p))) }
        }

        #[doc = concat!("`", stringify!($get), "`: reads ", $doc, " at `pAddr_p` (little-endian; 0 for NULL).")]
        ///
        /// # Safety
        #[doc = concat!("`pAddr_p` must be NULL or valid for reads of ", stringify!($n), " bytes.")]
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $get(pAddr_p: *mut c_void) -> $ty {
            // SAFETY: the caller's contract, passed on.
            let v = value::<$n>(unsafe { get::<$n>(pAddr_p) });
            <$ty>::try_from(v).unwrap_or(<$ty>::MAX)
        }
    };
}

ami_pair!(AmiSetWord, AmiGetWord, WORD, 2, "2 bytes");
ami_pair!(AmiSetDword, AmiGetDword, DWORD, 4, "4 bytes");
ami_pair!(AmiSetDword24, AmiGetDword24, DWORD, 3, "3 bytes");
ami_pair!(AmiSetQword40, AmiGetQword40, QWORD, 5, "5 bytes");
ami_pair!(AmiSetQword48, AmiGetQword48, QWORD, 6, "6 bytes");
ami_pair!(AmiSetQword56, AmiGetQword56, QWORD, 7, "7 bytes");
ami_pair!(AmiSetQword64, AmiGetQword64, QWORD, 8, "8 bytes");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn little_endian_at_any_alignment() {
        // CiA 301 7.1.2: multi-byte values are sent least significant byte first.
        let mut buf = [0u8; 10];
        let p = buf.as_mut_ptr().wrapping_add(1) as *mut c_void;
        // SAFETY: 9 bytes remain after offset 1.
        unsafe {
            AmiSetWord(p, 0x1234);
            assert_eq!(buf[1..3], [0x34, 0x12]);
            assert_eq!(AmiGetWord(p), 0x1234);
            AmiSetDword24(p, 0x00AB_CDEF);
            assert_eq!(buf[1..5], [0xEF, 0xCD, 0xAB, 0x00]);
            AmiSetDword(p, 0x0102_0304);
            assert_eq!(AmiGetDword(p), 0x0102_0304);
            assert_eq!(buf[1..5], [4, 3, 2, 1]);
            AmiSetQword40(p, 0x11_2233_4455);
            assert_eq!(buf[1..6], [0x55, 0x44, 0x33, 0x22, 0x11]);
            assert_eq!(AmiGetQword40(p), 0x11_2233_4455);
            AmiSetQword64(p, 0x0807_0605_0403_0201);
            assert_eq!(buf[1..9], [1, 2, 3, 4, 5, 6, 7, 8]);
            assert_eq!(AmiGetQword56(p), 0x07_0605_0403_0201);
            assert_eq!(AmiGetWord(core::ptr::null_mut()), 0);
        }
    }
}
