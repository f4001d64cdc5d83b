//! Slave-side CCM services of the C API: pre-defined error field
//! (`CcmClearPreDefinedErrorField`), life guarding slave (`CcmInitLgs`,
//! `CcmConfigLgs`), SYNC producer (`CcmConfigSyncProducer`), TIME producer
//! (`CcmTspSend`) and store / restore (`CcmInitStore`,
//! `CcmStoreCheckArchivState`, `CcmStoreRestoreDefault`).
//!
//! Conventions as in [`super::ccm`]: `tCopKernel` results, pointers checked
//! first, kCopIllegalInstance before `CcmInitCANopen`, kCopNoResource from
//! inside an OBD callback.

use super::MAX_INSTANCES;
use super::global::{self, Instance, code};
use super::instance;
use super::ptr::{self, c_try};
use super::types::*;
use crate::error::{CopKernel, CopResult};
use crate::store::image::NvFault;
use crate::store::{Driver, StorageDriver};
use crate::wire::time::TimeOfDay;

/// `CcmClearPreDefinedErrorField`: empties the pre-defined error field
/// 0x1003 (sub 0 = 0, entries 0) and resets the error register 0x1001, as
/// writing 0 to 0x1003 sub 0 over SDO does. Returns kCopSuccessful, or
/// kCopObdIndexNotExist when the dictionary has no 0x1003 (nothing
/// changes).
#[unsafe(no_mangle)]
pub extern "C" fn CcmClearPreDefinedErrorField(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
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
pub extern "C" fn CcmInitLgs(#[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run(|i| {
        i.stack.init_lgs();
    })
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
pub extern "C" fn CcmConfigLgs(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wLifeGuardTime_p: WORD,
    bLifeGuardFactor_p: BYTE,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run_at(|i, now| {
        i.stack
            .config_lgs(wLifeGuardTime_p, bLifeGuardFactor_p, now)
    })
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
pub extern "C" fn CcmConfigSyncProducer(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    dwSyncId_p: DWORD,
    dwSyncCycleTime_p: DWORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run_at(|i, now| {
        i.stack
            .config_sync_producer(dwSyncId_p, dwSyncCycleTime_p, now)
    })
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
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    dwTimeStampId: DWORD,
    pTimeOfDay_p: *const tTimeOfDay,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
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

/// The application's driver as the stack's [`StorageDriver`]. Its methods
/// are the only places that call the driver's functions (the worst-case
/// stack analysis resolves their calls to the application's
/// `tCopStoreDriver`, docs/tms570.md).
struct CStore(&'static tCopStoreDriver);

impl CStore {
    /// `m_fpOpen` (optional): kCopCcmStoreHwError when it fails.
    #[inline(never)]
    fn open(&self) -> CopResult {
        if let Some(open) = self.0.m_fpOpen {
            // SAFETY: the application's function with its own argument.
            if unsafe { open(self.0.m_pArg) } != CopKernel::Successful.code() {
                return Err(CopKernel::CcmStoreHwError);
            }
        }
        Ok(())
    }
}

fn nv(r: tCopKernel) -> Result<(), NvFault> {
    if r == CopKernel::Successful.code() {
        Ok(())
    } else {
        Err(NvFault)
    }
}

fn len32(n: usize) -> Result<DWORD, NvFault> {
    DWORD::try_from(n).map_err(|_| NvFault)
}

impl StorageDriver for CStore {
    fn size(&self) -> u32 {
        self.0.m_dwSize
    }
    fn align(&self) -> u32 {
        self.0.m_dwAlign
    }
    fn read(&self, offset: u32, out: &mut [u8]) -> Result<(), NvFault> {
        let f = self.0.m_fpRead.ok_or(NvFault)?;
        // SAFETY: the application's function (checked non-NULL at
        // registration) gets a buffer of exactly `out.len()` bytes.
        nv(unsafe { f(self.0.m_pArg, offset, out.as_mut_ptr(), len32(out.len())?) })
    }
    fn write(&self, offset: u32, data: &[u8]) -> Result<(), NvFault> {
        let f = self.0.m_fpWrite.ok_or(NvFault)?;
        // SAFETY: as in `read`; the data are only read.
        nv(unsafe { f(self.0.m_pArg, offset, data.as_ptr(), len32(data.len())?) })
    }
    fn erase(&self, offset: u32, len: u32) -> Result<(), NvFault> {
        let f = self.0.m_fpErase.ok_or(NvFault)?;
        // SAFETY: the application's function, no pointer of ours.
        nv(unsafe { f(self.0.m_pArg, offset, len) })
    }
    fn commit(&self) -> Result<(), NvFault> {
        let f = self.0.m_fpCommit.ok_or(NvFault)?;
        // SAFETY: as in `erase`.
        nv(unsafe { f(self.0.m_pArg) })
    }
}

/// The registered drivers, one per instance (a `&'static` the stack can
/// keep: the C structure itself is the application's static).
static STORES: [StoreCell; MAX_INSTANCES] =
    [const { StoreCell(core::cell::UnsafeCell::new(None)) }; MAX_INSTANCES];

struct StoreCell(core::cell::UnsafeCell<Option<CStore>>);

// SAFETY: the API is single-threaded (cop.h); a cell is written only by
// `CcmSetStoreDriver` for the current instance, inside `global::with`,
// which refuses re-entry, and only after the stack dropped the previous
// reference to it.
unsafe impl Sync for StoreCell {}

/// `CcmSetStoreDriver`: registers the application's non-volatile memory
/// (`tCopStoreDriver`, `cop_types.h`) for the current instance, or none
/// (NULL). May be called before `CcmInitCANopen` (then the instance the
/// next `CcmInitCANopen` creates uses it); takes effect with the next
/// `CcmInitStore`. Returns kCopSuccessful; kCopInvalidParam for a
/// structure without m_fpRead, m_fpWrite, m_fpErase or m_fpCommit;
/// kCopNoResource from inside an OBD callback. The structure must stay valid and unchanged while the
/// instance lives.
///
/// # Safety
/// `pDriver_p` is NULL or points to a `tCopStoreDriver` that lives as long
/// as the instance.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmSetStoreDriver(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pDriver_p: *const tCopStoreDriver,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract: NULL or a structure that outlives the
    // instance, never changed (so a shared `'static` reference is sound).
    let drv: Option<&'static tCopStoreDriver> = unsafe { pDriver_p.as_ref() };
    if let Some(d) = drv {
        if d.m_fpRead.is_none()
            || d.m_fpWrite.is_none()
            || d.m_fpErase.is_none()
            || d.m_fpCommit.is_none()
        {
            return CopKernel::InvalidParam.code();
        }
    }
    let Some(cell) = STORES.get(global::current()) else {
        return CopKernel::IllegalInstance.code();
    };
    // The stack forgets the old driver before its cell is replaced; before
    // `CcmInitCANopen` there is no stack, and `CcmInitStore` takes the
    // driver from the cell.
    let live = global::with(|i| i.stack.set_store_driver(None, 0));
    if live == Err(CopKernel::NoResource) {
        return CopKernel::NoResource.code();
    }
    // SAFETY: see `StoreCell`: no reference into the cell is alive now
    // (the stack's was just dropped), and no other code runs.
    unsafe { *cell.0.get() = drv.map(CStore) };
    if live.is_ok() {
        code(global::with(|i| {
            register(i);
            CopResult::Ok(())
        }))
    } else {
        CopKernel::Successful.code()
    }
}

/// Hands the current instance's registered driver (if any) to its stack.
fn register(i: &mut Instance) {
    // SAFETY: see `StoreCell`; only read here, and the cell is not written
    // while this shared reference lives in the stack (`CcmSetStoreDriver`
    // takes it back first).
    let stored = STORES
        .get(global::current())
        .and_then(|c| unsafe { (*c.0.get()).as_ref() });
    match stored {
        Some(s) => i.stack.set_store_driver(Some(Driver(s)), s.0.m_dwConfigKey),
        None => i.stack.set_store_driver(None, 0),
    }
}

/// `CcmInitStore`: opens the registered storage driver (`m_fpOpen`) and
/// loads the stored parameters (`CcmSetStoreDriver`, README "Store and
/// restore"). Returns kCopSuccessful (with or without a stored image);
/// kCopCcmStoreHwError without a driver — start-up goes on with the
/// dictionary's defaults, "save" is refused with SDO abort 0x08000020,
/// "load" restores the defaults at the next reset — or when the driver
/// fails; kCopCcmStoreUnvalidState for an image of another dictionary or
/// configuration key (ignored: nothing of it is applied, the next "save"
/// replaces it); kCopIllegalInstance before `CcmInitCANopen`.
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitStore(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    code(global::with(|i| {
        register(i);
        // SAFETY: see `StoreCell`; only read here.
        if let Some(Some(s)) = STORES
            .get(global::current())
            .map(|c| unsafe { &*c.0.get() })
        {
            s.open()?;
        }
        i.stack.init_store()
    }))
}

/// `CcmStoreCheckArchivState`: kCopSuccessful when the stored image holds
/// every part of `bCurrentOdPart_p`; kCopCcmStoreUnvalidState when it does
/// not (or nothing is stored); kCopCcmStoreHwError without a driver (or
/// before `CcmInitStore`); kCopObdIllegalPart when `bCurrentOdPart_p` is
/// not a combination of `kObdPart*` bits.
#[unsafe(no_mangle)]
pub extern "C" fn CcmStoreCheckArchivState(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    bCurrentOdPart_p: tObdPart,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    code(global::with(|i| i.stack.check_archive(bCurrentOdPart_p)))
}

/// `CcmStoreRestoreDefault`: erases the stored parameters (with a
/// driver) so that the next reset starts from the dictionary's defaults
/// (as after "load" on 0x1011 sub 1). Returns kCopSuccessful,
/// kCopCcmStoreHwError when the driver fails, kCopIllegalInstance before
/// `CcmInitCANopen`.
#[unsafe(no_mangle)]
pub extern "C" fn CcmStoreRestoreDefault(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    code(global::with(|i| i.stack.restore_default()))
}
