//! Slave-side CCM services of the C API: pre-defined error field
//! (`CcmClearPreDefinedErrorField`), life guarding slave (`CcmInitLgs`,
//! `CcmConfigLgs`), SYNC producer (`CcmConfigSyncProducer`), TIME producer
//! (`CcmTspSend`) and store / restore (`CcmInitStore`,
//! `CcmStoreCheckArchivState`, `CcmStoreRestoreDefault`).
//!
//! Conventions as in [`super::ccm`]: `tCopKernel` results, pointers checked
//! first, kCopIllegalInstance before `CcmInitCANopen`, kCopNoResource from
//! inside an OBD callback.

use super::driver::TgtClock;
use super::global::{self, Instance, code, drain};
use super::ptr::{self, c_try};
use super::types::*;
use crate::error::CopKernel;
use crate::port::Clock;
use crate::wire::time::TimeOfDay;

/// `CcmClearPreDefinedErrorField`: empties the pre-defined error field
/// 0x1003 (sub 0 = 0, entries 0) and resets the error register 0x1001, as
/// writing 0 to 0x1003 sub 0 over SDO does. Returns kCopSuccessful, or
/// kCopObdIndexNotExist when the dictionary has no 0x1003 (nothing
/// changes).
#[unsafe(no_mangle)]
pub extern "C" fn CcmClearPreDefinedErrorField() -> tCopKernel {
    code(global::with(|i| i.stack.clear_error_field()))
}

/// `CcmInitLgs` (only with `NMTS_USE_LIFEGUARDING`): starts the life
/// guarding slave. Once the NMT master's first guard request has arrived,
/// every further request must come within guard time × life time factor
/// (0x100C × 0x100D); otherwise the node sends emergency 0x8130 (error
/// register bits 0 and 4, recorded in 0x1001 / 0x1003; in STOPPED only
/// recorded), once per loss. Returns kCopSuccessful. May be called from the
/// NMT callback at kNmtEvEnterInitialising.
#[cfg(nmts_use_lifeguarding)]
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitLgs() -> tCopKernel {
    code(global::with(|i| {
        i.stack.init_lgs();
        Ok(())
    }))
}

/// `CcmConfigLgs` (only with `NMTS_USE_LIFEGUARDING`): guard time in ms and
/// life time factor, written to 0x100C / 0x100D where the dictionary has
/// them (kept by the stack otherwise, until reset communication); 0 in
/// either switches supervision off. Returns kCopSuccessful;
/// kCopNmtLifeguardVsHeartbeat when a non-zero life time is configured
/// while the producer heartbeat time 0x1017 is not 0 (nothing changes); or
/// the code of a refused object write.
#[cfg(nmts_use_lifeguarding)]
#[unsafe(no_mangle)]
pub extern "C" fn CcmConfigLgs(wLifeGuardTime_p: WORD, bLifeGuardFactor_p: BYTE) -> tCopKernel {
    let now = TgtClock.now();
    let r = global::with(|i| {
        i.stack
            .config_lgs(wLifeGuardTime_p, bLifeGuardFactor_p, now)
    });
    drain();
    code(r)
}

/// `CcmConfigSyncProducer`: with bit 30 (`CANID_SYNC_PRODUCER`) set in
/// `dwSyncId_p` this node sends SYNC (DLC 0) on that identifier every
/// `dwSyncCycleTime_p` µs while PRE-OPERATIONAL or OPERATIONAL, and its own
/// synchronous PDOs react to it; without bit 30, or with cycle time 0, it
/// sends none. The cycle time is counted in ticks of 100 µs, rounded down
/// (at least one tick). The values go to 0x1005 / 0x1006 where the
/// dictionary has them (kept by the stack otherwise, until reset
/// communication); the COB-ID is also the SYNC consumer's. Returns
/// kCopSuccessful; kCopInvalidParam for a restricted or malformed
/// identifier (nothing changes); or the code of a refused object write.
#[unsafe(no_mangle)]
pub extern "C" fn CcmConfigSyncProducer(dwSyncId_p: DWORD, dwSyncCycleTime_p: DWORD) -> tCopKernel {
    let now = TgtClock.now();
    let r = global::with(|i| {
        i.stack
            .config_sync_producer(dwSyncId_p, dwSyncCycleTime_p, now)
    });
    drain();
    code(r)
}

/// `CcmTspSend`: sends one TIME frame (CiA 301: 6 bytes, milliseconds
/// after midnight in 28 bits, then days since 1 January 1984, both
/// little-endian) on `dwTimeStampId` (bit 29: 29-bit identifier; bits 30 and
/// 31 are ignored). Returns kCopSuccessful; kCopInvalidParam for NULL, for
/// `m_dwMs` of 86 400 000 or more, or for a restricted or malformed
/// identifier; kCopNmtStateError unless connected and PRE-OPERATIONAL or
/// OPERATIONAL; or the driver's code.
///
/// # Safety
/// `pTimeOfDay_p` must be NULL or point to a valid `tTimeOfDay`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmTspSend(
    dwTimeStampId: DWORD,
    pTimeOfDay_p: *const tTimeOfDay,
) -> tCopKernel {
    // SAFETY: the caller's contract (NULL or a valid tTimeOfDay).
    let p = c_try!(unsafe { ptr::read(pTimeOfDay_p) });
    let Some(t) = TimeOfDay::new(p.m_dwMs, p.m_wDays) else {
        return CopKernel::InvalidParam.code();
    };
    code(global::with(|i| {
        let Instance { stack, port, .. } = i;
        stack.send_time_stamp(port, dwTimeStampId, t)
    }))
}

/// `CcmInitStore`: this library has no non-volatile storage driver, so it
/// returns kCopCcmStoreHwError (kCopIllegalInstance before
/// `CcmInitCANopen`). Nothing else depends on it: "save" on 0x1010 is
/// refused with SDO abort 0x08000020 and "load" on 0x1011 restores the
/// defaults at the next reset, whether or not this was called.
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitStore() -> tCopKernel {
    code(global::with(|i| i.stack.init_store()))
}

/// `CcmStoreCheckArchivState`: whether stored parameters of a part exist.
/// Returns kCopCcmStoreHwError (no storage, so never — the application
/// configures its defaults, as it does for an invalid archive), or
/// kCopObdIllegalPart when `bCurrentOdPart_p` is not a combination of
/// `kObdPart*` bits.
#[unsafe(no_mangle)]
pub extern "C" fn CcmStoreCheckArchivState(bCurrentOdPart_p: tObdPart) -> tCopKernel {
    code(global::with(|i| i.stack.check_archive(bCurrentOdPart_p)))
}

/// `CcmStoreRestoreDefault`: deletes the stored parameters — there are none
/// — so that the next reset starts from the dictionary's defaults, which
/// is what every reset of this library does (as after "load" on 0x1011
/// sub 1). Returns kCopSuccessful (kCopIllegalInstance before
/// `CcmInitCANopen`).
#[unsafe(no_mangle)]
pub extern "C" fn CcmStoreRestoreDefault() -> tCopKernel {
    code(global::with(|i| i.stack.restore_default()))
}
