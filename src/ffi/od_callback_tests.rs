//! Dictionary tests through C-ABI callbacks: events and their order,
//! vetoes, kObdEvAbortSdo, kObdEvWrStringDomain, table validation. (Here
//! because a C callback needs `unsafe`, which only this module may use.)

use core::sync::atomic::AtomicU8;
use std::sync::Mutex;

use crate::error::{CopKernel, OdError};
use crate::od::table::{ObdCbParam, ObdVStringDomain};
use crate::od::{
    Access, ByteOrder, DataType, NoHooks, ObdEntry, ObdSize, ObdSubEntry, ObdVarEntry,
    ObjectDictionary, decl, event,
};

/// Events seen by [`record`] (event, subindex).
static SEEN: Mutex<Vec<(u8, u8)>> = Mutex::new(Vec::new());
/// Serialises the tests of this file (shared statics).
static SERIAL: Mutex<()> = Mutex::new(());

fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

fn seen() -> Vec<(u8, u8)> {
    std::mem::take(&mut *SEEN.lock().unwrap())
}

/// Records every event; refuses a write of 0xEE (abort 0x06090030); on
/// kObdEvWrStringDomain enlarges the object to the download size and moves
/// it to BIG_BUF when more than the current size is written.
unsafe extern "C" fn record(p: *mut ObdCbParam) -> u32 {
    // SAFETY: the dictionary passes a valid parameter block.
    let p = unsafe { &mut *p };
    SEEN.lock().unwrap().push((p.m_ObdEvent, p.m_bSubIndex));
    if p.m_ObdEvent == event::PRE_WRITE && !p.m_pArg.is_null() {
        // SAFETY: PreWrite points to the source data (at least one byte here).
        if unsafe { *(p.m_pArg as *const u8) } == 0xEE {
            p.m_dwAbortCode = 0x0609_0030;
            return 0x39;
        }
    }
    if p.m_ObdEvent == event::WR_STRING_DOMAIN {
        // SAFETY: WrStringDomain points to a tObdVStringDomain.
        let d = unsafe { &mut *(p.m_pArg as *mut ObdVStringDomain) };
        if d.m_DownloadSize > d.m_ObjSize {
            d.m_pData = BIG_BUF.as_ptr() as *mut core::ffi::c_void;
            d.m_ObjSize = BIG_BUF.len() as ObdSize;
        }
    }
    0
}

static SMALL_BUF: [AtomicU8; 4] = decl::zeroed();
static BIG_BUF: [AtomicU8; 16] = decl::zeroed();
static DOMAIN: ObdVarEntry = ObdVarEntry::new();
crate::od_ram!(static S2000, V: u8 = 0 => UInt8, RW);
static S2001: [ObdSubEntry; 1] = decl::var_object(DataType::Domain, Access::RW, &DOMAIN, 0);
static MAN: [ObdEntry; 2] = [
    ObdEntry::new(0x2000, &S2000, Some(record)),
    ObdEntry::new(0x2001, &S2001, Some(record)),
];

#[test]
fn write_and_read_events_in_order() {
    let _g = serial();
    let od = ObjectDictionary::new(&[], &MAN, &[]).unwrap();
    seen();
    od.write(0x2000, 0, ByteOrder::Wire, &[7], &mut NoHooks)
        .unwrap();
    assert_eq!(
        seen(),
        vec![
            (event::CHECK_EXIST, 0),
            (event::INIT_WRITE, 0),
            (event::PRE_WRITE, 0),
            (event::POST_WRITE, 0)
        ]
    );
    let mut b = [0u8; 1];
    od.read(0x2000, 0, ByteOrder::Wire, &mut b).unwrap();
    assert_eq!(
        seen(),
        vec![
            (event::CHECK_EXIST, 0),
            (event::PRE_READ, 0),
            (event::POST_READ, 0)
        ]
    );
    assert_eq!(b, [7]);
}

#[test]
fn callback_veto_changes_nothing() {
    let _g = serial();
    let od = ObjectDictionary::new(&[], &MAN, &[]).unwrap();
    od.write(0x2000, 0, ByteOrder::Wire, &[5], &mut NoHooks)
        .unwrap();
    let r = od.write(0x2000, 0, ByteOrder::Wire, &[0xEE], &mut NoHooks);
    assert_eq!(
        r,
        Err(OdError {
            kernel: CopKernel::ObdValueToHigh,
            abort: 0x0609_0030
        })
    );
    assert_eq!(od.read_uint(0x2000, 0), Ok(5));
}

#[test]
fn sdo_abort_is_notified() {
    let _g = serial();
    let od = ObjectDictionary::new(&[], &MAN, &[]).unwrap();
    seen();
    od.notify_sdo_abort(0x2000, 0, 0x0504_0000);
    od.notify_sdo_abort(0x2FFF, 0, 0x0504_0000);
    assert_eq!(seen(), vec![(event::ABORT_SDO, 0)]);
}

#[test]
fn string_domain_event_may_move_the_buffer() {
    let _g = serial();
    DOMAIN.attach(&SMALL_BUF);
    let od = ObjectDictionary::new(&[], &MAN, &[]).unwrap();
    seen();
    // 10 bytes into a 4-byte domain: the callback moves it to a 16-byte
    // buffer, so the write succeeds and lands there.
    od.write(0x2001, 0, ByteOrder::Wire, b"0123456789", &mut NoHooks)
        .unwrap();
    assert!(seen().contains(&(event::WR_STRING_DOMAIN, 0)));
    assert_eq!(&decl::get(&BIG_BUF)[..10], b"0123456789");
    assert_eq!(decl::get(&SMALL_BUF), [0; 4]);
    let mut out = [0u8; 16];
    assert_eq!(od.read(0x2001, 0, ByteOrder::Wire, &mut out), Ok(16));
}

#[test]
fn unsorted_tables_are_refused() {
    static BAD: [ObdEntry; 2] = [
        ObdEntry::new(0x2001, &S2001, None),
        ObdEntry::new(0x2000, &S2000, None),
    ];
    let e = ObjectDictionary::new(&[], &BAD, &[]).unwrap_err();
    assert_eq!((e.code, e.index), (CopKernel::ObdIllegalPart, 0x2000));
}
