//! The object dictionary: lookup, access rights, byte order, value ranges,
//! OBD callbacks.
//!
//! The tables come from the application's `objdict.h` (through
//! `include/objdef.h`), from Rust code, or from the dynamic OD; all use the
//! format of [`table`]. Lookup is a binary search over the
//! sorted part tables (O(log n)); unsorted tables are refused when the
//! dictionary is created.
//!
//! The protocol modules never bypass this module: SDO, PDO, SRDO and the C
//! API all read and write through [`ObjectDictionary::read`] and
//! [`ObjectDictionary::write`], so access rights, ranges, module hooks and
//! application callbacks apply to every path alike.

pub mod dcf;
pub mod decl;
pub mod dynamic;
pub mod eds;
// The table format shared with C: raw pointers into the application's
// statics, the one place of the core that needs `unsafe`.
#[allow(unsafe_code)]
pub mod table;
mod types;
pub mod value;

pub use types::{Access, DataType, Encoding};

pub use table::{
    CallbackHandle, CbArg, ObdCallback, ObdEntry, ObdSize, ObdSubEntry, ObdVarEntry, Storage, kind,
};

use core::sync::atomic::AtomicU8;
use core::sync::atomic::Ordering::Relaxed;

use crate::error::{CopKernel, OdError, OdResult, SdoAbort};

/// Byte order of data crossing the dictionary boundary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ByteOrder {
    /// The CPU's order and the C variable's width (`CcmReadObject`).
    Native,
    /// CANopen order: little-endian, type width (SDO, PDO, SRDO, DCF).
    Wire,
}

/// OBD callback events (`tObdEvent`, kObdEv*).
#[allow(missing_docs)]
pub mod event {
    pub const PRE_READ: u8 = 0x00;
    pub const POST_READ: u8 = 0x01;
    pub const PRE_WRITE: u8 = 0x02;
    pub const POST_WRITE: u8 = 0x03;
    pub const INIT_WRITE: u8 = 0x04;
    pub const ABORT_SDO: u8 = 0x05;
    pub const CHECK_EXIST: u8 = 0x06;
    pub const WR_STRING_DOMAIN: u8 = 0x07;
}

/// Largest fixed-size value (numbers, TIME_OF_DAY) in bytes.
pub const MAX_FIXED: usize = 8;

/// The dictionary parts (`kObdPart*`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// 0x1000–0x1FFF.
    Generic,
    /// 0x2000–0x5FFF.
    Manufacturer,
    /// 0x6000–0x9FFF.
    Device,
    /// Everything else and the dynamic OD.
    User,
}

impl Part {
    /// The part an index belongs to by its number.
    pub const fn of(index: u16) -> Part {
        match index {
            0x1000..=0x1FFF => Part::Generic,
            0x2000..=0x5FFF => Part::Manufacturer,
            0x6000..=0x9FFF => Part::Device,
            _ => Part::User,
        }
    }

    const fn slot(self) -> usize {
        match self {
            Part::Generic => 0,
            Part::Manufacturer => 1,
            Part::Device => 2,
            Part::User => 3,
        }
    }
}

/// One addressed subindex.
#[derive(Clone, Copy, Debug)]
pub struct Object {
    entry: &'static ObdEntry,
    desc: &'static ObdSubEntry,
    typ: DataType,
    sub: u8,
    element: u8,
}

impl Object {
    /// Index.
    pub fn index(&self) -> u16 {
        self.entry.index()
    }
    /// Subindex.
    pub fn sub(&self) -> u8 {
        self.sub
    }
    /// Data type.
    pub fn data_type(&self) -> DataType {
        self.typ
    }
    /// Access attributes.
    pub fn access(&self) -> Access {
        self.desc.access()
    }
    /// The index entry (callback).
    pub fn entry(&self) -> &'static ObdEntry {
        self.entry
    }
    /// The subindex description.
    pub fn desc(&self) -> &'static ObdSubEntry {
        self.desc
    }
    /// Where the value lives.
    pub fn storage(&self) -> OdResult<Storage> {
        self.desc
            .storage(usize::from(self.element))
            .ok_or(OdError::NO_VAR)
    }
    /// Width of the variable in memory (capacity for strings/domains).
    pub fn native_size(&self) -> OdResult<usize> {
        Ok(match self.storage()? {
            Storage::Ram(m) => m.len(),
            Storage::Rom(r) => r.len(),
            Storage::RamString(b) => b.len().saturating_sub(1),
            Storage::RomString(r) => r.len(),
            Storage::Var(v) => v.data().ok_or(OdError::NO_VAR)?.len(),
        })
    }
}

/// One index entry, found once: its subindices are looked up without
/// searching the dictionary again ([`ObjectDictionary::entry`]).
#[derive(Clone, Copy, Debug)]
pub struct Entry {
    entry: &'static ObdEntry,
    /// Its subindex table.
    subs: &'static [ObdSubEntry],
}

impl Entry {
    /// Index.
    pub fn index(&self) -> u16 {
        self.entry.index()
    }

    /// The table entry.
    pub fn obd_entry(&self) -> &'static ObdEntry {
        self.entry
    }

    /// The handle of a table entry.
    #[inline(always)]
    fn new(entry: &'static ObdEntry) -> Entry {
        Entry {
            entry,
            subs: entry.subs(),
        }
    }

    /// Looks up a subindex of this entry (as [`ObjectDictionary::find`]).
    #[inline]
    pub fn find(&self, sub: u8) -> OdResult<Object> {
        find_in_entry(self.entry, sub)
    }

    /// The description of `sub` when it is where it usually is: at position
    /// `sub` of the table.
    #[inline(always)]
    fn at_position(&self, sub: u8) -> Option<&'static ObdSubEntry> {
        self.subs.get(usize::from(sub)).filter(|d| d.sub() == sub)
    }

    /// The variable of `sub` when it is the common case of the fast paths:
    /// a number in a plain RAM variable of exactly its wire size, at its
    /// usual position.
    #[inline(always)]
    fn plain_number(&self, sub: u8) -> Option<&'static [AtomicU8]> {
        let desc = self.at_position(sub)?;
        let wire = NUMERIC_WIRE_SIZE
            .get(usize::from(desc.m_bType))
            .copied()
            .unwrap_or(0);
        if desc.m_dwSize != u32::from(wire) {
            return None;
        }
        desc.ram_var(0)
    }

    /// Reads a numeric subindex as an unsigned integer without access
    /// checks or callbacks, as [`ObjectDictionary::read_uint`] does: the
    /// value's wire bytes (little-endian) read as a number.
    #[inline]
    pub fn read_uint(&self, sub: u8) -> OdResult<u64> {
        // The common case, a number in a plain RAM variable of exactly its
        // wire size at its usual position, directly: the value's bytes are
        // the wire bytes (little-endian).
        if let Some(v) = self.plain_number(sub).and_then(load_uint) {
            return Ok(v);
        }
        self.read_uint_general(sub)
    }

    /// Reads a fixed-size subindex in wire form (little-endian, type width)
    /// into `out` without access checks or callbacks, as
    /// [`ObjectDictionary::peek`] with [`ByteOrder::Wire`] does; returns the
    /// number of bytes. Bytes of `out` beyond them are not touched.
    #[inline]
    pub fn read_wire(&self, sub: u8, out: &mut [u8; MAX_FIXED]) -> OdResult<usize> {
        if let Some(n) = self.plain_number(sub).and_then(|m| load_wire(m, out)) {
            return Ok(n);
        }
        self.read_wire_general(sub, out)
    }

    /// [`Entry::read_wire`] for every other object.
    #[inline(never)]
    fn read_wire_general(&self, sub: u8, out: &mut [u8; MAX_FIXED]) -> OdResult<usize> {
        peek_object(&self.find(sub)?, ByteOrder::Wire, out)
    }

    /// [`Entry::read_uint`] for every other object.
    #[inline(never)]
    fn read_uint_general(&self, sub: u8) -> OdResult<u64> {
        read_uint_of(&self.find(sub)?)
    }
}

/// The value of a fixed-size object as an unsigned integer: its wire bytes
/// (little-endian) read as a number, as [`ObjectDictionary::peek`] with
/// [`ByteOrder::Wire`] gives them.
fn read_uint_of(obj: &Object) -> OdResult<u64> {
    let mut buf = [0u8; MAX_FIXED];
    let n = peek_object(obj, ByteOrder::Wire, &mut buf)?;
    Ok(value::le_to_u64(buf.get(..n).unwrap_or(&[])))
}

/// Wire size of the numeric types by type code (0: not a number, or not a
/// known type).
// Evaluated at compile time: an index out of bounds would not compile.
#[allow(clippy::indexing_slicing)]
const NUMERIC_WIRE_SIZE: [u8; 256] = {
    let mut table = [0u8; 256];
    let mut code = 0;
    while code < 256 {
        if let Some(t) = DataType::from_code(code as u16) {
            if let Encoding::Numeric { wire, .. } = t.encoding() {
                table[code] = wire as u8;
            }
        }
        code += 1;
    }
    table
};

/// A native unsigned integer of 1, 2 or 4 bytes in RAM (the sizes of the
/// fast path of [`Entry::read_uint`]; four bytes, the most common size of
/// the objects read this way, tested first).
#[inline(always)]
fn load_uint(m: &[AtomicU8]) -> Option<u64> {
    if m.len() > 2 {
        let [b0, b1, b2, b3] = <&[AtomicU8; 4]>::try_from(m).ok()?;
        let bytes = [
            b0.load(Relaxed),
            b1.load(Relaxed),
            b2.load(Relaxed),
            b3.load(Relaxed),
        ];
        return Some(u64::from(u32::from_ne_bytes(bytes)));
    }
    if let Ok([b0, b1]) = <&[AtomicU8; 2]>::try_from(m) {
        let bytes = [b0.load(Relaxed), b1.load(Relaxed)];
        return Some(u64::from(u16::from_ne_bytes(bytes)));
    }
    let [b0] = <&[AtomicU8; 1]>::try_from(m).ok()?;
    Some(u64::from(b0.load(Relaxed)))
}

/// A native number of 1, 2 or 4 bytes in RAM in wire order (little-endian)
/// into `out`; `None` for other sizes.
#[inline(always)]
fn load_wire(m: &[AtomicU8], out: &mut [u8; MAX_FIXED]) -> Option<usize> {
    let le = cfg!(target_endian = "little");
    if m.len() > 2 {
        let [b0, b1, b2, b3] = <&[AtomicU8; 4]>::try_from(m).ok()?;
        let [o0, o1, o2, o3, ..] = out;
        let (x0, x1, x2, x3) = if le {
            (b0, b1, b2, b3)
        } else {
            (b3, b2, b1, b0)
        };
        *o0 = x0.load(Relaxed);
        *o1 = x1.load(Relaxed);
        *o2 = x2.load(Relaxed);
        *o3 = x3.load(Relaxed);
        return Some(4);
    }
    if let Ok([b0, b1]) = <&[AtomicU8; 2]>::try_from(m) {
        let [o0, o1, ..] = out;
        let (x0, x1) = if le { (b0, b1) } else { (b1, b0) };
        *o0 = x0.load(Relaxed);
        *o1 = x1.load(Relaxed);
        return Some(2);
    }
    let [b0] = <&[AtomicU8; 1]>::try_from(m).ok()?;
    let [o0, ..] = out;
    *o0 = b0.load(Relaxed);
    Some(1)
}

/// Subindex `sub` of `entry` ([`Entry::find`]).
#[inline(always)]
fn find_in_entry(entry: &'static ObdEntry, sub: u8) -> OdResult<Object> {
    // The usual layout: subindex n at position n (an entry without table
    // takes the general path, which refuses it).
    let at_n = if entry.m_pSubIndex.is_null() {
        None
    } else {
        entry.subs().get(usize::from(sub))
    };
    match at_n {
        Some(desc) if desc.sub() == sub => object(entry, desc, sub, 0),
        _ => find_sub(entry, sub),
    }
}

/// The object of subindex `sub` described by `desc` (array element
/// `element`); `kCopObdSubindexNotExist` for a data type this library does
/// not know.
#[inline(always)]
fn object(
    entry: &'static ObdEntry,
    desc: &'static ObdSubEntry,
    sub: u8,
    element: u8,
) -> OdResult<Object> {
    match TYPE_OF_CODE.get(usize::from(desc.m_bType)) {
        Some(Some(typ)) => Ok(Object {
            entry,
            desc,
            typ: *typ,
            sub,
            element,
        }),
        _ => Err(OdError::SUBINDEX),
    }
}

/// [`DataType::from_code`] for every byte value, as a table.
// Evaluated at compile time: an index out of bounds would not compile.
#[allow(clippy::indexing_slicing)]
const TYPE_OF_CODE: [Option<DataType>; 256] = {
    let mut table = [None; 256];
    let mut code = 0;
    while code < 256 {
        table[code] = DataType::from_code(code as u16);
        code += 1;
    }
    table
};

/// [`Entry::find`] for a subindex that is not at its own position in the
/// table: searched among the subindices, else an element of a trailing
/// array.
#[inline(never)]
fn find_sub(entry: &'static ObdEntry, sub: u8) -> OdResult<Object> {
    let subs = entry.subs();
    let (desc, element) = match subs.binary_search_by_key(&sub, |s| s.sub()) {
        Ok(i) => (subs.get(i).ok_or(OdError::SUBINDEX)?, 0u8),
        Err(_) => array_element(entry, sub).ok_or(OdError::SUBINDEX)?,
    };
    object(entry, desc, sub, element)
}

/// A value checked and converted for storing.
#[derive(Clone, Copy, Debug)]
pub struct Staged {
    native: [u8; MAX_FIXED],
    len: usize,
    fixed: bool,
}

impl Staged {
    /// The native bytes of a fixed-size value (empty for strings/domains).
    pub fn native(&self) -> &[u8] {
        if self.fixed {
            self.native.get(..self.len).unwrap_or(&[])
        } else {
            &[]
        }
    }
    /// Length that will be stored.
    pub fn len(&self) -> usize {
        self.len
    }
    /// True for a zero-length write.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The value as an unsigned integer (fixed-size values).
    pub fn as_u64(&self) -> Option<u64> {
        if self.fixed {
            value::native_to_u64(self.native())
        } else {
            None
        }
    }
}

/// Module reactions to dictionary writes, implemented by the stack: the
/// SRDO, PDO, SDO, NMT and EMCY modules check and follow their parameters
/// through these hooks.
pub trait WriteHooks {
    /// Called after length and range checks, before the application's
    /// kObdEvPreWrite callback. `Err` refuses the write; nothing changes.
    fn check(&mut self, od: &ObjectDictionary, obj: &Object, value: &Staged) -> OdResult;
    /// Called immediately before the value is stored (the write can no
    /// longer fail): for example, invalidate 0x13FE.
    fn before_store(&mut self, od: &ObjectDictionary, obj: &Object, value: &Staged);
    /// Called after the value is stored.
    fn after_store(&mut self, od: &ObjectDictionary, obj: &Object);
}

/// Hooks that do nothing (dictionary tests, tools).
pub struct NoHooks;

impl WriteHooks for NoHooks {
    fn check(&mut self, _: &ObjectDictionary, _: &Object, _: &Staged) -> OdResult {
        Ok(())
    }
    fn before_store(&mut self, _: &ObjectDictionary, _: &Object, _: &Staged) {}
    fn after_store(&mut self, _: &ObjectDictionary, _: &Object) {}
}

/// An unsigned integer type a value is read as
/// ([`ObjectDictionary::read_or`]).
pub trait UintValue: Copy {
    /// The low bits of `v` (what `v as Self` keeps).
    fn truncate(v: u64) -> Self;
}

macro_rules! uint_value {
    ($($t:ty),+) => {
        $(impl UintValue for $t {
            #[inline]
            fn truncate(v: u64) -> Self {
                v as $t
            }
        })+
    };
}
uint_value!(u8, u16, u32, u64);

/// The object dictionary.
#[derive(Clone, Copy, Debug)]
pub struct ObjectDictionary {
    /// Generic, manufacturer, device and user part ([`Part::slot`]).
    parts: [PartTable; 4],
    /// What the application's OBD and variable callbacks receive first
    /// ([`CallbackHandle`]).
    handle: CallbackHandle,
}

/// Number of index ranges of a part's lookup directory ([`PartTable`]).
const RANGES: usize = 32;

/// [`PartTable::window`] when the whole table is searched.
const WHOLE: u8 = 0xFF;
/// [`PartTable::fast`]: windows of 16 entries (the common size, tested
/// first).
const FAST_16: u8 = 0x01;
/// [`PartTable::fast`]: windows of 8 entries.
const FAST_8: u8 = 0x02;
/// [`PartTable::fast`]: windows of 4 entries.
const FAST_4: u8 = 0x04;
/// [`PartTable::fast`]: tables of at most 8 entries, searched whole.
const FAST_SMALL: u8 = 0x08;

/// One part: its sorted table and a lookup directory computed when the
/// table is checked.
///
/// The span from the part's first to its last index is cut into [`RANGES`]
/// ranges of `1 << shift` indices. Every range holds at most `1 << window`
/// entries, so the entry of an index lies in the `1 << window` entries from
/// the first entry of its range; `starts` holds that position for each
/// range, moved back where needed so that the window ends within the table.
/// A lookup takes its range in constant time and binary-searches a window
/// of a power of two entries (fixed probe positions, no bounds to track).
/// The window is never larger than the table, so the search stays
/// O(log n) whatever the distribution of indices, and when they are spread
/// over the part it saves up to five of the comparisons of a search of the
/// whole table. Tables whose ranges do not fit (few entries in one
/// cluster) are searched whole.
#[derive(Clone, Copy, Debug)]
struct PartTable {
    /// The entries, indices strictly ascending.
    table: &'static [ObdEntry],
    /// Index of the first entry.
    base: u16,
    /// Range of `index` = `(index - base) >> shift` (wrapping; 0..=11).
    shift: u8,
    /// log2 of the window size, or [`WHOLE`].
    window: u8,
    /// [`FAST_16`], [`FAST_8`] or [`FAST_SMALL`] for the parts searched by
    /// [`PartTable::find_windowed`], else 0.
    fast: u8,
    /// First position of the window of each range.
    starts: [u16; RANGES],
}

impl PartTable {
    /// An empty part.
    const EMPTY: PartTable = PartTable {
        table: &[],
        base: 0,
        shift: 0,
        window: WHOLE,
        fast: 0,
        starts: [0; RANGES],
    };

    /// The part of a sorted table (checked by [`validate_part`]).
    fn new(table: &'static [ObdEntry]) -> PartTable {
        let (Some(first), Some(last)) = (table.first(), table.last()) else {
            return PartTable::EMPTY;
        };
        let base = first.index();
        let span = last.index().wrapping_sub(base);
        let mut shift = 0u8;
        while usize::from(span >> shift) >= RANGES {
            shift += 1;
        }
        let range_of = |e: &ObdEntry| usize::from(e.index().wrapping_sub(base) >> shift);
        // Where each range starts, and its largest number of entries.
        let mut starts = [0usize; RANGES];
        let mut largest = 0usize;
        let mut pos = 0usize;
        for (r, start) in starts.iter_mut().enumerate() {
            *start = pos;
            while table.get(pos).is_some_and(|e| range_of(e) == r) {
                pos += 1;
            }
            largest = largest.max(pos - *start);
        }
        // Windows of 16 entries where the table is long enough (one compare
        // more for ranges of up to eight entries, but one window size for
        // the common case), else as small as the ranges allow.
        let window = if largest <= 16 && table.len() >= 16 {
            16
        } else {
            largest.max(4).next_power_of_two()
        };
        if window > table.len() {
            return PartTable {
                table,
                // Up to eight entries: searched in order.
                fast: if table.len() <= 8 { FAST_SMALL } else { 0 },
                ..PartTable::EMPTY
            };
        }
        let last_window = table.len() - window;
        PartTable {
            table,
            base,
            shift,
            window: window.trailing_zeros() as u8,
            fast: match window {
                16 => FAST_16,
                8 => FAST_8,
                4 => FAST_4,
                _ => 0,
            },
            // A window start is at most the table length minus the window,
            // below 65,536 for any table.
            starts: starts.map(|s| u16::try_from(s.min(last_window)).unwrap_or(0)),
        }
    }

    /// The entry of `index` in this part when its window has 4, 8 or 16
    /// entries or the table at most 8; `None` when not found or the window
    /// is another size.
    #[inline(always)]
    fn find_windowed(&self, index: u16) -> Option<&'static ObdEntry> {
        // An index beyond the last range cannot be in the table; taken
        // modulo the number of ranges it is searched where it cannot match.
        let r = (usize::from(index.wrapping_sub(self.base)) >> self.shift) % RANGES;
        let start = usize::from(*self.starts.get(r)?);
        let table = self.table;
        // Bit tests (not a switch), so that the common size is tested first.
        if self.fast & FAST_16 != 0 {
            search_fixed::<16>(table, start, index)
        } else if self.fast & FAST_8 != 0 {
            search_fixed::<8>(table, start, index)
        } else if self.fast & FAST_4 != 0 {
            search_fixed::<4>(table, start, index)
        } else if self.fast & FAST_SMALL != 0 {
            search_small(table, index)
        } else {
            None
        }
    }

    /// The entry of `index` in this part.
    fn find(&self, index: u16) -> Option<&'static ObdEntry> {
        if self.window == WHOLE {
            return search(self.table, index);
        }
        // An index beyond the last range is not in the table.
        let r = usize::from(index.wrapping_sub(self.base)) >> self.shift;
        let start = usize::from(*self.starts.get(r)?);
        // Windows are at most as long as the table (65,536 entries).
        let size = 1usize << self.window.min(16);
        search_window(self.table.get(start..start + size)?, index)
    }
}

/// The part slot ([`Part::slot`]) of each index by its top four bits.
const SLOT_OF_TOP_NIBBLE: [u8; 16] = [3, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3];

/// Binary search of the `W` entries (4, 8 or 16) from `start`: each step keeps
/// the half that can hold `index`. Written out step by step, because
/// size-optimised builds do not unroll loops; with the lengths known at
/// every step there are no bounds to check.
#[inline(always)]
fn search_fixed<const W: usize>(
    table: &'static [ObdEntry],
    start: usize,
    index: u16,
) -> Option<&'static ObdEntry> {
    let mut window: &'static [ObdEntry] = table.get(start..start + W)?;
    if W >= 16 {
        window = half(window, 8, index);
    }
    if W >= 8 {
        window = half(window, 4, index);
    }
    window = half(window, 2, index);
    window = half(window, 1, index);
    window.first().filter(|e| e.index() == index)
}

/// Search of a table of at most 8 entries: the first entry not below
/// `index`, in order.
#[inline(always)]
fn search_small(table: &'static [ObdEntry], index: u16) -> Option<&'static ObdEntry> {
    table
        .iter()
        .find(|e| e.index() >= index)
        .filter(|e| e.index() == index)
}

/// One step of a binary search over `2 * n` entries: the upper `n` when
/// their first index is not above `index`, else the lower `n` (over fewer
/// entries: the upper part when it exists and qualifies, else the lower
/// `n` or all of them).
#[inline(always)]
fn half(window: &'static [ObdEntry], n: usize, index: u16) -> &'static [ObdEntry] {
    let (low, high) = window.split_at(n.min(window.len()));
    match high.first() {
        Some(e) if e.index() <= index => high,
        _ => low,
    }
}

/// Binary search of a window of a power of two entries.
fn search_window(window: &'static [ObdEntry], index: u16) -> Option<&'static ObdEntry> {
    let mut pos = 0usize;
    let mut step = window.len() / 2;
    while step > 0 {
        if window.get(pos + step).is_some_and(|e| e.index() <= index) {
            pos += step;
        }
        step /= 2;
    }
    window.get(pos).filter(|e| e.index() == index)
}

/// Binary search of a whole sorted table: a first probe leaves a window of
/// a power of two entries, which [`search_window`] halves.
fn search(table: &'static [ObdEntry], index: u16) -> Option<&'static ObdEntry> {
    let n = table.len();
    if n == 0 {
        return None;
    }
    let window = 1usize << (usize::BITS - 1 - n.leading_zeros());
    let start = if table.get(n - window).is_some_and(|e| e.index() <= index) {
        n - window
    } else {
        0
    };
    search_window(table.get(start..start + window)?, index)
}

/// Why a table was refused when the dictionary was created.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TableError {
    /// `kCopObdIllegalPart` (order) or `kCopObdUnknownObjectType` (entry).
    pub code: CopKernel,
    /// The first offending index.
    pub index: u16,
    /// The offending subindex (0 for order errors of the index table).
    pub sub: u8,
}

impl ObjectDictionary {
    /// An empty dictionary.
    pub const fn empty() -> Self {
        ObjectDictionary {
            parts: [PartTable::EMPTY; 4],
            handle: table::FIRST_HANDLE,
        }
    }

    /// A dictionary from the three static parts. Every table is checked:
    /// indices strictly ascending (else `kCopObdIllegalPart`), subindices
    /// strictly ascending, known data types, variable sizes that fit their
    /// type and storage present (else `kCopObdUnknownObjectType`).
    pub fn new(
        generic: &'static [ObdEntry],
        manufacturer: &'static [ObdEntry],
        device: &'static [ObdEntry],
    ) -> Result<Self, TableError> {
        let mut od = ObjectDictionary::empty();
        for (slot, table) in od.parts.iter_mut().zip([generic, manufacturer, device]) {
            validate_part(table)?;
            *slot = PartTable::new(table);
        }
        Ok(od)
    }

    /// Sets what the application's OBD and variable callbacks receive first
    /// (the C API's instance handle in a multi-instance build).
    pub fn set_callback_handle(&mut self, handle: CallbackHandle) {
        self.handle = handle;
    }

    /// What the application's OBD and variable callbacks receive first.
    pub fn callback_handle(&self) -> CallbackHandle {
        self.handle
    }

    /// Replaces the user part (dynamic OD); checked like the static parts.
    pub fn set_user_part(&mut self, user: &'static [ObdEntry]) -> Result<(), TableError> {
        validate_part(user)?;
        if let Some(slot) = self.parts.get_mut(Part::User.slot()) {
            *slot = PartTable::new(user);
        }
        Ok(())
    }

    /// The table of one part.
    pub fn part(&self, part: Part) -> &'static [ObdEntry] {
        self.parts.get(part.slot()).map_or(&[], |p| p.table)
    }

    /// Number of index entries.
    pub fn len(&self) -> usize {
        self.parts.iter().map(|p| p.table.len()).sum()
    }

    /// True for an empty dictionary.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Every index entry, part by part.
    pub fn entries(&self) -> impl Iterator<Item = &'static ObdEntry> + '_ {
        self.parts.iter().flat_map(|p| p.table.iter())
    }

    /// The index entry of `index`: searched in the part its number belongs
    /// to, then (for indices outside the user part's own range) in the user
    /// part, where the dynamic OD may have added it.
    #[inline]
    pub fn find_entry(&self, index: u16) -> Option<&'static ObdEntry> {
        match self.find_entry_fast(index) {
            Some(e) => Some(e),
            None => self.find_entry_slow(index),
        }
    }

    /// The part slot of `index`.
    #[inline(always)]
    fn slot_of(index: u16) -> usize {
        SLOT_OF_TOP_NIBBLE
            .get(usize::from(index >> 12))
            .map_or(0, |s| usize::from(*s & 3))
    }

    /// The common case of [`ObjectDictionary::find_entry`]: the entry in
    /// its own part, found in a window of 8 or 16 entries. `None` when
    /// that does not settle it ([`ObjectDictionary::find_entry_slow`]).
    #[inline(always)]
    fn find_entry_fast(&self, index: u16) -> Option<&'static ObdEntry> {
        self.parts.get(Self::slot_of(index))?.find_windowed(index)
    }

    /// [`ObjectDictionary::find_entry`] without the fast path.
    #[inline(never)]
    fn find_entry_slow(&self, index: u16) -> Option<&'static ObdEntry> {
        let slot = Self::slot_of(index);
        if let Some(e) = self.parts.get(slot)?.find(index) {
            return Some(e);
        }
        if slot == Part::User.slot() {
            return None;
        }
        self.parts.get(Part::User.slot())?.find(index)
    }

    /// The index entry of `index` as a handle that looks up its subindices
    /// without searching the index again (several subindices of one
    /// object, e.g. an SRDO's parameters for its CRC).
    #[inline]
    pub fn entry(&self, index: u16) -> OdResult<Entry> {
        self.find_entry(index).map(Entry::new).ok_or(OdError::INDEX)
    }

    /// Looks up index and subindex.
    #[inline(never)]
    pub fn find(&self, index: u16, sub: u8) -> OdResult<Object> {
        match self.find_entry_fast(index) {
            Some(entry) => find_in_entry(entry, sub),
            None => self.find_slow(index, sub),
        }
    }

    /// [`ObjectDictionary::find`] without the fast path of the index search.
    #[inline(never)]
    fn find_slow(&self, index: u16, sub: u8) -> OdResult<Object> {
        match self.find_entry_slow(index) {
            Some(entry) => find_in_entry(entry, sub),
            None => Err(OdError::INDEX),
        }
    }

    /// Highest subindex an entry answers (for EDS export and SDO checks).
    pub fn sub_count(&self, entry: &'static ObdEntry) -> usize {
        let subs = entry.subs();
        match subs.last() {
            Some(last) if last.access().0 & Access::ARRAY != 0 => {
                usize::from(last.sub()) + array_len(entry).saturating_sub(1)
            }
            Some(last) => usize::from(last.sub()) + 1,
            None => 0,
        }
    }

    /// Current size of a value in `order` (strings: their length).
    pub fn size_of(&self, obj: &Object, order: ByteOrder) -> OdResult<usize> {
        let native = obj.native_size()?;
        Ok(match (order, obj.typ.wire_size()) {
            (ByteOrder::Wire, Some(w)) => w,
            _ => match obj.storage()? {
                Storage::RamString(b) => string_len(b),
                _ => native,
            },
        })
    }

    /// Reads a value without access checks or callbacks (stack-internal use:
    /// CRC, mapping, diagnostics). Returns the number of bytes written.
    pub fn peek(&self, obj: &Object, order: ByteOrder, out: &mut [u8]) -> OdResult<usize> {
        peek_object(obj, order, out)
    }

    /// Reads a numeric value as an unsigned integer (stack-internal).
    pub fn read_uint(&self, index: u16, sub: u8) -> OdResult<u64> {
        self.entry(index)?.read_uint(sub)
    }

    /// [`ObjectDictionary::read_uint`] as a `T` (its low bits), or
    /// `default` where the object does not exist or cannot be read: the
    /// read of a configuration value that the stack keeps itself on a
    /// dictionary without the object.
    pub fn read_or<T: UintValue>(&self, index: u16, sub: u8, default: T) -> T {
        self.read_uint(index, sub).map_or(default, T::truncate)
    }

    /// Reads an object for an application or SDO client: existence and
    /// read access are checked and the entry's callback sees
    /// kObdEvCheckExist, kObdEvPreRead and kObdEvPostRead.
    pub fn read(&self, index: u16, sub: u8, order: ByteOrder, out: &mut [u8]) -> OdResult<usize> {
        let obj = self.locate(index, sub)?;
        if !obj.access().readable() {
            return Err(OdError::READ);
        }
        self.callback(&obj, event::PRE_READ, CbArg::None)?;
        let n = self.peek(&obj, order, out)?;
        self.callback(
            &obj,
            event::POST_READ,
            CbArg::Data(out.get_mut(..n).unwrap_or(&mut [])),
        )?;
        Ok(n)
    }

    /// Tells the entry's callback that an SDO transfer of this object was
    /// aborted (kObdEvAbortSdo); `m_pArg` points to the abort code (DWORD,
    /// CPU byte order). Unknown objects are ignored.
    pub fn notify_sdo_abort(&self, index: u16, sub: u8, code: u32) {
        if let Some(entry) = self.find_entry(index) {
            let mut c = code.to_ne_bytes();
            let _ = entry.notify(self.handle, event::ABORT_SDO, sub, CbArg::Data(&mut c));
        }
    }

    /// Finds an object and asks its callback whether it exists.
    pub fn locate(&self, index: u16, sub: u8) -> OdResult<Object> {
        let obj = self.find(index, sub)?;
        obj.entry
            .notify(self.handle, event::CHECK_EXIST, sub, CbArg::None)
            .map_err(|_| OdError::SUBINDEX)?;
        Ok(obj)
    }

    /// Checks that a write of `size` bytes can start (SDO initiate): object
    /// exists, is writable and the size fits; the callback sees
    /// kObdEvInitWrite.
    pub fn begin_write(&self, index: u16, sub: u8, size: Option<usize>) -> OdResult<Object> {
        let obj = self.locate(index, sub)?;
        if !obj.access().writable() {
            return Err(OdError::WRITE);
        }
        if let Some(n) = size {
            self.check_length(&obj, ByteOrder::Wire, n)?;
        }
        let mut s: ObdSize = ObdSize::try_from(obj.native_size()?).unwrap_or(ObdSize::MAX);
        self.callback(&obj, event::INIT_WRITE, CbArg::Size(&mut s))?;
        Ok(obj)
    }

    fn check_length(&self, obj: &Object, order: ByteOrder, n: usize) -> OdResult {
        let exact = match order {
            ByteOrder::Wire => obj.typ.wire_size(),
            ByteOrder::Native => obj.typ.wire_size().map(|_| obj.native_size().unwrap_or(0)),
        };
        match exact {
            Some(e) if n > e => Err(OdError::TOO_LONG),
            Some(e) if n < e => Err(OdError::TOO_SHORT),
            Some(_) => Ok(()),
            None => {
                if n > obj.native_size()? {
                    Err(OdError::TOO_LONG)
                } else {
                    Ok(())
                }
            }
        }
    }

    /// Checks and converts a value for `obj` without storing it.
    pub fn stage(&self, obj: &Object, order: ByteOrder, data: &[u8]) -> OdResult<Staged> {
        self.check_length(obj, order, data.len())?;
        let mut staged = Staged {
            native: [0; MAX_FIXED],
            len: data.len(),
            fixed: false,
        };
        if obj.typ.wire_size().is_some() {
            let size = obj.native_size()?;
            let dst = staged.native.get_mut(..size).ok_or(OdError::LENGTH)?;
            match order {
                ByteOrder::Wire => value::wire_to_native(obj.typ, data, size, dst)?,
                ByteOrder::Native => dst.copy_from_slice(data),
            }
            staged.len = size;
            staged.fixed = true;
            if let Some((low, high)) = obj.desc.limits() {
                let v = staged.native();
                if value::compare(obj.typ, v, low) == Some(core::cmp::Ordering::Less) {
                    return Err(OdError::TOO_LOW);
                }
                if value::compare(obj.typ, v, high) == Some(core::cmp::Ordering::Greater) {
                    return Err(OdError::TOO_HIGH);
                }
            }
            if obj.typ == DataType::Bool && value::native_to_u64(staged.native()).unwrap_or(0) > 1 {
                return Err(OdError::new(
                    CopKernel::ObdValueToHigh,
                    SdoAbort::ValueTooHigh,
                ));
            }
        }
        Ok(staged)
    }

    /// Writes an object for an application or SDO client: existence, write
    /// access, length and range are checked, then the module hooks and the
    /// entry's callback (kObdEvPreWrite) may refuse; only then is the value
    /// stored, all at once, and kObdEvPostWrite follows. A refused write
    /// changes nothing.
    pub fn write(
        &self,
        index: u16,
        sub: u8,
        order: ByteOrder,
        data: &[u8],
        hooks: &mut impl WriteHooks,
    ) -> OdResult {
        let obj = self.begin_write(index, sub, None)?;
        if obj.typ.wire_size().is_none() {
            // Strings and domains: the callback may resize or move the
            // application's buffer before the length is checked.
            obj.entry
                .string_domain_event(self.handle, obj.sub, obj.storage()?, data.len())
                .map_err(|(abort, ret)| OdError {
                    kernel: kernel_from_callback(ret),
                    abort,
                })?;
        }
        let staged = self.stage(&obj, order, data)?;
        hooks.check(self, &obj, &staged)?;
        self.pre_write_callback(&obj, &staged, data)?;
        hooks.before_store(self, &obj, &staged);
        self.store(&obj, &staged, data)?;
        hooks.after_store(self, &obj);
        if let Ok(Storage::Var(v)) = obj.storage() {
            v.notify(self.handle);
        }
        self.post_write_callback(&obj);
        Ok(())
    }

    fn pre_write_callback(&self, obj: &Object, staged: &Staged, data: &[u8]) -> OdResult {
        if !obj.entry.has_callback() {
            return Ok(());
        }
        if staged.fixed {
            let mut copy = staged.native;
            let n = staged.len;
            self.callback(
                obj,
                event::PRE_WRITE,
                CbArg::Data(copy.get_mut(..n).unwrap_or(&mut [])),
            )
        } else {
            self.pre_write_callback_copy(obj, data)
        }
    }

    /// [`Self::pre_write_callback`] of a string or domain: the callback
    /// sees a copy of the source data (at most one SDO buffer; longer data
    /// is passed without copy). Out of line, so that the buffer is on the
    /// stack only while such a callback runs, not under every write
    /// (worst-case stack, docs/tms570.md).
    #[inline(never)]
    fn pre_write_callback_copy(&self, obj: &Object, data: &[u8]) -> Result<(), OdError> {
        let mut copy = [0u8; crate::config::SDOS_BUFFER_SIZE];
        match copy.get_mut(..data.len()) {
            Some(c) => {
                c.copy_from_slice(data);
                self.callback(obj, event::PRE_WRITE, CbArg::Data(c))
            }
            None => self.callback(obj, event::PRE_WRITE, CbArg::None),
        }
    }

    fn post_write_callback(&self, obj: &Object) {
        // The write has happened; a refusal at this point cannot undo it and
        // is ignored (SYS TEC semantics: kObdEvPostWrite is a notification).
        let _ = self.callback(obj, event::POST_WRITE, CbArg::None);
    }

    fn callback(&self, obj: &Object, ev: u8, arg: CbArg<'_>) -> OdResult {
        obj.entry
            .notify(self.handle, ev, obj.sub, arg)
            .map_err(|(abort, ret)| OdError {
                kernel: kernel_from_callback(ret),
                abort,
            })
    }

    /// Stores a staged value (no checks, no callbacks).
    pub fn store(&self, obj: &Object, staged: &Staged, data: &[u8]) -> OdResult {
        match obj.storage()? {
            Storage::Ram(m) if staged.fixed => value::store(m, staged.native()),
            Storage::Ram(m) => {
                // Byte arrays without terminator: write and zero the rest so
                // that the stored value is exactly the written one.
                let n = data.len().min(m.len());
                value::store(m.get(..n).unwrap_or(&[]), data);
                for b in m.get(n..).unwrap_or(&[]) {
                    b.store(0, core::sync::atomic::Ordering::Relaxed);
                }
            }
            Storage::RamString(b) => {
                let n = data.len().min(b.len().saturating_sub(1));
                value::store(b.get(..n).unwrap_or(&[]), data);
                if let Some(t) = b.get(n) {
                    t.store(0, core::sync::atomic::Ordering::Relaxed);
                }
            }
            Storage::Var(v) => {
                let m = v.data().ok_or(OdError::NO_VAR)?;
                if staged.fixed {
                    value::store(m, staged.native());
                } else {
                    // A domain keeps its size (m_Size; the kObdEvWrStringDomain
                    // callback may change it): a shorter value is followed
                    // by zeros, as in RAM byte arrays, so no old data remain.
                    let n = data.len().min(m.len());
                    value::store(m.get(..n).unwrap_or(&[]), data);
                    for b in m.get(n..).unwrap_or(&[]) {
                        b.store(0, core::sync::atomic::Ordering::Relaxed);
                    }
                }
            }
            Storage::Rom(_) | Storage::RomString(_) => return Err(OdError::WRITE),
        }
        Ok(())
    }

    /// Writes a value bypassing access rights and callbacks (the stack's
    /// own bookkeeping, e.g. 0x13FE = 0 or 0x1001). Fixed-size types only.
    pub fn poke_uint(&self, index: u16, sub: u8, v: u64) -> OdResult {
        let obj = self.find(index, sub)?;
        let wire = obj.typ.wire_size().ok_or(OdError::LENGTH)?;
        let bytes = v.to_le_bytes();
        let staged = self.stage_unchecked(&obj, bytes.get(..wire).unwrap_or(&[]))?;
        self.store(&obj, &staged, &[])
    }

    fn stage_unchecked(&self, obj: &Object, wire: &[u8]) -> OdResult<Staged> {
        let size = obj.native_size()?;
        let mut staged = Staged {
            native: [0; MAX_FIXED],
            len: size,
            fixed: true,
        };
        value::wire_to_native(
            obj.typ,
            wire,
            size,
            staged.native.get_mut(..size).ok_or(OdError::LENGTH)?,
        )?;
        Ok(staged)
    }

    /// Restores the default of every RAM subindex with an index in
    /// `from..=to` (NMT reset node / reset communication). Subindices
    /// without default keep their value; attached application variables
    /// (USERDEF) get their default when one is declared.
    pub fn restore_defaults(&self, from: u16, to: u16) {
        for entry in self.entries().filter(|e| (from..=to).contains(&e.index())) {
            let subs = entry.subs();
            for desc in subs {
                let elements = if desc.access().0 & Access::ARRAY != 0 {
                    array_len(entry)
                } else {
                    1
                };
                for el in 0..elements {
                    restore_one(desc, el);
                }
            }
        }
    }
}

/// [`ObjectDictionary::peek`].
fn peek_object(obj: &Object, order: ByteOrder, out: &mut [u8]) -> OdResult<usize> {
    let mut tmp = [0u8; MAX_FIXED];
    let fixed = obj.typ.wire_size().is_some();
    match obj.storage()? {
        Storage::Ram(m) | Storage::RamString(m) if fixed => {
            let t = tmp.get_mut(..m.len()).ok_or(OdError::LENGTH)?;
            value::load(m, t);
            finish_read(obj, order, t, out)
        }
        Storage::Rom(r) | Storage::RomString(r) => finish_read(obj, order, r, out),
        Storage::Ram(m) => {
            let dst = out.get_mut(..m.len()).ok_or(OdError::TOO_LONG)?;
            value::load(m, dst);
            Ok(m.len())
        }
        Storage::RamString(b) => {
            let n = string_len(b);
            let dst = out.get_mut(..n).ok_or(OdError::TOO_LONG)?;
            value::load(b.get(..n).unwrap_or(&[]), dst);
            Ok(n)
        }
        Storage::Var(v) => {
            let m = v.data().ok_or(OdError::NO_VAR)?;
            if fixed {
                let t = tmp.get_mut(..m.len()).ok_or(OdError::LENGTH)?;
                value::load(m, t);
                finish_read(obj, order, t, out)
            } else {
                let dst = out.get_mut(..m.len()).ok_or(OdError::TOO_LONG)?;
                value::load(m, dst);
                Ok(m.len())
            }
        }
    }
}

fn finish_read(obj: &Object, order: ByteOrder, native: &[u8], out: &mut [u8]) -> OdResult<usize> {
    match order {
        ByteOrder::Wire => value::native_to_wire(obj.typ, native, out),
        ByteOrder::Native => {
            let dst = out.get_mut(..native.len()).ok_or(OdError::TOO_LONG)?;
            dst.copy_from_slice(native);
            Ok(native.len())
        }
    }
}

fn restore_one(desc: &ObdSubEntry, element: usize) {
    let Some(def) = desc.default_value() else {
        return;
    };
    match desc.storage(element) {
        Some(Storage::Ram(m)) if def.len() == m.len() => value::store(m, def),
        Some(Storage::RamString(b)) => {
            let n = def.len().min(b.len().saturating_sub(1));
            value::store(b.get(..n).unwrap_or(&[]), def);
            for t in b.get(n..).unwrap_or(&[]) {
                t.store(0, core::sync::atomic::Ordering::Relaxed);
            }
        }
        Some(Storage::Var(v)) => {
            if let Some(m) = v.data() {
                if m.len() == def.len() {
                    value::store(m, def);
                }
            }
        }
        _ => {}
    }
}

/// Maps the `tCopKernel` an application callback returned: its own code if
/// it is a known OBD code, otherwise `kCopObdAccessViolation`.
fn kernel_from_callback(ret: u32) -> CopKernel {
    match ret {
        0x31 => CopKernel::ObdIndexNotExist,
        0x32 => CopKernel::ObdSubindexNotExist,
        0x33 => CopKernel::ObdReadViolation,
        0x34 => CopKernel::ObdWriteViolation,
        0x38 => CopKernel::ObdValueToLow,
        0x39 => CopKernel::ObdValueToHigh,
        0x3A => CopKernel::ObdValueLengthError,
        _ => CopKernel::ObdAccessViolation,
    }
}

/// Length of a NUL-terminated string in a buffer of capacity + 1 bytes.
fn string_len(buf: &[core::sync::atomic::AtomicU8]) -> usize {
    let cap = buf.len().saturating_sub(1);
    buf.iter()
        .take(cap)
        .position(|b| b.load(core::sync::atomic::Ordering::Relaxed) == 0)
        .unwrap_or(cap)
}

/// Number of elements of an array entry: the value of its subindex 0.
fn array_len(entry: &ObdEntry) -> usize {
    let Some(first) = entry.subs().first() else {
        return 0;
    };
    let mut b = [0u8; 1];
    match first.storage(0) {
        Some(Storage::Rom(r)) => r.first().map_or(0, |v| usize::from(*v)),
        Some(Storage::Ram(m)) => {
            value::load(m.get(..1).unwrap_or(&[]), &mut b);
            usize::from(b[0])
        }
        _ => 0,
    }
}

/// The array element `sub` addresses, if the entry's last subindex is an
/// array (kObdAccArray) that covers it.
fn array_element(entry: &'static ObdEntry, sub: u8) -> Option<(&'static ObdSubEntry, u8)> {
    let last = entry.subs().last()?;
    if last.access().0 & Access::ARRAY == 0 || sub < last.sub() {
        return None;
    }
    let element = sub - last.sub();
    let count = array_len(entry);
    // Subindex 1 is element 0; the array has `count` elements.
    if usize::from(sub) > count {
        return None;
    }
    Some((last, element))
}

fn validate_part(part: &[ObdEntry]) -> Result<(), TableError> {
    let mut prev: Option<u16> = None;
    for e in part {
        if prev.is_some_and(|p| p >= e.index()) {
            return Err(TableError {
                code: CopKernel::ObdIllegalPart,
                index: e.index(),
                sub: 0,
            });
        }
        prev = Some(e.index());
        let mut prev_sub: Option<u8> = None;
        for s in e.subs() {
            let bad = |sub| TableError {
                code: CopKernel::ObdUnknownObjectType,
                index: e.index(),
                sub,
            };
            if prev_sub.is_some_and(|p| p >= s.sub()) {
                return Err(TableError {
                    code: CopKernel::ObdIllegalPart,
                    index: e.index(),
                    sub: s.sub(),
                });
            }
            prev_sub = Some(s.sub());
            let typ = s.data_type().ok_or(bad(s.sub()))?;
            let storage_ok = match s.m_bKind {
                kind::RAM | kind::RAM_VSTRING | kind::VAR_ENTRY => !s.m_pCurrent.is_null(),
                kind::ROM | kind::ROM_VSTRING => !s.m_pDefault.is_null(),
                _ => false,
            };
            if !storage_ok {
                return Err(bad(s.sub()));
            }
            if matches!(s.m_bKind, kind::RAM | kind::ROM) && !value::size_fits(typ, s.size()) {
                return Err(bad(s.sub()));
            }
            if s.access().ranged() && s.m_pDefault.is_null() {
                return Err(bad(s.sub()));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    static SUBS: [ObdSubEntry; 1] = [ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1])];

    /// The leaked test tables, kept reachable (Miri's leak check).
    static TABLES: std::sync::Mutex<Vec<&'static [ObdEntry]>> = std::sync::Mutex::new(Vec::new());

    fn table(indices: &[u16]) -> &'static [ObdEntry] {
        let entries: Vec<ObdEntry> = indices
            .iter()
            .map(|&i| ObdEntry::new(i, &SUBS, None))
            .collect();
        let table: &'static [ObdEntry] = Box::leak(entries.into_boxed_slice());
        TABLES.lock().unwrap().push(table);
        table
    }

    /// Every index (a sample under Miri) is found exactly where a scan of
    /// the parts finds it: own part first, then the user part.
    fn check_against_scan(od: &ObjectDictionary) {
        let step = if cfg!(miri) { 251 } else { 1 };
        let map = |part: Part| -> std::collections::HashMap<u16, *const ObdEntry> {
            od.part(part)
                .iter()
                .map(|e| (e.index(), e as *const _))
                .collect()
        };
        let parts = [Part::Generic, Part::Manufacturer, Part::Device, Part::User].map(map);
        let scan = |index: u16| {
            let own = &parts[Part::of(index).slot()];
            own.get(&index).or(parts[3].get(&index)).copied()
        };
        let mut probes: Vec<u16> = (0..=0xFFFFu16).step_by(step).collect();
        for e in od.entries().step_by(if cfg!(miri) { 7 } else { 1 }) {
            let i = e.index();
            probes.extend([i, i.wrapping_add(1), i.wrapping_sub(1)]);
        }
        for index in probes {
            let got = od.find_entry(index).map(|e| e as *const ObdEntry);
            assert_eq!(got, scan(index), "index {index:#06x}");
            assert_eq!(od.find(index, 0).is_ok(), got.is_some());
        }
    }

    #[test]
    fn part_slots_by_top_nibble_match_part_of() {
        for index in (0..=0xFFFFu16).step_by(0x100) {
            let slot = ObjectDictionary::slot_of(index);
            assert_eq!(slot, Part::of(index).slot(), "index {index:#06x}");
            assert_eq!(slot, ObjectDictionary::slot_of(index | 0xFF));
        }
    }

    #[test]
    fn lookups_agree_with_a_scan_for_every_table_shape() {
        let spread = |n: usize, from: u16, span: u16| -> Vec<u16> {
            (0..n)
                .map(|i| from + (i * usize::from(span) / n) as u16)
                .collect()
        };
        let shapes: Vec<Vec<u16>> = vec![
            vec![],
            vec![0x2000],
            vec![0x2000, 0x2001],
            // Few entries (the whole table is searched).
            spread(7, 0x2000, 0x4000),
            // Windows of 8 and 16, the sizes of the fast path.
            spread(12, 0x2000, 0x4000),
            spread(16, 0x2000, 0x4000),
            spread(300, 0x2000, 0x4000),
            // One dense cluster and a few outliers: large windows.
            (0x2000..0x2000 + 200).chain([0x3000, 0x5FFF]).collect(),
            // All entries at the ends of the part.
            (0x2000..0x2010).chain(0x5FF0..=0x5FFF).collect(),
            spread(if cfg!(miri) { 600 } else { 3000 }, 0x2000, 0x4000),
        ];
        for shape in &shapes {
            let od = ObjectDictionary::new(&[], table(shape), &[]).unwrap();
            check_against_scan(&od);
        }
        // The user part: own indices and objects of the other parts' ranges
        // (found there only when the own part does not have them).
        let mut od = ObjectDictionary::new(
            table(&spread(40, 0x1000, 0x1000)),
            table(&spread(300, 0x2000, 0x4000)),
            table(&[0x6000, 0x6001, 0x9FFF]),
        )
        .unwrap();
        let user: Vec<u16> = [0x0001, 0x1001, 0x2001, 0x2002, 0x6002]
            .into_iter()
            .chain(spread(100, 0xA000, 0x5FFF))
            .collect();
        od.set_user_part(table(&user)).unwrap();
        check_against_scan(&od);
        // The largest possible table: every index.
        if !cfg!(miri) {
            let all: Vec<u16> = (0..=0xFFFF).collect();
            let mut od = ObjectDictionary::empty();
            od.set_user_part(table(&all)).unwrap();
            for index in 0..=0xFFFFu16 {
                assert_eq!(od.find_entry(index).map(|e| e.index()), Some(index));
            }
        }
    }

    #[test]
    fn entry_handles_read_like_the_general_path() {
        // Every subindex of the reference dictionary (numbers of every width
        // and sign in RAM and ROM, strings, domains, application variables,
        // arrays) and of a table with the cases beside the fast path (a
        // number narrower than its variable, eight bytes, a string) reads
        // the same through an entry handle and through peek.
        static V3: [AtomicU8; 4] = decl::zeroed();
        static V8: [AtomicU8; 8] = decl::zeroed();
        static VS: [AtomicU8; 5] = decl::zeroed();
        static VB: [AtomicU8; 1] = decl::zeroed();
        static VI: [AtomicU8; 2] = decl::zeroed();
        static EXTRA_SUBS: [ObdSubEntry; 6] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[5]),
            ObdSubEntry::ram(1, DataType::UInt24, Access::RW, &V3, None),
            ObdSubEntry::ram(2, DataType::UInt64, Access::RW, &V8, None),
            ObdSubEntry::ram_string(3, Access::RW, &VS, c"ab"),
            ObdSubEntry::ram(4, DataType::Bool, Access::RW, &VB, None),
            ObdSubEntry::ram(5, DataType::Int16, Access::RW, &VI, None),
        ];
        static EXTRA: [ObdEntry; 1] = [ObdEntry::new(0x6000, &EXTRA_SUBS, None)];
        for (v, bytes) in [
            (&V3[..], &0x00AB_CDEFu32.to_ne_bytes()[..]),
            (&V8[..], &0x0102_0304_0506_0708u64.to_ne_bytes()[..]),
            (&VS[..], &b"xyz\0\0"[..]),
            (&VB[..], &[1u8][..]),
            (&VI[..], &(-2i16).to_ne_bytes()[..]),
        ] {
            value::store(v, bytes);
        }
        let reference = crate::testod::dictionary();
        reference.restore_defaults(0x1000, 0x5FFF);
        let (generic, manufacturer) = crate::testod::parts();
        let extra = ObjectDictionary::new(generic, manufacturer, &EXTRA).unwrap();
        let mut count = 0;
        for od in [reference, extra] {
            for e in od.entries() {
                let entry = od.entry(e.index()).unwrap();
                assert_eq!(entry.index(), e.index());
                // Under Miri: the existing subindices, the two after them
                // and 255 (the others are refused like those).
                let last = e
                    .subs()
                    .iter()
                    .map(|d| usize::from(d.sub()))
                    .max()
                    .unwrap_or(0)
                    + 2;
                let subs = (0..=u8::MAX)
                    .filter(|&s| !cfg!(miri) || usize::from(s) <= last || s == u8::MAX);
                for sub in subs {
                    let direct = od.find(e.index(), sub);
                    let via_entry = entry.find(sub);
                    assert_eq!(direct.is_ok(), via_entry.is_ok());
                    let Ok(obj) = direct else {
                        assert!(entry.read_uint(sub).is_err());
                        continue;
                    };
                    count += 1;
                    let at = format!("{:#06x}/{sub}", e.index());
                    assert_eq!(entry.read_uint(sub), read_uint_of(&obj), "{at}");
                    assert_eq!(od.read_uint(e.index(), sub), entry.read_uint(sub), "{at}");
                    let mut peeked = [0u8; MAX_FIXED];
                    let mut wire = [0u8; MAX_FIXED];
                    let n = od.peek(&obj, ByteOrder::Wire, &mut peeked);
                    assert_eq!(entry.read_wire(sub, &mut wire), n, "{at}");
                    if let Ok(n) = n {
                        assert_eq!(wire[..n], peeked[..n], "{at}");
                    }
                }
            }
        }
        assert!(count > 30);
        assert_eq!(
            crate::testod::dictionary().entry(0x5555).err(),
            Some(OdError::INDEX)
        );
    }
}
