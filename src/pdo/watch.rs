//! The change watch of one TPDO for `CCM_USE_PDO_CHECK_VAR`: which bytes
//! of memory its payload is made of, resolved once from the mapping, and
//! what they held when its payload was last sampled.
//!
//! A TPDO's payload is a function of the bytes of its mapped variables
//! alone (the mapping and the dictionary fixed): `sample` finds each
//! mapped object, reads its storage and converts it. So while those bytes
//! are the bytes they were when the payload was sampled, sampling again
//! gives the same payload, and the comparison of every cycle needs only
//! one pass over a flat list of byte addresses. Constants (ROM objects,
//! dummy entries) cannot change and have no bytes in it. A byte of an
//! application variable (`tObdVarEntry`) is read through its entry on
//! every pass, so that attaching another variable is seen; such a mapping
//! is resolved again each time its bytes are taken, with the variables'
//! sizes of that moment.
//!
//! The resolution depends on the mapping and on the dictionary: the PDO
//! module drops it ([`Watch::forget`]) whenever either may have changed
//! (every reload of a PDO's parameters, a static data block attached or
//! detached, NMT state changes, a dictionary replaced or rebuilt).

use core::sync::atomic::{AtomicU8, Ordering};

use super::Payload;
use crate::od::{ObdVarEntry, ObjectDictionary, Storage};
use crate::wire::pdo::MapEntry;

/// The change watch a PDO channel carries: a TPDO's is a [`Watch`], an
/// RPDO has none ([`NoWatch`]), so that receive channels do not hold the
/// pieces of a mapping they never compare.
pub(crate) trait Watching {
    /// A watch without resolution.
    const NEW: Self;
    /// Drops the resolution: the mapping or the dictionary may have
    /// changed.
    fn forget(&mut self);
}

/// The watch of an RPDO: nothing to resolve.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NoWatch;

impl Watching for NoWatch {
    const NEW: Self = NoWatch;
    #[inline]
    fn forget(&mut self) {}
}

impl Watching for Watch {
    const NEW: Self = Watch::new();
    #[inline]
    fn forget(&mut self) {
        Watch::forget(self);
    }
}

/// Bytes a watch holds; a mapping with more bytes of variables in RAM is
/// compared by sampling it (as without a watch).
const RAW: usize = 8;

/// One watched byte.
#[derive(Clone, Copy, Debug)]
enum Byte {
    /// A byte of a dictionary variable in RAM (native byte order).
    Ram(&'static AtomicU8),
    /// Byte `at` of an application variable attached through a
    /// `tObdVarEntry`, which had `len` bytes when the bytes were taken.
    Var {
        entry: &'static ObdVarEntry,
        at: u8,
        len: u8,
    },
}

impl Byte {
    /// The byte now; `None` when an application variable is no longer
    /// the size it was (detached, or another one attached).
    #[inline(always)]
    fn load(self) -> Option<u8> {
        match self {
            Byte::Ram(m) => Some(m.load(Ordering::Relaxed)),
            Byte::Var { entry, at, len } => match entry.data() {
                Some(m) if m.len() == usize::from(len) => {
                    m.get(usize::from(at)).map(|b| b.load(Ordering::Relaxed))
                }
                _ => None,
            },
        }
    }
}

/// What a watch knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum State {
    /// Nothing resolved (the mapping or the dictionary changed).
    Unresolved,
    /// Bytes resolved, their values not taken.
    Resolved,
    /// Values taken, the payload not yet.
    Ready,
    /// Bytes resolved and `raw` holds their values of the sampled
    /// `payload`.
    Taken,
    /// The mapping has more bytes than a watch holds, an object that
    /// cannot be resolved, or an application variable without data:
    /// every comparison samples.
    Unwatched,
}

/// The watch of one TPDO (see the module documentation).
#[derive(Clone, Debug)]
pub(crate) struct Watch {
    state: State,
    /// Bytes in `bytes` (and `raw`).
    count: u8,
    /// The mapping has application variables: their size and place are
    /// looked up again whenever the bytes are taken.
    retake: bool,
    /// The watched bytes, in mapping order.
    bytes: [Byte; RAW],
    /// Their values when the payload was sampled.
    raw: [u8; RAW],
    payload: Payload,
    /// The channel's last sent payload equals `payload` (set by
    /// [`Watch::settle`]); cleared whenever either may change.
    settled: bool,
}

/// A placeholder for the unused places of [`Watch::bytes`].
static NO_BYTE: AtomicU8 = AtomicU8::new(0);

impl Watch {
    /// A watch without resolution.
    pub(crate) const fn new() -> Watch {
        Watch {
            state: State::Unresolved,
            count: 0,
            retake: false,
            bytes: [Byte::Ram(&NO_BYTE); RAW],
            raw: [0; RAW],
            payload: Payload {
                data: [0; 8],
                len: 0,
            },
            settled: false,
        }
    }

    /// Drops the resolution: the mapping or the dictionary may have
    /// changed.
    #[inline]
    pub(crate) fn forget(&mut self) {
        self.state = State::Unresolved;
        self.settled = false;
    }

    /// Records that the channel's last sent payload is the one taken:
    /// from now on, while the watched bytes stay as they are,
    /// [`Watch::quiet`] is true without a payload being formed.
    #[inline]
    pub(crate) fn settle(&mut self) {
        self.settled = self.state == State::Taken;
    }

    /// The channel's last sent payload changed: it is no longer known to
    /// equal the taken one.
    #[inline]
    pub(crate) fn unsettle(&mut self) {
        self.settled = false;
    }

    /// True when the payload is known to equal the channel's last sent one
    /// and the watched bytes have not changed since: the comparison of
    /// this cycle would find nothing.
    #[inline]
    pub(crate) fn quiet(&self) -> bool {
        self.settled && self.same_bytes()
    }

    /// The payload `sample` would give now, when the watched bytes are
    /// those of the last sample; `None` when they differ (or nothing was
    /// taken): then sample, and [`Watch::take`] the result.
    #[inline]
    pub(super) fn unchanged(&self) -> Option<Payload> {
        self.same_bytes().then_some(self.payload)
    }

    /// The watched bytes are those taken last (false when nothing was
    /// taken since the resolution).
    #[inline]
    fn same_bytes(&self) -> bool {
        if self.state != State::Taken {
            return false;
        }
        let n = usize::from(self.count);
        let (Some(bytes), Some(raw)) = (self.bytes.get(..n), self.raw.get(..n)) else {
            return false;
        };
        bytes.iter().zip(raw).all(|(b, r)| b.load() == Some(*r))
    }

    /// Resolves the mapping if needed and takes the values of the watched
    /// bytes, before the caller samples (a variable changed in between
    /// then differs in the next comparison instead of being missed).
    /// `false` when the mapping is not watched.
    pub(crate) fn take_bytes(&mut self, od: &ObjectDictionary, entries: &[u32]) -> bool {
        if self.state == State::Unresolved || self.retake {
            self.resolve(od, entries);
        }
        self.settled = false;
        if self.state == State::Unwatched {
            return false;
        }
        self.state = State::Resolved;
        let n = usize::from(self.count);
        let mut raw = [0u8; RAW];
        for (dst, b) in raw.iter_mut().zip(self.bytes.iter().take(n)) {
            match b.load() {
                Some(v) => *dst = v,
                None => return false,
            }
        }
        self.raw = raw;
        self.state = State::Ready;
        true
    }

    /// The payload sampled after [`Watch::take_bytes`] returned `true`.
    pub(super) fn take(&mut self, payload: Payload) {
        if self.state == State::Ready {
            self.payload = payload;
            self.state = State::Taken;
        }
    }

    /// Finds the bytes of the mapped variables, in mapping order; an
    /// application variable with the size and place it has now.
    fn resolve(&mut self, od: &ObjectDictionary, entries: &[u32]) {
        self.state = State::Unwatched;
        self.count = 0;
        self.retake = false;
        let mut at = 0usize;
        for raw in entries {
            let e = MapEntry::decode(*raw);
            let Ok(obj) = od.find(e.index, e.sub) else {
                return;
            };
            match obj.storage() {
                Ok(Storage::Rom(_) | Storage::RomString(_)) => {}
                Ok(Storage::Ram(m) | Storage::RamString(m)) => {
                    let Some(dst) = self.bytes.get_mut(at..at + m.len()) else {
                        return;
                    };
                    for (d, b) in dst.iter_mut().zip(m) {
                        *d = Byte::Ram(b);
                    }
                    at += m.len();
                }
                Ok(Storage::Var(entry)) => {
                    self.retake = true;
                    // Without data (or empty) there is nothing to compare:
                    // sampled until a variable is attached.
                    let Some(m) = entry.data().filter(|m| !m.is_empty()) else {
                        return;
                    };
                    let (Some(dst), Ok(len)) =
                        (self.bytes.get_mut(at..at + m.len()), u8::try_from(m.len()))
                    else {
                        return;
                    };
                    for (i, d) in (0u8..).zip(dst.iter_mut()) {
                        *d = Byte::Var { entry, at: i, len };
                    }
                    at += m.len();
                }
                Err(_) => return,
            }
        }
        // `at` <= RAW: every range above was inside `bytes`.
        self.count = at as u8;
        self.state = State::Resolved;
    }
}

#[cfg(test)]
mod tests {
    //! The watch alone, on a dictionary of its own: a RAM variable and an
    //! application variable (`tObdVarEntry`) mapped into one TPDO.

    use core::sync::atomic::{AtomicU8, Ordering};

    use super::*;
    use crate::od::{Access, DataType, ObdEntry, ObdSubEntry, decl};

    static RAM: [AtomicU8; 1] = decl::zeroed();
    static VAR: ObdVarEntry = ObdVarEntry::new();
    static APP_A: [AtomicU8; 2] = decl::zeroed();
    static APP_B: [AtomicU8; 2] = decl::zeroed();
    static APP_SHORT: [AtomicU8; 1] = decl::zeroed();
    static UNATTACHED: ObdVarEntry = ObdVarEntry::new();
    static WIDE: [AtomicU8; 8] = decl::zeroed();
    static S2000: [ObdSubEntry; 6] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[5]),
        ObdSubEntry::ram(1, DataType::UInt8, Access::PRW, &RAM, None),
        ObdSubEntry::var(2, DataType::UInt16, Access::PRW, &VAR, 2, None),
        ObdSubEntry::rom(3, DataType::UInt8, Access::PR, &[7]),
        ObdSubEntry::var(4, DataType::UInt16, Access::PRW, &UNATTACHED, 2, None),
        ObdSubEntry::ram(5, DataType::UInt64, Access::PRW, &WIDE, None),
    ];
    static MANUFACTURER: [ObdEntry; 1] = [ObdEntry::new(0x2000, &S2000, None)];
    static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

    /// Mapping entries (CiA 301 7.5.2.36: index, subindex, bits).
    const RAM_U8: u32 = 0x2000_0108;
    const VAR_U16: u32 = 0x2000_0210;
    const ROM_U8: u32 = 0x2000_0308;
    const UNATTACHED_U16: u32 = 0x2000_0410;
    const WIDE_U64: u32 = 0x2000_0540;

    fn fresh() -> (std::sync::MutexGuard<'static, ()>, ObjectDictionary) {
        let g = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
        for m in RAM.iter().chain(&APP_A).chain(&APP_B).chain(&APP_SHORT) {
            m.store(0, Ordering::Relaxed);
        }
        assert!(VAR.attach(&APP_A));
        (g, ObjectDictionary::new(&[], &MANUFACTURER, &[]).unwrap())
    }

    /// Takes the bytes and a payload (its content does not matter to the
    /// watch) the way `watched_sample` does; true when watched.
    fn take(w: &mut Watch, od: &ObjectDictionary, entries: &[u32]) -> bool {
        let watched = w.take_bytes(od, entries);
        if watched {
            w.take(Payload {
                data: [0xAB; 8],
                len: 3,
            });
        }
        watched
    }

    /// The watched bytes are those taken: the payload taken stands.
    fn same(w: &Watch) -> bool {
        w.unchanged().is_some()
    }

    #[test]
    fn a_change_of_any_watched_byte_is_seen_and_constants_are_no_bytes() {
        let (_g, od) = fresh();
        let mut w = Watch::new();
        assert!(!same(&w), "nothing taken yet");
        assert!(take(&mut w, &od, &[RAM_U8, ROM_U8, VAR_U16]));
        let p = w.unchanged().expect("nothing changed");
        assert_eq!((p.data[0], p.len), (0xAB, 3), "the payload taken");
        RAM[0].store(1, Ordering::Relaxed);
        assert!(!same(&w), "the RAM byte changed");
        RAM[0].store(0, Ordering::Relaxed);
        assert!(same(&w), "back to the bytes taken");
        APP_A[1].store(9, Ordering::Relaxed);
        assert!(!same(&w), "the application variable's second byte");
        assert!(take(&mut w, &od, &[RAM_U8, ROM_U8, VAR_U16]));
        assert!(same(&w), "taken again with the new byte");
    }

    #[test]
    fn an_application_variable_is_read_through_its_entry_on_every_pass() {
        let (_g, od) = fresh();
        let mut w = Watch::new();
        assert!(take(&mut w, &od, &[VAR_U16, RAM_U8]));
        // Another variable with the same bytes: the payload is the same.
        assert!(VAR.attach(&APP_B));
        assert!(same(&w), "same bytes, same payload");
        APP_B[0].store(5, Ordering::Relaxed);
        assert!(!same(&w), "the newly attached variable changed");
        assert!(take(&mut w, &od, &[VAR_U16, RAM_U8]));
        assert!(same(&w));
        APP_A[0].store(6, Ordering::Relaxed);
        assert!(same(&w), "the variable attached before is no longer read");
        // A variable of another size is a change, even with equal bytes.
        APP_SHORT[0].store(5, Ordering::Relaxed);
        assert!(VAR.attach(&APP_SHORT));
        assert!(!same(&w), "another size");
        assert!(take(&mut w, &od, &[VAR_U16, RAM_U8]));
        assert!(same(&w), "taken with its new size");
        RAM[0].store(3, Ordering::Relaxed);
        assert!(!same(&w), "the RAM byte after the shorter variable");
    }

    #[test]
    fn what_cannot_be_watched_is_sampled_every_time() {
        let (_g, od) = fresh();
        // No variable attached yet.
        let mut w = Watch::new();
        assert!(!take(&mut w, &od, &[UNATTACHED_U16]));
        assert!(!same(&w));
        // More than the watch's bytes: 8 + 1.
        let mut w = Watch::new();
        assert!(!take(&mut w, &od, &[WIDE_U64, RAM_U8]));
        assert!(!same(&w));
        // An object the dictionary does not have.
        let mut w = Watch::new();
        assert!(!take(&mut w, &od, &[0x2100_0108]));
        assert!(!same(&w));
        // Exactly the watch's bytes is watched.
        let mut w = Watch::new();
        assert!(take(&mut w, &od, &[WIDE_U64]));
        assert!(same(&w));
        WIDE[7].store(1, Ordering::Relaxed);
        assert!(!same(&w), "the last of eight bytes");
        WIDE[7].store(0, Ordering::Relaxed);
    }

    #[test]
    fn forget_settle_and_quiet() {
        let (_g, od) = fresh();
        let mut w = Watch::new();
        assert!(take(&mut w, &od, &[RAM_U8]));
        assert!(!w.quiet(), "not settled");
        w.settle();
        assert!(w.quiet());
        RAM[0].store(2, Ordering::Relaxed);
        assert!(!w.quiet(), "a byte changed");
        RAM[0].store(0, Ordering::Relaxed);
        assert!(w.quiet());
        w.unsettle();
        assert!(!w.quiet(), "the last sent payload changed");
        w.settle();
        w.forget();
        assert!(!w.quiet() && w.unchanged().is_none(), "forgotten");
        // A new mapping after forget: the RAM byte is no longer watched.
        assert!(take(&mut w, &od, &[VAR_U16]));
        RAM[0].store(4, Ordering::Relaxed);
        assert!(same(&w), "0x2000 sub 1 no longer mapped");
    }
}
