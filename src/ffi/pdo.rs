//! The SYS TEC PDO and SYNC API (cop.h "functions within ccmdfpdo.c,
//! ccmstpdo.c, ccmsnpdo.c, ccmsync.c"): `CcmDefinePdoTab`,
//! `CcmDefineStaticPdoTab`, `CcmSignalStaticPdo`, `CcmSignalCheckVar`,
//! `CcmSignalVar`, `CcmSendPdo`, `CcmInitSyncConsumer`,
//! `CcmConfigSyncConsumer`, `CcmEnterCriticalSectionPdoProcess`,
//! `CcmLeaveCriticalSectionPdoProcess`, and the per-PDO `tPdoCallback`s.
//!
//! Conventions as in [`super::ccm`]: results are `tCopKernel` values,
//! pointers are checked first (`kCopInvalidParam` for NULL), every function
//! returns `kCopIllegalInstance` before `CcmInitCANopen` and
//! `kCopNoResource` when called from inside an OBD callback.

use core::ffi::c_void;

use super::callbacks::{pdo_slot, set_pdo};
use super::global::{self, code};
use super::instance;
use super::ptr::{self, c_try};
#[cfg(multi_instance)]
use super::types::tCopInstanceHdl;
use super::types::{BYTE, DWORD, WORD, assert_offsets, tCopKernel};
use crate::error::CopKernel;
use crate::pdo::{Direction, PDO_MAX_MAPPENTRIES, PdoParam, StaticPdoParam};

pub use super::types::tPdoCallback;

/// `kPdoTypeSend`.
pub const kPdoTypeSend: BYTE = 0;
/// `kPdoTypeRecv`.
pub const kPdoTypeRecv: BYTE = 1;
/// `PDO_INVALID_INDEX` (`tPdoIndex` is a WORD).
pub const PDO_INVALID_INDEX: WORD = 0xFFFF;

/// `tPdoParamValid` flags of `tPdoParam::m_bValidFlag`.
pub mod pdo_valid {
    /// kPdoValidCanId.
    pub const CAN_ID: u8 = 0x01;
    /// kPdoValidTxType.
    pub const TX_TYPE: u8 = 0x02;
    /// kPdoValidInihibitTime (sic).
    pub const INHIBIT_TIME: u8 = 0x04;
    /// kPdoValidEventTime.
    pub const EVENT_TIME: u8 = 0x08;
    /// kPdoValidNrOfEntries.
    pub const NR_OF_ENTRIES: u8 = 0x10;
    /// kPdoValidMappObjects.
    pub const MAPP_OBJECTS: u8 = 0x20;
    /// kPdoValidCallback.
    pub const CALLBACK: u8 = 0x40;
    /// kPdoValidCommunication.
    pub const COMMUNICATION: u8 = 0x0F;
    /// kPdoValidMapping.
    pub const MAPPING: u8 = 0x30;
    /// kPdoValidAll.
    pub const ALL: u8 = 0x7F;
}

/// `tPdoParam` (`CcmDefinePdoTab`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tPdoParam {
    /// Which fields are valid (`kPdoValid*`).
    pub m_bValidFlag: BYTE,
    /// Communication parameter index.
    pub m_wPdoCommuIndex: WORD,
    /// `kPdoTypeSend` or `kPdoTypeRecv`.
    pub m_bPdoType: BYTE,
    /// Added to the identifier of `m_dwCanId` (0: none).
    pub m_bNodeID: BYTE,
    /// COB-ID (CiA 301 layout).
    pub m_dwCanId: DWORD,
    /// Transmission type.
    pub m_bTxTyp: BYTE,
    /// Inhibit time (100 µs).
    pub m_wInhibitTime: WORD,
    /// Event timer (ms).
    pub m_wEventTime: WORD,
    /// Number of mapped objects.
    pub m_bNrOfEntries: BYTE,
    /// Mapping entries (index << 16 | subindex << 8 | bits).
    pub m_adwMappParam: [DWORD; PDO_MAX_MAPPENTRIES],
    /// The PDO's callback.
    pub m_fpCallback: tPdoCallback,
}

/// `tPdoStaticParam` (`CcmDefineStaticPdoTab`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tPdoStaticParam {
    /// Communication parameter index.
    pub m_wPdoCommuIndex: WORD,
    /// COB-ID (CiA 301 layout).
    pub m_dwCanId: DWORD,
    /// Transmission type.
    pub m_bTxTyp: BYTE,
    /// Inhibit time (100 µs).
    pub m_wInhibitTime: WORD,
    /// Event timer (ms).
    pub m_wEventTime: WORD,
    /// Number of bytes at `m_pVarData` (at most 8).
    pub m_bSize: BYTE,
    /// The PDO's data.
    pub m_pVarData: *mut c_void,
    /// The PDO's callback.
    pub m_fpCallback: tPdoCallback,
}

/// `tMPdoParam` (multiplexed PDOs; declared for source compatibility, the
/// MPDO services are not part of this library).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tMPdoParam {
    /// 0 SAM, 1 DAM.
    pub m_bMPdoType: BYTE,
    /// Index.
    pub m_wIndex: WORD,
    /// Subindex.
    pub m_bSubindex: BYTE,
    /// Data.
    pub m_pData: *mut c_void,
    /// `tObdType` (a WORD).
    pub m_ObjType: WORD,
}

const PTR: usize = core::mem::size_of::<*const c_void>();
const fn round_up(n: usize, to: usize) -> usize {
    n.div_ceil(to) * to
}
assert_offsets!(tPdoParam {
    m_wPdoCommuIndex: 2,
    m_bNodeID: 5,
    m_dwCanId: 8,
    m_bTxTyp: 12,
    m_wInhibitTime: 14,
    m_wEventTime: 16,
    m_bNrOfEntries: 18,
    m_adwMappParam: 20,
});
// ARM (ILP32): 56 bytes with 8 entries; LP64 host: 64.
static_assertions::const_assert_eq!(
    core::mem::size_of::<tPdoParam>(),
    round_up(20 + 4 * PDO_MAX_MAPPENTRIES, PTR) + PTR
);
assert_offsets!(tPdoStaticParam {
    m_dwCanId: 4,
    m_bTxTyp: 8,
    m_wInhibitTime: 10,
    m_wEventTime: 12,
    m_bSize: 14,
    m_pVarData: 16,
});
// ARM: 24 bytes; LP64 host: 32.
static_assertions::const_assert_eq!(core::mem::size_of::<tPdoStaticParam>(), 16 + 2 * PTR);
assert_offsets!(tMPdoParam {
    m_bSubindex: 4,
    m_pData: round_up(5, PTR),
});
// ARM: 16 bytes; LP64 host: 24.
static_assertions::const_assert_eq!(
    core::mem::size_of::<tMPdoParam>(),
    round_up(round_up(5, PTR) + PTR + 2, PTR)
);
// ILP32: 56 bytes with 8 entries, 280 with 64 (PDO_MAX_MAPPENTRIES).
#[cfg(target_pointer_width = "32")]
static_assertions::const_assert_eq!(
    core::mem::size_of::<tPdoParam>(),
    24 + 4 * PDO_MAX_MAPPENTRIES
);
#[cfg(target_pointer_width = "32")]
static_assertions::const_assert_eq!(core::mem::size_of::<tPdoStaticParam>(), 24);
static_assertions::assert_eq_size!(tPdoCallback, *const c_void);

/// Converts one `tPdoParam` into the core's definition (pure, so that the
/// valid-flag rules can be tested without a driver).
pub fn pdo_param(p: &tPdoParam) -> Result<PdoParam<'_>, CopKernel> {
    let direction = match p.m_bPdoType {
        kPdoTypeSend => Direction::Tx,
        kPdoTypeRecv => Direction::Rx,
        _ => return Err(CopKernel::InvalidParam),
    };
    let f = p.m_bValidFlag;
    let has = |flag: u8| f & flag != 0;
    if has(pdo_valid::NR_OF_ENTRIES) && usize::from(p.m_bNrOfEntries) > PDO_MAX_MAPPENTRIES {
        return Err(CopKernel::PdoLengthExceeded);
    }
    Ok(PdoParam {
        commu_index: p.m_wPdoCommuIndex,
        direction,
        node_id: p.m_bNodeID,
        cob_id: has(pdo_valid::CAN_ID).then_some(p.m_dwCanId),
        tx_type: has(pdo_valid::TX_TYPE).then_some(p.m_bTxTyp),
        inhibit_time: has(pdo_valid::INHIBIT_TIME).then_some(p.m_wInhibitTime),
        event_time: has(pdo_valid::EVENT_TIME).then_some(p.m_wEventTime),
        entry_count: has(pdo_valid::NR_OF_ENTRIES).then_some(p.m_bNrOfEntries),
        entries: has(pdo_valid::MAPP_OBJECTS).then_some(&p.m_adwMappParam[..]),
        notify: has(pdo_valid::CALLBACK).then_some(p.m_fpCallback.is_some()),
    })
}

/// `CcmDefinePdoTab`: defines PDOs from a table (normally in the NMT
/// callback at kNmtEvResetCommunication). Each entry writes its valid
/// parameters through the dictionary in the CiA 301 order (PDO invalid,
/// communication parameters, mapping, COB-ID last), so the same rules as
/// for an SDO download apply; `m_bNodeID` is added to the identifier of
/// `m_dwCanId` when its node-ID bits (0..6) are 0 (a base such as 0x180);
/// a full identifier (0x181 with node 1) is used as it is. Entries before a failing one stay defined; the failing PDO
/// stays invalid.
///
/// Returns kCopSuccessful; kCopInvalidParam (NULL table, `m_bPdoType`
/// neither kPdoTypeSend nor kPdoTypeRecv or not matching the index, a
/// reserved transmission type, a restricted or malformed COB-ID);
/// kCopPdoNotExist (no such PDO in the dictionary or beyond
/// `PDO_MAX_RXPDO_IN_OBD` / `PDO_MAX_TXPDO_IN_OBD`); kCopPdoLengthExceeded
/// (more than `PDO_MAX_MAPPENTRIES` entries or more than 64 bits);
/// kCopPdoErrorMapp (object not mappable or wrong length);
/// kCopPdoGranularityMismatch; kCopPdoVarNotFound (mapped object missing);
/// kCopObdWriteViolation (a parameter object is constant).
///
/// # Safety
/// `pPdoTab_p` must be NULL or point to `wNumOfPdos_p` valid entries.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmDefinePdoTab(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pPdoTab_p: *const tPdoParam,
    wNumOfPdos_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (wNumOfPdos_p entries; NULL refused).
    let tab = c_try!(unsafe { ptr::slice(pPdoTab_p, usize::from(wNumOfPdos_p)) });
    global::run_at(|i, now| {
        for p in tab {
            let param = pdo_param(p)?;
            if p.m_bValidFlag & pdo_valid::CALLBACK != 0 {
                if pdo_slot(p.m_wPdoCommuIndex).is_none() {
                    return Err(CopKernel::PdoNotExist);
                }
                set_pdo(p.m_wPdoCommuIndex, p.m_fpCallback, global::current());
            }
            i.stack.define_pdo(&param, now)?;
        }
        Ok(())
    })
}

/// `CcmDefineStaticPdoTab`: defines PDOs whose data are a byte block of
/// the application (`m_pVarData`, `m_bSize` bytes) instead of a mapping.
/// The communication parameters are written as by `CcmDefinePdoTab`; the
/// callback is registered when `m_fpCallback` is not NULL. The block must
/// stay valid while the stack runs.
///
/// Returns kCopSuccessful; kCopInvalidParam (NULL table, NULL
/// `m_pVarData` with a size, a reserved transmission type, a restricted
/// COB-ID); kCopPdoNotExist; kCopPdoLengthExceeded (`m_bSize` above 8).
///
/// # Safety
/// `pPdoTab_p` must be NULL or point to `wNumOfPdos_p` valid entries whose
/// `m_pVarData` blocks outlive the stack.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmDefineStaticPdoTab(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pPdoTab_p: *const tPdoStaticParam,
    wNumOfPdos_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (wNumOfPdos_p entries; NULL refused).
    let tab = c_try!(unsafe { ptr::slice(pPdoTab_p, usize::from(wNumOfPdos_p)) });
    for p in tab {
        if p.m_pVarData.is_null() && p.m_bSize > 0 {
            return CopKernel::InvalidParam.code();
        }
        if p.m_bSize > 8 {
            return CopKernel::PdoLengthExceeded.code();
        }
    }
    global::run_at(|i, now| {
        for p in tab {
            let data = if p.m_bSize == 0 {
                &[]
            } else {
                // SAFETY: the caller's contract (m_bSize bytes that outlive
                // the stack; NULL was refused above).
                unsafe { ptr::lent_bytes(p.m_pVarData, usize::from(p.m_bSize)) }?
            };
            if pdo_slot(p.m_wPdoCommuIndex).is_none() {
                return Err(CopKernel::PdoNotExist);
            }
            set_pdo(p.m_wPdoCommuIndex, p.m_fpCallback, global::current());
            let param = StaticPdoParam {
                commu_index: p.m_wPdoCommuIndex,
                cob_id: p.m_dwCanId,
                tx_type: p.m_bTxTyp,
                inhibit_time: p.m_wInhibitTime,
                event_time: p.m_wEventTime,
                data,
                notify: p.m_fpCallback.is_some(),
            };
            i.stack.define_static_pdo(&param, now)?;
        }
        Ok(())
    })
}

/// `CcmSignalStaticPdo`: signals that a TPDO's data changed. Types 254/255
/// are sent in the next `CcmProcess` (inhibit time permitting), type 0 with
/// the next SYNC; other types ignore the signal.
///
/// Returns kCopSuccessful or kCopPdoNotExist (not a TPDO of the
/// dictionary).
#[unsafe(no_mangle)]
pub extern "C" fn CcmSignalStaticPdo(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wCommuIndex_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    code(global::with(|i| i.stack.signal_pdo(wCommuIndex_p)))
}

/// `CcmSignalCheckVar`: the next `CcmProcess` compares the data of every
/// event-driven and type 0 TPDO with what it sent last and signals the
/// changed ones. Returns kCopSuccessful.
#[unsafe(no_mangle)]
pub extern "C" fn CcmSignalCheckVar(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run(|i| {
        i.stack.signal_check_var();
    })
}

/// `CcmSignalVar`: signals every valid TPDO that maps the variable at
/// `pVar_p` (the variable of a RAM object or the one attached with
/// `CcmDefineVarTab`). The pointer is compared, never dereferenced.
///
/// Returns kCopSuccessful, kCopInvalidParam (NULL) or kCopPdoVarNotFound
/// (no valid TPDO maps the variable).
#[unsafe(no_mangle)]
pub extern "C" fn CcmSignalVar(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pVar_p: *mut c_void,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let addr = c_try!(ptr::address(pVar_p));
    code(global::with(|i| i.stack.signal_var_at(addr)))
}

/// `CcmSendPdo`: samples and sends a TPDO now without looking at its
/// transmission type, inhibit time or event timer (both restart). The
/// PDO's callback runs before this function returns.
///
/// Returns kCopSuccessful; kCopPdoNotExist (not a TPDO of the dictionary);
/// kCopNmtStateError (node not OPERATIONAL); kCopPdoErrorSend (PDO
/// invalid); kCopPdoErrorPdoEncode (a mapped object cannot be read); the
/// driver's code (e.g. kCopCdrvTxBuffLowOverrun).
#[unsafe(no_mangle)]
pub extern "C" fn CcmSendPdo(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wCommuIndex_p: WORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run_at(|i, now| i.stack.send_pdo(&mut i.port, wCommuIndex_p, now))
}

/// `CcmInitSyncConsumer`: (re)reads 0x1005–0x1007. The SYNC consumer is
/// active from the start (COB-ID of 0x1005, 0x80 without that object).
/// Returns kCopSuccessful.
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitSyncConsumer(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    code(global::with(|i| i.stack.init_sync_consumer()))
}

/// `CcmConfigSyncConsumer`: sets the SYNC COB-ID and the synchronous
/// window length (µs), through 0x1005 / 0x1007 where the dictionary has
/// them.
///
/// Returns kCopSuccessful or kCopInvalidParam (bit 30 set — making this
/// node the SYNC producer is `CcmConfigSyncProducer`'s job —, a restricted
/// or malformed identifier).
#[unsafe(no_mangle)]
pub extern "C" fn CcmConfigSyncConsumer(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    dwSyncId_p: DWORD,
    dwSyncWindowLength_p: DWORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run_at(|i, now| {
        i.stack
            .config_sync_consumer(dwSyncId_p, dwSyncWindowLength_p, now)
    })
}

/// `CcmEnterCriticalSectionPdoProcess`: until the matching leave,
/// `CcmProcess` neither writes received PDO data into variables nor reads
/// variables for TPDOs (received RPDOs are kept, the latest per PDO). Calls
/// nest. Ignored before `CcmInitCANopen` and inside OBD callbacks.
#[unsafe(no_mangle)]
pub extern "C" fn CcmEnterCriticalSectionPdoProcess(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) {
    instance::ccm_enter!(InstanceHandle);
    let _ = global::with(|i| i.stack.enter_critical_pdo());
}

/// `CcmLeaveCriticalSectionPdoProcess`: ends one level of
/// `CcmEnterCriticalSectionPdoProcess`; kept RPDO data reach their
/// variables in the next `CcmProcess`.
#[unsafe(no_mangle)]
pub extern "C" fn CcmLeaveCriticalSectionPdoProcess(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) {
    instance::ccm_enter!(InstanceHandle);
    let _ = global::with(|i| i.stack.leave_critical_pdo());
}

#[cfg(test)]
mod tests {
    use super::*;

    unsafe extern "C" fn cb(_w: WORD) -> tCopKernel {
        0
    }

    fn param(flags: u8) -> tPdoParam {
        tPdoParam {
            m_bValidFlag: flags,
            m_wPdoCommuIndex: 0x1800,
            m_bPdoType: kPdoTypeSend,
            m_bNodeID: 3,
            m_dwCanId: 0x180,
            m_bTxTyp: 254,
            m_wInhibitTime: 10,
            m_wEventTime: 100,
            m_bNrOfEntries: 2,
            m_adwMappParam: [0x2000_0108; PDO_MAX_MAPPENTRIES],
            m_fpCallback: Some(cb),
        }
    }

    #[test]
    fn valid_flags_select_fields() {
        let all = param(pdo_valid::ALL);
        let p = pdo_param(&all).unwrap();
        assert_eq!(p.direction, Direction::Tx);
        assert_eq!(p.node_id, 3);
        assert_eq!(p.cob_id, Some(0x180));
        assert_eq!(p.tx_type, Some(254));
        assert_eq!(p.inhibit_time, Some(10));
        assert_eq!(p.event_time, Some(100));
        assert_eq!(p.entry_count, Some(2));
        assert_eq!(p.entries.map(<[u32]>::len), Some(PDO_MAX_MAPPENTRIES));
        assert_eq!(p.notify, Some(true));

        let comm = param(pdo_valid::COMMUNICATION);
        let p = pdo_param(&comm).unwrap();
        assert_eq!((p.entry_count, p.entries, p.notify), (None, None, None));
        assert!(p.cob_id.is_some() && p.event_time.is_some());

        let map = param(pdo_valid::MAPPING);
        let p = pdo_param(&map).unwrap();
        assert_eq!((p.cob_id, p.tx_type, p.inhibit_time), (None, None, None));
        assert_eq!(p.entry_count, Some(2));

        let mut no_cb = param(pdo_valid::CALLBACK);
        no_cb.m_fpCallback = None;
        assert_eq!(pdo_param(&no_cb).unwrap().notify, Some(false));
    }

    #[test]
    fn direction_and_count_are_checked() {
        let mut p = param(pdo_valid::ALL);
        p.m_bPdoType = kPdoTypeRecv;
        assert_eq!(pdo_param(&p).unwrap().direction, Direction::Rx);
        p.m_bPdoType = 2;
        assert_eq!(pdo_param(&p).err(), Some(CopKernel::InvalidParam));
        let mut p = param(pdo_valid::ALL);
        p.m_bNrOfEntries = PDO_MAX_MAPPENTRIES as u8 + 1;
        assert_eq!(pdo_param(&p).err(), Some(CopKernel::PdoLengthExceeded));
        // Without kPdoValidNrOfEntries the count field is not looked at.
        p.m_bValidFlag = pdo_valid::CAN_ID;
        assert!(pdo_param(&p).is_ok());
    }
}
