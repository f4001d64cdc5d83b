//! The dynamic object dictionary (SYS TEC CcmDyn): `DynBuildOd`,
//! `DynDestroyOd`, `tProcessImageDscrpt`, and the pool the tables live in.
//!
//! The decisions (what a container does, in which order, what is refused)
//! are in [`crate::od::dynamic`], the pool ([`DynPool`]) beside the
//! dictionary (`src/od/dynamic/pool.rs`, its memory in `src/od/table.rs`),
//! the stack's part in `src/ccm/dynod.rs`; this file holds the exported
//! functions and the pool of each instance.
//!
//! # The pool (no heap)
//! The original takes the tables from `COP_MALLOC`; this library takes them
//! from a static pool of `OBD_DYNAMIC_POOL_SIZE` bytes (build switch,
//! default 8192; 0 when `OBD_USE_DYNAMIC_OD` is FALSE). One build uses it
//! from offset 0, in this order:
//!
//! | region | size |
//! |---|---|
//! | index table (`tObdEntry`): the application's user part merged with the new objects, sorted | (user entries + new indices) × `size_of::<ObdEntry>()` (16 bytes on 32-bit targets) |
//! | subindex tables (`tObdSubEntry`) of the new objects | new subindices × `size_of::<ObdSubEntry>()` (16 bytes on 32-bit targets) |
//! | PDO channels, only when `PDO_MAX_RXPDO_IN_OBD` / `PDO_MAX_TXPDO_IN_OBD` is 0 and the container has PDOs of that direction: the RPDOs', then the TPDOs' | (highest RPDO number + 1) × the state of one RPDO + (highest TPDO number + 1) × the state of one TPDO, which includes its change watch ([`crate::pdo::channel_size`] of each direction) |
//! | variables that are not in the process image | their C width; strings capacity + 1 |
//! | snapshot of the existing values the build overwrites | 5 bytes + the value per write (undo of a refused build) |
//! | copy of the container's index segment | its size (the values re-applied after NMT resets) |
//!
//! A container whose tables do not fit is refused with `kCopDynNoMemory`
//! before anything changes. Single-instance builds have one pool; host
//! builds (`std`) one per simulated instance.
//!
//! ## Build-time data
//! While a build runs, the last bytes of the pool hold what makes it
//! linear in the container's entries instead of quadratic:
//!
//! | at the end of the pool | size |
//! |---|---|
//! | notes of the plan (whether each entry writes an existing object) | 1 byte per entry |
//! | index of the entries ([`crate::od::dcf::Container::parse_indexed`]) | 8 bytes per entry, 10 with an address segment ([`crate::od::dcf::index_scratch_len`]; 12/14 for index segments from 64 KiB on) |
//!
//! They are built right after the pool is claimed, before the container is
//! checked, and lie where the copy of the index segment and the unused
//! rest of the pool are: the tables and the snapshot are written below
//! them, the copy over them as the build's last step. Between them, the
//! bytes from the copy's place to the notes hold the bitmap that checks
//! that no two variables share bytes of the process image (one bit per
//! byte of the image). When the pool has no room for them beside the
//! tables the build goes on without them (the same checks and result,
//! slower); they never make a container refused that fits. A pool in use
//! by another stack is not touched: the container is checked without them
//! and then refused with `kCopNoFreeInstance`, as before.
//!
//! # Lifetime rules
//! The tables belong to the stack they were built for until `DynDestroyOd`
//! (or [`DynPool::release`]). The process image handed to `DynBuildOd`
//! must stay valid as long: its variables are the dictionary's.

use core::ffi::c_void;

use super::global;
use super::instance;
#[cfg(multi_instance)]
use super::types::tCopInstanceHdl;
use super::types::{BYTE, DWORD, WORD, tCopKernel};
use crate::error::CopKernel;
use crate::od::dcf::HEADER_SIZE;
use crate::od::dynamic::DynPool;
use crate::port::Clock;

/// `tProcessImageDscrpt` (ccmdyn.h): the process image the application
/// hands to `DynBuildOd`, and the windows the build reports.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tProcessImageDscrpt {
    /// In: start of the process image (NULL: none).
    pub m_pbProcessImage: *mut BYTE,
    /// In: bytes available; out: bytes the container's image needs.
    pub m_dwProcessImageSize: DWORD,
    /// Out: offset of the input area.
    pub m_dwDynPIOffsetIn: DWORD,
    /// Out: size of the input area.
    pub m_dwDynPISizeIn: DWORD,
    /// Out: offset of the output area.
    pub m_dwDynPIOffsetOut: DWORD,
    /// Out: size of the output area.
    pub m_dwDynPISizeOut: DWORD,
}

static_assertions::const_assert_eq!(
    core::mem::offset_of!(tProcessImageDscrpt, m_pbProcessImage),
    0
);
static_assertions::const_assert_eq!(
    core::mem::offset_of!(tProcessImageDscrpt, m_dwProcessImageSize),
    size_of::<*mut u8>()
);
static_assertions::const_assert_eq!(
    core::mem::offset_of!(tProcessImageDscrpt, m_dwDynPISizeOut),
    size_of::<*mut u8>() + 16
);
#[cfg(target_pointer_width = "32")]
static_assertions::assert_eq_size!(tProcessImageDscrpt, [u8; 24]);
#[cfg(target_pointer_width = "64")]
static_assertions::assert_eq_size!(tProcessImageDscrpt, [u8; 32]);

/// Largest container `DynBuildOd` reads (16 MiB): a garbage size field
/// must not make it read far past the caller's data.
pub const MAX_CONTAINER: u32 = 0x0100_0000;
// ---------------------------------------------------------------------
// C API
// ---------------------------------------------------------------------

/// Bytes of the pool of each instance: `OBD_DYNAMIC_POOL_SIZE`, none when
/// `OBD_USE_DYNAMIC_OD` is FALSE.
pub const POOL_SIZE: usize = if crate::config::OBD_USE_DYNAMIC_OD {
    crate::config::OBD_DYNAMIC_POOL_SIZE
} else {
    0
};

static POOLS: [DynPool<POOL_SIZE>; global::MAX_INSTANCES] =
    [const { DynPool::new() }; global::MAX_INSTANCES];

fn pool() -> Option<&'static DynPool<POOL_SIZE>> {
    POOLS.get(global::current())
}

/// `DynBuildOd`: adds the objects of a binary DCF container to the
/// dictionary, writes its values into existing objects and reconfigures
/// the PDOs it names (seed manual L-1087d chapters 2, 3 and 5.1; the rules
/// are in the Rust documentation of `cop::od::dynamic`). Call it after
/// `CcmConnectToNet`. All or nothing: when it fails nothing has changed.
///
/// `pProcessImageDscrpt_p` may be NULL (no process image). Otherwise
/// `m_pbProcessImage`/`m_dwProcessImageSize` describe the image the
/// network variables are placed in (NULL/0: none), and on success the
/// function fills in the image size the container needs and the input and
/// output windows (from the container's parameter segment, or computed by
/// the offset rule).
///
/// Returns kCopSuccessful; kCopInvalidParam (NULL container);
/// kCopIllegalInstance (before `CcmInitCANopen`); kCopNoFreeInstance (a
/// dynamic OD is already built: call `DynDestroyOd` first);
/// kCopDynInvalidConfig (malformed or inconsistent container, a PDO
/// without mapping object, variables sharing bytes of the image, a
/// variable outside the input and output areas of the container's
/// process-image parameters); kCopDynNoMemory (the tables do not fit
/// `OBD_DYNAMIC_POOL_SIZE`, or a variable lies outside the process image);
/// kCopCobIllegalCanId; kCopCobNoFreeEntry (PDO number beyond
/// `PDO_MAX_RXPDO_IN_OBD` / `PDO_MAX_TXPDO_IN_OBD` when that is above 0;
/// with 0 the PDOs come from the pool); kCopCobAlreadyExist (two TPDOs with one
/// COB-ID); kCopObdIndexNotExist (an index that cannot be created:
/// 0x0000-0x0FFF, 0xFFFF); kCopObdSubindexNotExist (a subindex an existing
/// object does not have); kCopPdoErrorMapp; or the code of a value the
/// dictionary refused (kCopObdValueLengthError, kCopObdValueToHigh, ...).
/// `DynGetLastError` names the entry a refusal is about.
///
/// # Safety
/// `pbDcfSegCont_p` must point to a container readable for the size its
/// first DWORD names. The process image must stay valid (and is accessed
/// by the stack) until `DynDestroyOd`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn DynBuildOd(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pbDcfSegCont_p: *mut BYTE,
    pProcessImageDscrpt_p: *mut tProcessImageDscrpt,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let refuse = |code: CopKernel| {
        if let Some(p) = pool() {
            p.set_last(code, None);
        }
        code.code()
    };
    if pbDcfSegCont_p.is_null() {
        return refuse(CopKernel::InvalidParam);
    }
    // SAFETY: the caller provides at least the size field; read unaligned
    // because a BYTE array has no alignment.
    let head = unsafe { core::ptr::read_unaligned(pbDcfSegCont_p as *const [u8; 4]) };
    let size = u32::from_le_bytes(head);
    if (size as usize) < HEADER_SIZE || size > MAX_CONTAINER {
        return refuse(CopKernel::DynInvalidConfig);
    }
    // SAFETY: the caller guarantees `size` readable bytes (the container
    // names its own size).
    let bytes = unsafe { core::slice::from_raw_parts(pbDcfSegCont_p as *const u8, size as usize) };
    let image = if pProcessImageDscrpt_p.is_null() {
        None
    } else {
        // SAFETY: checked for NULL; the caller owns the descriptor.
        let d = unsafe { *pProcessImageDscrpt_p };
        if d.m_pbProcessImage.is_null() || d.m_dwProcessImageSize == 0 {
            None
        } else {
            // SAFETY: the caller hands the image for the lifetime of the
            // dynamic OD (documented above).
            Some(unsafe {
                super::ptr::static_bytes(
                    d.m_pbProcessImage as *mut c_void,
                    d.m_dwProcessImageSize as usize,
                )
            })
        }
    };
    let Some(pool) = pool() else {
        return CopKernel::IllegalInstance.code();
    };
    let now = super::driver::TgtClock.now();
    let r = global::with(|i| pool.build(&mut i.stack, &mut i.port, now, bytes, image));
    let code = match r {
        Ok(Ok(info)) => {
            if !pProcessImageDscrpt_p.is_null() {
                // SAFETY: checked for NULL above.
                let d = unsafe { &mut *pProcessImageDscrpt_p };
                d.m_dwProcessImageSize = info.pi.total;
                d.m_dwDynPIOffsetIn = info.pi.input_offset;
                d.m_dwDynPISizeIn = info.pi.input_size;
                d.m_dwDynPIOffsetOut = info.pi.output_offset;
                d.m_dwDynPISizeOut = info.pi.output_size;
            }
            CopKernel::Successful
        }
        Ok(Err(e)) | Err(e) => e,
    };
    global::pump(|i, now| i.stack.drain(&mut i.port, now));
    code.code()
}

/// `DynGetLastError` (this library's extension, not part of the SYS TEC
/// API): why the last `DynBuildOd` of the instance was refused. Writes the
/// index, subindex and byte offset (from the container's start) of the
/// container entry the refusal is about, and the code `DynBuildOd`
/// returned; index, subindex and offset are 0 when the refusal concerns
/// the container or the pool as a whole (header, sizes, memory, a second
/// build), and the code is kCopSuccessful after a build that succeeded or
/// before the first. Each pointer may be NULL (that value is not written).
///
/// Returns kCopSuccessful; kCopIllegalInstance when the instance has no
/// pool.
///
/// # Safety
/// Each non-NULL pointer must be valid for writing its type.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn DynGetLastError(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pwIndex_p: *mut WORD,
    pbSubIndex_p: *mut BYTE,
    pdwOffset_p: *mut DWORD,
    pCode_p: *mut tCopKernel,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let Some(pool) = pool() else {
        return CopKernel::IllegalInstance.code();
    };
    let (code, entry) = match pool.last_error() {
        Some(e) => (e.code, e.entry),
        None => (CopKernel::Successful.code(), None),
    };
    let (index, sub, offset) = entry.map_or((0, 0, 0), |b| (b.index, b.sub, b.offset));
    // SAFETY: each pointer is checked for NULL; the caller guarantees the
    // others are writable.
    unsafe {
        if !pwIndex_p.is_null() {
            pwIndex_p.write_unaligned(index);
        }
        if !pbSubIndex_p.is_null() {
            pbSubIndex_p.write(sub);
        }
        if !pdwOffset_p.is_null() {
            pdwOffset_p.write_unaligned(offset);
        }
        if !pCode_p.is_null() {
            pCode_p.write_unaligned(code);
        }
    }
    CopKernel::Successful.code()
}

/// `DynDestroyOd`: removes the dynamic OD and resets the PDO module (seed
/// manual 5.2): the PDO module sees kNmtEvPreResetCommunication, the
/// dynamic tables are dropped, the PDO communication and mapping
/// parameters of the static dictionary get their defaults and the PDO
/// module goes to PRE-OPERATIONAL (an NMT start makes PDOs run again).
/// The pool is free for the next `DynBuildOd`.
///
/// Also allowed after `CcmShutDownCANopen` (the order of the AWorks
/// adapter): then it only gives the pool back.
///
/// Returns kCopSuccessful; kCopIllegalInstance when there is neither an
/// initialised stack nor a dynamic OD to give back.
#[unsafe(no_mangle)]
pub extern "C" fn DynDestroyOd(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let Some(pool) = pool() else {
        return CopKernel::IllegalInstance.code();
    };
    let now = super::driver::TgtClock.now();
    let r = global::with(|i| {
        let had = i.stack.dynamic_od().is_some();
        let r = pool.destroy(&mut i.stack, &mut i.port, now);
        (had, r)
    });
    let code = match r {
        Ok((had, Ok(()))) => {
            if !had {
                // A claim left by an instance that was shut down.
                pool.release_detached();
            }
            CopKernel::Successful
        }
        Ok((_, Err(e))) => e,
        Err(CopKernel::IllegalInstance) => {
            if pool.release_detached() {
                CopKernel::Successful
            } else {
                CopKernel::IllegalInstance
            }
        }
        Err(e) => e,
    };
    global::pump(|i, now| i.stack.drain(&mut i.port, now));
    code.code()
}
