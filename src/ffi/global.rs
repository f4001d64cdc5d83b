//! The one stack instance behind the C API (single-instance build: the
//! `CCM_DECL_INSTANCE_HDL` macros are empty, so every `Ccm*` call addresses
//! this instance).
//!
//! Access is exclusive and checked at run time: while a `Ccm*` function is
//! inside the stack, a nested call (which can only come from an OBD callback
//! the stack is executing) is refused with `kCopNoResource` instead of
//! creating a second mutable reference. Event callbacks (`AppSrdoEvent`,
//! the NMT callback, ...) run after the stack has been released, so they may
//! call any `Ccm*` function.
//!
//! `CcmGetSrdoState` / `CcmSetSrdoState` reach the status byte through
//! [`srdo_status`] first: a pointer to the status table of the current
//! instance, valid exactly while no reference into the instance exists
//! (`SRDO_GATE`); in every other case they take [`with_srdo_status`] with
//! the checks and codes of [`with`].

use core::cell::{Cell, UnsafeCell};
use core::mem::MaybeUninit;
use core::sync::atomic::Ordering;

use super::callbacks::{self, Callbacks};
use super::driver::{CdrvPort, TgtClock};
use super::instance::app_call;
use super::types::{tCcmErrorCallback, tCopKernel};
use crate::ccm::Stack;
use crate::error::{CopKernel, CopResult, to_code};
use crate::event::Event;
use crate::port::Clock;
use crate::srdo::{MAX_SRDO_NUMBER, status};

/// Everything the C API keeps between calls.
pub struct Instance {
    /// The device.
    pub stack: Stack,
    /// The driver.
    pub port: CdrvPort,
    /// The application's callbacks.
    pub callbacks: Callbacks,
    /// The master application's node tables (read again when they change).
    pub tables: super::tables::AppTables,
}

pub use super::MAX_INSTANCES;

struct Global {
    /// The instances' storage. Slot `i` holds an initialised [`Instance`]
    /// exactly when bit `i` of `live` is set. Uninitialised storage, so that
    /// the global lies in .bss (zeroed at start-up) rather than in .data,
    /// which would keep an image of the whole stack in flash.
    instances: UnsafeCell<[MaybeUninit<Instance>; MAX_INSTANCES]>,
    /// Bit `i`: slot `i` is initialised.
    live: Cell<u8>,
    current: Cell<usize>,
    busy: Cell<bool>,
    pumping: Cell<bool>,
    /// The program monitor event the pump handed out last has more queued
    /// right behind it ([`deliver_progmon_run`]).
    progmon_run: Cell<bool>,
}

/// The SRDO status bytes of the current instance while nothing is inside
/// it (`Srdo::status_table`), else [`NO_SRDO`]: the fast path of
/// `CcmGetSrdoState` / `CcmSetSrdoState` ([`srdo_status`]). Set to
/// `NO_SRDO` before anything borrows the instances, and derived again from
/// the instance as the last step of every [`with`], so that it is never
/// used while a reference into the instance exists and always comes from
/// the latest borrow. A static of its own, so that the fast path reaches it
/// with one load.
struct SrdoGate(Cell<*mut [u8; MAX_SRDO_NUMBER + 1]>);

// SAFETY: as for `Global` (single-threaded C API).
unsafe impl Sync for SrdoGate {}

static SRDO_GATE: SrdoGate = SrdoGate(Cell::new(
    &NO_SRDO as *const [u8; MAX_SRDO_NUMBER + 1] as *mut _,
));

/// The status table while no instance may be reached through
/// [`SRDO_GATE`]: every number absent, so the fast path falls back to
/// [`with_srdo_status`], which finds the right code. Never written and
/// never referenced mutably: the fast path reads an entry through a raw
/// pointer and takes a reference only to an entry that is not absent.
static NO_SRDO: [u8; MAX_SRDO_NUMBER + 1] = [status::ABSENT; MAX_SRDO_NUMBER + 1];

// One bit of `live` per instance.
const _: () = assert!(MAX_INSTANCES <= 8);

// SAFETY: the C API is documented as single-threaded (one thread calls the
// Ccm* functions; callbacks run inside those calls). `busy` turns accidental
// re-entry into an error code instead of aliasing.
unsafe impl Sync for Global {}

static GLOBAL: Global = Global {
    instances: UnsafeCell::new([const { MaybeUninit::uninit() }; MAX_INSTANCES]),
    live: Cell::new(0),
    current: Cell::new(0),
    busy: Cell::new(false),
    pumping: Cell::new(false),
    progmon_run: Cell::new(false),
};

/// Makes the fast path of [`srdo_status`] fall back (the instance is about
/// to be borrowed, installed, removed or changed).
#[inline(always)]
fn forget_srdo_state() {
    SRDO_GATE
        .0
        .set(&NO_SRDO as *const [u8; MAX_SRDO_NUMBER + 1] as *mut _);
}

/// The `live` bit of the current slot (0 for an index out of range, which
/// `select` never sets).
fn current_bit() -> u8 {
    let i = GLOBAL.current.get();
    if i < MAX_INSTANCES { 1 << i } else { 0 }
}

/// Borrows the current slot's storage; `busy` must be held.
#[inline(always)]
fn slot() -> Option<&'static mut MaybeUninit<Instance>> {
    // SAFETY: only called while `busy` is true, so no other reference into
    // the cell exists until the caller clears `busy`.
    let all = unsafe { &mut *GLOBAL.instances.get() };
    all.get_mut(GLOBAL.current.get())
}

/// Borrows the current instance if there is one; `busy` must be held.
#[inline(always)]
fn instance() -> Option<&'static mut Instance> {
    let i = GLOBAL.current.get();
    let s = slot()?;
    // `slot` found slot `i`, so `i` < MAX_INSTANCES <= 8.
    if (GLOBAL.live.get() >> i) & 1 == 0 {
        return None;
    }
    // SAFETY: the slot's `live` bit is set, so `install` initialised it and
    // `remove` has not taken it out since.
    Some(unsafe { s.assume_init_mut() })
}

/// The instance the C API addresses (always 0 on a target).
pub fn current() -> usize {
    GLOBAL.current.get()
}

/// Selects the instance the C API addresses (host simulation only).
/// Returns `false` for an index out of range or while the stack is busy.
pub fn select(index: usize) -> bool {
    if index >= MAX_INSTANCES || GLOBAL.busy.get() {
        return false;
    }
    forget_srdo_state();
    GLOBAL.current.set(index);
    true
}

/// The instance an exported function of a multi-instance build addresses
/// ([`crate::ffi::instance::ccm_enter!`]): entered with the function's
/// handle, left when the function returns, so that a call from inside a
/// callback of another instance leaves that instance addressed again when
/// it returns.
#[cfg(multi_instance)]
pub struct Scope {
    previous: usize,
    entered: usize,
}

#[cfg(multi_instance)]
impl Scope {
    /// Addresses instance `handle`; `Err(kCopIllegalInstance)` for a handle
    /// of no slot. Whether the slot holds an instance is decided by
    /// [`with`] (kCopIllegalInstance before `CcmInitCANopen` and after
    /// `CcmShutDownCANopen`). Addressing the instance already addressed
    /// (every call of a one-instance loop, a callback's calls into its own
    /// instance) writes nothing.
    #[inline(always)]
    pub fn enter(handle: u8) -> Result<Scope, CopKernel> {
        let entered = usize::from(handle);
        if entered >= MAX_INSTANCES {
            return Err(CopKernel::IllegalInstance);
        }
        let previous = GLOBAL.current.get();
        if previous != entered {
            forget_srdo_state();
            GLOBAL.current.set(entered);
        }
        Ok(Scope { previous, entered })
    }
}

#[cfg(multi_instance)]
impl Drop for Scope {
    #[inline(always)]
    fn drop(&mut self) {
        if self.previous != self.entered {
            forget_srdo_state();
            GLOBAL.current.set(self.previous);
        }
    }
}

/// The handle of a free slot for `CcmInitCANopen` (the lowest), or
/// kCopNoFreeInstance. The slot is taken by [`install`] with the handle
/// addressed.
#[cfg(multi_instance)]
pub fn free_slot() -> Result<u8, CopKernel> {
    let live = GLOBAL.live.get();
    (0..MAX_INSTANCES)
        .find(|i| live & (1 << i) == 0)
        .map(|i| i as u8)
        .ok_or(CopKernel::NoFreeInstance)
}

/// Runs `f` with exclusive access to the instance.
/// `Err(kCopIllegalInstance)` before `CcmInitCANopen`, `Err(kCopNoResource)`
/// for a nested call.
pub fn with<R>(f: impl FnOnce(&mut Instance) -> R) -> Result<R, CopKernel> {
    with_inline(f)
}

/// [`with`], inlined into its caller (the pump, once per event).
#[inline(always)]
fn with_inline<R>(f: impl FnOnce(&mut Instance) -> R) -> Result<R, CopKernel> {
    if GLOBAL.busy.replace(true) {
        return Err(CopKernel::NoResource);
    }
    forget_srdo_state();
    let r = match instance() {
        Some(i) => {
            let r = f(i);
            SRDO_GATE.0.set(i.stack.srdo_mut().status_table());
            Ok(r)
        }
        None => Err(CopKernel::IllegalInstance),
    };
    GLOBAL.busy.set(false);
    r
}

/// The fast path of `CcmGetSrdoState` / `CcmSetSrdoState`: runs `f` on the
/// status byte of SRDO `commu_index` of the current instance and returns
/// `true`, or returns `false` without running it when the byte cannot be
/// reached this way (no such SRDO, no instance, a nested call, an instance
/// just installed or selected); the caller then takes [`with_srdo_status`],
/// which runs the checks in full and returns their codes.
#[inline(always)]
pub fn srdo_status(commu_index: u16, f: impl FnOnce(&mut u8)) -> bool {
    // 0x1300 + n gives n; every other index gives more than 64 (or 0, which
    // the table has as absent).
    let n = usize::from(commu_index ^ crate::srdo::COMMU_BASE);
    if n > MAX_SRDO_NUMBER {
        return false;
    }
    // SAFETY: `SRDO_GATE` points to NO_SRDO or to the status table of the
    // current instance, both `MAX_SRDO_NUMBER + 1` bytes, and `n` is within
    // them; reading through the raw pointer creates no reference, so it is
    // sound for the read-only NO_SRDO as well.
    let p = unsafe { SRDO_GATE.0.get().cast::<u8>().add(n) };
    // SAFETY: `p` is in bounds and points to an initialised byte (above).
    if unsafe { p.read() } & status::ABSENT != 0 {
        return false;
    }
    // SAFETY: every entry of NO_SRDO is absent, so `p` points into the
    // status table of the current instance, set as the last step of `with`
    // and replaced by NO_SRDO before anything borrows the instances again;
    // no reference into the instance exists meanwhile (the C API is
    // single-threaded), so this mutable reference aliases nothing.
    let st = unsafe { &mut *p };
    f(st);
    true
}

/// [`with`] for the SRDO status byte of `commu_index`, inlined into
/// `CcmGetSrdoState` / `CcmSetSrdoState`: runs `f` on the byte and returns
/// kCopSuccessful, or the same errors as [`with`] (kCopNoResource for a
/// nested call, kCopIllegalInstance before `CcmInitCANopen`), then
/// kCopSrdoNotExist for an index that is not an SRDO.
#[inline(always)]
pub fn with_srdo_status(commu_index: u16, f: impl FnOnce(&mut u8)) -> tCopKernel {
    if GLOBAL.busy.replace(true) {
        return CopKernel::NoResource.code();
    }
    forget_srdo_state();
    let r = match instance() {
        Some(i) => {
            let srdo = i.stack.srdo_mut();
            let r = match srdo.status_mut(commu_index) {
                Some(s) => {
                    f(s);
                    CopKernel::Successful.code()
                }
                None => CopKernel::SrdoNotExist.code(),
            };
            SRDO_GATE.0.set(srdo.status_table());
            r
        }
        None => CopKernel::IllegalInstance.code(),
    };
    GLOBAL.busy.set(false);
    r
}

/// Installs a new instance; `Err(kCopNoFreeInstance)` if one exists,
/// `Err(kCopNoResource)` for a nested call.
pub fn install(i: Instance) -> Result<(), CopKernel> {
    if GLOBAL.busy.replace(true) {
        return Err(CopKernel::NoResource);
    }
    forget_srdo_state();
    let bit = current_bit();
    let r = match slot() {
        Some(s) if bit != 0 && GLOBAL.live.get() & bit == 0 => {
            s.write(i);
            GLOBAL.live.set(GLOBAL.live.get() | bit);
            Ok(())
        }
        _ => Err(CopKernel::NoFreeInstance),
    };
    GLOBAL.busy.set(false);
    r
}

/// Whether a live instance other than the addressed one has a dictionary
/// whose first non-empty table is `table` (the same objdict.h tables:
/// two instances on one set of statics would share every value and every
/// attached variable). `false` for an empty table and for a nested call.
pub fn dictionary_in_use(table: &[crate::od::ObdEntry]) -> bool {
    if table.is_empty() || GLOBAL.busy.replace(true) {
        return false;
    }
    let own = GLOBAL.current.get();
    let live = GLOBAL.live.get();
    // SAFETY: `busy` is held, so no other reference into the cell exists
    // until it is cleared below; only slots whose `live` bit is set are
    // read, and `install` initialised those.
    let all = unsafe { &*GLOBAL.instances.get() };
    let used = all.iter().enumerate().any(|(i, slot)| {
        i != own
            && (live >> i) & 1 != 0
            // SAFETY: the slot's `live` bit is set (above).
            && core::ptr::eq(first_table(unsafe { slot.assume_init_ref() }), table.as_ptr())
    });
    GLOBAL.busy.set(false);
    used
}

/// The first entry of an instance's first non-empty dictionary table.
fn first_table(i: &Instance) -> *const crate::od::ObdEntry {
    use crate::od::Part;
    [Part::Generic, Part::Manufacturer, Part::Device]
        .into_iter()
        .map(|p| i.stack.od().part(p))
        .find(|t| !t.is_empty())
        .map_or(core::ptr::null(), |t| t.as_ptr())
}

/// Removes the instance.
pub fn remove() -> Result<Instance, CopKernel> {
    if GLOBAL.busy.replace(true) {
        return Err(CopKernel::NoResource);
    }
    forget_srdo_state();
    let bit = current_bit();
    let r = match slot() {
        Some(s) if GLOBAL.live.get() & bit != 0 => {
            GLOBAL.live.set(GLOBAL.live.get() & !bit);
            // SAFETY: the `live` bit was set, so the slot holds an
            // initialised instance; clearing the bit first means it is
            // moved out exactly once and never read again until `install`
            // writes a new one.
            Ok(unsafe { s.assume_init_read() })
        }
        _ => Err(CopKernel::IllegalInstance),
    };
    GLOBAL.busy.set(false);
    r
}

/// The `tCopKernel` of a call made through [`with`]: the instance's code
/// (kCopIllegalInstance, kCopNoResource) or the call's own.
pub fn code(r: Result<CopResult, CopKernel>) -> tCopKernel {
    match r {
        Ok(inner) => to_code(inner),
        Err(e) => e.code(),
    }
}

/// Runs `f` (a change that cannot fail) on the instance: kCopSuccessful,
/// or why the instance could not be entered.
pub fn run(f: impl FnOnce(&mut Instance)) -> tCopKernel {
    code(with(|i| {
        f(i);
        Ok(())
    }))
}

/// Runs `f` on the instance at the time of the call (`TgtGetTickCount`),
/// hands out the events it queued and returns its code.
pub fn run_at(f: impl FnOnce(&mut Instance, crate::port::Ticks) -> CopResult) -> tCopKernel {
    let now = TgtClock.now();
    let r = with(|i| f(i, now));
    drain();
    code(r)
}

/// Hands out the events an API call may have queued (a dictionary write,
/// an NMT command, a transmission).
pub fn drain() {
    pump(|i, now| i.stack.drain(&mut i.port, now));
}

/// [`with`] for an API function whose work may yield an SRDO's success
/// event (`f` returns the SRDO's communication index, or queues the event
/// when its `bool` argument is false): `AppSrdoEvent` runs at once, after
/// the instance is released, as the pump would hand the event out first;
/// then the pump takes what is still queued. Inside a callback (the pump
/// running) `f` is told to queue, so that callbacks never nest, and the
/// running pump hands the event out.
#[inline(always)]
pub fn with_srdo_event<R>(
    f: impl FnOnce(&mut Instance, bool) -> (R, Option<u16>),
) -> Result<R, CopKernel> {
    let direct = !GLOBAL.pumping.get();
    let (r, first, mut queued) = with(|i| {
        let (r, idx) = f(i, direct);
        let cb = i.callbacks.srdo.and_then(|c| c.m_fpSrdoEvent);
        (r, idx.map(|idx| (cb, idx)), i.stack.has_queued())
    })?;
    if let Some((cb, idx)) = first {
        GLOBAL.pumping.set(true);
        // An SRDO event never reports an error (`Pending::call`).
        let _ = callbacks::Pending::SrdoEvent(cb, idx).call(current());
        GLOBAL.pumping.set(false);
        // What the callback queued (through the API) goes out as the
        // pump's next steps would have taken it.
        queued = queued || with(|i| i.stack.has_queued()).unwrap_or(false);
    }
    if queued {
        drain();
    }
    Ok(r)
}

/// Reports a code to the callback registered with
/// `CcmRegisterErrorCallback` (if any): the code an application callback
/// returned, unchanged, or one of the library's.
pub fn report_error(code: tCopKernel) {
    let cb = with(|i| i.callbacks.error).ok().flatten();
    if let Some(cb) = cb {
        // SAFETY: the application's error callback; no argument object.
        unsafe { app_call!(cb, current(); core::ptr::null_mut(), code) };
    }
}

/// The error callbacks registered with `CcmRegisterErrorCallback` while a
/// slot held no instance, one per slot: `CcmInitCANopen` gives the next
/// instance of the slot the callback, so that it also hears of the
/// refusals of the start-up events (`CcmRegisterErrorCallback` returns
/// void and cannot refuse). Function pointers as atomic pointers, as the
/// PDO callbacks are kept (`callbacks.rs`).
static EARLY_ERROR_CALLBACKS: [core::sync::atomic::AtomicPtr<core::ffi::c_void>; MAX_INSTANCES] =
    [const { core::sync::atomic::AtomicPtr::new(core::ptr::null_mut()) }; MAX_INSTANCES];

/// `CcmRegisterErrorCallback` for the addressed slot: the instance's
/// callback, or, while the slot holds no instance, the one its next
/// instance starts with.
pub fn register_error_callback(cb: tCcmErrorCallback) {
    if with(|i| i.callbacks.error = cb).is_err() {
        if let Some(early) = EARLY_ERROR_CALLBACKS.get(current()) {
            early.store(
                cb.map_or(core::ptr::null_mut(), |f| f as *mut _),
                Ordering::Relaxed,
            );
        }
    }
}

/// Takes the callback registered for the addressed slot before its
/// instance existed ([`register_error_callback`]).
pub fn take_early_error_callback() -> tCcmErrorCallback {
    let p = EARLY_ERROR_CALLBACKS
        .get(current())?
        .swap(core::ptr::null_mut(), Ordering::Relaxed);
    if p.is_null() {
        return None;
    }
    // SAFETY: non-NULL entries were stored by `register_error_callback`
    // from a tCcmErrorCallback function pointer of the application.
    Some(unsafe { core::mem::transmute::<*mut core::ffi::c_void, ErrorCallbackFn>(p) })
}

/// The function type of a [`tCcmErrorCallback`].
type ErrorCallbackFn = <tCcmErrorCallback as super::callbacks::OptionFn>::Fn;

/// Hands out events one at a time: `next` runs inside the stack and yields
/// the next event; the callback runs outside. Returns `true` when an SRDO
/// error was reported as not handled by the application
/// (kCopSrdoNotHandledInApp).
///
/// Callbacks never nest: a `Ccm*` call made from inside a callback leaves
/// the events it queues (and those still queued) to the pump that is
/// already running, which hands them out after the callback has returned.
/// Otherwise, for example, the SRDO handshake would be checked before
/// `AppSrdoError` has finished, and kNmtEvPostResetCommunication would
/// arrive inside the application's kNmtEvResetCommunication handler.
pub fn pump(mut next: impl FnMut(&mut Instance, crate::port::Ticks) -> Option<Event>) -> bool {
    if GLOBAL.pumping.replace(true) {
        return false;
    }
    let not_handled = pump_events(&mut next);
    GLOBAL.pumping.set(false);
    not_handled
}

/// Hands one event to the application ([`callbacks::Pending::call`]) and
/// reports a refusal through the error callback. Out of line, so that the
/// pump of every API function stays small, except for the SRDO events of
/// received and sent SRDOs, which call their callback directly.
#[inline(never)]
fn deliver(p: callbacks::Pending) {
    if let Some(code) = p.call(current()) {
        report_error(code);
    }
}

/// The pump's loop, out of line: only [`pump`] calls it, never while it
/// runs (`pumping`), which the worst-case stack analysis relies on
/// (scripts/tms570/stack.py `--pump`, docs/tms570.md): a `Ccm*` call made
/// from inside a callback does not reach the stack's processing again.
#[inline(never)]
fn pump_events(next: &mut impl FnMut(&mut Instance, crate::port::Ticks) -> Option<Event>) -> bool {
    let mut not_handled = false;
    loop {
        // An event already queued (a run of program monitor events, the
        // events of one frame) needs no time: the clock is read only when
        // the stack has to work.
        let step = with_inline(|i| {
            let p = i
                .stack
                .queued_event()
                .or_else(|| next(i, TgtClock.now()))
                .map(|e| callbacks::Pending::take(e, &i.callbacks));
            if let Some(callbacks::Pending::ProgMon(..)) = p {
                GLOBAL.progmon_run.set(i.stack.progmon_queued());
            }
            p
        });
        match step {
            Ok(Some(p @ callbacks::Pending::SrdoEvent(..))) => {
                // Never reports an error (`Pending::call`).
                let _ = p.call(current());
            }
            Ok(Some(p @ callbacks::Pending::ProgMon(..))) => {
                // Never reports an error (`Pending::call`).
                let _ = p.call(current());
                if GLOBAL.progmon_run.get() {
                    deliver_progmon_run(p);
                }
            }
            Ok(Some(p)) => {
                not_handled |= p.is_not_handled();
                deliver(p);
            }
            _ => break,
        }
    }
    not_handled
}

/// After `first` (a program monitor event the pump handed out): the ones
/// queued right behind it (a timer pass over the SRDOs queues one per
/// SRDO), taken in one borrow of the instance and handed to
/// `AppProgMonEvent` one after the other. The calls, their order and their
/// arguments are those of one event per pump step, without a return into
/// the stack between them; what a callback queues meanwhile comes after
/// them, as it would. Out of line, so that the pump's other steps carry
/// nothing of it.
#[inline(never)]
fn deliver_progmon_run(first: callbacks::Pending) {
    let callbacks::Pending::ProgMon(Some(cb), _) = first else {
        return;
    };
    // The action queue holds at most QUEUE_CAPACITY events.
    let mut events = [0u8; crate::event::QUEUE_CAPACITY];
    let mut len = 0;
    let _ = with_inline(|i| {
        for slot in events.iter_mut() {
            let Some(e) = i.stack.queued_progmon() else {
                break;
            };
            *slot = e as u8;
            len += 1;
        }
    });
    let instance = current();
    for &e in events.iter().take(len) {
        // SAFETY: AppProgMonEvent of the application (objdef.h), as
        // `Pending::call` calls it; its result is not evaluated.
        let _ = unsafe { app_call!(cb, instance; u32::from(e)) };
    }
}

/// `CopSimSelectInstance`: simulation only (`sim-instances` builds, and so
/// every `std` build) — selects
/// which of up to [`MAX_INSTANCES`] nodes the following `Ccm*` calls
/// address, so one process can run several nodes on a simulated bus.
/// Returns kCopSuccessful, or kCopIllegalInstance for an index out of range
/// (or when called from inside a callback).
#[cfg(all(feature = "sim-instances", not(multi_instance)))]
#[unsafe(no_mangle)]
pub extern "C" fn CopSimSelectInstance(bInstance_p: super::types::BYTE) -> tCopKernel {
    if select(usize::from(bInstance_p)) {
        CopKernel::Successful.code()
    } else {
        CopKernel::IllegalInstance.code()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn instance(node: u8) -> Instance {
        Instance {
            stack: Stack::new(crate::testod::dictionary(), node).unwrap(),
            port: CdrvPort::default(),
            callbacks: Callbacks::default(),
            tables: Default::default(),
        }
    }

    #[test]
    fn instances_are_installed_used_and_removed_once() {
        // With the next test, the only tests of this binary that use the
        // process-wide instances (both hold the SRDO network's lock).
        let _serial = crate::sim::srdo_net::lock();
        let slot = MAX_INSTANCES - 1;
        assert!(select(slot));
        assert_eq!(with(|_| ()).err(), Some(CopKernel::IllegalInstance));
        assert_eq!(remove().err(), Some(CopKernel::IllegalInstance));
        assert_eq!(install(instance(5)), Ok(()));
        assert_eq!(install(instance(6)).err(), Some(CopKernel::NoFreeInstance));
        assert_eq!(with(|i| i.stack.node_id()), Ok(5));
        // While the instance is in use, everything else is refused.
        let nested = with(|i| {
            i.stack.node_id();
            (
                with(|_| ()).err(),
                select(0),
                install(instance(7)).err(),
                remove().err(),
            )
        });
        let busy = Some(CopKernel::NoResource);
        assert_eq!(nested, Ok((busy, false, busy, busy)));
        assert_eq!(current(), slot);
        if slot > 0 {
            // Another slot is empty and independent.
            assert!(select(0));
            assert_eq!(with(|_| ()).err(), Some(CopKernel::IllegalInstance));
            assert!(select(slot));
        }
        let removed = remove().unwrap();
        assert_eq!(removed.stack.node_id(), 5);
        assert_eq!(with(|_| ()).err(), Some(CopKernel::IllegalInstance));
        assert_eq!(remove().err(), Some(CopKernel::IllegalInstance));
        // The slot takes a new instance after the removal.
        assert_eq!(install(instance(9)), Ok(()));
        assert_eq!(with(|i| i.stack.node_id()), Ok(9));
        assert_eq!(remove().map(|i| i.stack.node_id()), Ok(9));
        assert!(!select(MAX_INSTANCES));
        assert!(select(0));
    }

    /// `srdo_status` (the fast path of `CcmGetSrdoState` /
    /// `CcmSetSrdoState`) reaches the byte only while the instance is free
    /// and has the SRDO; everything else falls back to `with_srdo_status`
    /// and its codes.
    #[test]
    fn srdo_status_fast_path_only_while_the_instance_is_free() {
        let _serial = crate::sim::srdo_net::lock();
        let slot = MAX_INSTANCES - 1;
        let read = || {
            let mut v = None;
            srdo_status(0x1301, |s| v = Some(*s)).then_some(v).flatten()
        };
        assert!(select(slot));
        assert_eq!(read(), None, "no instance");
        assert_eq!(
            with_srdo_status(0x1301, |_| ()),
            CopKernel::IllegalInstance.code()
        );
        let od = crate::sim::srdo_net::consumer::od().unwrap();
        let mut i = instance(5);
        i.stack = Stack::new(od, 2).unwrap();
        assert_eq!(install(i), Ok(()));
        assert_eq!(read(), None, "not reached through an instance yet");
        assert_eq!(with_srdo_status(0x1301, |s| *s = 0x30), 0);
        assert_eq!(read(), Some(0x30), "the table of the latest borrow");
        assert!(srdo_status(0x1301, |s| *s = 0xC0));
        assert_eq!(with(|i| i.stack.srdo().get_state(0x1301)), Ok(Ok(0xC0)));
        // Absent SRDOs and indices that are no SRDO's are never reached.
        for idx in [0x1300, 0x1303, 0x1340, 0x1341, 0x1401, 0x0301, 0xFFFF] {
            assert!(!srdo_status(idx, |_| unreachable!()), "{idx:#06x}");
            assert_eq!(
                with_srdo_status(idx, |_| ()),
                CopKernel::SrdoNotExist.code()
            );
        }
        // While the instance is borrowed (an OBD callback's nested call).
        let nested = with(|_| {
            (
                srdo_status(0x1301, |_| unreachable!()),
                with_srdo_status(0x1301, |_| ()),
            )
        });
        assert_eq!(nested, Ok((false, CopKernel::NoResource.code())));
        assert_eq!(read(), Some(0xC0));
        if slot > 0 {
            assert!(select(0));
            assert_eq!(read(), None, "another instance selected");
            assert!(select(slot));
        }
        assert_eq!(with_srdo_status(0x1301, |_| ()), 0);
        assert!(remove().is_ok());
        assert_eq!(read(), None, "removed");
        assert_eq!(
            with_srdo_status(0x1301, |_| ()),
            CopKernel::IllegalInstance.code()
        );
        assert!(select(0));
    }
}
