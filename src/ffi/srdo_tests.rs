//! The SRDO entry points of [`super::srdo`] called as a C application
//! calls them, on a driver written here (the `Cdrv*` / `TgtGetTickCount`
//! functions the library imports): return codes, what reaches the driver,
//! what the dictionary holds afterwards. (Here because the C entry points
//! and the driver's C functions need `unsafe`, which only this module may
//! use.)
//!
//! The node is the producer of [`crate::sim::srdo_net`] (node 1, SRDO 1
//! transmit on 0x101/0x102, SRDO 2 disabled on 0x103/0x104), installed in
//! the last instance slot as `CcmInitCANopen` installs it.

use core::ffi::c_void;
use core::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Mutex, MutexGuard};

use super::callbacks::Callbacks;
use super::ccm::{CcmConnectToNet, CcmNmtsExecCommand, CcmProcess, CcmWriteObject};
use super::driver::CdrvPort;
use super::global::{self, Instance, MAX_INSTANCES};
use super::srdo::*;
use super::types::*;
use crate::ccm::{NmtCommand, Stack};
use crate::error::CopKernel;
use crate::sim::srdo_net::{self, producer};

// ---- the driver ------------------------------------------------------------

/// Frames the stack wrote (identifier, data).
static SENT: Mutex<Vec<(u32, Vec<u8>)>> = Mutex::new(Vec::new());
/// Transmissions still to refuse (kCopCdrvTxBuffHighOverrun each).
static REFUSE: AtomicU32 = AtomicU32::new(0);
/// The tick counter (100 us), moved by the tests only.
static TICKS: AtomicU32 = AtomicU32::new(0);
/// Frames for the stack to read (identifier, data), oldest first.
static RECEIVED: Mutex<Vec<(u32, Vec<u8>)>> = Mutex::new(Vec::new());

#[unsafe(no_mangle)]
extern "C" fn CdrvInit(_p: *mut tCdrvInitParam) -> tCopKernel {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvDeleteInstance() -> tCopKernel {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvWriteMsg(p: *mut tCdrvMsg) -> tCopKernel {
    // (The tests run one at a time, under the SRDO network's lock.)
    let refuse = REFUSE.load(Ordering::SeqCst);
    if refuse > 0 {
        REFUSE.store(refuse - 1, Ordering::SeqCst);
        return CopKernel::CdrvTxBuffHighOverrun.code();
    }
    // SAFETY: the library passes a valid message for the call's duration.
    let m = unsafe { &*p };
    let len = usize::from(m.m_bSize.min(8));
    SENT.lock()
        .unwrap()
        .push((u32::from(m.m_CanId), m.m_bData[..len].to_vec()));
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvReadMsg(pp: *mut *mut tCdrvMsg) -> tCopKernel {
    let mut rx = RECEIVED.lock().unwrap();
    if rx.is_empty() {
        return CopKernel::CdrvNoMsg.code();
    }
    let (id, data) = rx.remove(0);
    let mut m = tCdrvMsg {
        m_CanId: id as tCanId,
        m_bSize: data.len() as u8,
        ..tCdrvMsg::default()
    };
    m.m_bData[..data.len()].copy_from_slice(&data);
    // One buffer entry per frame, freed by CdrvReleaseMsg.
    // SAFETY: the library passes a valid pointer for the entry's address.
    unsafe { *pp = Box::into_raw(Box::new(m)) };
    CopKernel::CdrvMsgHigh.code()
}
#[unsafe(no_mangle)]
extern "C" fn CdrvReleaseMsg(p: *mut tCdrvMsg) -> tCopKernel {
    // SAFETY: `p` is an entry CdrvReadMsg handed out (Box::into_raw),
    // released once.
    drop(unsafe { Box::from_raw(p) });
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvDefineCanId(_p: *mut tCdrvMsg) -> tCopKernel {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvUndefineCanId(_p: *mut tCdrvMsg) -> tCopKernel {
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvGetStatus(p: *mut u16) -> tCopKernel {
    // SAFETY: the library passes a valid WORD.
    unsafe { *p = 0 };
    0
}
#[unsafe(no_mangle)]
extern "C" fn CdrvResetStatus(_s: u16) -> tCopKernel {
    0
}
#[unsafe(no_mangle)]
extern "C" fn TgtGetTickCount() -> tTime {
    TICKS.load(Ordering::SeqCst)
}

/// Takes the frames written since the last call.
fn sent() -> Vec<(u32, Vec<u8>)> {
    std::mem::take(&mut *SENT.lock().unwrap())
}

// ---- the node ----------------------------------------------------------------

/// The producer installed and connected (PRE-OPERATIONAL); removed again
/// on drop. Holds the lock of the SRDO network's statics, which the other
/// users of the process-wide instances hold too.
struct Node {
    _serial: MutexGuard<'static, ()>,
}

impl Node {
    fn new() -> Node {
        Node::with_callbacks(Callbacks::default())
    }

    /// [`Node::new`] with the application's callbacks.
    fn with_callbacks(callbacks: Callbacks) -> Node {
        let serial = srdo_net::lock();
        assert!(global::select(MAX_INSTANCES - 1));
        let _ = global::remove();
        REFUSE.store(0, Ordering::SeqCst);
        TICKS.store(0, Ordering::SeqCst);
        RECEIVED.lock().unwrap().clear();
        let stack = Stack::new(producer::od().unwrap(), 1).unwrap();
        let instance = Instance {
            stack,
            port: CdrvPort::default(),
            callbacks,
            tables: Default::default(),
        };
        assert_eq!(global::install(instance), Ok(()));
        assert_eq!(CcmProcess(), 0, "start-up (defaults loaded)");
        assert_eq!(CcmConnectToNet(), 0);
        sent();
        Node { _serial: serial }
    }

    /// `CcmWriteObject` of `bytes` (CPU byte order).
    fn write(&self, index: u16, sub: u8, bytes: &[u8]) -> tCopKernel {
        // SAFETY: `bytes` is readable for its length.
        unsafe { CcmWriteObject(index, sub, bytes.as_ptr().cast(), bytes.len() as tObdSize) }
    }

    /// Defines the variable fields (static mapping), writes the CRC of
    /// SRDO 1 and 2 (`CcmCalcSrdoCrc`) and declares the configuration
    /// valid.
    fn seal(&self) {
        // SAFETY: the producer's fields are statics of the mapped length
        // (SRDO 2 maps the first pair of SRDO 1).
        #[cfg(srdo_static_mapping)]
        unsafe {
            let (n, i) = (
                producer::NORMAL.as_ptr() as *mut c_void,
                producer::INVERTED.as_ptr() as *mut c_void,
            );
            assert_eq!(CcmStaticDefineSrdoVarFields(0x1301, n, i), 0);
            assert_eq!(CcmStaticDefineSrdoVarFields(0x1302, n, i), 0);
        }
        for idx in [0x1301u16, 0x1302] {
            let crc = crc_of(idx);
            assert_eq!(
                self.write(0x13FF, (idx - 0x1300) as u8, &crc.to_ne_bytes()),
                0
            );
        }
        assert_eq!(self.write(0x13FE, 0, &[0xA5]), 0);
    }

    /// NMT start, and the first-transmission delay (0.5 ms x node-ID) over.
    fn operational(&self) {
        assert_eq!(CcmNmtsExecCommand(NmtCommand::StartRemoteNode as u16), 0);
        assert_eq!(CcmProcess(), 0);
        TICKS.fetch_add(10, Ordering::SeqCst);
        sent();
    }
}

impl Drop for Node {
    fn drop(&mut self) {
        let _ = global::remove();
        assert!(global::select(0));
    }
}

/// `CcmCalcSrdoCrc` of `idx` (must succeed).
fn crc_of(idx: u16) -> u16 {
    let mut crc = 0u16;
    // SAFETY: `crc` is a writable WORD.
    assert_eq!(unsafe { CcmCalcSrdoCrc(idx, &mut crc) }, 0);
    crc
}

/// Sets the producer's variables: the normal data and their inverted copies
/// (`pair2_inverted_ok` false leaves pair 2 not inverted).
fn set_data(pair1: u16, pair2: u16, pair2_inverted_ok: bool) {
    let put = |buf: &[core::sync::atomic::AtomicU8], v: u16| {
        for (b, x) in buf.iter().zip(v.to_ne_bytes()) {
            b.store(x, Ordering::SeqCst);
        }
    };
    put(&producer::NORMAL[0..2], pair1);
    put(&producer::NORMAL[2..4], pair2);
    put(&producer::INVERTED[0..2], !pair1);
    put(
        &producer::INVERTED[2..4],
        if pair2_inverted_ok { !pair2 } else { pair2 },
    );
}

/// `CcmGetSrdoState` of `idx`: the code and the byte.
fn state_of(idx: u16) -> (tCopKernel, u8) {
    let mut s = 0xEEu8;
    // SAFETY: `s` is a writable byte.
    let r = unsafe { CcmGetSrdoState(&mut s, idx) };
    (r, s)
}

// ---- the tests -------------------------------------------------------------------

// req: M-2.8.1-SEND, SB-4-ALL
#[test]
fn send_all_keeps_the_first_of_two_errors() {
    let node = Node::new();
    // SRDO 2 becomes a transmit SRDO too (0x1382 maps 0x6200 / 0x6300 sub 1).
    assert_eq!(node.write(0x1302, 1, &[1]), 0);
    node.seal();
    node.operational();
    // Pair 2 not inverted: SRDO 1 (both pairs) fails its data check and
    // sends nothing; SRDO 2 (pair 1 only) is sent to a driver that refuses.
    set_data(0x1234, 0x5678, false);
    REFUSE.store(1, Ordering::SeqCst);
    assert_eq!(CcmSendSrdo(0), CopKernel::SrdoDataError.code());
    assert_eq!(sent(), vec![], "nothing on the bus");
    assert_eq!(REFUSE.load(Ordering::SeqCst), 0, "SRDO 2 was attempted");
    // Each alone gives its own code.
    assert_eq!(CcmSendSrdo(0x1301), CopKernel::SrdoDataError.code());
    REFUSE.store(1, Ordering::SeqCst);
    assert_eq!(CcmSendSrdo(0x1302), CopKernel::CdrvTxBuffHighOverrun.code());
    // Only SRDO 1 failing (the driver refuses its first frame): its code
    // is returned, SRDO 2 is still sent.
    set_data(0x1234, 0x5678, true);
    TICKS.fetch_add(1000, Ordering::SeqCst);
    REFUSE.store(1, Ordering::SeqCst);
    assert_eq!(SrdoSend(0), CopKernel::CdrvTxBuffHighOverrun.code());
    let ids: Vec<u32> = sent().iter().map(|f| f.0).collect();
    assert_eq!(ids, vec![0x103, 0x104]);
    // Both good: both sent, in index order, each normal frame first.
    TICKS.fetch_add(1000, Ordering::SeqCst);
    assert_eq!(CcmSendSrdo(0), 0);
    let frames = sent();
    let ids: Vec<u32> = frames.iter().map(|f| f.0).collect();
    assert_eq!(ids, vec![0x101, 0x102, 0x103, 0x104]);
    // 0x101 carries the normal data of both pairs (CANopen byte order).
    assert_eq!(frames[0].1, vec![0x34, 0x12, 0x78, 0x56]);
    assert_eq!(frames[1].1, vec![0xCB, 0xED, 0x87, 0xA9]);
}

// req: M-2.8.1-SEND
#[test]
fn calls_without_an_instance_are_refused() {
    let _serial = srdo_net::lock();
    assert!(global::select(MAX_INSTANCES - 1));
    let _ = global::remove();
    let illegal = CopKernel::IllegalInstance.code();
    assert_eq!(CcmSendSrdo(0), illegal, "the lookup inside the loop");
    assert_eq!(CcmSendSrdo(0x1301), illegal);
    assert_eq!(state_of(0x1301).0, illegal);
    assert_eq!(CcmSetSrdoState(0x30, 0x1301), illegal);
    let mut idx = 0u16;
    // SAFETY: `idx` is a writable WORD.
    assert_eq!(unsafe { CcmCheckSrdoConfig(&mut idx) }, illegal);
    let mut crc = 0u16;
    // SAFETY: `crc` is a writable WORD.
    assert_eq!(unsafe { CcmCalcSrdoCrc(0x1301, &mut crc) }, illegal);
    let init = init_param(0);
    // SAFETY: `init` is a valid tSrdoInitParam.
    assert_eq!(unsafe { SrdoInit(&init) }, illegal);
    assert_eq!(SrdoDeleteInstance(), illegal);
    assert_eq!(SrdoNmtEvent(0), illegal);
    assert!(global::select(0));
}

/// A `tSrdoInitParam` with the granularity `g` (the table is not read).
fn init_param(g: u8) -> tSrdoInitParam {
    tSrdoInitParam {
        m_SrdoTabParam: tSrdoTabParam {
            m_pSrdoTable: core::ptr::null_mut(),
            m_SrdoCount: 0,
        },
        m_bGranularity: g,
        m_pbSrdoConfigValid: core::ptr::null_mut(),
    }
}

// req: M-2.4-GRANULARITY
#[test]
fn srdo_init_refuses_another_granularity() {
    let node = Node::new();
    node.seal();
    // SAFETY: NULL is refused before it is read.
    assert_eq!(
        unsafe { SrdoInit(core::ptr::null()) },
        CopKernel::InvalidParam.code()
    );
    let lib = crate::config::SRDO_GRANULARITY;
    let other = if lib == 8 { 16 } else { 8 };
    for g in [other, lib.wrapping_mul(2), 1] {
        let p = init_param(g);
        // SAFETY: `p` is a valid tSrdoInitParam.
        assert_eq!(
            unsafe { SrdoInit(&p) },
            CopKernel::SrdoGranularityMismatch.code(),
            "granularity {g}"
        );
        // SAFETY: as above.
        assert_eq!(
            unsafe { SrdoAddInstance(&p) },
            CopKernel::SrdoGranularityMismatch.code()
        );
    }
    // A refused SrdoInit left the module running: it sends.
    node.operational();
    set_data(1, 2, true);
    assert_eq!(CcmSendSrdo(0x1301), 0);
    assert_eq!(sent().len(), 2);
    // 0 (not given) and the library's value re-read the objects and stop
    // the SRDOs until the next transition to OPERATIONAL.
    for g in [0, lib] {
        let p = init_param(g);
        // SAFETY: `p` is a valid tSrdoInitParam.
        assert_eq!(unsafe { SrdoInit(&p) }, 0, "granularity {g}");
        TICKS.fetch_add(1000, Ordering::SeqCst);
        assert_eq!(CcmSendSrdo(0x1301), CopKernel::SrdoNmtError.code());
        assert_eq!(
            CcmNmtsExecCommand(NmtCommand::EnterPreOperational as u16),
            0
        );
        node.seal();
        node.operational();
        assert_eq!(CcmSendSrdo(0x1301), 0);
        assert_eq!(sent().len(), 2);
    }
}

// req: M-2.5.3-STATUS
#[test]
fn srdo_state_is_read_and_written_through_the_c_calls() {
    let _node = Node::new();
    assert_eq!(state_of(0x1301), (0, 0));
    // Bits 0-3 are reserved: written as 0.
    assert_eq!(CcmSetSrdoState(0xA5, 0x1301), 0);
    assert_eq!(state_of(0x1301), (0, 0xA0));
    assert_eq!(SrdoSetState(0x3F, 0x1302), 0);
    // SAFETY: a writable byte.
    let mut s = 0u8;
    assert_eq!(unsafe { SrdoGetState(&mut s, 0x1302) }, 0);
    assert_eq!(s, 0x30);
    assert_eq!(state_of(0x1301), (0, 0xA0), "SRDO 1 unchanged");
    let none = CopKernel::SrdoNotExist.code();
    for idx in [0x1300, 0x1303, 0x1341] {
        assert_eq!(state_of(idx), (none, 0xEE), "{idx:#x}: nothing written");
        assert_eq!(CcmSetSrdoState(0x30, idx), none);
    }
    // SAFETY: NULL is refused.
    assert_eq!(
        unsafe { CcmGetSrdoState(core::ptr::null_mut(), 0x1301) },
        CopKernel::InvalidParam.code()
    );
}

/// The status calls as the first call after the instance is selected (the
/// library has no status table of the instance at hand yet): the same byte
/// and the same write rule (manual 2.5.3: bits 4-7, bits 0-3 reserved 0).
// req: M-2.5.3-STATUS
#[test]
fn srdo_state_calls_first_after_selecting_the_instance() {
    let _node = Node::new();
    assert_eq!(CcmSetSrdoState(0x30, 0x1301), 0);
    assert!(global::select(MAX_INSTANCES - 1));
    assert_eq!(state_of(0x1301), (0, 0x30));
    assert!(global::select(MAX_INSTANCES - 1));
    assert_eq!(CcmSetSrdoState(0x9F, 0x1301), 0);
    assert_eq!(state_of(0x1301), (0, 0x90));
    assert!(global::select(MAX_INSTANCES - 1));
    let none = CopKernel::SrdoNotExist.code();
    assert_eq!(CcmSetSrdoState(0x30, 0x1303), none);
    assert_eq!(state_of(0x1303), (none, 0xEE));
}

// req: M-2.8.2-CHECK, M-2.8.8-CALCCRC
#[test]
fn check_config_names_the_first_bad_srdo() {
    let node = Node::new();
    node.seal();
    let mut idx = 0x5555u16;
    // SAFETY: `idx` is a writable WORD.
    assert_eq!(unsafe { CcmCheckSrdoConfig(&mut idx) }, 0);
    assert_eq!(idx, 0x5555, "nothing written on success");
    // SRDO 2's SCT changed: its CRC no longer matches.
    let before = crc_of(0x1302);
    assert_eq!(node.write(0x1302, 2, &40u16.to_ne_bytes()), 0);
    assert_ne!(crc_of(0x1302), before);
    // SAFETY: as above.
    assert_eq!(
        unsafe { SrdoCheckConfig(&mut idx) },
        CopKernel::SrdoCfgCrcError.code()
    );
    assert_eq!(idx, 0x1302);
    // SAFETY: NULL is refused.
    assert_eq!(
        unsafe { CcmCheckSrdoConfig(core::ptr::null_mut()) },
        CopKernel::InvalidParam.code()
    );
    // CcmCalcSrdoCrc = the module's CRC; SrdoCalcSrdoCrc wants a NULL entry.
    let module = global::with(|i| i.stack.srdo().calc_crc(i.stack.od(), 0x1302));
    assert_eq!(module, Ok(Ok(crc_of(0x1302))));
    let mut crc = 0u16;
    // SAFETY: `crc` is a writable WORD; the entry pointer is not read.
    unsafe {
        assert_eq!(SrdoCalcSrdoCrc(0x1302, core::ptr::null_mut(), &mut crc), 0);
        assert_eq!(crc, crc_of(0x1302));
        let mut dummy = 0u8;
        assert_eq!(
            SrdoCalcSrdoCrc(0x1302, (&mut dummy as *mut u8).cast(), &mut crc),
            CopKernel::InvalidParam.code()
        );
        assert_eq!(
            CcmCalcSrdoCrc(0x1303, &mut crc),
            CopKernel::SrdoNotExist.code()
        );
        assert_eq!(
            CcmCalcSrdoCrc(0x1301, core::ptr::null_mut()),
            CopKernel::InvalidParam.code()
        );
    }
}

// req: M-2.8.1-SEND
#[test]
fn get_srdo_param_reports_direction_sct_and_mapping() {
    let node = Node::new();
    let mut c = tSrdoCommuParam {
        m_bDirection: 0xEE,
        m_wSct: 0xEEEE,
    };
    // SAFETY: `c` is writable; the mapping pointer is NULL.
    unsafe {
        assert_eq!(CcmGetSrdoParam(0x1301, &mut c, core::ptr::null_mut()), 0);
    }
    assert_eq!((c.m_bDirection, c.m_wSct), (1, srdo_net::SCT_MS));
    let mut c2 = tSrdoCommuParam {
        m_bDirection: 0xEE,
        m_wSct: 0,
    };
    // SAFETY: as above.
    assert_eq!(unsafe { SrdoGetCommuParam(0x1302, &mut c2) }, 0);
    assert_eq!((c2.m_bDirection, c2.m_wSct), (0, srdo_net::SCT_MS));
    // SAFETY: NULL refused; an absent SRDO writes nothing.
    unsafe {
        assert_eq!(
            SrdoGetCommuParam(0x1301, core::ptr::null_mut()),
            CopKernel::InvalidParam.code()
        );
        assert_eq!(
            CcmGetSrdoParam(0x1303, &mut c, core::ptr::null_mut()),
            CopKernel::SrdoNotExist.code()
        );
    }
    assert_eq!(c.m_bDirection, 1);
    mapping(&node);
}

/// A `tSrdoMappParam` the library has not written (0xEE objects).
fn unset_mapp() -> tSrdoMappParam {
    tSrdoMappParam {
        m_bNoOfMappedObjects: 0xEE,
        m_apMappedVariable: [core::ptr::null_mut(); crate::config::SRDO_MAX_MAPPENTRIES],
    }
}

#[cfg(not(srdo_static_mapping))]
fn mapping(node: &Node) {
    let mut m = unset_mapp();
    // SAFETY: `m` is writable.
    assert_eq!(
        unsafe { CcmGetSrdoParam(0x1301, core::ptr::null_mut(), &mut m) },
        0
    );
    assert_eq!(m.m_bNoOfMappedObjects, 4);
    let at =
        |buf: &'static [core::sync::atomic::AtomicU8], i: usize| buf[i..].as_ptr() as *mut c_void;
    assert_eq!(
        m.m_apMappedVariable[..4],
        [
            at(&producer::NORMAL, 0),
            at(&producer::INVERTED, 0),
            at(&producer::NORMAL, 2),
            at(&producer::INVERTED, 2)
        ]
    );
    // A mapping entry naming an absent object: a NULL pointer for it.
    assert_eq!(node.write(0x1382, 1, &0x6400_0110u32.to_ne_bytes()), 0);
    let mut c = tSrdoCommuParam {
        m_bDirection: 0xEE,
        m_wSct: 0xEEEE,
    };
    // SAFETY: both writable.
    assert_eq!(unsafe { CcmGetSrdoParam(0x1302, &mut c, &mut m) }, 0);
    assert_eq!((c.m_bDirection, m.m_bNoOfMappedObjects), (0, 2));
    assert_eq!(
        m.m_apMappedVariable[..2],
        [core::ptr::null_mut(), at(&producer::INVERTED, 0)]
    );
    // SAFETY: NULL is refused.
    assert_eq!(
        unsafe { SrdoGetMappParam(0x1301, core::ptr::null_mut()) },
        CopKernel::InvalidParam.code()
    );
    // SAFETY: `m` is writable.
    assert_eq!(unsafe { SrdoGetMappParam(0x1301, &mut m) }, 0);
    assert_eq!(m.m_bNoOfMappedObjects, 4);
}

#[cfg(srdo_static_mapping)]
fn mapping(_node: &Node) {
    let mut m = unset_mapp();
    // SAFETY: `m` is writable (and refused: no mapping parameters).
    assert_eq!(
        unsafe { CcmGetSrdoParam(0x1301, core::ptr::null_mut(), &mut m) },
        CopKernel::InvalidParam.code()
    );
    assert_eq!(m.m_bNoOfMappedObjects, 0xEE);
}

// req: SB-9-LEAVE
#[test]
fn delete_instance_stops_and_nmt_event_must_match_the_state() {
    let node = Node::new();
    node.seal();
    use crate::event::NmtEvent;
    let nmt_error = CopKernel::SrdoNmtError.code();
    assert_eq!(SrdoNmtEvent(NmtEvent::EnterPreOperational as u32), 0);
    assert_eq!(SrdoNmtEvent(NmtEvent::EnterOperational as u32), nmt_error);
    assert_eq!(SrdoNmtEvent(NmtEvent::EnterStopped as u32), nmt_error);
    assert_eq!(SrdoNmtEvent(NmtEvent::PostResetCommunication as u32), 0);
    assert_eq!(
        SrdoNmtEvent(NmtEvent::PostResetCommunication as u32 + 1),
        nmt_error
    );
    node.operational();
    assert_eq!(SrdoNmtEvent(NmtEvent::EnterOperational as u32), 0);
    assert_eq!(
        SrdoNmtEvent(NmtEvent::EnterPreOperational as u32),
        nmt_error
    );
    set_data(7, 8, true);
    assert_eq!(CcmSendSrdo(0x1301), 0);
    assert_eq!(sent().len(), 2);
    assert_eq!(SrdoDeleteInstance(), 0);
    TICKS.fetch_add(1000, Ordering::SeqCst);
    assert_eq!(CcmSendSrdo(0x1301), CopKernel::SrdoNmtError.code());
    assert_eq!(SrdoProcess(), 0);
    assert_eq!(sent(), vec![], "stopped: no refresh either");
}

// req: M-1.3-GFC
#[cfg(srdo_use_gfc)]
#[test]
fn send_gfc_only_operational_and_enabled() {
    let node = Node::new();
    node.seal();
    assert_eq!(node.write(0x1300, 0, &[0]), 0);
    node.operational();
    assert_eq!(SrdoSendGfc(), CopKernel::SrdoInvalid.code(), "0x1300 = 0");
    assert_eq!(
        CcmNmtsExecCommand(NmtCommand::EnterPreOperational as u16),
        0
    );
    assert_eq!(node.write(0x1300, 0, &[1]), 0);
    assert_eq!(
        CcmSendGfc(),
        CopKernel::SrdoNmtError.code(),
        "PRE-OPERATIONAL"
    );
    node.operational();
    assert_eq!(sent(), vec![]);
    assert_eq!(CcmSendGfc(), 0);
    // CiA 304: the GFC is identifier 0x001 without data.
    assert_eq!(sent(), vec![(0x001, vec![])]);
    REFUSE.store(1, Ordering::SeqCst);
    assert_eq!(SrdoSendGfc(), CopKernel::CdrvTxBuffHighOverrun.code());
    assert_eq!(SrdoSendGfc(), 0);
    assert_eq!(sent().len(), 1);
}

// req: SB-9-LEAVE
#[test]
fn srdo_process_is_a_processing_cycle() {
    let _node = Node::new();
    use crate::event::NmtEvent;
    // CiA 301 NMT "start remote node" for node 1: 0x000 [01 01].
    RECEIVED.lock().unwrap().push((0x000, vec![0x01, 0x01]));
    assert_eq!(
        SrdoNmtEvent(NmtEvent::EnterOperational as u32),
        CopKernel::SrdoNmtError.code()
    );
    assert_eq!(SrdoProcess(), 0);
    assert!(RECEIVED.lock().unwrap().is_empty(), "the frame was read");
    assert_eq!(SrdoNmtEvent(NmtEvent::EnterOperational as u32), 0);
    // "Stop remote node": STOPPED matches kNmtEvEnterStopped only.
    RECEIVED.lock().unwrap().push((0x000, vec![0x02, 0x01]));
    assert_eq!(SrdoProcess(), 0);
    assert_eq!(SrdoNmtEvent(NmtEvent::EnterStopped as u32), 0);
    assert_eq!(
        SrdoNmtEvent(NmtEvent::EnterOperational as u32),
        CopKernel::SrdoNmtError.code()
    );
}

// ---- AppSrdoEvent after CcmSendSrdo ------------------------------------------

/// `AppSrdoEvent` calls: the index, and how many callbacks were running
/// (this one included) when it was called.
static SRDO_EVENTS: Mutex<Vec<(u16, u32)>> = Mutex::new(Vec::new());
/// Callbacks running now.
static DEPTH: AtomicU32 = AtomicU32::new(0);
/// `AppSrdoEvent` sends SRDO 2 (through `CcmSendSrdo`) when SRDO 1's
/// event comes, and keeps the code here.
static NESTED_SEND: AtomicU32 = AtomicU32::new(u32::MAX);

extern "C" fn app_srdo_event(idx: WORD) -> tCopKernel {
    let depth = DEPTH.fetch_add(1, Ordering::SeqCst) + 1;
    SRDO_EVENTS.lock().unwrap().push((idx, depth));
    if idx == 0x1301 && NESTED_SEND.load(Ordering::SeqCst) == u32::MAX - 1 {
        NESTED_SEND.store(CcmSendSrdo(0x1302), Ordering::SeqCst);
    }
    DEPTH.fetch_sub(1, Ordering::SeqCst);
    0
}

fn srdo_callbacks() -> Callbacks {
    Callbacks {
        srdo: Some(tSrdoAppCallbacks {
            m_fpSrdoEvent: Some(app_srdo_event),
            m_fpSrdoError: None,
            m_fpGfcEvent: None,
            m_fpProgMonEvent: None,
        }),
        ..Callbacks::default()
    }
}

/// Manual 2.8.1: after a successful `CcmSendSrdo` the stack calls
/// `AppSrdoEvent` with the SRDO's index, once, before `CcmSendSrdo`
/// returns; a `CcmSendSrdo` made inside that callback sends at once, but
/// its `AppSrdoEvent` runs after the running callback has returned, never
/// inside it (callbacks do not nest), also when nothing else is queued
/// (without the program monitor).
// req: M-2.8.1-SEND
#[test]
fn send_calls_app_srdo_event_once_and_never_nested() {
    let node = Node::with_callbacks(srdo_callbacks());
    assert_eq!(node.write(0x1302, 1, &[1]), 0);
    node.seal();
    node.operational();
    set_data(0x1234, 0x5678, true);
    SRDO_EVENTS.lock().unwrap().clear();
    NESTED_SEND.store(u32::MAX, Ordering::SeqCst);
    assert_eq!(CcmSendSrdo(0x1301), 0);
    assert_eq!(*SRDO_EVENTS.lock().unwrap(), vec![(0x1301, 1)]);
    assert_eq!(sent().len(), 2);
    SRDO_EVENTS.lock().unwrap().clear();
    sent();
    // Inside SRDO 1's event, SRDO 2 is sent.
    NESTED_SEND.store(u32::MAX - 1, Ordering::SeqCst);
    TICKS.fetch_add(1000, Ordering::SeqCst);
    assert_eq!(CcmSendSrdo(0x1301), 0);
    assert_eq!(
        NESTED_SEND.load(Ordering::SeqCst),
        0,
        "the nested send succeeded"
    );
    let ids: Vec<u32> = sent().iter().map(|f| f.0).collect();
    assert_eq!(ids, vec![0x101, 0x102, 0x103, 0x104]);
    assert_eq!(
        *SRDO_EVENTS.lock().unwrap(),
        vec![(0x1301, 1), (0x1302, 1)],
        "SRDO 2's event after SRDO 1's callback returned"
    );
    drop(node);
}
