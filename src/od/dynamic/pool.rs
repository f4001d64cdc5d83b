//! The pool of the dynamic OD: its state (claimed, the last refusal), the
//! layout of one build's regions and the steps of a build that need no raw
//! pointer. The memory and the code that lays the tables out in it are in
//! [`crate::od::table`] (the dictionary's one module allowed `unsafe`); the
//! Rust entry points that take the stack (`build`, `destroy`, `release`)
//! in `src/ccm/dynod.rs`; the layout is documented with the C API
//! (`src/ffi/dynod.rs`).

use core::mem::{align_of, size_of};
use core::sync::atomic::{AtomicU8, Ordering};

use super::{Blame, BuildInfo, Initial, NewSub, Place, Plan, Target};
use crate::error::CopKernel;
use crate::od::table::DynPool;
use crate::od::value;
use crate::od::{ObdEntry, ObdSubEntry, Part};
use crate::port::{CanPort, Ticks};

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

pub(crate) fn align_up(n: usize, a: usize) -> usize {
    n.div_ceil(a) * a
}

/// Offsets of the regions of one build.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Layout {
    pub(crate) entries: usize,
    pub(crate) subs_at: usize,
    pub(crate) subs: usize,
    pub(crate) rx_at: usize,
    pub(crate) rx_channels: usize,
    pub(crate) tx_at: usize,
    pub(crate) tx_channels: usize,
    pub(crate) data_at: usize,
    pub(crate) snap_at: usize,
    pub(crate) copy_at: usize,
    pub(crate) end: usize,
}

impl Layout {
    /// The regions for `plan` beside `user` entries of the user part, with
    /// RPDO channels of type `R` and TPDO channels of type `T` (these after
    /// those).
    pub(crate) fn of<R, T>(plan: &Plan<'_>, user: usize) -> Option<Layout> {
        let entries = user.checked_add(plan.new_indices)?;
        let subs_at = align_up(
            entries.checked_mul(size_of::<ObdEntry>())?,
            align_of::<ObdSubEntry>(),
        );
        let subs_end = subs_at.checked_add(plan.new_subs.checked_mul(size_of::<ObdSubEntry>())?)?;
        let rx_at = align_up(subs_end, align_of::<R>());
        let rx_end = rx_at.checked_add(plan.rx_channels.checked_mul(size_of::<R>())?)?;
        let tx_at = align_up(rx_end, align_of::<T>());
        let tx_end = tx_at.checked_add(plan.tx_channels.checked_mul(size_of::<T>())?)?;
        let data_at = if plan.rx_channels == 0 && plan.tx_channels == 0 {
            subs_end
        } else {
            tx_end
        };
        let snap_at = data_at.checked_add(plan.data_bytes)?;
        let copy_at = snap_at.checked_add(plan.snapshot_bytes)?;
        let end = copy_at.checked_add(plan.container().index_segment().len())?;
        Some(Layout {
            entries,
            subs_at,
            subs: plan.new_subs,
            rx_at,
            rx_channels: plan.rx_channels,
            tx_at,
            tx_channels: plan.tx_channels,
            data_at,
            snap_at,
            copy_at,
            end,
        })
    }
}
impl<const N: usize> DynPool<N> {
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

    pub(crate) fn id(&self) -> usize {
        self as *const Self as usize
    }

    /// [`DynPool::build`] for every [`Target`]: `DynBuildOd` for Rust: applies `container` to `stack` (see
    /// [`crate::od::dynamic`]), with the variables of the process image in
    /// `image` when given. All or nothing: on `Err` the dictionary, the
    /// modules' parameters and the pool are as before.
    ///
    /// Errors: `kCopNoFreeInstance` when `stack` already has a dynamic OD
    /// or the pool is in use; `kCopDynInvalidConfig`, `kCopDynNoMemory`,
    /// `kCopCobIllegalCanId`, `kCopCobNoFreeEntry`, `kCopCobAlreadyExist`,
    /// `kCopObdIndexNotExist`, `kCopObdSubindexNotExist`,
    /// `kCopPdoErrorMapp`, or the code of a write the dictionary refused.
    pub(crate) fn build_in(
        &'static self,
        stack: &mut impl Target,
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

    /// [`DynPool::destroy`] for every [`Target`].
    pub(crate) fn destroy_in(
        &'static self,
        stack: &mut impl Target,
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

    /// Gives the pool back without a stack: only for the C API, after
    /// `CcmShutDownCANopen` removed the instance that used it.
    /// Gives the pool back when `installed` (the dynamic OD of a stack
    /// that is going away) lives in it.
    pub(crate) fn release_owned(&self, installed: Option<&super::Installed>) {
        if installed.is_some_and(|d| d.pool == self.id()) {
            self.claimed.store(false, Ordering::Release);
        }
    }

    pub(crate) fn release_detached(&self) -> bool {
        self.claimed.swap(false, Ordering::AcqRel)
    }
}

pub(crate) fn copy_entry(o: &ObdEntry) -> ObdEntry {
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
pub(crate) fn init_image(plan: &Plan<'_>, image: &'static [AtomicU8]) {
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
