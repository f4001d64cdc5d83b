//! Object dictionary writes and reads through the C API
//! (`CcmWriteObject` / `CcmReadObject`) with arbitrary indices, subindices,
//! sizes and data, on the reference dictionary initialised through the same
//! path an application takes (`CcmInitCANopen` with an `ObdInitRam`).
//! Checked: no crash; a refused write leaves the value as it was; an
//! accepted write of a fixed-size object reads back identically; a read
//! never reports more bytes than the buffer holds.
#![no_main]

use core::ffi::c_void;
use std::sync::Once;

use cop::ffi::ccm::{CcmInitCANopen, CcmReadObject, CcmWriteObject};
use cop::ffi::types::*;
use libfuzzer_sys::fuzz_target;

// --- the application side: driver, clock, dictionary --------------------
#[unsafe(no_mangle)]
extern "C" fn CdrvInit(_: *mut tCdrvInitParam) -> u32 {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvDeleteInstance() -> u32 {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvWriteMsg(_: *mut tCdrvMsg) -> u32 {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvReadMsg(_: *mut *mut tCdrvMsg) -> u32 {
    0x10
}
#[unsafe(no_mangle)]
extern "C" fn CdrvReleaseMsg(_: *mut tCdrvMsg) -> u32 {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvDefineCanId(_: *mut tCdrvMsg) -> u32 {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvUndefineCanId(_: *mut tCdrvMsg) -> u32 {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvGetStatus(s: *mut u16) -> u32 {
    // SAFETY: the library passes a valid WORD.
    unsafe { *s = 0 };
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvResetStatus(_: u16) -> u32 {
    0
}
#[unsafe(no_mangle)]
extern "C" fn TgtGetTickCount() -> u32 {
    0
}

unsafe extern "C" fn obd_init_ram(p: *mut c_void) -> u32 {
    if p.is_null() {
        return 0;
    }
    let (generic, manufacturer) = cop::testod::parts();
    // Tables for the C path end with an index of 0xFFFF: copy them into
    // terminated arrays once.
    static mut GEN: Vec<cop::od::ObdEntry> = Vec::new();
    static mut MAN: Vec<cop::od::ObdEntry> = Vec::new();
    let end = || cop::od::ObdEntry::new(0xFFFF, &[], None);
    // SAFETY: called once, from CcmInitCANopen, before any other access.
    unsafe {
        let g = &mut *core::ptr::addr_of_mut!(GEN);
        let m = &mut *core::ptr::addr_of_mut!(MAN);
        for e in generic {
            g.push(cop::od::ObdEntry::new(e.index(), e.subs(), e.m_fpCallback));
        }
        g.push(end());
        for e in manufacturer {
            m.push(cop::od::ObdEntry::new(e.index(), e.subs(), e.m_fpCallback));
        }
        m.push(end());
        let ram = &mut *(p as *mut tObdRamParam);
        ram.m_pGenericPart = g.as_ptr();
        ram.m_pManufacturerPart = m.as_ptr();
        ram.m_pbAbiSignature = &cop::ffi::COP_LIB_ABI_SIGNATURE;
    }
    0
}

static INIT: Once = Once::new();

fn init() {
    INIT.call_once(|| {
        let mut p = tCcmInitParam {
            m_bInitNodeId: 3,
            m_BaudIndex: 4,
            m_pBdiTable: core::ptr::null(),
            m_wSizeOfBdiTab: 0,
            m_dwAmr: 0xFFFF_FFFF,
            m_dwAcr: 0,
            m_HwParam: tCdrvHwParam {
                m_apvRaw: [core::ptr::null_mut(); 2],
            },
            m_fpCanInterruptEnable: None,
            m_fpNmtEventCallback: None,
            m_fpObdInitRam: Some(obd_init_ram),
        };
        // SAFETY: valid parameter block.
        let r = unsafe { CcmInitCANopen(&mut p, 1) };
        assert_eq!(r, 0, "CcmInitCANopen");
    });
}

const INDICES: [u16; 17] = [
    0x1000, 0x1001, 0x1008, 0x1017, 0x1018, 0x2000, 0x2001, 0x2002, 0x2003, 0x2004, 0x2005, 0x2006,
    0x2007, 0x2008, 0x2009, 0x200A, 0x200B,
];

fn read(index: u16, sub: u8, cap: usize) -> (u32, Vec<u8>) {
    let mut buf = vec![0u8; cap];
    let mut n: tObdSize = cap.min(255) as tObdSize;
    // SAFETY: buf holds `n` bytes.
    let r = unsafe { CcmReadObject(index, sub, buf.as_mut_ptr() as *mut c_void, &mut n) };
    assert!(usize::from(n) <= cap, "read reported more than the buffer");
    buf.truncate(if r == 0 { usize::from(n) } else { 0 });
    (r, buf)
}

fuzz_target!(|data: &[u8]| {
    init();
    // Each record: [index selector, sub, size, data...size bytes].
    let mut rest = data;
    while let [sel, sub, size, tail @ ..] = rest {
        let index = if sel & 0x80 != 0 {
            0x1000 + u16::from(*sel) * 0x41
        } else {
            INDICES[usize::from(*sel) % INDICES.len()]
        };
        let n = usize::from(*size).min(tail.len());
        let (value, next) = tail.split_at(n);
        rest = next;
        let (rb, before) = read(index, *sub, 255);
        // SAFETY: `value` holds n bytes.
        let w = unsafe {
            CcmWriteObject(index, *sub, value.as_ptr() as *const c_void, n as tObdSize)
        };
        let (ra, after) = read(index, *sub, 255);
        if w != 0 {
            assert_eq!((rb, &before), (ra, &after), "refused write changed {index:#x}.{sub}");
        } else if ra == 0 && matches!(n, 1 | 2 | 4 | 8) && after.len() == n {
            assert_eq!(after, value, "write of {index:#x}.{sub} did not read back");
        }
        let _ = read(index, *sub, usize::from(*size));
    }
});
