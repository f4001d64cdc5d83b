//! SRDO / GFC C API (manual L-1077d sections 2.8, 2.11, 2.12): the CCM
//! functions `CcmSendSrdo`, `CcmCheckSrdoConfig`, `CcmSendGfc`,
//! `CcmGetSrdoState`, `CcmSetSrdoState`, `CcmGetSrdoParam`,
//! `CcmStaticDefineSrdoVarFields`, `CcmCalcSrdoCrc`, and the module
//! functions `Srdo*` with the same parameters.
//!
//! Conventions as in [`super::ccm`]. The application's callbacks
//! (`AppSrdoEvent`, `AppSrdoError`, `AppGfcEvent`, `AppProgMonEvent`) run
//! inside these calls and inside `CcmProcess`, with the stack released, so
//! they may call `CcmGetSrdoState` / `CcmSetSrdoState`.

use core::ffi::c_void;

use super::driver::TgtClock;
use super::global::{self, Instance, code};
use super::instance;
use super::ptr::{self, Out, c_try};
use super::types::*;
use crate::error::CopKernel;
use crate::event::{NmtEvent, NmtState};
use crate::port::Clock;

/// `CcmSendSrdo`: sends one transmit SRDO (`wSrdoCommuIndex_p` =
/// 0x1301..0x1340) or, with 0, every transmit SRDO in index order. Before
/// sending, the inverted data are checked bit by bit against the normal
/// data; on a mismatch nothing is sent and `AppSrdoError` reports
/// kCopSrdoDataError. After a successful transmission `AppSrdoEvent` runs.
///
/// Returns kCopSuccessful; kCopSrdoNotExist (no such SRDO); kCopSrdoNmtError
/// (not OPERATIONAL, or within the first-transmission delay of 0.5 ms ×
/// node-ID after entering OPERATIONAL); kCopSrdoInvalidCfg (0x13FE is not
/// 0xA5, or the configuration check failed when the node entered
/// OPERATIONAL); kCopSrdoInvalid (direction 0); kCopSrdoRxTxConflict (a receive
/// SRDO); kCopSrdoDataError; the driver's code when it refuses a frame.
/// With 0, every transmit SRDO is attempted and the first error is
/// returned.
#[unsafe(no_mangle)]
pub extern "C" fn CcmSendSrdo(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wSrdoCommuIndex_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    if wSrdoCommuIndex_p != 0 {
        return send_one(wSrdoCommuIndex_p);
    }
    let mut first = CopKernel::Successful.code();
    for idx in 0x1301u16..=0x1340 {
        let is_tx = global::with(|i| {
            i.stack
                .srdo()
                .commu_param(i.stack.od(), idx)
                .map(|p| p.direction == 1)
                .unwrap_or(false)
        });
        match is_tx {
            Ok(true) => {
                let r = send_one(idx);
                if r != 0 && first == 0 {
                    first = r;
                }
            }
            Ok(false) => {}
            Err(e) => return e.code(),
        }
    }
    first
}

fn send_one(idx: WORD) -> tCopKernel {
    let now = TgtClock.now();
    let r = global::with_srdo_event(|i, direct| {
        let Instance { stack, port, .. } = i;
        match stack.send_srdo_first(port, idx, now, direct) {
            Ok(e) => (Ok(()), e),
            Err(e) => (Err(e), None),
        }
    });
    code(r)
}

/// `SrdoSend`: the module function behind `CcmSendSrdo`.
#[unsafe(no_mangle)]
pub extern "C" fn SrdoSend(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    wSrdoCommuIndex_p: WORD,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    instance::here!(CcmSendSrdo, wSrdoCommuIndex_p)
}

/// `CcmCheckSrdoConfig`: checks every SRDO (including disabled ones): CRC
/// against 0x13FF, direction, timing, COB-IDs, mapping. On an error the
/// communication index of the first bad SRDO is stored in
/// `*pwCommuIndex_p`. Returns kCopSuccessful, kCopInvalidParam (NULL), or
/// the first error: kCopSrdoCfgCrcError, kCopSrdoInvalidCfg (direction
/// above 2 or a transmission type other than 254), kCopSrdoCfgTimingError,
/// kCopSrdoCfgIdError, kCopSrdoCanIdAlreadyInUse, kCopSrdoErrorMapp,
/// kCopSrdoLengthExceeded, kCopSrdoGranularityMismatch.
///
/// # Safety
/// `pwCommuIndex_p` must be NULL or valid for writing a WORD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmCheckSrdoConfig(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pwCommuIndex_p: *mut WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or a writable WORD).
    let out = c_try!(unsafe { ptr::out(pwCommuIndex_p) });
    check_config(out)
}

/// `CcmCheckSrdoConfig` once its pointer is checked. The C entry points
/// that take pointers are `unsafe fn`s, which cargo-mutants does not
/// mutate: each converts its pointers and hands over to a safe function
/// like this one, which holds the logic.
fn check_config(out: Out<WORD>) -> tCopKernel {
    match global::with(|i| i.stack.srdo().check_config(i.stack.od())) {
        Ok(Ok(())) => 0,
        Ok(Err((e, idx))) => {
            out.set(idx);
            e.code()
        }
        Err(e) => e.code(),
    }
}

/// `SrdoCheckConfig`: the module function behind `CcmCheckSrdoConfig`.
///
/// # Safety
/// As `CcmCheckSrdoConfig`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoCheckConfig(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    pwCommuIndex_p: *mut WORD,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: same contract.
    unsafe { instance::here!(CcmCheckSrdoConfig, pwCommuIndex_p) }
}

/// `CcmSendGfc` (only with `SRDO_USE_GFC`): sends the global fail-safe
/// command (id 0x001, DLC 0); the application then sends an SRDO.
/// kCopSrdoNmtError when not OPERATIONAL, kCopSrdoInvalid when 0x1300 is
/// not 1, the driver's code when it refuses the frame.
#[cfg(srdo_use_gfc)]
#[unsafe(no_mangle)]
pub extern "C" fn CcmSendGfc(#[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    code(global::with(|i| {
        let Instance { stack, port, .. } = i;
        let state = stack.nmt_state();
        stack.srdo_mut().send_gfc(port, state)
    }))
}

/// `SrdoSendGfc`: the module function behind `CcmSendGfc`.
#[cfg(srdo_use_gfc)]
#[unsafe(no_mangle)]
pub extern "C" fn SrdoSendGfc(#[cfg(multi_instance)] pInstance: tCopPtrInstance) -> tCopKernel {
    instance::mco_enter!(pInstance);
    instance::here!(CcmSendGfc,)
}

/// `CcmGetSrdoState`: reads the status byte of an SRDO (manual 2.5.3).
/// kCopInvalidParam (NULL), kCopSrdoNotExist.
///
/// # Safety
/// `pbSrdoState_p` must be NULL or valid for writing a byte.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmGetSrdoState(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pbSrdoState_p: *mut BYTE,
    wSrdoCommuIndex_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or a writable byte).
    let out = c_try!(unsafe { ptr::out(pbSrdoState_p) });
    get_state(out, wSrdoCommuIndex_p)
}

/// `CcmGetSrdoState` once its pointer is checked.
fn get_state(out: Out<BYTE>, idx: WORD) -> tCopKernel {
    let mut state = 0;
    if !global::srdo_status(idx, |s| state = *s) {
        let r = global::with_srdo_status(idx, |s| state = *s);
        if r != CopKernel::Successful.code() {
            return r;
        }
    }
    out.set(state);
    CopKernel::Successful.code()
}

/// `SrdoGetState`: the module function behind `CcmGetSrdoState`.
///
/// # Safety
/// As `CcmGetSrdoState`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoGetState(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    pbSrdoState_p: *mut BYTE,
    wSrdoCommuIndex_p: WORD,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: same contract.
    unsafe { instance::here!(CcmGetSrdoState, pbSrdoState_p, wSrdoCommuIndex_p) }
}

/// `CcmSetSrdoState`: writes bits 4-7 of the status byte (bits 0-3 are
/// reserved and stay 0). kCopSrdoNotExist.
#[unsafe(no_mangle)]
pub extern "C" fn CcmSetSrdoState(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    bSrdoState_p: BYTE,
    wSrdoCommuIndex_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // The reserved bits 0-3 of an SRDO's status byte are always 0, so
    // `merge_state` keeps nothing of the old byte on the fast path.
    let fast = |s: &mut u8| *s = bSrdoState_p & !crate::srdo::status::RESERVED_MASK;
    if global::srdo_status(wSrdoCommuIndex_p, fast) {
        return CopKernel::Successful.code();
    }
    global::with_srdo_status(wSrdoCommuIndex_p, |s| {
        *s = crate::srdo::merge_state(*s, bSrdoState_p);
    })
}

/// `SrdoSetState`: the module function behind `CcmSetSrdoState`.
#[unsafe(no_mangle)]
pub extern "C" fn SrdoSetState(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    bSrdoState_p: BYTE,
    wSrdoCommuIndex_p: WORD,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    instance::here!(CcmSetSrdoState, bSrdoState_p, wSrdoCommuIndex_p)
}

/// The communication parameters of `idx` as the C structure.
fn commu_struct(idx: WORD) -> Result<tSrdoCommuParam, CopKernel> {
    let c = global::with(|i| i.stack.srdo().commu_param(i.stack.od(), idx))??;
    Ok(tSrdoCommuParam {
        m_bDirection: c.direction,
        m_wSct: c.sct_ms,
    })
}

/// Writes the communication parameters of `idx` to `p`.
fn get_commu(idx: WORD, p: Out<tSrdoCommuParam>) -> tCopKernel {
    p.give(Ok(commu_struct(idx)))
}

/// The mapping parameters of `idx` as the C structure.
#[cfg(not(srdo_static_mapping))]
fn mapp_struct(idx: WORD) -> Result<tSrdoMappParam, CopKernel> {
    let m = global::with(|i| i.stack.srdo().mapp_param(i.stack.od(), idx))??;
    let mut out = tSrdoMappParam {
        m_bNoOfMappedObjects: m.count,
        m_apMappedVariable: [core::ptr::null_mut(); crate::config::SRDO_MAX_MAPPENTRIES],
    };
    for (o, v) in out.m_apMappedVariable.iter_mut().zip(m.vars.iter()) {
        *o = v.map_or(core::ptr::null_mut(), |s| s.as_ptr() as *mut c_void);
    }
    Ok(out)
}

/// Writes the mapping parameters of `idx` to `p`.
#[cfg(not(srdo_static_mapping))]
fn get_mapp(idx: WORD, p: Out<tSrdoMappParam>) -> tCopKernel {
    p.give(Ok(mapp_struct(idx)))
}

/// `CcmGetSrdoParam`: direction and SCT (`tSrdoCommuParam`) and, with
/// dynamic mapping, the number of mapped objects and pointers to the mapped
/// variables (`tSrdoMappParam`; NULL entries for dummy mappings). NULL
/// structure pointers are skipped. With static mapping the mapping
/// parameters do not exist: a non-NULL third argument gives
/// kCopInvalidParam. kCopSrdoNotExist, kCopSrdoErrorMapp. A refused call
/// writes neither structure.
///
/// # Safety
/// Non-NULL pointers must be valid for writing their structure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmGetSrdoParam(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wSrdoCommuIndex_p: WORD,
    pSrdoCommuParam_p: *mut tSrdoCommuParam,
    pSrdoMappParam_p: *mut tSrdoMappParam,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (each NULL, skipped, or writable).
    let (commu, mapp) = unsafe { (ptr::out(pSrdoCommuParam_p), ptr::out(pSrdoMappParam_p)) };
    get_param(wSrdoCommuIndex_p, commu.ok(), mapp.ok())
}

/// `CcmGetSrdoParam` once its pointers are checked (`None`: NULL).
fn get_param(
    idx: WORD,
    commu_out: Option<Out<tSrdoCommuParam>>,
    mapp_out: Option<Out<tSrdoMappParam>>,
) -> tCopKernel {
    let exists = global::with(|i| i.stack.srdo().get_state(idx).map(|_| ()));
    if let Err(e) = exists.and_then(|r| r) {
        return e.code();
    }
    #[cfg(srdo_static_mapping)]
    if mapp_out.is_some() {
        return CopKernel::InvalidParam.code();
    }
    // Both results first, then the writes: a refusal leaves the caller's
    // structures as they were.
    let commu = match commu_out {
        None => None,
        Some(_) => Some(c_try!(commu_struct(idx))),
    };
    #[cfg(not(srdo_static_mapping))]
    let mapp = match mapp_out {
        None => None,
        Some(_) => Some(c_try!(mapp_struct(idx))),
    };
    if let (Some(out), Some(c)) = (commu_out, commu) {
        out.set(c);
    }
    #[cfg(not(srdo_static_mapping))]
    if let (Some(out), Some(m)) = (mapp_out, mapp) {
        out.set(m);
    }
    0
}

/// `SrdoGetCommuParam`: direction and SCT of an SRDO. kCopInvalidParam
/// (NULL), kCopSrdoNotExist.
///
/// # Safety
/// `pSrdoCommuParam_p` must be NULL or valid for writing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoGetCommuParam(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    wSrdoCommuIndex_p: WORD,
    pSrdoCommuParam_p: *mut tSrdoCommuParam,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: the caller's contract (NULL or writable).
    let out = c_try!(unsafe { ptr::out(pSrdoCommuParam_p) });
    get_commu(wSrdoCommuIndex_p, out)
}

/// `SrdoGetMappParam` (dynamic mapping only). kCopInvalidParam (NULL),
/// kCopSrdoNotExist, kCopSrdoErrorMapp.
///
/// # Safety
/// `pSrdoMappParam_p` must be NULL or valid for writing.
#[cfg(not(srdo_static_mapping))]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoGetMappParam(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    wSrdoCommuIndex_p: WORD,
    pSrdoMappParam_p: *mut tSrdoMappParam,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: the caller's contract (NULL or writable).
    let out = c_try!(unsafe { ptr::out(pSrdoMappParam_p) });
    get_mapp(wSrdoCommuIndex_p, out)
}

/// `CcmCalcSrdoCrc`: the CRC-16 over one SRDO's parameters as they are now
/// (also for a disabled SRDO; nothing is compared). kCopInvalidParam (NULL),
/// kCopSrdoNotExist.
///
/// # Safety
/// `pwCrc_p` must be NULL or valid for writing a WORD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmCalcSrdoCrc(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    wCommuIndex_p: WORD,
    pwCrc_p: *mut WORD,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: the caller's contract (NULL or a writable WORD).
    let out = c_try!(unsafe { ptr::out(pwCrc_p) });
    calc_crc(wCommuIndex_p, out)
}

/// `CcmCalcSrdoCrc` once its pointer is checked.
fn calc_crc(idx: WORD, out: Out<WORD>) -> tCopKernel {
    out.give(global::with(|i| i.stack.srdo().calc_crc(i.stack.od(), idx)))
}

/// `SrdoCalcSrdoCrc`: as `CcmCalcSrdoCrc`; `pSrdoEntry_p` must be NULL
/// (manual 2.11.13), otherwise kCopInvalidParam.
///
/// # Safety
/// `pwCrc_p` must be NULL or valid for writing a WORD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoCalcSrdoCrc(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    wCommuIndex_p: WORD,
    pSrdoEntry_p: *mut c_void,
    pwCrc_p: *mut WORD,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: the caller's contract (NULL or a writable WORD); the entry
    // pointer is only compared with NULL.
    let out = c_try!(unsafe { ptr::out(pwCrc_p) });
    calc_crc_without_entry(wCommuIndex_p, !pSrdoEntry_p.is_null(), out)
}

/// `SrdoCalcSrdoCrc` once its pointers are checked: kCopInvalidParam
/// when an entry pointer was given.
fn calc_crc_without_entry(idx: WORD, entry_given: bool, out: Out<WORD>) -> tCopKernel {
    if entry_given {
        return CopKernel::InvalidParam.code();
    }
    calc_crc(idx, out)
}

/// `CcmStaticDefineSrdoVarFields` (only with `SRDO_USE_STATIC_MAPPING`):
/// hands an SRDO its two contiguous variable fields (normal and inverted
/// data, at most 8 bytes each, no padding). The library checks that the
/// fields are exactly the variables the OD mapping points to and copies
/// frames directly from and to them. kCopInvalidParam (NULL),
/// kCopSrdoNotExist, kCopSrdoErrorMapp (fields do not match the mapping),
/// kCopSrdoLengthExceeded (> 8 bytes), kCopSrdoNmtError (OPERATIONAL).
///
/// # Safety
/// Both fields must stay valid for the mapped length for as long as the
/// stack runs (they are application statics in practice).
#[cfg(srdo_static_mapping)]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmStaticDefineSrdoVarFields(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wCommuIndex_p: WORD,
    pNormalData_p: *mut c_void,
    pInversData_p: *mut c_void,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    if pNormalData_p.is_null() || pInversData_p.is_null() {
        return CopKernel::InvalidParam.code();
    }
    code(global::with(|i| {
        let len = usize::from(i.stack.srdo().mapped_len(i.stack.od(), wCommuIndex_p)?);
        // SAFETY: the caller guarantees both fields hold the mapped length
        // for the lifetime of the stack (NULL was refused above).
        let (n, v) = unsafe {
            (
                ptr::lent_bytes(pNormalData_p, len)?,
                ptr::lent_bytes(pInversData_p, len)?,
            )
        };
        let Instance { stack, .. } = i;
        let od = *stack.od();
        stack
            .srdo_mut()
            .static_define_var_fields(&od, wCommuIndex_p, n, v)
    }))
}

/// `SrdoStaticDefineVarFields`: the module function behind
/// `CcmStaticDefineSrdoVarFields`.
///
/// # Safety
/// As `CcmStaticDefineSrdoVarFields`.
#[cfg(srdo_static_mapping)]
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoStaticDefineVarFields(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    wCommuIndex_p: WORD,
    pNormalData_p: *mut c_void,
    pInversData_p: *mut c_void,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: same contract.
    unsafe {
        instance::here!(
            CcmStaticDefineSrdoVarFields,
            wCommuIndex_p,
            pNormalData_p,
            pInversData_p
        )
    }
}

/// `SrdoInit` (manual 2.11.1): `CcmInitCANopen` initialises the SRDO module
/// itself; calling this afterwards re-reads the SRDO objects of the
/// dictionary and stops every SRDO until the next transition to
/// OPERATIONAL. kCopInvalidParam (NULL), kCopSrdoGranularityMismatch when
/// `m_bGranularity` differs from the library's `SRDO_GRANULARITY`,
/// kCopIllegalInstance before `CcmInitCANopen`.
///
/// # Safety
/// `pInitParam_p` must be NULL or point to a valid `tSrdoInitParam`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoInit(
    #[cfg(multi_instance)] pInstancePtr: *mut tCopPtrInstance,
    pInitParam_p: *const tSrdoInitParam,
) -> tCopKernel {
    instance::mco_enter_ptr!(pInstancePtr);
    // SAFETY: the caller's contract (NULL or a valid tSrdoInitParam).
    unsafe { init_from(pInitParam_p) }
}

/// `SrdoInit` / `SrdoAddInstance` of the addressed instance.
///
/// # Safety
/// `pInitParam_p` must be NULL or point to a valid `tSrdoInitParam`.
unsafe fn init_from(pInitParam_p: *const tSrdoInitParam) -> tCopKernel {
    // SAFETY: the caller's contract (NULL or a valid tSrdoInitParam).
    let p = c_try!(unsafe { ptr::read(pInitParam_p) });
    init(&p)
}

/// `SrdoInit` with a copy of its parameters.
fn init(p: &tSrdoInitParam) -> tCopKernel {
    if p.m_bGranularity != 0 && p.m_bGranularity != crate::config::SRDO_GRANULARITY {
        return CopKernel::SrdoGranularityMismatch.code();
    }
    code(global::with(|i| {
        let od = *i.stack.od();
        i.stack.srdo_mut().init(&od)
    }))
}

/// `SrdoAddInstance`: behaves like `SrdoInit` (the SRDO module of an
/// instance is created by `CcmInitCANopen`).
///
/// # Safety
/// As `SrdoInit`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SrdoAddInstance(
    #[cfg(multi_instance)] pInstancePtr: *mut tCopPtrInstance,
    pInitParam_p: *const tSrdoInitParam,
) -> tCopKernel {
    instance::mco_enter_ptr!(pInstancePtr);
    // SAFETY: the caller's contract (NULL or a valid tSrdoInitParam).
    unsafe { init_from(pInitParam_p) }
}

/// `SrdoDeleteInstance`: stops every SRDO (as leaving OPERATIONAL does);
/// they restart with the next transition to OPERATIONAL.
#[unsafe(no_mangle)]
pub extern "C" fn SrdoDeleteInstance(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    let now = TgtClock.now();
    code(global::with(|i| {
        let node = i.stack.node_id();
        let od = *i.stack.od();
        i.stack
            .srdo_mut()
            .on_state(&od, NmtState::PreOperational, node, now);
        Ok(())
    }))
}

/// `SrdoNmtEvent`: the stack passes every NMT event to the SRDO module
/// itself. Called by the application, an event that matches the node's
/// current state is accepted (kCopSuccessful, nothing changes); one that
/// contradicts it gives kCopSrdoNmtError, so the module can never run out
/// of step with the node.
#[unsafe(no_mangle)]
pub extern "C" fn SrdoNmtEvent(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    NmtEvent_p: tNmtEvent,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    code(global::with(|i| {
        let s = i.stack.nmt_state();
        let consistent = match NmtEvent_p {
            x if x == NmtEvent::EnterOperational as u32 => s == NmtState::Operational,
            x if x == NmtEvent::EnterPreOperational as u32 => s == NmtState::PreOperational,
            x if x == NmtEvent::EnterStopped as u32 => s == NmtState::Stopped,
            x if x <= NmtEvent::PostResetCommunication as u32 => true,
            _ => false,
        };
        if consistent {
            Ok(())
        } else {
            Err(CopKernel::SrdoNmtError)
        }
    }))
}

/// `SrdoProcess`: one processing cycle of the stack (received frames, SRDO
/// checks, timers), exactly as `CcmProcess`, which already calls the SRDO
/// module; returns kCopSrdoNotHandledInApp when an error reported in this
/// cycle was not acknowledged by `AppSrdoError` (status bits 6-7 = 10).
#[unsafe(no_mangle)]
pub extern "C" fn SrdoProcess(#[cfg(multi_instance)] pInstance: tCopPtrInstance) -> tCopKernel {
    instance::mco_enter!(pInstance);
    instance::here!(super::ccm::CcmProcess,)
}
