//! The CCM core API: `CcmInitCANopen`, `CcmConnectToNet`, `CcmProcess`,
//! `CcmShutDownCANopen`, `CcmReadObject`, `CcmWriteObject`, NMT, EMCY,
//! heartbeat and variable tables.
//!
//! Conventions for every function here: the result is a `tCopKernel`
//! (32-bit, the values of errordef.h); pointers are checked before use
//! (`kCopInvalidParam` for NULL); before `CcmInitCANopen` every function
//! returns `kCopIllegalInstance`; called from inside an OBD callback they
//! return `kCopNoResource`.

use core::ffi::c_void;

use super::callbacks::Callbacks;
use super::driver::{self, TgtClock};
use super::global::{self, Instance, code};
use super::instance;
use super::ptr::{self, c_try};
use super::types::*;
use crate::ccm::{NmtCommand, Stack};
use crate::error::{CopKernel, CopResult, to_code};
use crate::od::{ByteOrder, ObjectDictionary, Storage};
use crate::port::Clock;
use crate::wire::emcy::Emergency;

/// Version word of this library: major, minor, release
/// (`COP_STACK_VERSION` layout: bits 0-7 major, 8-15 minor, 16-31 release).
pub const STACK_VERSION: u32 = 5 | (60 << 8) | (1 << 16);

/// `CopGetStackVersion`: the version word (see `COP_GET_MAJOR_VERSION`).
#[unsafe(no_mangle)]
pub extern "C" fn CopGetStackVersion() -> DWORD {
    STACK_VERSION
}

/// `CcmInitCANopen`: builds the dictionary from the application's
/// `ObdInitRam`, initialises the driver (`CdrvInit`) and the stack, and runs
/// the start-up NMT events (kNmtEvEnterInitialising, kNmtEvResetNode,
/// kNmtEvPreResetCommunication, kNmtEvResetCommunication,
/// kNmtEvPostResetCommunication) through the NMT callback. The node stays
/// in INITIALISATION until `CcmConnectToNet`.
///
/// Returns kCopSuccessful; kCopInvalidParam (NULL parameter, no
/// `m_fpObdInitRam`, a `tCcmInitCall` other than the four of cop_types.h,
/// or dictionary tables another instance uses: each instance needs its own
/// objdict.h tables, `OBD_INIT_RAM_NAME`); with several instances
/// kCopInvalidInstanceParam (NULL handle pointer); kCopWrongSignature (objdef.h built with another
/// configuration than the library); kCopObdIllegalPart /
/// kCopObdUnknownObjectType (a dictionary table is unsorted or malformed);
/// kCopInvalidNodeId (node-ID not 1..127, or 0xFF where the build has the
/// LSS slave, `CCM_MODULE_LSSS` in `CCM_MODULE_INTEGRATION`: a node
/// without node-ID, see `CcmProcessLssInitState`); kCopNoFreeInstance (already
/// initialised); the driver's code from `CdrvInit`; an SRDO configuration
/// code from the SRDO module.
///
/// With several instances (`COP_MAX_INSTANCES` > 1) the new instance takes
/// the lowest free handle, written to `*pInstanceHandle` before the
/// start-up NMT events reach the callback (`CCM_ILLINSTANCE_HDL` on a
/// failure); `kCcmFirstInstance` / `kCcmAddCcmInstFirstCdrvInst` start the
/// driver with `CdrvInit`, `kCcmAdditionalInstance` /
/// `kCcmAddCcmInstAddCdrvInst` with `CdrvAddInstance`.
///
/// # Safety
/// `pInitParam_p` must be NULL or point to a valid `tCcmInitParam`;
/// `pInstanceHandle` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmInitCANopen(
    #[cfg(multi_instance)] pInstanceHandle: *mut tCopInstanceHdl,
    pInitParam_p: *mut tCcmInitParam,
    FirstCall_p: tCcmInitCall,
) -> tCopKernel {
    let Some(first) = instance::first_driver_instance(FirstCall_p) else {
        return CopKernel::InvalidParam.code();
    };
    // SAFETY: the caller's contract (NULL or a valid tCcmInitParam).
    let p = c_try!(unsafe { ptr::read(pInitParam_p) });
    instance::ccm_enter_new!(pInstanceHandle => out);
    match init(&p, first) {
        Ok(()) => {
            out.publish();
            global::pump(|i, now| i.stack.drain(&mut i.port, now));
            CopKernel::Successful.code()
        }
        Err(e) => e.code(),
    }
}

fn init(p: &tCcmInitParam, first: bool) -> CopResult {
    let Some(init_ram) = p.m_fpObdInitRam else {
        return Err(CopKernel::InvalidParam);
    };
    if global::with(|_| ()).is_ok() {
        return Err(CopKernel::NoFreeInstance);
    }
    let mut ram = tObdRamParam::zeroed();
    // SAFETY: ObdInitRam (objdef.h) fills the tObdRamParam it is given.
    let ret = unsafe { init_ram(&mut ram as *mut tObdRamParam as *mut c_void) };
    if ret != 0 {
        return Err(CopKernel::InvalidParam);
    }
    if !core::ptr::eq(ram.m_pbAbiSignature, &super::COP_LIB_ABI_SIGNATURE) {
        return Err(CopKernel::WrongSignature);
    }
    // SAFETY: objdef.h emits each part as a static array ending with index
    // 0xFFFF (or NULL for an absent part).
    let (generic, man, dev, usr) = unsafe {
        (
            ptr::c_table(ram.m_pGenericPart),
            ptr::c_table(ram.m_pManufacturerPart),
            ptr::c_table(ram.m_pDevicePart),
            ptr::c_table(ram.m_pUserPart),
        )
    };
    // Each instance its own objdict.h tables (OBD_INIT_RAM_NAME): two on
    // one set would share every value and attached variable.
    if let Some(first) = [generic, man, dev].into_iter().find(|t| !t.is_empty()) {
        if global::dictionary_in_use(first) {
            return Err(CopKernel::InvalidParam);
        }
    }
    let mut od = ObjectDictionary::new(generic, man, dev).map_err(|e| e.code)?;
    od.set_user_part(usr).map_err(|e| e.code)?;
    od.set_callback_handle(instance::callback_handle());
    // SAFETY: objdef.h points to a static tSrdoAppCallbacks or leaves
    // the pointer NULL (no SRDO objects).
    let srdo_callbacks = unsafe { ptr::read(ram.m_pSrdoCallbacks) }.ok();
    let mut cdrv = tCdrvInitParam {
        m_BaudIndex: p.m_BaudIndex,
        m_pBdiTable: p.m_pBdiTable,
        m_wSizeOfBdiTab: p.m_wSizeOfBdiTab,
        m_dwAmr: p.m_dwAmr,
        m_dwAcr: p.m_dwAcr,
        m_HwParam: p.m_HwParam,
        m_RxBuffHigh: ram.m_RxBuffHigh,
        m_TxBuffHigh: ram.m_TxBuffHigh,
        m_RxBuffLow: ram.m_RxBuffLow,
        m_TxBuffLow: ram.m_TxBuffLow,
        m_fpEnableInterrupt: p.m_fpCanInterruptEnable,
    };
    #[cfg(ccm_module_lsss)]
    let stack = Stack::with_lss(od, p.m_bInitNodeId)?;
    #[cfg(not(ccm_module_lsss))]
    let stack = Stack::new(od, p.m_bInitNodeId)?;
    let port = driver::init(&mut cdrv, first)?;
    global::install(Instance {
        stack,
        port,
        callbacks: Callbacks {
            nmt: p.m_fpNmtEventCallback,
            error: global::take_early_error_callback(),
            srdo: srdo_callbacks,
            ..Callbacks::default()
        },
        tables: Default::default(),
    })
}

/// `CcmShutDownCANopen`: stops the stack and deletes the driver instance
/// (`CdrvDeleteInstance`). kCopIllegalInstance when not initialised.
#[unsafe(no_mangle)]
pub extern "C" fn CcmShutDownCANopen(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    match global::remove() {
        Ok(i) => to_code(driver::delete_instance(&i.port)),
        Err(e) => e.code(),
    }
}

/// `CcmConnectToNet`: INITIALISATION -> PRE-OPERATIONAL (boot-up message,
/// kNmtEvEnterPreOperational). kCopNmtStateError when already connected,
/// kCopLsssInvalidNodeId while the node has no node-ID (LSS).
#[unsafe(no_mangle)]
pub extern "C" fn CcmConnectToNet(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let r = global::with(|i| i.stack.connect());
    if matches!(r, Ok(Ok(()))) {
        global::pump(|i, now| i.stack.drain(&mut i.port, now));
    }
    code(r)
}

/// `CcmProcess`: one processing cycle (received frames, SRDO checks,
/// timers); the application's callbacks run inside this call. Returns
/// kCopSuccessful, kCopIllegalInstance before `CcmInitCANopen`, or
/// kCopSrdoNotHandledInApp when an SRDO error reported in this cycle was
/// not acknowledged by `AppSrdoError` (manual 2.11.6; the application has
/// also been told through `AppSrdoError` itself).
#[unsafe(no_mangle)]
pub extern "C" fn CcmProcess(#[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let r = global::with(|i| {
        i.tables.sync(&mut i.stack, &mut i.port);
        i.stack.begin_cycle()
    });
    if r.is_err() {
        return code(r.map(|()| Ok(())));
    }
    if global::pump(|i, now| i.stack.poll(&mut i.port, now)) {
        return CopKernel::SrdoNotHandledInApp.code();
    }
    CopKernel::Successful.code()
}

/// `CcmProcessLssInitState`: one processing cycle (as `CcmProcess`) of a
/// node started without node-ID (0xFF, LSS slave built in), before
/// `CcmConnectToNet`: only LSS requests (CiA 305) are answered. Returns
/// kCopLsssInvalidNodeId while the node has no node-ID; kCopSuccessful once
/// an LSS master gave it one and switched the LSS state back to waiting
/// (the node took it with a reset communication, whose NMT events ran in
/// this call), and for a node that has one from the start;
/// kCopIllegalInstance before `CcmInitCANopen`.
#[unsafe(no_mangle)]
pub extern "C" fn CcmProcessLssInitState(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let r = instance::here!(CcmProcess,);
    if r != CopKernel::Successful.code() {
        return r;
    }
    code(global::with(|i| i.stack.lss_init_state()))
}

/// `CcmReadObject`: copies the value of an object (CPU byte order) into
/// `pDstData_p`; `*pSize_p` is the buffer size on entry and the number of
/// bytes read on return.
///
/// Returns kCopSuccessful, kCopInvalidParam (NULL pointer),
/// kCopObdIndexNotExist, kCopObdSubindexNotExist, kCopObdReadViolation,
/// kCopObdValueLengthError (buffer too small), kCopObdVarEntryNotExist
/// (USERDEF object without variable), or the code an OBD callback returned.
///
/// # Safety
/// `pDstData_p` must be valid for `*pSize_p` bytes of writes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmReadObject(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wIndex_p: WORD,
    bSubindex_p: BYTE,
    pDstData_p: *mut c_void,
    pSize_p: *mut tObdSize,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (a size variable, NULL refused).
    let size = c_try!(unsafe { ptr::out(pSize_p) });
    // SAFETY: the caller's contract (`*pSize_p` writable bytes; NULL
    // refused).
    let out = c_try!(unsafe { ptr::bytes_mut(pDstData_p, obd_size_len(size.get())) });
    let r = global::with(|i| {
        i.stack
            .read_object(wIndex_p, bSubindex_p, ByteOrder::Native, out)
    });
    match r {
        Ok(Ok(n)) => {
            // n <= the buffer's size, which came as a tObdSize.
            size.set(n as tObdSize);
            CopKernel::Successful.code()
        }
        Ok(Err(e)) => e.kernel.code(),
        Err(e) => e.code(),
    }
}

/// `CcmWriteObject`: writes an object (CPU byte order) through the same
/// checks as an SDO download: access rights, size, value range, module
/// rules (SRDO parameters), OBD callbacks. A refused write changes
/// nothing.
///
/// Returns kCopSuccessful, kCopInvalidParam (NULL data with a size),
/// kCopObdIndexNotExist, kCopObdSubindexNotExist, kCopObdWriteViolation,
/// kCopObdValueLengthError, kCopObdValueToLow, kCopObdValueToHigh,
/// kCopObdVarEntryNotExist, kCopSrdo* codes for SRDO parameters, or the code
/// an OBD callback returned.
///
/// # Safety
/// `pSrcData_p` must be valid for `Size_p` bytes of reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmWriteObject(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wIndex_p: WORD,
    bSubindex_p: BYTE,
    pSrcData_p: *const c_void,
    Size_p: tObdSize,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (`Size_p` readable bytes).
    let data =
        c_try!(unsafe { ptr::slice_or_empty(pSrcData_p as *const u8, obd_size_len(Size_p)) });
    let now = TgtClock.now();
    let r = global::with(|i| {
        i.stack
            .write_object(wIndex_p, bSubindex_p, ByteOrder::Native, data, now)
            .map_err(|e| e.kernel)
    });
    let c = code(r);
    // A write may have queued events (e.g. an SRDO configuration change).
    global::pump(|i, now| i.stack.drain(&mut i.port, now));
    c
}

/// `CcmObdGetNodeState`: the NMT state (`kNodeState*`), 0 before
/// initialisation.
#[unsafe(no_mangle)]
pub extern "C" fn CcmObdGetNodeState(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> BYTE {
    instance::ccm_enter!(InstanceHandle);
    global::with(|i| i.stack.nmt_state() as u8).unwrap_or(0)
}

/// `CcmLsssGetNodeId`: this node's ID (0xFF while a node started for LSS
/// has none, see `CcmProcessLssInitState`), 0 before initialisation.
#[unsafe(no_mangle)]
pub extern "C" fn CcmLsssGetNodeId(#[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl) -> BYTE {
    instance::ccm_enter!(InstanceHandle);
    global::with(|i| i.stack.node_id()).unwrap_or(0)
}

/// `CcmNmtsExecCommand`: a local NMT command (kNmtComm*).
/// kCopNmtUnknownCommand for an unknown value, kCopNmtStateError before
/// `CcmConnectToNet`.
#[unsafe(no_mangle)]
pub extern "C" fn CcmNmtsExecCommand(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    NmtCommand_p: tNmtCommand,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let Some(cmd) = NmtCommand::from_u16(NmtCommand_p) else {
        return CopKernel::NmtUnknownCommand.code();
    };
    let r = global::with(|i| i.stack.exec_command(cmd));
    global::pump(|i, now| i.stack.drain(&mut i.port, now));
    code(r)
}

/// `CcmRegisterErrorCallback`: the callback that hears of the codes the
/// application's callbacks return (unchanged: an NMT callback returning
/// an error at kNmtEvResetCommunication, also inside `CcmInitCANopen`) and
/// of the library's own reports; NULL removes it. Registered before
/// `CcmInitCANopen`, it is the callback of the instance that call starts
/// (the function returns void, so it cannot refuse).
#[unsafe(no_mangle)]
pub extern "C" fn CcmRegisterErrorCallback(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    fpErrorCallback_p: tCcmErrorCallback,
) {
    instance::ccm_enter!(InstanceHandle);
    global::register_error_callback(fpErrorCallback_p);
}

/// `CcmConfigHbp`: sets the producer heartbeat time (writes 0x1017).
/// kCopNmtLifeguardVsHeartbeat for a non-zero time while life guarding is
/// configured (`CcmInitLgs` and a non-zero life time); otherwise the codes
/// of the object write.
#[unsafe(no_mangle)]
pub extern "C" fn CcmConfigHbp(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wHbProducerTime_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let now = TgtClock.now();
    code(global::with(|i| i.stack.config_hbp(wHbProducerTime_p, now)))
}

/// `CcmConfigEmcp`: sets the EMCY COB-ID (bit 31 disables the producer),
/// through 0x1014 where the dictionary has it; called from the NMT
/// callback at kNmtEvResetCommunication it holds after the reset.
/// kCopInvalidParam for a COB-ID an emergency cannot use (bit 30 set, an
/// identifier CiA 301 reserves, 29 bits without CAN 2.0B); otherwise the
/// codes of the object write.
#[unsafe(no_mangle)]
pub extern "C" fn CcmConfigEmcp(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    dwEmcpProducerCobId_p: DWORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let now = TgtClock.now();
    code(global::with(|i| {
        i.stack.config_emcp(dwEmcpProducerCobId_p, now)
    }))
}

/// `CcmSendEmergency`: sends an emergency message and records it in
/// 0x1001/0x1003. kCopInvalidParam for NULL, kCopNmtStateError when not
/// connected or STOPPED, kCopNoResource when the inhibit-time queue is full,
/// kCopCobIllegalCanId when the producer is switched off (0x1014 bit 31).
///
/// # Safety
/// `pEmcpParam_p` must be NULL or point to a valid `tEmcParam`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmSendEmergency(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pEmcpParam_p: *const tEmcParam,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or a valid tEmcParam).
    let p = c_try!(unsafe { ptr::read(pEmcpParam_p) });
    let e = Emergency {
        code: p.m_wEmcyErrorCode,
        register: p.m_bErrorRegister,
        manufacturer: p.m_abManufactErrorCode,
    };
    let now = TgtClock.now();
    code(global::with(|i| {
        i.stack.send_emergency(&mut i.port, now, e)
    }))
}

/// `CcmDefineVarTab`: attaches application variables to USERDEF / DOMAIN
/// objects (their `tObdVarEntry`). kCopInvalidParam for NULL (the table,
/// or an `m_pData` of NULL with kVarValidData: then no entry is taken),
/// kCopObdIndexNotExist / kCopObdSubindexNotExist, kCopObdVarEntryNotExist
/// when the object is not a USERDEF/DOMAIN object, kCopObdValueLengthError
/// when the size does not fit the object's type. Entries before a failing
/// one stay defined.
///
/// # Safety
/// `pVarTab_p` must point to `wNumOfVars_p` valid entries whose `m_pData`
/// variables outlive the stack.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmDefineVarTab(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pVarTab_p: *const tVarParam,
    wNumOfVars_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (wNumOfVars_p entries; NULL refused).
    let tab = c_try!(unsafe { ptr::slice(pVarTab_p, usize::from(wNumOfVars_p)) });
    // A NULL variable is refused before anything changes (README, API
    // conventions: NULL pointers give kCopInvalidParam).
    if tab
        .iter()
        .any(|v| v.m_bValidFlag & var_valid::DATA != 0 && v.m_pData.is_null())
    {
        return CopKernel::InvalidParam.code();
    }
    code(global::with(|i| {
        for v in tab {
            define_var(i.stack.od(), v)?;
        }
        Ok(())
    }))
}

fn define_var(od: &ObjectDictionary, v: &tVarParam) -> CopResult {
    let obj = od.find(v.m_wIndex, v.m_bSubindex).map_err(|e| e.kernel)?;
    let Ok(Storage::Var(entry)) = obj
        .desc()
        .storage(0)
        .ok_or(())
        .and_then(|_| obj.storage().map_err(|_| ()))
    else {
        return Err(CopKernel::ObdVarEntryNotExist);
    };
    use core::sync::atomic::Ordering::Relaxed;
    if v.m_bValidFlag & var_valid::SIZE != 0 {
        let size = obd_size_len(v.m_Size);
        if let Some(w) = obj.data_type().wire_size() {
            if !crate::od::value::size_fits(obj.data_type(), size) || size < w {
                return Err(CopKernel::ObdValueLengthError);
            }
        }
        entry.m_Size.store(v.m_Size, Relaxed);
    }
    if v.m_bValidFlag & var_valid::DATA != 0 {
        entry.m_pData.store(v.m_pData, Relaxed);
    }
    if v.m_bValidFlag & var_valid::CALLBACK != 0 {
        let f = v
            .m_fpCallback
            .map_or(core::ptr::null_mut(), |f| f as *mut c_void);
        entry.m_fpCallback.store(f, Relaxed);
    }
    if v.m_bValidFlag & var_valid::ARG != 0 {
        entry.m_pArg.store(v.m_pArg, Relaxed);
    }
    Ok(())
}
