//! What changes with several instances (`COP_MAX_INSTANCES` > 1 in
//! `copcfg.h`, the build's `multi_instance` cfg): everything of the C edge
//! that depends on the instance form is here, as the original's
//! `instdef.h` keeps it in one header.
//!
//! * Every exported `Ccm*` function has a first parameter
//!   `#[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl` and opens with
//!   `ccm_enter!`; a module function (`Srdo*`, `SdocGetTransmittedBytes`)
//!   has `#[cfg(multi_instance)] pInstance: tCopPtrInstance` and opens with
//!   `mco_enter!`. In a single-instance build both macros are empty and
//!   the parameter does not exist, so the prototypes and the code are those
//!   of a build without instances.
//! * `include/cop.h` is generated from the same functions
//!   (`scripts/header.sh`): the parameter becomes `CCM_DECL_INSTANCE_HDL_` /
//!   `MCO_DECL_INSTANCE_PTR_`, which `cop_types.h` defines for both forms.
//! * The application's callbacks get the handle of the instance whose event
//!   they handle: their types are written with `app_fn!` and called with
//!   `app_call!`; the handle comes from the pump of that instance
//!   (`global`), never from a shared "current" setting a callback could
//!   see in another state.
//! * The driver gets the instance pointer its `CdrvInit` /
//!   `CdrvAddInstance` returned for this controller (`driver.rs`).
//!
//! A handle is the index of the instance's slot in the registry
//! (`global`): 0 .. `COP_MAX_INSTANCES`. A module instance pointer points to
//! a `tCopInstanceHdl` holding the handle: `SrdoAddInstance` hands out a
//! pointer into [`MODULE_HANDLES`], and an application may pass the address
//! of its own copy of the handle (`&bInstanceHandle`), as the public AWorks
//! adapters do.

use super::types::{BYTE, tCopKernel};
use crate::error::CopKernel;

/// `tCopInstanceHdl`: the handle of a stack instance.
pub type tCopInstanceHdl = BYTE;

/// `tCopPtrInstance`: the instance pointer of the module layer (a pointer to
/// the instance's handle).
pub type tCopPtrInstance = *mut core::ffi::c_void;

/// `CCM_ILLINSTANCE_HDL`: no instance (the out-parameter of a failed
/// `CcmInitCANopen`).
pub const CCM_ILLINSTANCE_HDL: tCopInstanceHdl = 0xFF;

/// The handles as module instance pointers point to them: entry `i` holds
/// `i`.
// Evaluated at compile time: an index out of range fails the build, it
// cannot panic at run time.
#[allow(clippy::indexing_slicing)]
pub static MODULE_HANDLES: [tCopInstanceHdl; super::MAX_INSTANCES] = {
    let mut t = [0; super::MAX_INSTANCES];
    let mut i = 0;
    while i < super::MAX_INSTANCES {
        t[i] = i as tCopInstanceHdl;
        i += 1;
    }
    t
};

/// The module instance pointer of handle `h` (a pointer into
/// [`MODULE_HANDLES`]), NULL for a handle out of range.
pub fn module_pointer(h: usize) -> tCopPtrInstance {
    MODULE_HANDLES
        .get(h)
        .map_or(core::ptr::null_mut(), |b| b as *const BYTE as *mut _)
}

/// The handle a module instance pointer points to:
/// `Err(kCopInvalidInstanceParam)` for NULL.
///
/// # Safety
/// `p` is NULL or points to a readable `tCopInstanceHdl`.
#[inline(always)]
pub unsafe fn handle_of_pointer(p: tCopPtrInstance) -> Result<tCopInstanceHdl, CopKernel> {
    let p = p as *const tCopInstanceHdl;
    if p.is_null() {
        return Err(CopKernel::InvalidInstanceParam);
    }
    // SAFETY: the caller's contract (a readable handle byte).
    Ok(unsafe { p.read() })
}

/// The C result of a refusal to enter an instance, for each return type of
/// the exported functions: the `tCopKernel` code, or the value a function
/// without a code returns for "no instance".
pub trait Refusal {
    /// The value returned when the instance cannot be entered.
    fn refusal(e: CopKernel) -> Self;
}

impl Refusal for tCopKernel {
    #[inline(always)]
    fn refusal(e: CopKernel) -> Self {
        e.code()
    }
}

/// `CcmObdGetNodeState`, `CcmLsssGetNodeId`: 0, as before
/// `CcmInitCANopen` (no instance, no node state, no node-ID).
impl Refusal for BYTE {
    #[inline(always)]
    fn refusal(_: CopKernel) -> Self {
        0
    }
}

/// The functions without a result (`CcmEnterCriticalSectionPdoProcess`,
/// ...): nothing happens.
impl Refusal for () {
    #[inline(always)]
    fn refusal(_: CopKernel) -> Self {}
}

/// Opens an exported `Ccm*` function: addresses the instance of the
/// function's `InstanceHandle` until the function returns, or returns the
/// function's refusal ([`Refusal`]: `kCopIllegalInstance` for a handle ≥
/// `COP_MAX_INSTANCES`; a shut-down instance's handle is refused by the
/// registry as before `CcmInitCANopen`). Empty in a single-instance build.
#[cfg(multi_instance)]
macro_rules! ccm_enter {
    ($h:ident) => {
        let _scope = match $crate::ffi::global::Scope::enter($h) {
            Ok(s) => s,
            Err(e) => return $crate::ffi::instance::Refusal::refusal(e),
        };
    };
}
#[cfg(not(multi_instance))]
macro_rules! ccm_enter {
    ($h:ident) => {};
}
pub(crate) use ccm_enter;

/// Opens an exported module function (`Srdo*`): as [`ccm_enter!`] for the
/// handle the instance pointer points to (`kCopInvalidInstanceParam` for
/// NULL). Empty in a single-instance build.
#[cfg(multi_instance)]
macro_rules! mco_enter {
    ($p:ident) => {
        // SAFETY: the caller's contract: `$p` is NULL or points to the
        // instance's handle (SrdoAddInstance's pointer or the
        // application's own copy of the handle).
        let _scope = match unsafe { $crate::ffi::instance::handle_of_pointer($p) }
            .and_then($crate::ffi::global::Scope::enter)
        {
            Ok(s) => s,
            Err(e) => return $crate::ffi::instance::Refusal::refusal(e),
        };
    };
}
#[cfg(not(multi_instance))]
macro_rules! mco_enter {
    ($p:ident) => {};
}
pub(crate) use mco_enter;

/// Opens `SrdoInit` / `SrdoAddInstance` of a multi-instance build
/// (`MCO_DECL_PTR_INSTANCE_PTR_`): `*pInstancePtr` names the instance as a
/// module instance pointer does (kCopInvalidInstanceParam when either
/// pointer is NULL), and is set to this library's pointer of that instance
/// ([`module_pointer`]). Empty in a single-instance build.
#[cfg(multi_instance)]
macro_rules! mco_enter_ptr {
    ($pp:ident) => {
        let _scope = {
            let pp: *mut $crate::ffi::instance::tCopPtrInstance = $pp;
            if pp.is_null() {
                return $crate::error::CopKernel::InvalidInstanceParam.code();
            }
            // SAFETY: the caller's contract: a readable and writable
            // pointer variable holding NULL or a module instance pointer.
            let inner = unsafe { pp.read() };
            // SAFETY: as for `mco_enter!`.
            let scope = match unsafe { $crate::ffi::instance::handle_of_pointer(inner) }
                .and_then($crate::ffi::global::Scope::enter)
            {
                Ok(s) => s,
                Err(e) => return e.code(),
            };
            // SAFETY: as above (writable).
            unsafe {
                pp.write($crate::ffi::instance::module_pointer(
                    $crate::ffi::global::current(),
                ))
            };
            scope
        };
    };
}
#[cfg(not(multi_instance))]
macro_rules! mco_enter_ptr {
    ($pp:ident) => {};
}
pub(crate) use mco_enter_ptr;

/// Calls another exported function of the C API for the instance the
/// caller addresses: `here!(CcmSendSrdo(w))` passes that instance's handle
/// first in a multi-instance build.
#[cfg(multi_instance)]
macro_rules! here {
    ($f:path, $($a:expr),*) => {
        $f($crate::ffi::global::current() as $crate::ffi::instance::tCopInstanceHdl $(, $a)*)
    };
}
#[cfg(not(multi_instance))]
macro_rules! here {
    ($f:path, $($a:expr),*) => {
        $f($($a),*)
    };
}
pub(crate) use here;

/// `tCcmInitCall` values: whether the driver is initialised with
/// `CdrvInit` (`kCcmFirstInstance`, `kCcmAddCcmInstFirstCdrvInst`: the first
/// instance of the driver) or with `CdrvAddInstance`
/// (`kCcmAdditionalInstance`, `kCcmAddCcmInstAddCdrvInst`); `None` for a
/// value that is none of the four (kCopInvalidParam). A single-instance
/// build always calls `CdrvInit`.
pub fn first_driver_instance(call: super::types::tCcmInitCall) -> Option<bool> {
    match call {
        // kCcmAdditionalInstance, kCcmAddCcmInstAddCdrvInst
        0x00 | 0x03 => Some(!cfg!(multi_instance)),
        // kCcmFirstInstance, kCcmAddCcmInstFirstCdrvInst
        0x01 | 0x02 => Some(true),
        _ => None,
    }
}

/// What the dictionary of the instance being created hands its OBD and
/// variable callbacks first (its handle in a multi-instance build).
#[cfg(multi_instance)]
pub fn callback_handle() -> crate::od::CallbackHandle {
    super::global::current() as u8
}
/// What the dictionary hands its OBD and variable callbacks first: nothing
/// in a single-instance build.
#[cfg(not(multi_instance))]
pub fn callback_handle() -> crate::od::CallbackHandle {
    crate::od::table::NoHandle
}

/// Where `CcmInitCANopen` of a multi-instance build reports the new
/// instance's handle.
#[cfg(multi_instance)]
pub struct HandleOut {
    out: *mut tCopInstanceHdl,
    handle: tCopInstanceHdl,
}

#[cfg(multi_instance)]
impl HandleOut {
    /// Writes the handle to the application's variable (before the start-up
    /// callbacks run, so that they may find it there).
    pub fn publish(&self) {
        // SAFETY: `out` was checked and written in `enter_new`; the
        // application's variable lives across its CcmInitCANopen call.
        unsafe { self.out.write(self.handle) };
    }
}

/// The out-parameter of a single-instance `CcmInitCANopen`: none.
#[cfg(not(multi_instance))]
pub struct HandleOut;

#[cfg(not(multi_instance))]
impl HandleOut {
    /// Nothing to report.
    pub fn publish(&self) {}
}

/// Opens `CcmInitCANopen` of a multi-instance build: `Err` with
/// kCopInvalidInstanceParam for a NULL handle pointer, kCopNoFreeInstance
/// when every slot holds an instance; else the scope of the lowest free
/// slot and where to report its handle. The application's variable holds
/// `CCM_ILLINSTANCE_HDL` until the instance exists.
///
/// # Safety
/// `out` is NULL or points to a writable `tCopInstanceHdl`.
#[cfg(multi_instance)]
pub unsafe fn enter_new(
    out: *mut tCopInstanceHdl,
) -> Result<(super::global::Scope, HandleOut), CopKernel> {
    if out.is_null() {
        return Err(CopKernel::InvalidInstanceParam);
    }
    // SAFETY: the caller's contract (writable).
    unsafe { out.write(CCM_ILLINSTANCE_HDL) };
    let handle = super::global::free_slot()?;
    let scope = super::global::Scope::enter(handle)?;
    Ok((scope, HandleOut { out, handle }))
}

/// Opens `CcmInitCANopen`: `ccm_enter_new!(pInstanceHandle => out)` enters
/// a free slot ([`enter_new`]) and binds `out` ([`HandleOut`]), or returns
/// the refusal. In a single-instance build only `out` (which reports
/// nothing) is bound.
#[cfg(multi_instance)]
macro_rules! ccm_enter_new {
    ($p:ident => $out:ident) => {
        // SAFETY: the caller's contract: NULL or a writable handle.
        let (_scope, $out) = match unsafe { $crate::ffi::instance::enter_new($p) } {
            Ok(x) => x,
            Err(e) => return e.code(),
        };
    };
}
#[cfg(not(multi_instance))]
macro_rules! ccm_enter_new {
    ($p:ident => $out:ident) => {
        let $out = $crate::ffi::instance::HandleOut;
    };
}
pub(crate) use ccm_enter_new;

/// The type of an application callback: `app_fn!(fn(WORD) -> tCopKernel)`
/// is `Option<unsafe extern "C" fn(WORD) -> tCopKernel>`, with the
/// instance handle first in a multi-instance build
/// (`CCM_DECL_INSTANCE_HDL_`).
#[cfg(multi_instance)]
macro_rules! app_fn {
    (fn($($a:ty),*) $(-> $r:ty)?) => {
        Option<unsafe extern "C" fn($crate::ffi::instance::tCopInstanceHdl $(, $a)*) $(-> $r)?>
    };
}
#[cfg(not(multi_instance))]
macro_rules! app_fn {
    (fn($($a:ty),*) $(-> $r:ty)?) => {
        Option<unsafe extern "C" fn($($a),*) $(-> $r)?>
    };
}
pub(crate) use app_fn;

/// Calls an application callback of an [`app_fn!`] type (unwrapped):
/// `app_call!(cb, instance; a, b)` passes the handle of slot `instance`
/// first in a multi-instance build and nothing more otherwise. The caller
/// wraps it in `unsafe` with its SAFETY reason.
#[cfg(multi_instance)]
macro_rules! app_call {
    ($cb:expr, $inst:expr; $($a:expr),*) => {
        $cb($inst as $crate::ffi::instance::tCopInstanceHdl $(, $a)*)
    };
}
#[cfg(not(multi_instance))]
macro_rules! app_call {
    ($cb:expr, $inst:expr; $($a:expr),*) => {{
        let _ = &$inst;
        $cb($($a),*)
    }};
}
pub(crate) use app_call;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn module_pointers_point_to_their_handles() {
        for h in 0..super::super::MAX_INSTANCES {
            let p = module_pointer(h);
            // SAFETY: a pointer into MODULE_HANDLES.
            assert_eq!(unsafe { handle_of_pointer(p) }, Ok(h as u8));
        }
        assert!(module_pointer(super::super::MAX_INSTANCES).is_null());
        // SAFETY: NULL is refused before any read.
        assert_eq!(
            unsafe { handle_of_pointer(core::ptr::null_mut()) },
            Err(CopKernel::InvalidInstanceParam)
        );
    }

    #[test]
    fn refusals_per_return_type() {
        assert_eq!(
            <tCopKernel as Refusal>::refusal(CopKernel::IllegalInstance),
            CopKernel::IllegalInstance.code()
        );
        assert_eq!(<BYTE as Refusal>::refusal(CopKernel::IllegalInstance), 0);
    }
}
