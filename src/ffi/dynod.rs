//! The dynamic object dictionary (SYS TEC CcmDyn): `DynBuildOd`,
//! `DynDestroyOd`, `tProcessImageDscrpt`, and the pool the tables live in.
//!
//! The decisions (what a container does, in which order, what is refused)
//! are in [`crate::od::dynamic`]; this file only lays the tables out in
//! memory, which needs raw pointers.
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
//! | PDO channels, only when `PDO_MAX_RXPDO_IN_OBD` / `PDO_MAX_TXPDO_IN_OBD` is 0 and the container has PDOs of that direction | (highest RPDO number + 1 + highest TPDO number + 1) × the state of one PDO ([`crate::pdo::channel_size`]) |
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

use core::cell::UnsafeCell;
use core::ffi::c_void;
use core::mem::{align_of, size_of};
use core::sync::atomic::{AtomicBool, AtomicU8, AtomicU32, Ordering};

use super::global;
use super::types::{BYTE, DWORD, WORD, tCopKernel};
use crate::ccm::Stack;
use crate::error::CopKernel;
use crate::od::Part;
use crate::od::dcf::{Container, HEADER_SIZE};
use crate::od::dynamic::{
    Blame, BuildInfo, Initial, Installed, NewSub, Place, Plan, image_overlaps_in,
};
use crate::od::value;
use crate::od::{ObdEntry, ObdSubEntry};
use crate::pdo::Channel;
use crate::port::{CanPort, Clock, Ticks};

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

/// The pool's bytes, zero from the start (a `static` in `.bss`), so that
/// they can always be lent out as `&mut [u8]`.
#[repr(C, align(8))]
struct Mem<const N: usize>([u8; N]);

/// Storage for the tables of one dynamic object dictionary (see the module
/// docs for the layout). Declare it as a `static`; it is claimed by a
/// build and given back by [`DynPool::destroy`] or [`DynPool::release`].
///
/// ```
/// use cop::od::dynamic::DynPool;
/// static POOL: DynPool<4096> = DynPool::new();
/// assert!(!POOL.is_in_use());
/// ```
pub struct DynPool<const N: usize> {
    mem: UnsafeCell<Mem<N>>,
    claimed: AtomicBool,
    /// The last build's refusal: code (0 after a build that succeeded).
    last_code: AtomicU32,
    /// Index << 8 | subindex of the entry it was about (0: none).
    last_entry: AtomicU32,
    /// Byte offset of that entry in the container.
    last_offset: AtomicU32,
}

/// What [`DynPool::last_error`] reports about the last build.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BuildError {
    /// The code the build returned (`tCopKernel`, [`CopKernel::code`]).
    pub code: u32,
    /// The container entry the refusal is about; `None` when it concerns
    /// the container or the pool as a whole (header, sizes, memory, a
    /// second build).
    pub entry: Option<Blame>,
}

// SAFETY: the memory is written only by the build that claimed the pool
// (`claimed` is taken with compare-exchange) and read through the tables
// afterwards; the stack API is single-threaded per instance.
unsafe impl<const N: usize> Sync for DynPool<N> {}

impl<const N: usize> Default for DynPool<N> {
    fn default() -> Self {
        Self::new()
    }
}

fn align_up(n: usize, a: usize) -> usize {
    n.div_ceil(a) * a
}

/// Offsets of the regions of one build.
#[derive(Clone, Copy, Debug)]
struct Layout {
    entries: usize,
    subs_at: usize,
    subs: usize,
    chan_at: usize,
    rx_channels: usize,
    tx_channels: usize,
    data_at: usize,
    snap_at: usize,
    copy_at: usize,
    end: usize,
}

impl Layout {
    fn of(plan: &Plan<'_>, user: usize) -> Option<Layout> {
        let entries = user.checked_add(plan.new_indices)?;
        let subs_at = align_up(
            entries.checked_mul(size_of::<ObdEntry>())?,
            align_of::<ObdSubEntry>(),
        );
        let subs_end = subs_at.checked_add(plan.new_subs.checked_mul(size_of::<ObdSubEntry>())?)?;
        let chan_at = align_up(subs_end, align_of::<Channel>());
        let channels = plan.rx_channels.checked_add(plan.tx_channels)?;
        let data_at = if channels == 0 {
            subs_end
        } else {
            chan_at.checked_add(channels.checked_mul(size_of::<Channel>())?)?
        };
        let snap_at = data_at.checked_add(plan.data_bytes)?;
        let copy_at = snap_at.checked_add(plan.snapshot_bytes)?;
        let end = copy_at.checked_add(plan.container().index_segment().len())?;
        Some(Layout {
            entries,
            subs_at,
            subs: plan.new_subs,
            chan_at,
            rx_channels: plan.rx_channels,
            tx_channels: plan.tx_channels,
            data_at,
            snap_at,
            copy_at,
            end,
        })
    }
}

impl<const N: usize> DynPool<N> {
    /// An unused pool.
    pub const fn new() -> Self {
        DynPool {
            mem: UnsafeCell::new(Mem([0; N])),
            claimed: AtomicBool::new(false),
            last_code: AtomicU32::new(0),
            last_entry: AtomicU32::new(0),
            last_offset: AtomicU32::new(0),
        }
    }

    /// Size in bytes.
    pub const fn capacity(&self) -> usize {
        N
    }

    /// The refusal of the last build with this pool (`None` when it
    /// succeeded or there was none yet).
    pub fn last_error(&self) -> Option<BuildError> {
        let code = self.last_code.load(Ordering::Acquire);
        if code == CopKernel::Successful.code() {
            return None;
        }
        let e = self.last_entry.load(Ordering::Acquire);
        let entry = (e != 0).then(|| Blame {
            index: (e >> 8) as u16,
            sub: e as u8,
            offset: self.last_offset.load(Ordering::Acquire),
        });
        Some(BuildError { code, entry })
    }

    pub(crate) fn set_last(&self, code: CopKernel, entry: Option<Blame>) {
        let (e, off) = entry.map_or((0, 0), |b| {
            ((u32::from(b.index) << 8) | u32::from(b.sub), b.offset)
        });
        self.last_entry.store(e, Ordering::Release);
        self.last_offset.store(off, Ordering::Release);
        self.last_code.store(code.code(), Ordering::Release);
    }

    /// True while a build uses the pool.
    pub fn is_in_use(&self) -> bool {
        self.claimed.load(Ordering::Acquire)
    }

    fn id(&self) -> usize {
        self as *const Self as usize
    }

    fn base(&self) -> *mut u8 {
        self.mem.get() as *mut u8
    }

    /// `DynBuildOd` for Rust: applies `container` to `stack` (see
    /// [`crate::od::dynamic`]), with the variables of the process image in
    /// `image` when given. All or nothing: on `Err` the dictionary, the
    /// modules' parameters and the pool are as before.
    ///
    /// Errors: `kCopNoFreeInstance` when `stack` already has a dynamic OD
    /// or the pool is in use; `kCopDynInvalidConfig`, `kCopDynNoMemory`,
    /// `kCopCobIllegalCanId`, `kCopCobNoFreeEntry`, `kCopCobAlreadyExist`,
    /// `kCopObdIndexNotExist`, `kCopObdSubindexNotExist`,
    /// `kCopPdoErrorMapp`, or the code of a write the dictionary refused.
    pub fn build(
        &'static self,
        stack: &mut Stack,
        port: &mut impl CanPort,
        now: Ticks,
        container: &[u8],
        image: Option<&'static [AtomicU8]>,
    ) -> Result<BuildInfo, CopKernel> {
        if stack.dynamic_od().is_some() {
            self.set_last(CopKernel::NoFreeInstance, None);
            return Err(CopKernel::NoFreeInstance);
        }
        // The pool is claimed before the container is read, because the
        // index of its entries is built in the pool. A pool in use (the
        // tables of another stack) is not touched: the container is then
        // checked without index (the same checks, by scanning it) and the
        // build refused with kCopNoFreeInstance after them, as a free pool
        // would have been claimed after them.
        let claimed = self
            .claimed
            .compare_exchange(false, true, Ordering::AcqRel, Ordering::Acquire)
            .is_ok();
        let mut blame = None;
        let r = self.plan_and_fill(claimed, stack, port, now, container, image, &mut blame);
        if r.is_err() && claimed {
            self.claimed.store(false, Ordering::Release);
        }
        match &r {
            Ok(_) => self.set_last(CopKernel::Successful, None),
            Err(e) => self.set_last(*e, blame),
        }
        r
    }

    #[allow(clippy::too_many_arguments)]
    fn plan_and_fill(
        &'static self,
        claimed: bool,
        stack: &mut Stack,
        port: &mut impl CanPort,
        now: Ticks,
        container: &[u8],
        image: Option<&'static [AtomicU8]>,
        blame: &mut Option<Blame>,
    ) -> Result<BuildInfo, CopKernel> {
        let image_len = image.map_or(0, <[AtomicU8]>::len);
        let plan = if claimed {
            // SAFETY: the pool is claimed by this build, so nothing else
            // uses its memory, and no reference into it exists (a previous
            // build's tables were detached from their stack before the pool
            // was given back). Its N bytes are initialised (`Mem` starts
            // zeroed and is only ever written with bytes).
            let scratch = unsafe { core::slice::from_raw_parts_mut(self.base(), N) };
            let c = Container::parse_indexed(container, scratch).map_err(|e| e.kernel())?;
            // SAFETY: the index took the last `index_len()` bytes of the
            // pool; the bytes before it are not referred to any more (the
            // slice above is not used again).
            let notes = unsafe { core::slice::from_raw_parts_mut(self.base(), N - c.index_len()) };
            Plan::new_blamed(c, stack.od(), image_len, notes, blame)?
        } else {
            let c = Container::parse(container).map_err(|e| e.kernel())?;
            Plan::new_blamed(c, stack.od(), image_len, &mut [], blame)?
        };
        let original = stack.od().part(Part::User);
        let layout = Layout::of(&plan, original.len()).ok_or(CopKernel::DynNoMemory)?;
        if layout.end > N {
            return Err(CopKernel::DynNoMemory);
        }
        if !claimed {
            return Err(CopKernel::NoFreeInstance);
        }
        // The index and the plan's notes lie at the end of the pool; the
        // tables and the snapshot are written before them, the copy of the
        // index segment over them at the very end. When the tables would
        // reach them, the build goes on without them.
        let index_at = N - plan.container().index_len() - plan.notes_len();
        let plan = if index_at < layout.copy_at {
            plan.without_index()
        } else {
            plan
        };
        self.fill(
            &plan, &layout, index_at, original, stack, port, now, image, blame,
        )
    }

    #[allow(clippy::too_many_arguments)]
    fn fill(
        &'static self,
        plan: &Plan<'_>,
        layout: &Layout,
        index_at: usize,
        original: &'static [ObdEntry],
        stack: &mut Stack,
        port: &mut impl CanPort,
        now: Ticks,
        image: Option<&'static [AtomicU8]>,
        blame: &mut Option<Blame>,
    ) -> Result<BuildInfo, CopKernel> {
        // The pool is claimed by this build, so nothing else writes it; the
        // only references into it are the container's index and the plan's
        // notes, at `index_at..N`, which is not below `copy_at` while the
        // plan uses them (checked by the caller). `layout.end <= N` was
        // checked, so every region is inside `mem`. Every byte of the
        // regions that is read later is written below first (tables, the
        // variables' initial values, the snapshot records).
        let base = self.base();
        let entries_ptr = base as *mut ObdEntry;
        // SAFETY: subs_at + subs * size <= end <= N (Layout::of).
        let subs_ptr = unsafe { base.add(layout.subs_at) } as *mut ObdSubEntry;
        // SAFETY: data_at <= end <= N.
        let mut data_ptr = unsafe { base.add(layout.data_at) };
        let data_end = layout.snap_at;

        let mut written_entries = 0usize;
        let mut written_subs = 0usize;
        let mut orig = original.iter().peekable();
        let mut put_entry = |e: ObdEntry| -> Result<(), CopKernel> {
            if written_entries >= layout.entries {
                return Err(CopKernel::DynInvalidConfig);
            }
            // SAFETY: written_entries < entries; the region holds `entries`
            // properly aligned ObdEntry slots (offset 0 of an 8-aligned pool).
            unsafe { entries_ptr.add(written_entries).write(e) };
            written_entries += 1;
            Ok(())
        };
        for (index, subs) in plan.new_objects() {
            while let Some(o) = orig.next_if(|o| o.index() < index) {
                put_entry(copy_entry(o))?;
            }
            let first = written_subs;
            for d in subs {
                let d = d?;
                if written_subs >= layout.subs {
                    return Err(CopKernel::DynInvalidConfig);
                }
                let current: *mut c_void = match d.place {
                    Place::Pool => {
                        let len = d.storage_len();
                        // SAFETY: data_ptr stays within data_at..snap_at:
                        // the plan counted `storage_len` for every pool
                        // variable into data_bytes (checked below).
                        let used = unsafe { data_ptr.offset_from(base) } as usize;
                        if used + len > data_end {
                            return Err(CopKernel::DynInvalidConfig);
                        }
                        // SAFETY: the range is inside the zeroed, claimed
                        // pool and no other reference to it exists.
                        let dst = unsafe { core::slice::from_raw_parts_mut(data_ptr, len) };
                        d.initial_bytes(dst)?;
                        let p = data_ptr as *mut c_void;
                        // SAFETY: stays within the region (checked above).
                        data_ptr = unsafe { data_ptr.add(len) };
                        p
                    }
                    Place::Image(off) => {
                        let img = image.ok_or(CopKernel::DynInvalidConfig)?;
                        let var = img
                            .get(off as usize..off as usize + d.storage_len())
                            .ok_or(CopKernel::DynNoMemory)?;
                        var.as_ptr() as *mut c_void
                    }
                };
                let e = ObdSubEntry {
                    m_bSubIndex: d.sub,
                    m_bType: d.typ.code(),
                    m_bAccess: d.access.0,
                    m_bKind: d.kind,
                    m_dwSize: d.size,
                    m_pDefault: core::ptr::null(),
                    m_pCurrent: current,
                };
                // SAFETY: written_subs < subs; the region holds `subs`
                // aligned slots.
                unsafe { subs_ptr.add(written_subs).write(e) };
                written_subs += 1;
            }
            let count =
                u8::try_from(written_subs - first).map_err(|_| CopKernel::DynInvalidConfig)?;
            put_entry(ObdEntry {
                m_wIndex: index,
                // SAFETY: `first` <= written_subs <= subs.
                m_pSubIndex: unsafe { subs_ptr.add(first) },
                m_bCount: count,
                m_fpCallback: None,
            })?;
        }
        for o in orig {
            put_entry(copy_entry(o))?;
        }
        if written_entries != layout.entries || written_subs != layout.subs {
            return Err(CopKernel::DynInvalidConfig);
        }
        // SAFETY: snap_at..copy_at is initialised pool memory nobody else
        // refers to.
        let snapshot: &mut [u8] = unsafe {
            core::slice::from_raw_parts_mut(
                base.add(layout.snap_at),
                layout.copy_at - layout.snap_at,
            )
        };
        // SAFETY: every slot was written above; from now on the tables are
        // only read (until the pool is given back).
        let merged: &'static [ObdEntry] =
            unsafe { core::slice::from_raw_parts(entries_ptr, layout.entries) };
        // SAFETY: as above.
        let subs: &'static [ObdSubEntry] =
            unsafe { core::slice::from_raw_parts(subs_ptr, layout.subs) };

        if let Some(img) = image {
            // The bytes between the copy region's start and the index are
            // free until the copy is made (the last step).
            let free_end = if plan.container().is_indexed() {
                index_at
            } else {
                N
            };
            // SAFETY: copy_at..free_end lies inside the pool, after every
            // table and the snapshot and before the index; nothing refers
            // to it.
            let free = unsafe {
                core::slice::from_raw_parts_mut(
                    base.add(layout.copy_at),
                    free_end.saturating_sub(layout.copy_at),
                )
            };
            if image_overlaps_in(img, subs, free) {
                return Err(CopKernel::DynInvalidConfig);
            }
        }
        let mut candidate = *stack.od();
        candidate
            .set_user_part(merged)
            .map_err(|_| CopKernel::DynInvalidConfig)?;
        plan.check_pdos_blamed(&candidate, blame)?;

        // The candidate is the stack's dictionary with the new user part,
        // already validated.
        *stack.od_mut() = candidate;
        let pooled = layout.rx_channels + layout.tx_channels > 0;
        if pooled {
            // SAFETY: chan_at is aligned for Channel and chan_at + channels
            // * size <= data_at <= N (Layout::of); the region is claimed
            // pool memory nobody else refers to. Every slot is written
            // before the slices are made.
            let (rx, tx) = unsafe {
                let first = base.add(layout.chan_at) as *mut Channel;
                let total = layout.rx_channels + layout.tx_channels;
                for i in 0..total {
                    first.add(i).write(Channel::new());
                }
                (
                    core::slice::from_raw_parts_mut(first, layout.rx_channels),
                    core::slice::from_raw_parts_mut(
                        first.add(layout.rx_channels),
                        layout.tx_channels,
                    ),
                )
            };
            stack.pdo_mut().attach_pooled(
                (layout.rx_channels > 0).then_some(rx),
                (layout.tx_channels > 0).then_some(tx),
            );
            stack.reload_configuration(port, now);
        }
        if let Err(e) = plan.apply_blamed(stack, snapshot, now, blame) {
            let _ = stack.od_mut().set_user_part(original);
            if pooled {
                stack.pdo_mut().detach_pooled(port);
            }
            stack.reload_configuration(port, now);
            return Err(e);
        }
        if let Some(img) = image {
            init_image(plan, img);
        }
        let info = BuildInfo {
            pi: plan.pi,
            new_indices: plan.new_indices,
            new_subs: plan.new_subs,
            pool_used: layout.end,
        };
        // The plan (and its index) is not used from here on: the copy of
        // the index segment, kept for the resets, takes the end of the
        // layout.
        let segment = plan.container().index_segment();
        // SAFETY: copy_at + segment.len() = end <= N; the source is the
        // caller's container, which does not overlap the pool; the index
        // that lay here is not read any more.
        let values: &'static [u8] = unsafe {
            let dst = base.add(layout.copy_at);
            core::ptr::copy_nonoverlapping(segment.as_ptr(), dst, segment.len());
            core::slice::from_raw_parts(dst, segment.len())
        };
        stack.set_dynamic_od(Some(Installed {
            values,
            original_user: original,
            pool: self.id(),
        }));
        stack.reload_configuration(port, now);
        Ok(info)
    }

    /// `DynDestroyOd` for Rust: removes the dynamic OD of `stack` and
    /// resets the PDO module as seed manual 5.2 describes
    /// (the sequence is in `Stack::destroy_dynamic_od`), then gives the
    /// pool back. Also without a dynamic OD the PDO module is reset (as the
    /// original does). `kCopIllegalInstance` when the stack's dynamic OD
    /// lives in another pool.
    pub fn destroy(
        &'static self,
        stack: &mut Stack,
        port: &mut impl CanPort,
        now: Ticks,
    ) -> Result<(), CopKernel> {
        let original = match stack.dynamic_od() {
            Some(d) if d.pool != self.id() => return Err(CopKernel::IllegalInstance),
            Some(d) => {
                let o = d.original_user_part();
                stack.destroy_dynamic_od(o, port, now);
                self.claimed.store(false, Ordering::Release);
                return Ok(());
            }
            None => stack.od().part(Part::User),
        };
        stack.destroy_dynamic_od(original, port, now);
        Ok(())
    }

    /// Gives the pool back after the stack that used it is gone (taking the
    /// stack by value makes sure it is).
    pub fn release(&'static self, stack: Stack) {
        // `stack` is dropped when this function returns.
        let ours = stack.dynamic_od().is_some_and(|d| d.pool == self.id());
        if ours {
            self.claimed.store(false, Ordering::Release);
        }
    }

    /// Gives the pool back without a stack: only for the C API, after
    /// `CcmShutDownCANopen` removed the instance that used it.
    fn release_detached(&self) -> bool {
        self.claimed.swap(false, Ordering::AcqRel)
    }
}

fn copy_entry(o: &ObdEntry) -> ObdEntry {
    ObdEntry {
        m_wIndex: o.m_wIndex,
        m_pSubIndex: o.m_pSubIndex,
        m_bCount: o.m_bCount,
        m_fpCallback: o.m_fpCallback,
    }
}

/// Writes the initial values of the variables placed in the process image
/// (after every check passed, so that a refused build leaves the image
/// alone too).
fn init_image(plan: &Plan<'_>, image: &'static [AtomicU8]) {
    for (_, subs) in plan.new_objects() {
        for d in subs.flatten() {
            write_image(&d, image);
        }
    }
}

fn write_image(d: &NewSub<'_>, image: &[AtomicU8]) {
    let Place::Image(off) = d.place else {
        return;
    };
    if matches!(d.initial, Initial::Count(_)) {
        return;
    }
    let mut tmp = [0u8; 8];
    let len = d.storage_len();
    let (Some(buf), Some(var)) = (
        tmp.get_mut(..len),
        image.get(off as usize..off as usize + len),
    ) else {
        return;
    };
    if d.initial_bytes(buf).is_ok() {
        value::store(var, buf);
    }
}

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
    pbDcfSegCont_p: *mut BYTE,
    pProcessImageDscrpt_p: *mut tProcessImageDscrpt,
) -> tCopKernel {
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
    pwIndex_p: *mut WORD,
    pbSubIndex_p: *mut BYTE,
    pdwOffset_p: *mut DWORD,
    pCode_p: *mut tCopKernel,
) -> tCopKernel {
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
pub extern "C" fn DynDestroyOd() -> tCopKernel {
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
