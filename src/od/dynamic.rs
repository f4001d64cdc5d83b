//! The dynamic object dictionary (SYS TEC CcmDyn, seed manual L-1087d):
//! what a binary DCF container ([`super::dcf`]) does to a dictionary.
//!
//! This module decides; [`DynPool`] lays the tables out in its static
//! memory (`pool.rs`, the raw pointers in [`crate::od::table`]); the stack
//! applies the result through `Target` (`src/ccm/dynod.rs`), and
//! [`crate::ffi::dynod`] exports `DynBuildOd` / `DynDestroyOd`. [`DynPool`]
//! is the safe Rust entry point.
//!
//! # What a container does (seed Bild 2)
//! Every entry either addresses an object that exists (the static parts or
//! a user part the application declared) or creates one:
//! * **existing, writable**: the value is written through the normal
//!   dictionary write path ([`crate::ccm::Stack::write_object`]): length,
//!   range, module hooks (PDO, SRDO, heartbeat...) and application
//!   callbacks apply; numbers arrive little-endian and are stored in the
//!   CPU's byte order.
//! * **existing, not writable** (read-only or constant): the entry is
//!   checked for existence and otherwise ignored; the firmware's value
//!   wins. Real containers carry such entries (0x1000, 0x1008, 0x1018):
//!   the identity and device type stay the firmware's.
//! * **existing, describing the device** ([`describes_structure`]): sub 0
//!   of the pre-defined error field 0x1003 (the number of entries the
//!   device holds, at most its subindices, else `kCopDynInvalidConfig`)
//!   and the store / restore capabilities 0x1010 / 0x1011 sub 1.. are
//!   checked and not written: written, they would be commands (clear the
//!   error history, save or restore), and 0x1003 sub 0 accepts only 0.
//! * **new**: the object is created in the user part. Its type comes from
//!   the attribute byte (BOOLEAN, VISIBLE_STRING, NUMERIC = UNSIGNEDn of the
//!   entry's size, none = DOMAIN), its access from the READ/WRITE/PDO_MAPP
//!   bits. Objects of 0xA000–0xAFFF are network variables: numeric,
//!   read-write, mappable whatever the attribute says, with the type of
//!   seed table 2 (UNSIGNEDn of the size from 0xA900 on); their subindex 0
//!   is the read-only UNSIGNED8 count when the object has other
//!   subindices. An array or record without subindex 0 in the container
//!   gets one (read-only, the highest subindex).
//!
//! # Process image
//! When the caller hands a process image, new fixed-size variables are
//! placed in it: by the address segment when the container has one (a word
//! of 0xFFFF keeps the variable in the pool), otherwise by the CiA 302/405
//! rule of seed chapter 6 ([`super::dcf::rule_offset`]) for 0xA000–0xA8FF,
//! with the areas of the parameter segment, or inputs from 0 and outputs
//! after them ([`super::dcf::PiLayout`]). Strings, domains and everything
//! without a place live in the pool. A variable outside the image is
//! `kCopDynNoMemory`; two variables sharing bytes `kCopDynInvalidConfig`.
//! With a parameter segment, a variable must lie within the image size it
//! names and inside its input or its output area
//! ([`super::dcf::PiParams::covers`]; `kCopDynInvalidConfig` otherwise).
//! Which of the two is not checked: containers of other tools place RPDO
//! data of 0xA480.. in the input area and TPDO data of 0xA000.. in the
//! output area, the other way round from seed table 2.
//!
//! # PDOs (seed Bild 2, chapter 3)
//! A PDO the container touches is reconfigured as a unit, whatever order
//! the container uses: first it is made invalid (COB-ID bit 31) and its
//! mapping count set to 0, then the other values are written in container
//! order, then the mapping count, last the COB-ID (the CiA 301 procedure,
//! so the PDO module's rules accept every step). Every communication
//! object needs its mapping object and the other way round (0x1400 needs
//! 0x1600, 0x1801 needs 0x1A01), in the container or in the dictionary.
//! Before anything changes, the final state of every touched PDO is
//! checked: a valid COB-ID must be usable (`kCopCobIllegalCanId`), the PDO
//! number must be below the module's capacity (`kCopCobNoFreeEntry`), the
//! mapping must hold (`kCopPdoErrorMapp`) and two valid TPDOs must not
//! share a COB-ID (`kCopCobAlreadyExist`).
//!
//! # All or nothing
//! The container is validated, every entry checked against the dictionary
//! and the new tables built and checked on a copy of the dictionary before
//! the first write. If a write is refused all the same (a module rule or
//! an application callback), every value written so far is put back from
//! a snapshot, the user part is restored and the modules re-read their
//! parameters.
//!
//! # Cost
//! With the index of the container's entries and the notes of the plan
//! ([`Container::parse_indexed`], [`Plan::new_with_notes`], both in the
//! pool for `DynBuildOd`) a build costs O(n log n) in the number of
//! entries n (a sort; linear for a sorted container), plus a dictionary
//! lookup per entry and the writes. Without them (a pool too small for
//! them, or [`Plan::new`]) every question about the other entries scans
//! the container: the same decisions in O(n²).
//!
//! # Resets
//! After NMT reset communication (or reset node) the objects the container
//! wrote get the container's values again, static ones included: the
//! dynamic OD stays in force until `DynDestroyOd`.
//!
//! # Building twice, destroying
//! A second build without `DynDestroyOd` is refused with
//! `kCopNoFreeInstance` (the one dynamic OD of the instance is taken, as a
//! second `CcmInitCANopen` is). `DynDestroyOd` follows seed manual 5.2 (see
//! [`crate::ccm::Stack`]'s `destroy_dynamic_od`): the PDO module stops,
//! the dynamic tables go, the PDO parameters of the static dictionary get
//! their defaults and the PDO module is PRE-OPERATIONAL until the next NMT
//! start; other static objects keep the values the container gave them.
//!
//! # Build switches (seed chapter 4)
//! * `OBD_USE_DYNAMIC_OD` (build script key; `COP_OBD_USE_DYNAMIC_OD` for
//!   Rust builds, default on): FALSE leaves the C API without pool, so
//!   `DynBuildOd` answers `kCopDynNoMemory`. `OBD_DYNAMIC_POOL_SIZE`
//!   (default 8192, room for the 128 entries of a typical slave container) sizes the pool that replaces `COP_MALLOC`.
//! * `OBD_USER_OD`, `OBD_USE_VARIABLE_SUBINDEX_TAB`: the seed needs both
//!   for the dynamic OD; here the user part always exists and the new
//!   subindex tables are built in the pool, so they are accepted and not
//!   needed.
//! * `PDO_USE_BIT_MAPPING`, `PDO_GRANULARITY`: the PDO module's rules
//!   ([`crate::pdo::PDO_USE_BIT_MAPPING`], [`crate::pdo::PDO_GRANULARITY`],
//!   [`crate::pdo::PDO_MAX_MAPPENTRIES`]) judge every mapping a container
//!   sets up: a BOOLEAN (attribute 0x01) maps as one bit only with bit
//!   mapping, and a mapping longer than `PDO_MAX_MAPPENTRIES` entries is
//!   `kCopPdoErrorMapp`.

use core::sync::atomic::AtomicU8;

use super::dcf::{self, Container, Entry, PiArea, PiLayout, PiParams, attr};
use super::{Access, ByteOrder, DataType, ObdEntry, ObjectDictionary, Part, kind, value};
use crate::error::{CopKernel, CopResult};
use crate::pdo::mapping;
use crate::pdo::{Direction, PDO_MAX_MAPPENTRIES, PdoIndex, Role};
use crate::port::{CanPort, Ticks};
use crate::wire::pdo::{COB_INVALID, check_identifier};

pub(crate) mod pool;

pub use super::table::DynPool;
pub use pool::BuildError;

/// The stack a dynamic OD is built for, as the build sees it: the
/// dictionary, its write path, the PDO module's pooled channels and the
/// modules' reconfiguration. This module and the pool decide and lay the
/// tables out; the stack (`src/ccm/dynod.rs`) implements this interface
/// and so applies the result without the dictionary knowing the stack.
pub(crate) trait Target {
    /// The state of one RPDO (the PDO module's receive channel).
    type RxChannel: 'static;
    /// The state of one TPDO (the PDO module's transmit channel).
    type TxChannel: 'static;
    /// An RPDO channel as the PDO module starts it.
    fn new_rx_channel() -> Self::RxChannel;
    /// A TPDO channel as the PDO module starts it.
    fn new_tx_channel() -> Self::TxChannel;
    /// The stack's dictionary.
    fn od(&self) -> &ObjectDictionary;
    /// The stack's dictionary, to install a new user part.
    fn od_mut(&mut self) -> &mut ObjectDictionary;
    /// A write through the dictionary's checks and the modules' hooks.
    /// (`at`: index and subindex.)
    fn write(&mut self, at: (u16, u8), order: ByteOrder, data: &[u8], now: Ticks) -> CopResult;
    /// The installed dynamic OD.
    fn dynamic_od(&self) -> Option<&Installed>;
    /// Installs (or forgets) the dynamic OD.
    fn set_dynamic_od(&mut self, d: Option<Installed>);
    /// Hands the PDO module channels from the pool.
    fn attach_pooled(
        &mut self,
        rx: Option<&'static mut [Self::RxChannel]>,
        tx: Option<&'static mut [Self::TxChannel]>,
    );
    /// Takes the pooled channels back from the PDO module.
    fn detach_pooled(&mut self, port: &mut impl CanPort);
    /// Lets every module take over its parameters from the dictionary.
    fn reload_configuration(&mut self, port: &mut impl CanPort, now: Ticks);
    /// `DynDestroyOd`'s sequence (seed manual 5.2).
    fn destroy_dynamic_od(
        &mut self,
        original_user: &'static [ObdEntry],
        port: &mut impl CanPort,
        now: Ticks,
    );
}

/// The container entry a refused build is about (`DynGetLastError`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Blame {
    /// Index of the entry.
    pub index: u16,
    /// Subindex of the entry.
    pub sub: u8,
    /// Byte offset of the entry (its index field) from the container's
    /// start.
    pub offset: u32,
}

/// Bytes before an entry's value: index, subindex, length.
const ENTRY_HEAD: usize = 7;

impl Blame {
    /// Entry `e` of container `c`.
    pub fn of(c: &Container<'_>, e: &Entry<'_>) -> Blame {
        // The value is a slice of the container: its distance from the
        // start, less the entry's head, is the entry's offset.
        let at = (e.data.as_ptr() as usize)
            .wrapping_sub(c.bytes().as_ptr() as usize)
            .saturating_sub(ENTRY_HEAD);
        Blame {
            index: e.index,
            sub: e.sub,
            offset: u32::try_from(at).unwrap_or(u32::MAX),
        }
    }

    /// The last entry of `index`/`sub` in `c` (the one whose value counts).
    pub fn at(c: &Container<'_>, index: u16, sub: u8) -> Option<Blame> {
        c.entries_in(index, index)
            .filter(|e| e.sub == sub)
            .last()
            .map(|e| Blame::of(c, &e))
    }

    /// The first entry of `index` in `c`.
    pub fn first_of(c: &Container<'_>, index: u16) -> Option<Blame> {
        c.entries_in(index, index).next().map(|e| Blame::of(c, &e))
    }
}

/// Where a new variable lives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// In the pool.
    Pool,
    /// In the process image at this offset.
    Image(u32),
}

/// The initial value of a new subindex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Initial<'a> {
    /// From the container (CANopen byte order).
    Wire(&'a [u8]),
    /// A count the container did not carry (subindex 0 of an array).
    Count(u8),
}

/// Everything needed to create one new subindex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NewSub<'a> {
    /// Index.
    pub index: u16,
    /// Subindex.
    pub sub: u8,
    /// Data type.
    pub typ: DataType,
    /// Access attributes.
    pub access: Access,
    /// Storage kind (`kind::RAM` or `kind::RAM_VSTRING`).
    pub kind: u8,
    /// `m_dwSize`: variable width, or capacity of a string.
    pub size: u32,
    /// Initial value.
    pub initial: Initial<'a>,
    /// Where the variable lives.
    pub place: Place,
}

impl NewSub<'_> {
    /// Bytes of memory the variable takes (strings: one more for the NUL).
    pub fn storage_len(&self) -> usize {
        let n = self.size as usize;
        if self.kind == kind::RAM_VSTRING {
            n + 1
        } else {
            n
        }
    }

    /// Writes the initial value in memory format (numbers in the CPU's
    /// byte order and their C width) into `out` (`storage_len` bytes).
    pub fn initial_bytes(&self, out: &mut [u8]) -> Result<(), CopKernel> {
        let bad = CopKernel::DynInvalidConfig;
        match (self.initial, self.typ, self.size) {
            // UNSIGNEDn of its own width: the number in the CPU's byte
            // order, every byte written (what `wire_to_native` makes of it,
            // without its detours).
            (Initial::Wire(&[b]), DataType::UInt8, 1) => {
                *out.first_chunk_mut::<1>().ok_or(bad)? = [b];
                Ok(())
            }
            (Initial::Wire(&[b0, b1]), DataType::UInt16, 2) => {
                *out.first_chunk_mut::<2>().ok_or(bad)? =
                    u16::from_le_bytes([b0, b1]).to_ne_bytes();
                Ok(())
            }
            (Initial::Wire(&[b0, b1, b2, b3]), DataType::UInt32, 4) => {
                *out.first_chunk_mut::<4>().ok_or(bad)? =
                    u32::from_le_bytes([b0, b1, b2, b3]).to_ne_bytes();
                Ok(())
            }
            (Initial::Count(n), ..) => {
                out.fill(0);
                if let Some(b) = out.first_mut() {
                    *b = n;
                }
                Ok(())
            }
            (Initial::Wire(w), ..) if self.typ.wire_size().is_some() => {
                out.fill(0);
                value::wire_to_native(self.typ, w, self.size as usize, out).map_err(|_| bad)
            }
            (Initial::Wire(w), ..) => {
                out.fill(0);
                let dst = out.get_mut(..w.len()).ok_or(bad)?;
                dst.copy_from_slice(w);
                Ok(())
            }
        }
    }
}

/// The subindices of a new object ([`Plan::new_subs_of`]): the count the
/// container lacks first, if any, then every subindex of the container,
/// ascending.
#[derive(Clone, Debug)]
pub struct NewSubs<'a, 'p> {
    plan: &'p Plan<'a>,
    count: Option<NewSub<'a>>,
    subs: dcf::SubsOf<'p, 'a>,
}

impl<'a> Iterator for NewSubs<'a, '_> {
    type Item = Result<NewSub<'a>, CopKernel>;

    fn next(&mut self) -> Option<Self::Item> {
        if let Some(c) = self.count.take() {
            return Some(Ok(c));
        }
        let (first, e) = self.subs.next()?;
        Some(self.plan.describe(&first, &e))
    }
}

/// The result of a successful build.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BuildInfo {
    /// The process image as the container describes it (the parameter
    /// segment, or the layout of the offset rule).
    pub pi: PiParams,
    /// Objects created.
    pub new_indices: usize,
    /// Subindices created.
    pub new_subs: usize,
    /// Pool bytes in use.
    pub pool_used: usize,
}

/// What the stack keeps while a dynamic OD is installed.
#[derive(Clone, Copy, Debug)]
pub struct Installed {
    /// Copy of the container's index segment (re-applied after resets).
    pub(crate) values: &'static [u8],
    /// The user part before the build.
    pub(crate) original_user: &'static [ObdEntry],
    /// Identity of the pool the tables live in (its address).
    pub(crate) pool: usize,
}

impl Installed {
    /// The user part that was in place before the build.
    pub fn original_user_part(&self) -> &'static [ObdEntry] {
        self.original_user
    }
}

/// One write of the application sequence.
#[derive(Clone, Copy, Debug)]
enum Op<'a> {
    /// A value from the container.
    Value(&'a [u8]),
    /// A number computed by the sequence (COB-ID invalid, count 0).
    Uint(u64),
    /// The value the object had before the build (from the snapshot).
    Original,
}

#[derive(Clone, Copy, Debug)]
struct Write<'a> {
    index: u16,
    sub: u8,
    op: Op<'a>,
    /// Known to write an object an earlier write of the sequence wrote
    /// (a repeated entry of the plain step): its value before the build is
    /// in the snapshot already.
    repeat: bool,
}

/// Steps of the write sequence (module docs, "PDOs"), in their order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Step {
    Invalidate,
    ZeroCount,
    Plain,
    PdoValues,
    Counts,
    CobIds,
    Done,
}

/// A container checked against a dictionary.
#[derive(Clone, Copy, Debug)]
pub struct Plan<'a> {
    c: Container<'a>,
    od: ObjectDictionary,
    image_len: usize,
    layout: PiLayout,
    input_base: u32,
    output_base: u32,
    /// New index entries.
    pub new_indices: usize,
    /// New subindex entries (synthesised counts included).
    pub new_subs: usize,
    /// Pool bytes for variables that are not in the image.
    pub data_bytes: usize,
    /// Pool bytes for the snapshot of existing values.
    pub snapshot_bytes: usize,
    /// What `DynBuildOd` reports about the process image.
    pub pi: PiParams,
    /// One byte per entry, by position ([`NOTE_WRITES`], [`NOTE_PLAIN`],
    /// [`NOTE_EXISTS`]), when the plan was made with
    /// [`Plan::new_with_notes`]; empty otherwise.
    notes: &'a [u8],
    /// True when the container has entries of PDO parameters
    /// (0x1400–0x1BFF).
    pdo_entries: bool,
    /// RPDO channels the pool provides: when `PDO_MAX_RXPDO_IN_OBD` is 0
    /// (the PDOs come from the container) the highest RPDO number the
    /// container touches + 1, else 0 (the build's capacity applies).
    pub rx_channels: usize,
    /// TPDO channels the pool provides (as `rx_channels`).
    pub tx_channels: usize,
}

/// Note of an entry that writes an existing object (which exists before the
/// build and is writable).
const NOTE_WRITES: u8 = 0x01;
/// Note of such an entry outside the PDO parameters (the plain step of the
/// write sequence).
const NOTE_PLAIN: u8 = 0x02;
/// Note of an entry whose index exists before the build.
const NOTE_EXISTS: u8 = 0x04;

const RECORD_HEADER: usize = 5;

fn index_allowed(index: u16) -> bool {
    // 0x0000 does not exist, 0x0001-0x0FFF are data types, 0xFFFF ends a
    // table (`OBD_TABLE_INDEX_END`).
    (0x1000..0xFFFF).contains(&index)
}

fn unsigned_of(len: usize) -> Option<DataType> {
    Some(match len {
        1 => DataType::UInt8,
        2 => DataType::UInt16,
        3 => DataType::UInt24,
        4 => DataType::UInt32,
        5 => DataType::UInt40,
        6 => DataType::UInt48,
        7 => DataType::UInt56,
        8 => DataType::UInt64,
        _ => return None,
    })
}

/// Pre-defined error field (CiA 301): sub 0 counts the errors held.
const ERROR_FIELD: u16 = 0x1003;

/// True for existing entries that describe the device rather than set a
/// value, and so are not written (ordinary writes would be refused or
/// would act): sub 0 of the pre-defined error field (a DCF carries the
/// number of entries the device holds; writing it means "clear the
/// errors", and only 0 is accepted), and the subindices of 0x1010 / 0x1011
/// from 1 on (in a DCF the device's store / restore capabilities; written,
/// they are commands that need the signature "save" / "load").
pub fn describes_structure(index: u16, sub: u8) -> bool {
    matches!((index, sub), (ERROR_FIELD, 0) | (0x1010 | 0x1011, 1..))
}

/// 0x1003 sub 0 of a container: the number of entries the object holds,
/// at most the subindices the dictionary has (`kCopDynInvalidConfig`
/// otherwise: an existing object cannot grow).
fn check_error_field_count(od: &ObjectDictionary, data: &[u8]) -> Result<(), CopKernel> {
    let count = match data {
        [n] => *n,
        _ => return Err(CopKernel::DynInvalidConfig),
    };
    if count == 0 || od.find(ERROR_FIELD, count).is_ok() {
        Ok(())
    } else {
        Err(CopKernel::DynInvalidConfig)
    }
}

fn is_pdo_param(index: u16) -> bool {
    (0x1400..=0x1BFF).contains(&index)
}

impl<'a> Plan<'a> {
    /// Checks `c` against `od` (the dictionary before the build) for a
    /// process image of `image_len` bytes (0: none). Nothing changes.
    pub fn new(
        c: Container<'a>,
        od: &ObjectDictionary,
        image_len: usize,
    ) -> Result<Self, CopKernel> {
        Self::new_blamed(c, od, image_len, &mut [], &mut None)
    }

    /// [`Plan::new`] for a container with an index
    /// ([`Container::parse_indexed`]), keeping one byte per entry at the end
    /// of `scratch` (see [`Plan::notes_len`]) that spares the write
    /// sequence a dictionary lookup per entry. Same checks, same results;
    /// without index or when `scratch` is shorter than one byte per entry,
    /// the plan simply has no notes.
    pub fn new_with_notes(
        c: Container<'a>,
        od: &ObjectDictionary,
        image_len: usize,
        scratch: &'a mut [u8],
    ) -> Result<Self, CopKernel> {
        Self::new_blamed(c, od, image_len, scratch, &mut None)
    }

    /// Bytes the notes take at the end of the scratch given to
    /// [`Plan::new_with_notes`] (0 without notes).
    pub fn notes_len(&self) -> usize {
        self.notes.len()
    }

    /// [`Plan::new_with_notes`] (empty `scratch`: [`Plan::new`]) that names
    /// the entry a refusal is about in `blame` (`None`: the container as a
    /// whole).
    pub fn new_blamed(
        c: Container<'a>,
        od: &ObjectDictionary,
        image_len: usize,
        scratch: &'a mut [u8],
        blame: &mut Option<Blame>,
    ) -> Result<Self, CopKernel> {
        *blame = None;
        let notes: &'a mut [u8] = match scratch.len().checked_sub(c.len()) {
            Some(start) if c.is_indexed() => scratch.get_mut(start..).unwrap_or_default(),
            _ => &mut [],
        };
        let mut p = Plan {
            c,
            od: *od,
            image_len,
            layout: PiLayout::default(),
            input_base: 0,
            output_base: 0,
            new_indices: 0,
            new_subs: 0,
            data_bytes: 0,
            snapshot_bytes: 0,
            pi: PiParams::default(),
            notes: &[],
            pdo_entries: c.entries_in(0x1400, 0x1BFF).next().is_some(),
            rx_channels: 0,
            tx_channels: 0,
        };
        // With a capacity of 0 (obdcfg.h of a node whose PDOs all come
        // from its container) the channels of the PDOs the container
        // touches are taken from the pool.
        for e in c.entries_in(0x1400, 0x1BFF) {
            if let Some(q) = PdoIndex::of(e.index) {
                let n = usize::from(q.number) + 1;
                let (fixed, pooled) = match q.dir {
                    Direction::Rx => (crate::config::PDO_MAX_RXPDO_IN_OBD, &mut p.rx_channels),
                    Direction::Tx => (crate::config::PDO_MAX_TXPDO_IN_OBD, &mut p.tx_channels),
                };
                if fixed == 0 && n > *pooled {
                    *pooled = n;
                }
            }
        }
        // Only network variables of seed table 2 count for the layout.
        for e in c.entries_in(dcf::NETVAR_INPUT_BASE, 0xA8FF) {
            if !p.exists(e.index) {
                p.layout.add(e.index, e.sub);
            }
        }
        match c.pi_params() {
            Some(pi) => {
                p.pi = pi;
                p.input_base = pi.input_offset;
                p.output_base = pi.output_offset;
            }
            None => {
                p.pi = p.layout.params();
                p.input_base = 0;
                p.output_base = p.layout.output_offset();
            }
        }
        // Whether the index exists, for the indices of the two entries
        // before (containers often carry the subindices of an object one
        // after the other, or alternate between two objects).
        let mut known: [Option<(u16, bool)>; 2] = [None, None];
        // The snapshot bytes of the plain step's writes (existing writable
        // objects outside the PDO parameters, one write per entry), and the
        // first error sizing them meets.
        let mut plain_bytes = 0usize;
        let mut plain_err = None;
        // The existing object found last (containers may write one object
        // several times).
        let mut found: Option<(u16, u8, super::Object)> = None;
        for e in c.entries() {
            let r = (|| -> Result<(), CopKernel> {
                if !index_allowed(e.index) {
                    return Err(CopKernel::ObdIndexNotExist);
                }
                let note = notes.get_mut(e.position as usize);
                let exists = match known {
                    [Some((i, x)), _] | [_, Some((i, x))] if i == e.index => x,
                    _ => p.exists(e.index),
                };
                if known[0].is_none_or(|(i, _)| i != e.index) {
                    known = [Some((e.index, exists)), known[0]];
                }
                if exists {
                    let obj = match found {
                        Some((i, s, o)) if i == e.index && s == e.sub => o,
                        _ => od
                            .find(e.index, e.sub)
                            .map_err(|_| CopKernel::ObdSubindexNotExist)?,
                    };
                    found = Some((e.index, e.sub, obj));
                    let writable = obj.access().writable() && !describes_structure(e.index, e.sub);
                    if (e.index, e.sub) == (ERROR_FIELD, 0) {
                        check_error_field_count(od, e.data)?;
                    }
                    if writable {
                        od.stage(&obj, ByteOrder::Wire, e.data)
                            .map_err(|err| err.kernel)?;
                        if !is_pdo_param(e.index) {
                            match obj.native_size() {
                                Ok(size) => plain_bytes += RECORD_HEADER + size,
                                Err(err) => {
                                    plain_err.get_or_insert((err.kernel, Blame::of(&c, &e)));
                                }
                            }
                        }
                    }
                    if let Some(n) = note {
                        *n = match (writable, is_pdo_param(e.index)) {
                            (false, _) => NOTE_EXISTS,
                            (true, true) => NOTE_EXISTS | NOTE_WRITES,
                            (true, false) => NOTE_EXISTS | NOTE_WRITES | NOTE_PLAIN,
                        };
                    }
                    return Ok(());
                }
                if let Some(n) = note {
                    *n = 0;
                }
                let earlier;
                let first = if c.is_indexed() && c.is_first_occurrence(&e) {
                    &e
                } else {
                    earlier = c.first_occurrence(&e);
                    &earlier
                };
                let d = p.describe(first, &e)?;
                if first.position != e.position {
                    // A repeated entry of a new object must agree with the first.
                    if first.data.len() != e.data.len() || first.attr != e.attr {
                        return Err(CopKernel::DynInvalidConfig);
                    }
                    return Ok(());
                }
                p.new_subs += 1;
                if d.place == Place::Pool {
                    p.data_bytes += d.storage_len();
                }
                if c.is_first_of_index(&e) {
                    p.new_indices += 1;
                    // `Subindices::lacks_count` (the object has entry `e`).
                    let synth = usize::from(!c.has_sub_zero(&e));
                    // More than 255 subindices need as many entries.
                    if c.len() >= usize::from(u8::MAX)
                        && c.subindices(e.index).distinct + synth > usize::from(u8::MAX)
                    {
                        return Err(CopKernel::DynInvalidConfig);
                    }
                    if synth == 1 {
                        p.new_subs += 1;
                        p.data_bytes += 1;
                    }
                }
                Ok(())
            })();
            if let Err(err) = r {
                *blame = Some(Blame::of(&c, &e));
                return Err(err);
            }
        }
        p.notes = notes;
        // Snapshot size: a record per write of the sequence (`apply`
        // records each write). The plain step's were counted above; its
        // error counts where the step comes in the sequence.
        let mut seq = Sequence::new(&p);
        seq.skip_plain = true;
        let mut n = plain_bytes;
        while let Some(w) = seq.next(&p, od) {
            if seq.step > Step::Plain {
                if let Some((err, b)) = plain_err.take() {
                    *blame = Some(b);
                    return Err(err);
                }
            }
            *blame = Blame::at(&p.c, w.index, w.sub);
            let obj = od.find(w.index, w.sub).map_err(|e| e.kernel)?;
            n += RECORD_HEADER + obj.native_size().map_err(|e| e.kernel)?;
        }
        *blame = None;
        if let Some((err, b)) = plain_err {
            *blame = Some(b);
            return Err(err);
        }
        p.snapshot_bytes = n;
        Ok(p)
    }

    /// The container.
    pub fn container(&self) -> &Container<'a> {
        &self.c
    }

    /// The same plan answering its questions about the container without
    /// the container's index (by scanning it): for when the memory of the
    /// index is about to be reused.
    pub fn without_index(&self) -> Plan<'a> {
        Plan {
            c: self.c.without_index(),
            notes: &[],
            ..*self
        }
    }

    /// True when `index` exists in the dictionary before the build.
    pub fn exists(&self, index: u16) -> bool {
        self.od.find_entry(index).is_some()
    }

    /// Describes new subindex `e` (`first` is its first occurrence, which
    /// decides the place; `e` gives the value). Inlined into its two
    /// callers, one call per new subindex each; the rarer network
    /// variables and process-image places are functions of their own.
    #[inline(always)]
    fn describe(&self, first: &Entry<'a>, e: &Entry<'a>) -> Result<NewSub<'a>, CopKernel> {
        let bad = CopKernel::DynInvalidConfig;
        let len = e.data.len();
        let (typ, access, k, size) = if dcf::is_network_variable(e.index) {
            self.network_variable(e)?
        } else {
            let a = e.attr.ok_or(bad)?;
            let mut acc = 0u8;
            if a & attr::READ != 0 {
                acc |= Access::READ;
            }
            if a & attr::WRITE != 0 {
                acc |= Access::WRITE;
            }
            if a & attr::PDO_MAPP != 0 {
                acc |= Access::PDO;
            }
            match a & attr::TYPE_MASK {
                attr::BOOLEAN => (DataType::Bool, Access(acc), kind::RAM, 1),
                attr::VISIBLE_STRING => (DataType::VString, Access(acc), kind::RAM_VSTRING, len),
                attr::NUMERIC => {
                    let t = unsigned_of(len).ok_or(bad)?;
                    // dcf::element_size(t) for UNSIGNEDn of `len` bytes.
                    let width = match len {
                        1 | 2 => len,
                        3 | 4 => 4,
                        _ => 8,
                    };
                    (t, Access(acc), kind::RAM, width)
                }
                _ => (DataType::Domain, Access(acc), kind::RAM, len),
            }
        };
        if typ == DataType::Bool && e.data.first().is_some_and(|b| *b > 1) {
            return Err(bad);
        }
        let place = if self.image_len == 0 {
            Place::Pool
        } else {
            self.place(first, typ)?
        };
        Ok(NewSub {
            index: e.index,
            sub: e.sub,
            typ,
            access,
            kind: k,
            size: u32::try_from(size).map_err(|_| bad)?,
            initial: Initial::Wire(e.data),
            place,
        })
    }

    /// Type, access, kind and size of network variable `e` (0xA000–0xAFFF).
    #[inline(never)]
    fn network_variable(&self, e: &Entry<'a>) -> Result<(DataType, Access, u8, usize), CopKernel> {
        let bad = CopKernel::DynInvalidConfig;
        let len = e.data.len();
        if e.sub == 0 && self.c.entry_has_other_subs(e) {
            if len != 1 {
                return Err(bad);
            }
            return Ok((DataType::UInt8, Access::R, kind::RAM, 1));
        }
        let typ = match dcf::network_variable(e.index) {
            Some(nv) => nv.typ,
            None => unsigned_of(len).ok_or(bad)?,
        };
        if typ.wire_size() != Some(len) {
            return Err(bad);
        }
        let access = Access(Access::READ | Access::WRITE | Access::PDO);
        Ok((typ, access, kind::RAM, dcf::element_size(typ)))
    }

    #[inline(never)]
    fn place(&self, first: &Entry<'a>, typ: DataType) -> Result<Place, CopKernel> {
        if self.image_len == 0 || typ.wire_size().is_none() {
            return Ok(Place::Pool);
        }
        let size = dcf::element_size(typ);
        let at = if self.c.has_addresses() {
            match self.c.address_word(first) {
                Some(w) => u32::from(w),
                None => return Ok(Place::Pool),
            }
        } else {
            match dcf::rule_offset(first.index, first.sub) {
                Some((area, off, _)) => {
                    let base = match area {
                        PiArea::Input => self.input_base,
                        PiArea::Output => self.output_base,
                    };
                    base.checked_add(off).ok_or(CopKernel::DynNoMemory)?
                }
                None => return Ok(Place::Pool),
            }
        };
        let end = (at as usize)
            .checked_add(size)
            .ok_or(CopKernel::DynNoMemory)?;
        if end > self.image_len {
            return Err(CopKernel::DynNoMemory);
        }
        if self.c.pi_params().is_some() && !self.pi.covers(at, size) {
            return Err(CopKernel::DynInvalidConfig);
        }
        Ok(Place::Image(at))
    }

    /// The new indices in ascending order.
    pub fn new_index_list(&self) -> impl Iterator<Item = u16> + '_ {
        self.c.indices().filter(|i| !self.exists(*i))
    }

    /// The new objects in ascending order of their index, each with
    /// [`Plan::new_subs_of`] (without searching the index for each).
    pub fn new_objects(&self) -> impl Iterator<Item = (u16, NewSubs<'a, '_>)> + '_ {
        self.c
            .objects()
            .filter(|o| {
                // The notes tell for every entry whether its index exists.
                match o.entry_position().and_then(|p| self.notes.get(p as usize)) {
                    Some(n) => n & NOTE_EXISTS == 0,
                    None => !self.exists(o.index()),
                }
            })
            .map(|o| (o.index(), self.new_subs(o)))
    }

    /// The subindices of new object `index` in ascending order, each with
    /// its last value from the container.
    pub fn new_subs_of(&self, index: u16) -> NewSubs<'a, '_> {
        self.new_subs(self.c.subs_of(index))
    }

    fn new_subs<'p>(&'p self, subs: dcf::SubsOf<'p, 'a>) -> NewSubs<'a, 'p> {
        let count = subs.missing_count().map(|highest| NewSub {
            index: subs.index(),
            sub: 0,
            typ: DataType::UInt8,
            access: Access::R,
            kind: kind::RAM,
            size: 1,
            initial: Initial::Count(highest),
            place: Place::Pool,
        });
        NewSubs {
            plan: self,
            count,
            subs,
        }
    }

    /// The final value of `index`/`sub` after the build: the container's
    /// last entry for it, else what `candidate` holds.
    fn final_uint(&self, candidate: &ObjectDictionary, index: u16, sub: u8) -> u64 {
        match self.c.last_occurrence(index, sub) {
            Some(e) => value::le_to_u64(e.data),
            None => candidate.read_uint(index, sub).unwrap_or(0),
        }
    }

    /// True when `e` is the first entry of the container that belongs to
    /// its PDO (either of the PDO's two objects).
    fn first_of_pdo(&self, e: &Entry<'a>) -> bool {
        let Some(p) = PdoIndex::of(e.index) else {
            return false;
        };
        let other = match p.role {
            Role::Commu => p.mapp(),
            Role::Mapp => p.commu(),
        };
        self.c.is_first_of_index(e) && self.c.first_position(other).is_none_or(|q| q > e.position)
    }

    /// The PDOs the container touches, each once.
    fn touched_pdos(&self) -> impl Iterator<Item = PdoIndex> + '_ {
        self.c
            .entries_in(0x1400, 0x1BFF)
            .filter(move |e| self.first_of_pdo(e))
            .filter_map(|e| PdoIndex::of(e.index))
    }

    /// Checks the final state of every PDO the container touches against
    /// `candidate`, the dictionary with the new user part (module docs).
    pub fn check_pdos(&self, candidate: &ObjectDictionary) -> Result<(), CopKernel> {
        self.check_pdos_blamed(candidate, &mut None)
    }

    /// [`Plan::check_pdos`] naming in `blame` the first entry of the PDO
    /// that is refused.
    pub fn check_pdos_blamed(
        &self,
        candidate: &ObjectDictionary,
        blame: &mut Option<Blame>,
    ) -> Result<(), CopKernel> {
        for p in self.touched_pdos() {
            *blame = Blame::first_of(&self.c, p.commu()).or(Blame::first_of(&self.c, p.mapp()));
            let (commu, mapp) = (p.commu(), p.mapp());
            if candidate.find_entry(commu).is_none() || candidate.find_entry(mapp).is_none() {
                return Err(CopKernel::DynInvalidConfig);
            }
            if !self.exists(commu) && self.exists(mapp) {
                // A new PDO would be valid before its static mapping could
                // be rewritten: not supported.
                return Err(CopKernel::DynInvalidConfig);
            }
            let cob = self.final_uint(candidate, commu, 1) as u32;
            if cob & COB_INVALID == 0 {
                check_identifier(cob, crate::config::CDRV_CAN20B)
                    .map_err(|_| CopKernel::CobIllegalCanId)?;
                let capacity = match p.dir {
                    Direction::Rx => crate::config::PDO_MAX_RXPDO_IN_OBD.max(self.rx_channels),
                    Direction::Tx => crate::config::PDO_MAX_TXPDO_IN_OBD.max(self.tx_channels),
                };
                if usize::from(p.number) >= capacity {
                    return Err(CopKernel::CobNoFreeEntry);
                }
                if p.dir == Direction::Tx && self.cob_id_shared(candidate, p, cob) {
                    return Err(CopKernel::CobAlreadyExist);
                }
            }
            let count = self.final_uint(candidate, mapp, 0);
            let count = usize::try_from(count).unwrap_or(usize::MAX);
            if count > PDO_MAX_MAPPENTRIES {
                return Err(CopKernel::PdoErrorMapp);
            }
            let mut entries = [0u32; PDO_MAX_MAPPENTRIES];
            for (i, slot) in entries.iter_mut().enumerate().take(count) {
                let sub = u8::try_from(i + 1).map_err(|_| CopKernel::PdoErrorMapp)?;
                if candidate.find(mapp, sub).is_err() {
                    return Err(CopKernel::PdoErrorMapp);
                }
                *slot = self.final_uint(candidate, mapp, sub) as u32;
            }
            mapping::check_mapping(
                candidate,
                p.dir,
                entries.get(..count).unwrap_or(&[]),
                mapping::RULES,
            )
            .map_err(|_| CopKernel::PdoErrorMapp)?;
        }
        self.check_sdo_channels(candidate, blame)?;
        *blame = None;
        Ok(())
    }

    /// An SDO parameter object the container touches that has no channel
    /// in this build ([`crate::sdo::without_channel`]) must end with both
    /// COB-IDs invalid (bit 31): a valid one would name a server or client
    /// that never answers (`kCopSdosNoFreeEntry` / `kCopSdocNoFreeEntry`).
    fn check_sdo_channels(
        &self,
        candidate: &ObjectDictionary,
        blame: &mut Option<Blame>,
    ) -> Result<(), CopKernel> {
        let first = crate::sdo::PARAMETER_FIRST;
        for e in self.c.entries_in(first, crate::sdo::PARAMETER_LAST) {
            let Some(err) = crate::sdo::without_channel(e.index) else {
                continue;
            };
            // A subindex neither the container nor the dictionary has is
            // no COB-ID.
            let valid = [1, 2].into_iter().any(|sub| {
                let value = match self.c.last_occurrence(e.index, sub) {
                    Some(entry) => Some(value::le_to_u64(entry.data)),
                    None => candidate.read_uint(e.index, sub).ok(),
                };
                value.is_some_and(|v| v as u32 & COB_INVALID == 0)
            });
            if valid {
                *blame = Blame::first_of(&self.c, e.index);
                return Err(err);
            }
        }
        Ok(())
    }

    fn cob_id_shared(&self, candidate: &ObjectDictionary, p: PdoIndex, cob: u32) -> bool {
        candidate
            .entries()
            .filter_map(|e| PdoIndex::of(e.index()))
            .filter(|q| q.dir == Direction::Tx && q.role == Role::Commu && q.number != p.number)
            .any(|q| {
                let other = self.final_uint(candidate, q.commu(), 1) as u32;
                other & COB_INVALID == 0 && other & 0x1FFF_FFFF == cob & 0x1FFF_FFFF
            })
    }

    /// [`Plan::writes_existing`] for entry `e`'s index and subindex.
    fn entry_writes(&self, e: &Entry<'_>) -> bool {
        match self.notes.get(e.position as usize) {
            Some(n) => n & NOTE_WRITES != 0,
            None => self.writes_existing(e.index, e.sub),
        }
    }

    /// True when the existing object `index`/`sub` takes the container's
    /// values (exists before the build and is writable).
    fn writes_existing(&self, index: u16, sub: u8) -> bool {
        // `find` fails for an index the dictionary does not have.
        self.od
            .find(index, sub)
            .is_ok_and(|o| o.access().writable() && !describes_structure(index, sub))
    }

    /// Writes the container's values into `stack` in the order of the
    /// module docs; `stack` already has the new user part. `snapshot`
    /// (at least [`Plan::snapshot_bytes`]) first receives every value that
    /// will change; if a write is refused the values are put back and the
    /// refusal is returned.
    /// `blame` names the entry whose write was refused.
    pub(crate) fn apply_blamed(
        &self,
        stack: &mut impl Target,
        snapshot: &mut [u8],
        now: Ticks,
        blame: &mut Option<Blame>,
    ) -> Result<(), CopKernel> {
        // One record per write, in sequence order, except for the writes
        // known to repeat an object: one written twice otherwise is
        // recorded twice with the same value (nothing is written yet),
        // which costs snapshot bytes ([`Plan::snapshot_bytes`] counts one
        // record per write) but no search, and restores the same.
        let mut used = 0usize;
        let mut seq = Sequence::new(self);
        seq.skip_repeats = true;
        while let Some(w) = seq.next(self, stack.od()) {
            if !w.repeat {
                used = record(stack.od(), snapshot, used, w.index, w.sub)?;
            }
        }
        let records = snapshot.get(..used).unwrap_or(&[]);
        let mut seq = Sequence::new(self);
        let mut result = Ok(());
        while let Some(w) = seq.next(self, stack.od()) {
            if let Err(e) = write_one(stack, records, w, now) {
                *blame = Blame::at(&self.c, w.index, w.sub);
                result = Err(e);
                break;
            }
        }
        if result.is_err() {
            restore(stack.od(), records);
        }
        result
    }
}

/// Appends the current value of `index`/`sub` to the snapshot.
fn record(
    od: &ObjectDictionary,
    buf: &mut [u8],
    at: usize,
    index: u16,
    sub: u8,
) -> Result<usize, CopKernel> {
    let obj = od.find(index, sub).map_err(|e| e.kernel)?;
    let cap = obj.native_size().map_err(|e| e.kernel)?;
    let data_at = at + RECORD_HEADER;
    let dst = buf
        .get_mut(data_at..data_at + cap)
        .ok_or(CopKernel::DynNoMemory)?;
    let n = od
        .peek(&obj, ByteOrder::Native, dst)
        .map_err(|e| e.kernel)?;
    let len = u16::try_from(n).map_err(|_| CopKernel::DynNoMemory)?;
    let head = buf.get_mut(at..data_at).ok_or(CopKernel::DynNoMemory)?;
    let i = index.to_le_bytes();
    let l = len.to_le_bytes();
    head.copy_from_slice(&[i[0], i[1], sub, l[0], l[1]]);
    Ok(data_at + n)
}

/// The snapshot records: (index, sub, native bytes).
fn records(buf: &[u8]) -> impl Iterator<Item = (u16, u8, &[u8])> {
    let mut at = 0usize;
    core::iter::from_fn(move || {
        let h = buf.get(at..at + RECORD_HEADER)?;
        let index = u16::from_le_bytes([*h.first()?, *h.get(1)?]);
        let sub = *h.get(2)?;
        let len = usize::from(u16::from_le_bytes([*h.get(3)?, *h.get(4)?]));
        let data = buf.get(at + RECORD_HEADER..at + RECORD_HEADER + len)?;
        at += RECORD_HEADER + len;
        Some((index, sub, data))
    })
}

/// Puts every snapshot value back, without checks or callbacks.
fn restore(od: &ObjectDictionary, snapshot: &[u8]) {
    for (index, sub, data) in records(snapshot) {
        if let Ok(obj) = od.find(index, sub) {
            if let Ok(staged) = od.stage(&obj, ByteOrder::Native, data) {
                let _ = od.store(&obj, &staged, data);
            }
        }
    }
}

fn write_one(
    stack: &mut impl Target,
    snapshot: &[u8],
    w: Write<'_>,
    now: Ticks,
) -> Result<(), CopKernel> {
    match w.op {
        Op::Value(data) => stack.write((w.index, w.sub), ByteOrder::Wire, data, now),
        Op::Uint(v) => {
            let obj = stack.od().find(w.index, w.sub).map_err(|e| e.kernel)?;
            let n = obj.data_type().wire_size().unwrap_or(0).min(8);
            let bytes = v.to_le_bytes();
            stack.write(
                (w.index, w.sub),
                ByteOrder::Wire,
                bytes.get(..n).unwrap_or(&[]),
                now,
            )
        }
        Op::Original => {
            let Some((_, _, data)) =
                records(snapshot).find(|(i, s, _)| *i == w.index && *s == w.sub)
            else {
                return Ok(());
            };
            // Only a COB-ID that was valid before gets its value back (an
            // invalid one was never touched).
            let v = value::native_to_u64(data).unwrap_or(u64::from(COB_INVALID));
            if v & u64::from(COB_INVALID) != 0 {
                return Ok(());
            }
            stack.write((w.index, w.sub), ByteOrder::Native, data, now)
        }
    }
}

/// The write sequence, generated step by step so that it can read the
/// dictionary as it is while the writes go on.
#[derive(Clone, Debug)]
struct Sequence<'p, 'a> {
    step: Step,
    it: dcf::EntriesIn<'p, 'a>,
    /// Next position of the plain step when the plan has notes.
    pos: usize,
    /// Leave the plain step out (its writes were counted otherwise).
    skip_plain: bool,
    /// Leave out the writes known to repeat an object (only their first
    /// write matters for the snapshot).
    skip_repeats: bool,
}

/// The entries a step looks at: all of them for the plain values, those
/// of the PDO parameters (0x1400–0x1BFF) for the other steps.
fn step_entries<'p, 'a>(c: &'p Container<'a>, step: Step) -> dcf::EntriesIn<'p, 'a> {
    match step {
        Step::Plain => c.entries_in(0x0000, 0xFFFF),
        _ => c.entries_in(0x1400, 0x1BFF),
    }
}

impl<'p, 'a> Sequence<'p, 'a> {
    fn new(p: &'p Plan<'a>) -> Self {
        // Without PDO entries the steps before the plain one have nothing
        // to do.
        let step = if p.pdo_entries {
            Step::Invalidate
        } else {
            Step::Plain
        };
        Sequence {
            step,
            it: step_entries(&p.c, step),
            pos: 0,
            skip_plain: false,
            skip_repeats: false,
        }
    }

    /// The next entry the current step looks at. With notes the plain
    /// step reads only the entries that write existing objects (the
    /// others emit nothing).
    fn next_entry(&mut self, p: &Plan<'a>) -> Option<Entry<'a>> {
        if self.step == Step::Plain && self.skip_plain {
            return None;
        }
        if self.step == Step::Plain && !p.notes.is_empty() {
            // `next_plain` went through the notes.
            return None;
        }
        self.it.next()
    }

    /// The plain step with notes: the next entry that writes an existing
    /// object outside the PDO parameters ([`Sequence::emit`] of the plain
    /// step, without reading the others).
    fn next_plain(&mut self, p: &Plan<'a>) -> Option<Write<'a>> {
        while let Some(note) = p.notes.get(self.pos) {
            let pos = self.pos;
            self.pos += 1;
            if note & NOTE_PLAIN == 0 {
                continue;
            }
            if self.skip_repeats && !p.c.is_first_occurrence_at(pos) {
                continue;
            }
            let e = p.c.entry(pos)?;
            return Some(Write {
                index: e.index,
                sub: e.sub,
                op: Op::Value(e.data),
                // A plain object is written by this step only, once per
                // entry: the entries after its first repeat it.
                repeat: !p.c.is_first_occurrence_at(pos),
            });
        }
        None
    }

    #[inline]
    fn next(&mut self, p: &'p Plan<'a>, od: &ObjectDictionary) -> Option<Write<'a>> {
        if self.step == Step::Plain && !self.skip_plain && !p.notes.is_empty() {
            if let Some(w) = self.next_plain(p) {
                return Some(w);
            }
        }
        self.next_in_steps(p, od)
    }

    #[inline(never)]
    fn next_in_steps(&mut self, p: &'p Plan<'a>, od: &ObjectDictionary) -> Option<Write<'a>> {
        loop {
            if self.step == Step::Done {
                return None;
            }
            if self.step == Step::Plain && !self.skip_plain && !p.notes.is_empty() {
                if let Some(w) = self.next_plain(p) {
                    return Some(w);
                }
            }
            let Some(e) = self.next_entry(p) else {
                self.step = match self.step {
                    Step::Invalidate => Step::ZeroCount,
                    Step::ZeroCount => Step::Plain,
                    // The other steps concern PDO entries only.
                    Step::Plain if !p.pdo_entries => Step::Done,
                    Step::Plain => Step::PdoValues,
                    Step::PdoValues => Step::Counts,
                    Step::Counts => Step::CobIds,
                    Step::CobIds | Step::Done => Step::Done,
                };
                self.it = step_entries(&p.c, self.step);
                continue;
            };
            if let Some(w) = self.emit(p, od, &e) {
                return Some(w);
            }
        }
    }

    fn emit(&self, p: &Plan<'a>, od: &ObjectDictionary, e: &Entry<'a>) -> Option<Write<'a>> {
        let last = || p.c.is_last_occurrence(e);
        let value = Write {
            index: e.index,
            sub: e.sub,
            op: Op::Value(e.data),
            repeat: false,
        };
        match self.step {
            Step::Plain => {
                // A plain object is written by this step only, once per
                // entry: the entries after its first repeat it.
                let repeat = p.c.is_indexed() && !p.c.is_first_occurrence(e);
                return (!is_pdo_param(e.index) && p.entry_writes(e))
                    .then_some(Write { repeat, ..value });
            }
            Step::Done => return None,
            _ => {}
        }
        let q = PdoIndex::of(e.index)?;
        match self.step {
            Step::Invalidate => {
                if !p.first_of_pdo(e) || !p.writes_existing(q.commu(), 1) {
                    return None;
                }
                let cur = od.read_uint(q.commu(), 1).ok()?;
                (cur & u64::from(COB_INVALID) == 0).then_some(Write {
                    index: q.commu(),
                    sub: 1,
                    op: Op::Uint(cur | u64::from(COB_INVALID)),
                    repeat: false,
                })
            }
            Step::ZeroCount => {
                (p.first_of_pdo(e) && p.writes_existing(q.mapp(), 0)).then_some(Write {
                    index: q.mapp(),
                    sub: 0,
                    op: Op::Uint(0),
                    repeat: false,
                })
            }
            Step::PdoValues => {
                let special =
                    (q.role == Role::Commu && e.sub == 1) || (q.role == Role::Mapp && e.sub == 0);
                (!special && p.entry_writes(e)).then_some(value)
            }
            Step::Counts => {
                (q.role == Role::Mapp && e.sub == 0 && last() && p.entry_writes(e)).then_some(value)
            }
            Step::CobIds => {
                if q.role == Role::Commu && e.sub == 1 {
                    return (last() && p.entry_writes(e)).then_some(value);
                }
                // A touched PDO whose COB-ID the container does not name
                // gets its own value back.
                let named = p.c.last_occurrence(q.commu(), 1).is_some();
                (!named && p.first_of_pdo(e) && p.writes_existing(q.commu(), 1)).then_some(Write {
                    index: q.commu(),
                    sub: 1,
                    op: Op::Original,
                    repeat: false,
                })
            }
            Step::Plain | Step::Done => None,
        }
    }
}

/// Re-applies the values of an installed dynamic OD to the objects with an
/// index in `from..=to` (after the stack restored their defaults on NMT
/// reset node / reset communication). Existing objects get the values only
/// when they are writable, as at the build.
pub fn reapply(od: &ObjectDictionary, installed: &Installed, from: u16, to: u16) {
    for e in dcf::entries_of_index_segment(installed.values) {
        if !(from..=to).contains(&e.index) {
            continue;
        }
        let Ok(obj) = od.find(e.index, e.sub) else {
            continue;
        };
        let is_static = is_static(od, installed.original_user, e.index);
        if is_static && (!obj.access().writable() || describes_structure(e.index, e.sub)) {
            continue;
        }
        if let Ok(staged) = od.stage(&obj, ByteOrder::Wire, e.data) {
            let _ = od.store(&obj, &staged, e.data);
        }
    }
}

fn is_static(od: &ObjectDictionary, original_user: &[ObdEntry], index: u16) -> bool {
    let part = Part::of(index);
    (part != Part::User
        && od
            .part(part)
            .binary_search_by_key(&index, |e| e.index())
            .is_ok())
        || original_user
            .binary_search_by_key(&index, |e| e.index())
            .is_ok()
}

/// True when two of the subindices in `subs` that live in the memory range
/// `image` share a byte (each counted with its `storage_len`).
pub fn image_overlaps(image: &[AtomicU8], subs: &[super::ObdSubEntry]) -> bool {
    let start = image.as_ptr() as usize;
    let end = start + image.len();
    let span = |s: &super::ObdSubEntry| {
        let a = s.m_pCurrent as usize;
        (a >= start && a < end).then(|| (a, a + s.size().max(1)))
    };
    subs.iter().enumerate().any(|(i, a)| {
        let Some((a0, a1)) = span(a) else {
            return false;
        };
        subs.iter()
            .skip(i + 1)
            .any(|b| span(b).is_some_and(|(b0, b1)| a0 < b1 && b0 < a1))
    })
}

/// [`image_overlaps`] in O(subindices + their bytes): with a bitmap of the
/// image (one bit per byte) in `scratch` when it has room for it
/// (`image.len() / 8` bytes, rounded up), else by comparing every pair.
pub fn image_overlaps_in(
    image: &[AtomicU8],
    subs: &[super::ObdSubEntry],
    scratch: &mut [u8],
) -> bool {
    let Some(bits) = scratch.get_mut(..image.len().div_ceil(8)) else {
        return image_overlaps(image, subs);
    };
    let start = image.as_ptr() as usize;
    let end = start + image.len();
    bits.fill(0);
    for s in subs {
        let a = s.m_pCurrent as usize;
        if a < start || a >= end {
            continue;
        }
        let b = a.saturating_add(s.size().max(1));
        if b > end {
            // Past the image: the bitmap cannot tell.
            return image_overlaps(image, subs);
        }
        for byte in a - start..b - start {
            let Some(cell) = bits.get_mut(byte / 8) else {
                return image_overlaps(image, subs);
            };
            let mask = 1u8 << (byte % 8);
            if *cell & mask != 0 {
                return true;
            }
            *cell |= mask;
        }
    }
    false
}

#[cfg(test)]
mod tests;
