//! The application's callbacks: where they are kept and how an [`Event`] of
//! the stack becomes a call of one of them — the one adapter between the
//! stack's events and C function pointers.
//!
//! The instance registry ([`super::global`]) takes each event with its
//! callback (`Pending`) and calls it with the stack released
//! (`Pending::call`, `dispatch`); the exported functions register the
//! callbacks (`CcmInitNmtmEx`, `CcmDefinePdoTab`, ...). This module imports
//! neither of them.

use core::ffi::c_void;
use core::sync::atomic::{AtomicPtr, Ordering};

use super::instance::app_call;
use super::types::{
    tAppEmccEventCallback, tAppHbcEventCallback, tAppNmtmEventCallback, tCcmErrorCallback,
    tCcmNmtEventCallback, tCopKernel, tEmcParam, tPdoCallback, tProgMonCallback,
    tSdocCbFinishParam, tSdocCbFinished, tSrdoAppCallbacks, tSrdoEventCallback,
};
use crate::config::{PDO_MAX_RXPDO_IN_OBD, PDO_MAX_TXPDO_IN_OBD};
use crate::error::CopKernel;
use crate::event::Event;
use crate::pdo::{Direction, PdoIndex, Role};
use crate::wire::emcy::Emergency;

/// The application's callbacks (function pointers, copied out of the
/// instance before they are called).
#[derive(Clone, Copy, Debug, Default)]
pub struct Callbacks {
    /// `m_fpNmtEventCallback`.
    pub nmt: tCcmNmtEventCallback,
    /// `CcmRegisterErrorCallback`.
    pub error: tCcmErrorCallback,
    /// The application's SRDO callbacks (from objdef.h).
    pub srdo: Option<tSrdoAppCallbacks>,
    /// `CcmInitNmtmEx`.
    pub nmtm: tAppNmtmEventCallback,
    /// `CcmInitHbcEx`.
    pub hbc: tAppHbcEventCallback,
    /// `CcmInitEmccEx`.
    pub emcc: tAppEmccEventCallback,
    /// Finish callbacks of the SDO client channels (per transfer).
    pub sdoc: [tSdocCbFinished; crate::sdo::client::CAPACITY],
}

/// One event with the callback that handles it, taken out of the instance
/// while it is borrowed and called after it has been released. The SRDO
/// events of every received or sent SRDO carry only their function
/// pointer (no copy of [`Callbacks`]).
#[derive(Clone, Copy)]
pub(crate) enum Pending {
    /// `AppSrdoEvent(commu_index)`.
    SrdoEvent(tSrdoEventCallback, u16),
    /// `AppProgMonEvent(event)`.
    ProgMon(tProgMonCallback, u32),
    /// Any other event, with all the callbacks ([`dispatch`]).
    Other(Event, Callbacks),
}

impl Pending {
    /// The callback of `ev` among `cbs`.
    #[inline(always)]
    pub(crate) fn take(ev: Event, cbs: &Callbacks) -> Pending {
        match ev {
            Event::SrdoEvent(idx) => {
                Pending::SrdoEvent(cbs.srdo.and_then(|c| c.m_fpSrdoEvent), idx)
            }
            Event::ProgMon(e) => {
                Pending::ProgMon(cbs.srdo.and_then(|c| c.m_fpProgMonEvent), e as u32)
            }
            _ => Pending::Other(ev, *cbs),
        }
    }

    /// Calls the callback as [`dispatch`] does (the SRDO callbacks' return
    /// values are not evaluated); returns the code to report through the
    /// error callback, if any.
    #[inline(always)]
    pub(crate) fn call(self, instance: usize) -> Option<tCopKernel> {
        match self {
            Pending::SrdoEvent(Some(cb), idx) => {
                // SAFETY: AppSrdoEvent of the application (objdef.h).
                unsafe { app_call!(cb, instance; idx) };
                None
            }
            Pending::ProgMon(Some(cb), e) => {
                // SAFETY: AppProgMonEvent of the application (objdef.h).
                unsafe { app_call!(cb, instance; e) };
                None
            }
            Pending::SrdoEvent(None, _) | Pending::ProgMon(None, _) => None,
            Pending::Other(ev, cbs) => dispatch(ev, cbs, instance),
        }
    }

    /// An SRDO error the application did not acknowledge
    /// (kCopSrdoNotHandledInApp).
    #[inline(always)]
    pub(crate) fn is_not_handled(&self) -> bool {
        matches!(
            self,
            Pending::Other(Event::SrdoError(_, CopKernel::SrdoNotHandledInApp), _)
        )
    }
}

/// Calls the application for one event of instance `instance`. Runs with
/// the instance released, so the callback may call any `Ccm*` function.
/// Returns the code to report through the error callback
/// (`CcmRegisterErrorCallback`) when the event's callback refused: the
/// code the application returned, unchanged.
pub(crate) fn dispatch(ev: Event, cbs: Callbacks, instance: usize) -> Option<tCopKernel> {
    let srdo = cbs.srdo;
    match ev {
        Event::Nmt(e) => {
            if let Some(cb) = cbs.nmt {
                // SAFETY: the application's NMT callback from tCcmInitParam.
                let ret = unsafe { app_call!(cb, instance; e as u32) };
                if ret != 0 {
                    return Some(ret);
                }
            }
        }
        Event::SrdoEvent(idx) => {
            if let Some(cb) = srdo.and_then(|c| c.m_fpSrdoEvent) {
                // SAFETY: AppSrdoEvent of the application (objdef.h).
                unsafe { app_call!(cb, instance; idx) };
            }
        }
        Event::SrdoError(idx, code) => {
            if let Some(cb) = srdo.and_then(|c| c.m_fpSrdoError) {
                // SAFETY: AppSrdoError of the application (objdef.h).
                unsafe { app_call!(cb, instance; idx, code.code()) };
            }
        }
        Event::Gfc => {
            if let Some(cb) = srdo.and_then(|c| c.m_fpGfcEvent) {
                // SAFETY: AppGfcEvent of the application (objdef.h).
                unsafe { app_call!(cb, instance;) };
            }
        }
        Event::ProgMon(e) => {
            if let Some(cb) = srdo.and_then(|c| c.m_fpProgMonEvent) {
                // SAFETY: AppProgMonEvent of the application (objdef.h).
                unsafe { app_call!(cb, instance; e as u32) };
            }
        }
        Event::Hbc(node, e) => {
            if let Some(cb) = cbs.hbc {
                // SAFETY: the callback registered with CcmInitHbcEx.
                unsafe { app_call!(cb, instance; node, e as u32) };
            }
        }
        Event::Nmtm(node, e) => {
            if let Some(cb) = cbs.nmtm {
                // SAFETY: the callback registered with CcmInitNmtmEx.
                unsafe { app_call!(cb, instance; node, e as u32) };
            }
        }
        Event::SdocFinished {
            client,
            state,
            abort,
        } => {
            let slot = usize::from(client.wrapping_sub(crate::sdo::client::CLIENT_BASE_INDEX));
            if let Some(Some(cb)) = cbs.sdoc.get(slot).copied() {
                let mut p = tSdocCbFinishParam {
                    m_wClientIndex: client,
                    m_SdocState: u32::from(state),
                    m_dwAbortCode: abort,
                };
                // SAFETY: the finish callback given with CcmSdocStartTransfer;
                // `p` lives for the call.
                unsafe { app_call!(cb, instance; &mut p) };
            }
        }
        Event::Emcc(node, e) => emcc(node, e, cbs.emcc, instance),
        Event::Pdo(commu_index) => pdo(commu_index, instance),
    }
    None
}

/// Hands a received emergency to the callback of `CcmInitEmccEx` as a
/// `tEmcParam`: error code, error register and the five
/// manufacturer-specific bytes of the frame; `m_wAdditionalInfo` has no
/// counterpart in the frame and is 0. The structure lives for the call.
/// Without a callback (`CcmInitEmcc`) the emergency is not reported.
fn emcc(node: u8, e: Emergency, cb: tAppEmccEventCallback, instance: usize) {
    let Some(cb) = cb else {
        return;
    };
    let mut p = tEmcParam {
        m_wEmcyErrorCode: e.code,
        m_bErrorRegister: e.register,
        m_abManufactErrorCode: e.manufacturer,
        m_wAdditionalInfo: 0,
    };
    // SAFETY: the callback registered with CcmInitEmccEx; `p` lives for
    // the call.
    unsafe { app_call!(cb, instance; node, &mut p) };
}

/// PDO callbacks: one slot per RPDO (0x1400+n at n) and TPDO (0x1800+n at
/// `PDO_MAX_RXPDO_IN_OBD + n`), per instance. Function pointers are kept
/// as atomic pointers so that the table needs no lock. They are not part
/// of [`Callbacks`], which is copied for every event.
const SLOTS: usize = PDO_MAX_RXPDO_IN_OBD + PDO_MAX_TXPDO_IN_OBD;
static PDO_CALLBACKS: [[AtomicPtr<c_void>; SLOTS]; super::MAX_INSTANCES] =
    [const { [const { AtomicPtr::new(core::ptr::null_mut()) }; SLOTS] }; super::MAX_INSTANCES];

/// The callback slot of a communication index this build serves.
pub(crate) fn pdo_slot(commu_index: u16) -> Option<usize> {
    let p = PdoIndex::of(commu_index).filter(|p| p.role == Role::Commu)?;
    let n = usize::from(p.number);
    match p.dir {
        Direction::Rx => (n < PDO_MAX_RXPDO_IN_OBD).then_some(n),
        Direction::Tx => (n < PDO_MAX_TXPDO_IN_OBD).then_some(PDO_MAX_RXPDO_IN_OBD + n),
    }
}

/// Registers (or, with `None`, removes) the callback of a PDO of
/// `instance`; ignored for a communication index without a slot.
pub(crate) fn set_pdo(commu_index: u16, cb: tPdoCallback, instance: usize) {
    let Some(slot) = pdo_slot(commu_index) else {
        return;
    };
    let p = cb.map_or(core::ptr::null_mut(), |f| f as *mut c_void);
    if let Some(a) = PDO_CALLBACKS.get(instance).and_then(|row| row.get(slot)) {
        a.store(p, Ordering::Relaxed);
    }
}

/// The function type of a [`tPdoCallback`].
type tPdoCallbackFn = <tPdoCallback as OptionFn>::Fn;

/// The function type inside an `Option` of a function pointer.
pub(crate) trait OptionFn {
    type Fn;
}
impl<F> OptionFn for Option<F> {
    type Fn = F;
}

fn pdo_callback(commu_index: u16, instance: usize) -> tPdoCallback {
    let slot = pdo_slot(commu_index)?;
    let p = PDO_CALLBACKS
        .get(instance)?
        .get(slot)?
        .load(Ordering::Relaxed);
    if p.is_null() {
        return None;
    }
    // SAFETY: non-NULL entries were stored by `set_pdo` from a
    // tPdoCallback function pointer of the application.
    Some(unsafe { core::mem::transmute::<*mut c_void, tPdoCallbackFn>(p) })
}

/// Calls the PDO's callback for `Event::Pdo`. Its return value is not
/// evaluated (the PDO has already been processed).
fn pdo(commu_index: u16, instance: usize) {
    if let Some(cb) = pdo_callback(commu_index, instance) {
        // SAFETY: the application's tPdoCallback given with CcmDefinePdoTab
        // or CcmDefineStaticPdoTab.
        let _ = unsafe { app_call!(cb, instance; commu_index) };
    }
}

#[cfg(test)]
mod tests {
    use super::super::types::WORD;
    use super::*;

    unsafe extern "C" fn cb(_w: WORD) -> tCopKernel {
        0
    }

    #[test]
    fn pdo_slots_cover_the_configured_pdos() {
        assert_eq!(pdo_slot(0x1400), Some(0));
        assert_eq!(pdo_slot(0x1800), Some(PDO_MAX_RXPDO_IN_OBD));
        assert_eq!(pdo_slot(0x1600), None, "mapping index");
        assert_eq!(pdo_slot(0x1400 + PDO_MAX_RXPDO_IN_OBD as u16), None);
        assert_eq!(pdo_slot(0x1300), None);
    }

    #[test]
    fn pdo_callback_table_round_trip() {
        let last = super::super::MAX_INSTANCES - 1;
        set_pdo(0x1801, Some(cb), last);
        assert!(pdo_callback(0x1801, last).is_some());
        assert!(pdo_callback(0x1800, last).is_none());
        set_pdo(0x1801, None, last);
        assert!(pdo_callback(0x1801, last).is_none());
        // Out of range: nothing stored, nothing found.
        set_pdo(0x1801, Some(cb), last + 1);
        assert!(pdo_callback(0x1801, last + 1).is_none());
    }
}
