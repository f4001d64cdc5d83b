//! SRDO and GFC (CiA 304 / EN 50325-5; SYS TEC modules SRDO, SRDOSTC and
//! CCMSRDO, seed manual L-1077d chapter 2).
//!
//! Where to look:
//! * frame layouts and COB-ID rules: [`crate::wire::srdo`];
//! * the configuration check and its codes: `check.rs` ([`Srdo::check_config`]);
//! * the CRC over the parameters: [`crc`];
//! * how data move between frames and variables: `plan.rs`;
//! * what a write to 0x1300..0x13FF may do: `hooks.rs`;
//! * declaring the objects in Rust: [`objects`];
//! * transmission, reception, timers, status byte and events: this file.
//!
//! # Running
//! An SRDO runs only while the node is OPERATIONAL, object 0x13FE holds
//! 0xA5, the configuration check passes at the moment the node enters
//! OPERATIONAL, and its direction is not 0. Entering OPERATIONAL resets
//! every status byte to 0, builds the copy plans and the COB-ID dispatch
//! table, and starts fresh timers: the SCT of each receive SRDO runs from
//! that moment, and a transmit SRDO may first be sent 0.5 ms × node-ID
//! later (manual 2.5.1; earlier sends return `kCopSrdoNmtError`). Leaving
//! OPERATIONAL stops everything at once: held first frames are dropped and
//! no timeout is reported any more.
//!
//! # Reception (inside the stack cycle)
//! A received frame is dispatched in constant time through a table indexed
//! by its COB-ID (0x101..0x180). All times are the frames' receive
//! timestamps ([`RxFrame::time`], 100 µs ticks, wrapping).
//! * COB-ID 1 (normal data): if the SCT deadline has passed, SCT timeout is
//!   reported first; then a wrong DLC gives `kCopSrdoDlcNotValid` (a held
//!   first frame is dropped), a second first frame while one is held gives
//!   `kCopSrdoNotInOrder` (the newer frame is kept, so its pair can still
//!   complete), otherwise the frame is held.
//! * COB-ID 2 (inverted data): without a held first frame
//!   `kCopSrdoNotInOrder`; otherwise the held frame is consumed and, in this
//!   order, a gap above SRVT gives `kCopSrdoSrvtTimeout`, a wrong DLC
//!   `kCopSrdoDlcNotValid`, a bit that is not inverted `kCopSrdoDataError`.
//! * A valid pair writes the normal data to the normal variables and the
//!   inverted data to the inverted variables, re-arms the SCT (first frame
//!   of this pair + SCT) and reports success. On every error nothing is
//!   written.
//! * Boundaries: a pair whose second frame arrives exactly SRVT after the
//!   first is valid, later is a timeout; a first frame exactly SCT after the
//!   previous valid pair's first frame is in time, later is a timeout.
//! * SCT timeout is reported once per expiry and re-armed by the next valid
//!   pair; while a first frame that arrived in time is held and its SRVT has
//!   not passed, the SCT check waits for the pair to complete.
//! * `SRDO_CHECK_SRVT_BEFORE_1STRX` TRUE: the timer phase also reports
//!   `kCopSrdoSrvtTimeout` once SRVT has passed with only the first frame
//!   received (the frame is dropped); FALSE: the late second frame or the
//!   SCT check finds it.
//! * A receive overrun of the driver is reported as `kCopSrdoOverrun` for
//!   every running receive SRDO, before the cycle's frames.
//! * Remote frames with an SRDO COB-ID are ignored.
//!
//! # Status byte and events
//! Success: bits 4-5 := 00, then `Event::SrdoEvent(idx)` and the program
//! monitor event (`SrdoReceived` / `SrdoTransmitted`). Error: bits 4-5 :=
//! 01 and bits 6-7 := 01, then `Event::SrdoError(idx, code)`; when the
//! application has handled that event the stack runs
//! `Internal::SrdoCheckHandled`, which reports `Event::SrdoError(idx,
//! kCopSrdoNotHandledInApp)` if bits 6-7 are not 10 (manual 2.9.2) and then
//! `ProgMon(SrdoError)`. The `NotHandledInApp` report neither changes the
//! status byte nor is itself checked. When one step reports two errors for
//! the same SRDO, bits 4-7 are prepared again for the second one only after
//! the first one has been checked, so the application always sees 01/01
//! inside `AppSrdoError`.
//!
//! # Program monitor (`SRDO_USE_PROGMONITOR`), order within one cycle
//! 1. overrun reports, SRDOs in ascending index order;
//! 2. the received frames in arrival order (their error or success events);
//! 3. the timer phase: when the node is not OPERATIONAL exactly one
//!    `SctNotCheckedNotOperational`; otherwise per SRDO in ascending index
//!    order: receive SRDO: [SRVT timeout], [SCT timeout], `SctChecked`;
//!    transmit SRDO: `SctNotCheckedItIsTx`, then `SrdoError` once when its
//!    refresh time has passed without a transmission (again only after the
//!    next transmission); disabled SRDO, or every SRDO while the
//!    configuration is not valid: `SctNotCheckedItIsInvalid`.
//!
//! Transmissions happen in the application's `CcmSendSrdo` calls, outside
//! the cycle; their events follow the call.

mod check;
pub mod crc;
mod hooks;
pub mod objects;
mod plan;
#[cfg(test)]
mod tests;

#[cfg(not(srdo_static_mapping))]
use core::sync::atomic::AtomicU8;

#[cfg(not(srdo_static_mapping))]
use crate::config::SRDO_MAX_MAPPENTRIES;
use crate::config::{SRDO_ALLOW_GAPS_IN_OD, SRDO_MAX_SRDO_IN_OBD, SRDO_USE_PROGMONITOR};
use crate::error::{CopKernel, CopResult};
use crate::event::{Action, ActionQueue, Event, Internal, NmtState, ProgMonEvent, QUEUE_CAPACITY};
use crate::od::ObjectDictionary;
use crate::port::{CanPort, Priority, RxFrame, Ticks, ms_to_ticks};
use crate::wire::srdo::{self as wire, COB_ID_COUNT, COB_ID_MIN, SrdoCobIds};

/// The most actions one SRDO's timer step queues (an SRVT and an SCT
/// error, each with its check of the handshake, and the program monitor's
/// event), with one to spare.
const STEP_ACTIONS_MAX: usize = 6;

pub use crc::crc16;

pub use crate::wire::srdo::{
    COMMU_BASE, COMMU_FIRST, COMMU_LAST, CONFIG_VALID_INDEX, CRC_INDEX, GFC_PARAM_INDEX,
    MAPP_FIRST, MAPP_LAST, MAPP_OFFSET,
};
/// The value of 0x13FE that declares the configuration valid.
pub const CONFIG_VALID: u8 = 0xA5;
/// The only transmission type of an SRDO (asynchronous, manual 1.1.1).
pub const TRANSMISSION_TYPE: u8 = 254;
/// Number of SRDO communication indices (0x1301..=0x1340).
pub const MAX_SRDO_NUMBER: usize = 64;
/// First transmission after entering OPERATIONAL: 0.5 ms × node-ID, here
/// in 100 µs ticks per node-ID (manual 2.5.1).
pub const FIRST_SEND_DELAY_TICKS_PER_NODE: u32 = 5;

/// What [`Srdo::on_frame_first`] made of a received frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Received {
    /// Not an SRDO or GFC frame of this node.
    NotSrdo,
    /// Taken (its events, if any, are queued).
    Taken,
    /// Taken; the first event it reports (the rest are queued).
    Event(Event),
}

/// Bits of the SRDO status byte (manual 2.5.3).
pub mod status {
    /// Bits 4-5: result of the last transfer.
    pub const TRANSFER_MASK: u8 = 0x30;
    /// Bits 4-5 = 00: last transfer ok.
    pub const TRANSFER_OK: u8 = 0x00;
    /// Bits 4-5 = 01: last transfer failed.
    pub const TRANSFER_FAILED: u8 = 0x10;
    /// Bits 4-5 = 11: processed by the application.
    pub const TRANSFER_PROCESSED: u8 = 0x30;
    /// Bits 6-7: error handshake.
    pub const ERROR_MASK: u8 = 0xC0;
    /// Bits 6-7 = 01: set by the library before `AppSrdoError`.
    pub const ERROR_REPORTED: u8 = 0x40;
    /// Bits 6-7 = 10: set by the application inside `AppSrdoError`.
    pub const ERROR_HANDLED: u8 = 0x80;
    /// Bits 0-3: reserved, always 0.
    pub const RESERVED_MASK: u8 = 0x0F;
    /// Bit 0 (reserved, so never set in the status byte of an SRDO): the
    /// entry of a number without SRDO in [`super::Srdo::status_table`].
    pub const ABSENT: u8 = 0x01;
}

c_enum! {
    /// Information direction (0x1301+n sub 1, manual table 2); 3..=255 are
    /// reserved (`from_u8` gives `None`).
    pub enum Direction: u8, fn from_u8(u8) {
        /// The SRDO is switched off.
        Off = 0,
        /// Transmit SRDO.
        Transmit = 1,
        /// Receive SRDO.
        Receive = 2,
    }
}

/// A decoded SRDO mapping entry: the PDO format `index << 16 | sub << 8 |
/// bit length` (manual 1.1.2), decoded by [`crate::wire::pdo`].
pub use crate::wire::pdo::MapEntry as MappingEntry;

/// `tSrdoCommuParam`: what `CcmGetSrdoParam` reports of the communication
/// parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CommuParam {
    /// Information direction (0 off, 1 transmit, 2 receive).
    pub direction: u8,
    /// Refresh time (transmit) or SCT (receive) in ms.
    pub sct_ms: u16,
}

/// `tSrdoMappParam` (dynamic mapping only): number of mapped objects and
/// the variable of each, in mapping order. `None` for dummy entries and
/// objects without a RAM variable.
#[cfg(not(srdo_static_mapping))]
#[derive(Clone, Copy, Debug)]
pub struct MappParam {
    /// Number of mapped objects (0x1381+n sub 0).
    pub count: u8,
    /// The mapped variables.
    pub vars: [Option<&'static [AtomicU8]>; SRDO_MAX_MAPPENTRIES],
}

/// The age beyond which a held first frame counts as stale, far above
/// the largest SRVT (65,535 ms = 655,350 ticks) and below the 2^31 ticks
/// within which [`Ticks::since`] is exact: 2^30 ticks (1.24 days).
const HELD_LIMIT: u32 = 1 << 30;

/// Flags of [`Slot::flags`].
mod flag {
    /// A first (normal) frame is held, waiting for its inverted frame.
    pub const HOLDING: u8 = 0x01;
    /// The SCT (receive) or refresh (transmit) deadline is armed.
    pub const ARMED: u8 = 0x02;
    /// The SRDO runs (node OPERATIONAL, configuration valid, direction set).
    pub const ACTIVE: u8 = 0x04;
}

/// The run-time state of one SRDO (at most 64 bytes, a test checks).
#[derive(Clone, Copy, Debug)]
struct Slot {
    /// The data bytes of the held first frame as received (the bytes
    /// beyond the DLC are masked off where the data are used; a byte
    /// array, so that the slot needs no 8-byte alignment).
    held: [u8; 8],
    /// Receive time of the held first frame.
    held_at: Ticks,
    /// Receive: SCT deadline; transmit: refresh deadline.
    deadline: Ticks,
    /// Refresh time / SCT in ticks.
    sct: u32,
    /// SRVT in ticks.
    srvt: u16,
    /// COB-ID 1.
    cob1: u16,
    /// n of the communication index 0x1300 + n; 0 for an unused slot.
    number: u8,
    /// Direction while running (0 when not running).
    direction: u8,
    /// Data length of each frame in bytes.
    dlc: u8,
    /// [`flag`] bits.
    flags: u8,
    /// Error reports queued but not yet checked by `check_handled`.
    errors_pending: u8,
}

// The run-time state of an SRDO stays within 64 bytes on every target
// (performance goal; checked at compile time, so also for the TMS570).
const _: () = assert!(core::mem::size_of::<Slot>() <= 64);

impl Slot {
    const EMPTY: Slot = Slot {
        held: [0; 8],
        held_at: Ticks(0),
        deadline: Ticks(0),
        sct: 0,
        srvt: 0,
        cob1: 0,
        number: 0,
        direction: 0,
        dlc: 0,
        flags: 0,
        errors_pending: 0,
    };

    fn commu_index(&self) -> u16 {
        COMMU_BASE + u16::from(self.number)
    }
}

/// The SRDO module: every SRDO of the dictionary, the GFC, and the API of
/// manual sections 2.8 and 2.11.
#[derive(Clone, Debug)]
pub struct Srdo {
    slots: [Slot; SRDO_MAX_SRDO_IN_OBD],
    count: u8,
    /// Slot + 1 of SRDO n at position n - 1; 0 = no such SRDO.
    slot_of_commu: [u8; MAX_SRDO_NUMBER],
    /// The status byte (manual 2.5.3) of SRDO n at position n, so that
    /// `CcmGetSrdoState` / `CcmSetSrdoState` reach it with one look-up;
    /// [`status::ABSENT`] for a number without SRDO and at position 0.
    state: [u8; MAX_SRDO_NUMBER + 1],
    /// Slot + 1 of the running receive SRDO using COB-ID 0x101 + position.
    slot_of_cob: [u8; COB_ID_COUNT],
    #[cfg(not(srdo_static_mapping))]
    plans: [plan::Plan; SRDO_MAX_SRDO_IN_OBD],
    #[cfg(srdo_static_mapping)]
    fields: [Option<plan::Fields>; SRDO_MAX_SRDO_IN_OBD],
    running: bool,
    operational: bool,
    config_valid: bool,
    gfc_enabled: bool,
    gfc_ignored: u32,
    overrun_pending: u64,
    cursor: u8,
    not_operational_reported: bool,
    /// Transmit SRDOs: earliest first transmission after entering
    /// OPERATIONAL (the same for every SRDO of the node).
    tx_from: Ticks,
    /// The first-send delay has passed. Set by the first send, or timer
    /// step of a transmit SRDO, at or after `tx_from` (a pass comes at
    /// least every 2^30 ticks, [`Srdo::plan_timers`]), so `tx_from` is
    /// never compared with an instant 2^31 ticks or more after it.
    tx_open: bool,
    /// No armed SCT deadline of a running receive SRDO lies before this
    /// instant, so the timer phase has nothing to do until it has passed
    /// (without the program monitor; see [`Srdo::poll`]).
    due: Ticks,
    /// A first frame may be held (set when one is, cleared by a timer pass
    /// that finds none).
    holding_seen: bool,
}

impl Default for Srdo {
    fn default() -> Self {
        Self::new()
    }
}

/// Reads an 8-bit value (stack-internal, no access check).
pub(crate) fn read_u8(od: &ObjectDictionary, index: u16, sub: u8) -> Option<u8> {
    od.read_uint(index, sub).ok().map(|v| v as u8)
}

/// Reads a 16-bit value (stack-internal, no access check).
pub(crate) fn read_u16(od: &ObjectDictionary, index: u16, sub: u8) -> Option<u16> {
    od.read_uint(index, sub).ok().map(|v| v as u16)
}

/// Reads a 32-bit value (stack-internal, no access check).
pub(crate) fn read_u32(od: &ObjectDictionary, index: u16, sub: u8) -> Option<u32> {
    od.read_uint(index, sub).ok().map(|v| v as u32)
}

/// The status byte after `CcmSetSrdoState(value)`: bits 4-7 from `value`,
/// the reserved bits 0-3 unchanged (0).
#[inline(always)]
pub fn merge_state(old: u8, value: u8) -> u8 {
    (value & !status::RESERVED_MASK) | (old & status::RESERVED_MASK)
}

/// The communication index of a slot, if the slot is used.
fn commu_index_of(slots: &[Slot], slot: usize) -> Option<u16> {
    slots
        .get(slot)
        .filter(|s| s.number != 0)
        .map(Slot::commu_index)
}

/// The status byte of SRDO `number` (1..=64) in `state`.
#[inline(always)]
fn status_of(state: &mut [u8; MAX_SRDO_NUMBER + 1], number: u8) -> Option<&mut u8> {
    state.get_mut(usize::from(number))
}

/// Status after an error: bits 4-5 = 01, bits 6-7 = 01, reserved bits kept.
const fn error_status(status: u8) -> u8 {
    (status & status::RESERVED_MASK) | status::TRANSFER_FAILED | status::ERROR_REPORTED
}

impl Srdo {
    /// A module without SRDOs (call [`Srdo::init`]).
    pub const fn new() -> Self {
        Srdo {
            slots: [Slot::EMPTY; SRDO_MAX_SRDO_IN_OBD],
            count: 0,
            slot_of_commu: [0; MAX_SRDO_NUMBER],
            state: [status::ABSENT; MAX_SRDO_NUMBER + 1],
            slot_of_cob: [0; COB_ID_COUNT],
            #[cfg(not(srdo_static_mapping))]
            plans: [plan::Plan::EMPTY; SRDO_MAX_SRDO_IN_OBD],
            #[cfg(srdo_static_mapping)]
            fields: [None; SRDO_MAX_SRDO_IN_OBD],
            running: false,
            operational: false,
            config_valid: false,
            gfc_enabled: false,
            gfc_ignored: 0,
            overrun_pending: 0,
            cursor: 0,
            not_operational_reported: false,
            tx_from: Ticks(0),
            tx_open: false,
            due: Ticks(0),
            holding_seen: false,
        }
    }

    /// Finds the SRDO objects when the stack is created (`SrdoInit`).
    ///
    /// Every 0x1301+n present becomes an SRDO; it needs sub 1, 2, 3, 5, 6,
    /// its mapping 0x1381+n with sub 0 and the CRC entry 0x13FF sub n, and
    /// 0x13FE must exist once any SRDO does. Refusals:
    /// * `kCopSrdoNotExist`: a gap in 0x1301.. (SRDO n missing, a higher
    ///   one present) while `SRDO_ALLOW_GAPS_IN_OD` is FALSE;
    /// * `kCopNoResource`: more SRDOs than `SRDO_MAX_SRDO_IN_OBD`;
    /// * `kCopObdIndexNotExist` / `kCopObdSubindexNotExist`: a required
    ///   object or subindex is missing.
    pub fn init(&mut self, od: &ObjectDictionary) -> CopResult {
        self.discover(od, SRDO_MAX_SRDO_IN_OBD, SRDO_ALLOW_GAPS_IN_OD)
    }

    /// [`Srdo::init`] with the capacity and the gap rule as parameters (so
    /// both settings are testable in one build).
    fn discover(&mut self, od: &ObjectDictionary, capacity: usize, allow_gaps: bool) -> CopResult {
        *self = Srdo::new();
        let capacity = capacity.min(SRDO_MAX_SRDO_IN_OBD);
        let mut count = 0usize;
        for number in 1..=MAX_SRDO_NUMBER as u8 {
            let commu_index = COMMU_BASE + u16::from(number);
            if od.find_entry(commu_index).is_none() {
                continue;
            }
            if !allow_gaps && usize::from(number) != count + 1 {
                return Err(CopKernel::SrdoNotExist);
            }
            if count >= capacity {
                return Err(CopKernel::NoResource);
            }
            for sub in [1u8, 2, 3, 5, 6] {
                od.find(commu_index, sub).map_err(|e| e.kernel)?;
            }
            od.find(commu_index + MAPP_OFFSET, 0)
                .map_err(|e| e.kernel)?;
            od.find(CRC_INDEX, number).map_err(|e| e.kernel)?;
            let (Some(slot), Some(map), Some(st)) = (
                self.slots.get_mut(count),
                self.slot_of_commu.get_mut(usize::from(number) - 1),
                self.state.get_mut(usize::from(number)),
            ) else {
                return Err(CopKernel::NoResource);
            };
            *slot = Slot {
                number,
                ..Slot::EMPTY
            };
            count += 1;
            *map = count as u8;
            *st = 0;
        }
        if count > 0 {
            od.find(CONFIG_VALID_INDEX, 0).map_err(|e| e.kernel)?;
        }
        self.count = count as u8;
        self.load_cached(od);
        Ok(())
    }

    /// Number of SRDOs in the dictionary.
    pub fn count(&self) -> usize {
        usize::from(self.count)
    }

    /// The communication indices of all SRDOs, ascending.
    pub fn commu_indices(&self) -> impl Iterator<Item = u16> + '_ {
        self.slots.iter().take(self.count()).map(Slot::commu_index)
    }

    /// The communication indices of the SRDOs whose direction is transmit,
    /// ascending (`CcmSendSrdo(0)` sends each of them).
    pub fn transmit_indices<'a>(
        &'a self,
        od: &'a ObjectDictionary,
    ) -> impl Iterator<Item = u16> + 'a {
        self.commu_indices()
            .filter(move |&i| read_u8(od, i, 1) == Some(Direction::Transmit as u8))
    }

    /// True while SRDOs run (OPERATIONAL with a valid configuration).
    pub fn is_running(&self) -> bool {
        self.running
    }

    /// Received frames with the GFC id that were ignored (wrong DLC, remote
    /// frame, GFC off in 0x1300, node not PRE-OPERATIONAL/OPERATIONAL).
    pub fn gfc_ignored(&self) -> u32 {
        self.gfc_ignored
    }

    #[inline]
    fn slot_for(&self, commu_index: u16) -> Result<usize, CopKernel> {
        // Below 0x1301 the difference wraps far beyond the table.
        match self
            .slot_of_commu
            .get(usize::from(commu_index.wrapping_sub(COMMU_FIRST)))
        {
            Some(&s) if s != 0 => Ok(usize::from(s - 1)),
            _ => Err(CopKernel::SrdoNotExist),
        }
    }

    fn load_cached(&mut self, od: &ObjectDictionary) {
        self.gfc_enabled = read_u8(od, GFC_PARAM_INDEX, 0) == Some(1);
        self.config_valid = read_u8(od, CONFIG_VALID_INDEX, 0) == Some(CONFIG_VALID);
    }

    /// Takes over the configuration after reset communication: everything
    /// stops, the cached 0x1300/0x13FE are re-read, and the driver is asked
    /// to receive the GFC id and the COB-IDs the SRDOs have now.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, port: &mut impl CanPort) {
        self.stop();
        self.load_cached(od);
        self.subscribe(od, port);
    }

    /// Asks the driver to receive the GFC id and the COB-IDs every SRDO has
    /// in the dictionary now. The stack calls this after reset
    /// communication and again when the node enters OPERATIONAL, so COB-IDs
    /// configured over SDO in PRE-OPERATIONAL reach a filtering driver.
    pub fn subscribe(&self, od: &ObjectDictionary, port: &mut impl CanPort) {
        if crate::config::SRDO_USE_GFC {
            let _ = port.subscribe(wire::encode_gfc().id, Priority::High);
        }
        for i in 0..self.count() {
            let Some(commu_index) = commu_index_of(&self.slots, i) else {
                continue;
            };
            let cob1 = read_u32(od, commu_index, 5).unwrap_or(0);
            let cob2 = read_u32(od, commu_index, 6).unwrap_or(0);
            if let Ok(ids) = SrdoCobIds::new(cob1, cob2) {
                let _ =
                    port.subscribe(crate::port::CanId::std_masked(ids.normal()), Priority::High);
                let _ = port.subscribe(
                    crate::port::CanId::std_masked(ids.inverted()),
                    Priority::High,
                );
            }
        }
    }

    /// Reacts to an NMT state change (`SrdoNmtEvent`): see the module docs.
    pub fn on_state(&mut self, od: &ObjectDictionary, state: NmtState, node: u8, now: Ticks) {
        let was = self.operational;
        self.operational = state == NmtState::Operational;
        if !self.operational {
            self.stop();
            return;
        }
        if !was {
            for s in self.slots.iter_mut() {
                s.errors_pending = 0;
            }
            for st in self.state.iter_mut() {
                if *st != status::ABSENT {
                    *st = 0;
                }
            }
            self.start(od, node, now);
        }
    }

    fn stop(&mut self) {
        self.running = false;
        self.overrun_pending = 0;
        self.slot_of_cob = [0; COB_ID_COUNT];
        for s in self.slots.iter_mut() {
            s.flags = 0;
            s.direction = 0;
        }
    }

    fn start(&mut self, od: &ObjectDictionary, node: u8, now: Ticks) {
        self.stop();
        self.load_cached(od);
        if !self.config_valid || self.check_config(od).is_err() {
            return;
        }
        let tx_from = now.plus(FIRST_SEND_DELAY_TICKS_PER_NODE * u32::from(node));
        for i in 0..self.count() {
            let Some(commu_index) = commu_index_of(&self.slots, i) else {
                continue;
            };
            let Ok(p) = check::Params::read(od, commu_index) else {
                continue;
            };
            let Some(direction) = Direction::from_u8(p.direction) else {
                continue;
            };
            if direction == Direction::Off {
                continue;
            }
            let Ok(dlc) = check::mapped_len(od, commu_index) else {
                continue;
            };
            if !self.prepare_plan(od, i, commu_index) {
                continue;
            }
            let Some(s) = self.slots.get_mut(i) else {
                continue;
            };
            s.direction = p.direction;
            s.sct = ms_to_ticks(u32::from(p.sct_ms));
            s.srvt = ms_to_ticks(u32::from(p.srvt_ms)) as u16;
            s.cob1 = p.cob1 as u16;
            s.dlc = dlc;
            s.flags = flag::ACTIVE | flag::ARMED;
            if direction == Direction::Receive {
                s.deadline = now.plus(s.sct);
                let pos = usize::from(s.cob1 - COB_ID_MIN);
                for p in pos..pos + 2 {
                    if let Some(m) = self.slot_of_cob.get_mut(p) {
                        *m = (i + 1) as u8;
                    }
                }
            } else {
                s.deadline = tx_from.plus(s.sct);
            }
        }
        self.tx_from = tx_from;
        self.tx_open = false;
        self.running = true;
        self.plan_timers(now);
    }

    #[cfg(not(srdo_static_mapping))]
    fn prepare_plan(&mut self, od: &ObjectDictionary, slot: usize, commu_index: u16) -> bool {
        match (plan::Plan::build(od, commu_index), self.plans.get_mut(slot)) {
            (Some(p), Some(dst)) => {
                *dst = p;
                true
            }
            _ => false,
        }
    }

    #[cfg(srdo_static_mapping)]
    fn prepare_plan(&mut self, _od: &ObjectDictionary, slot: usize, _commu_index: u16) -> bool {
        matches!(self.fields.get(slot), Some(Some(_)))
    }

    #[cfg(not(srdo_static_mapping))]
    fn gather(&self, slot: usize, dlc: u8) -> Option<(u64, u64)> {
        self.plans.get(slot)?.gather(dlc)
    }

    #[cfg(srdo_static_mapping)]
    fn gather(&self, slot: usize, dlc: u8) -> Option<(u64, u64)> {
        let _ = dlc;
        self.fields.get(slot)?.as_ref()?.gather()
    }

    #[cfg(not(srdo_static_mapping))]
    #[inline(always)]
    fn scatter(&self, slot: usize, normal: u64, inverted: u64, dlc: u8) -> bool {
        match self.plans.get(slot) {
            Some(p) => p.scatter(normal, inverted, dlc),
            None => false,
        }
    }

    #[cfg(srdo_static_mapping)]
    #[inline(always)]
    fn scatter(&self, slot: usize, normal: u64, inverted: u64, dlc: u8) -> bool {
        let _ = dlc;
        matches!(self.fields.get(slot), Some(Some(f)) if f.scatter(normal, inverted))
    }

    // ----------------------------------------------------------------- events

    #[cold]
    fn report_error(&mut self, slot: usize, code: CopKernel, q: &mut ActionQueue) {
        let Some(s) = self.slots.get_mut(slot) else {
            return;
        };
        if s.errors_pending == 0 {
            if let Some(st) = status_of(&mut self.state, s.number) {
                *st = error_status(*st);
            }
        }
        s.errors_pending = s.errors_pending.saturating_add(1);
        q.emit(Event::SrdoError(s.commu_index(), code));
        q.schedule(Internal::SrdoCheckHandled(slot as u8));
    }

    /// Reports a successful transfer: status ok, the success event, then
    /// the program monitor's event. With `direct` (only with an empty
    /// queue) the success event is returned instead of queued, as what the
    /// queue would hand out first; else it is queued and `None` returned.
    #[inline(always)]
    fn report_ok(
        &mut self,
        slot: usize,
        pm: ProgMonEvent,
        q: &mut ActionQueue,
        direct: bool,
    ) -> Option<Event> {
        let e = if direct {
            self.mark_ok(slot)
        } else {
            // The status is set when the event's turn comes
            // (`Internal::SrdoOk`): an earlier event's callback may mark
            // the SRDO processed meanwhile (manual 2.9.1).
            q.schedule(Internal::SrdoOk(slot as u8));
            None
        };
        Self::progmon(q, pm);
        e
    }

    /// `Internal::SrdoOk`: the success event of `slot` whose turn has come,
    /// with the status of its transfer ("ok"), put in front of the queue.
    pub fn deliver_ok(&mut self, slot: u8, q: &mut ActionQueue) {
        if let Some(e) = self.mark_ok(usize::from(slot)) {
            q.push_front(Action::Emit(e));
        }
    }

    /// Status bits 4-5 := 00 (success); the event to report.
    #[inline(always)]
    fn mark_ok(&mut self, slot: usize) -> Option<Event> {
        let s = self.slots.get_mut(slot)?;
        if let Some(st) = status_of(&mut self.state, s.number) {
            *st &= !status::TRANSFER_MASK;
        }
        Some(Event::SrdoEvent(s.commu_index()))
    }

    #[inline(always)]
    fn progmon(q: &mut ActionQueue, pm: ProgMonEvent) {
        if SRDO_USE_PROGMONITOR {
            q.emit(Event::ProgMon(pm));
        }
    }

    /// Runs after the application handled `Event::SrdoError` for `slot`
    /// (`Internal::SrdoCheckHandled`): reports `kCopSrdoNotHandledInApp`
    /// when status bits 6-7 are not 10, then `ProgMon(SrdoError)`. Both go
    /// to the front of the queue so that an error's reports stay together.
    pub fn check_handled(&mut self, slot: u8, q: &mut ActionQueue) {
        let Some(s) = self.slots.get_mut(usize::from(slot)) else {
            return;
        };
        s.errors_pending = s.errors_pending.saturating_sub(1);
        let Some(st) = status_of(&mut self.state, s.number) else {
            return;
        };
        let handled = *st & status::ERROR_MASK == status::ERROR_HANDLED;
        if s.errors_pending > 0 {
            *st = error_status(*st);
        }
        if SRDO_USE_PROGMONITOR {
            q.push_front(Action::Emit(Event::ProgMon(ProgMonEvent::SrdoError)));
        }
        if !handled {
            q.push_front(Action::Emit(Event::SrdoError(
                s.commu_index(),
                CopKernel::SrdoNotHandledInApp,
            )));
        }
    }

    // -------------------------------------------------------------- reception

    /// The driver lost received frames: every running receive SRDO gets
    /// `kCopSrdoOverrun`, reported by [`Srdo::report_overrun`].
    pub fn on_rx_overrun(&mut self) {
        if !self.running {
            return;
        }
        let mut mask = 0u64;
        for (i, s) in self.slots.iter().enumerate().take(self.count()) {
            if s.flags & flag::ACTIVE != 0 && s.direction == Direction::Receive as u8 {
                mask |= 1u64 << i;
            }
        }
        self.overrun_pending = mask;
    }

    /// Reports pending overruns one SRDO per call (ascending index); `true`
    /// when none is left.
    pub fn report_overrun(&mut self, q: &mut ActionQueue) -> bool {
        if self.overrun_pending == 0 {
            return true;
        }
        let slot = self.overrun_pending.trailing_zeros() as usize;
        self.overrun_pending &= self.overrun_pending - 1;
        self.report_error(slot, CopKernel::SrdoOverrun, q);
        self.overrun_pending == 0
    }

    /// Offers a received frame; `true` when it was an SRDO or GFC frame.
    pub fn on_frame(&mut self, state: NmtState, frame: &RxFrame, q: &mut ActionQueue) -> bool {
        !matches!(self.take_frame::<false>(state, frame, q), Received::NotSrdo)
    }

    /// [`Srdo::on_frame`] for a receive loop that offers frames only while
    /// the queue is empty (the stack's): the success event of a completed
    /// pair comes back as [`Received::Event`], since the queue would hand
    /// it out first, instead of going through the queue; everything else
    /// (errors, the program monitor's event after the success event) is
    /// queued as by `on_frame`. Inlined into that loop.
    #[inline(always)]
    pub fn on_frame_first(
        &mut self,
        state: NmtState,
        frame: &RxFrame,
        q: &mut ActionQueue,
    ) -> Received {
        self.take_frame::<true>(state, frame, q)
    }

    /// [`Srdo::on_frame`]; with `FIRST` as [`Srdo::on_frame_first`].
    #[inline(always)]
    fn take_frame<const FIRST: bool>(
        &mut self,
        state: NmtState,
        frame: &RxFrame,
        q: &mut ActionQueue,
    ) -> Received {
        let f = &frame.frame;
        // An id in 0x101..=0x180 is an 11-bit id (an extended id has its
        // flag bit in the raw value); the table holds only the COB-IDs of
        // running receive SRDOs (none while the SRDOs are stopped).
        let raw = f.id.raw();
        if let Some(&entry) = self
            .slot_of_cob
            .get(raw.wrapping_sub(u32::from(COB_ID_MIN)) as usize)
        {
            let Some(slot) = entry.checked_sub(1) else {
                return Received::NotSrdo;
            };
            if f.rtr {
                return Received::Taken;
            }
            // Odd ids carry the normal data (COB-ID 1), even ids the
            // inverted data.
            if raw & 1 == 1 {
                self.on_normal(usize::from(slot), frame, q);
            } else if let Some(e) = self.on_inverted::<FIRST>(usize::from(slot), frame, q) {
                return Received::Event(e);
            }
            return Received::Taken;
        }
        if crate::config::SRDO_USE_GFC && wire::is_gfc_id(f) {
            self.on_gfc(f, state, q);
            return Received::Taken;
        }
        Received::NotSrdo
    }

    fn on_gfc(&mut self, f: &crate::port::CanFrame, state: NmtState, q: &mut ActionQueue) {
        let state_ok = matches!(state, NmtState::PreOperational | NmtState::Operational);
        if wire::is_valid_gfc(f) && self.gfc_enabled && state_ok {
            q.emit(Event::Gfc);
        } else {
            self.gfc_ignored = self.gfc_ignored.wrapping_add(1);
        }
    }

    #[inline(always)]
    fn on_normal(&mut self, slot: usize, rx: &RxFrame, q: &mut ActionQueue) {
        let Some(s) = self.slots.get_mut(slot) else {
            return;
        };
        let t = rx.time;
        let late = s.flags & flag::ARMED != 0 && t.is_after(s.deadline);
        if late {
            s.flags &= !flag::ARMED;
        }
        let error = if rx.frame.len != s.dlc {
            s.flags &= !flag::HOLDING;
            Some(CopKernel::SrdoDlcNotValid)
        } else {
            let twice = s.flags & flag::HOLDING != 0;
            s.flags |= flag::HOLDING;
            s.held = rx.frame.data;
            s.held_at = t;
            self.holding_seen |= !SRDO_USE_PROGMONITOR;
            twice.then_some(CopKernel::SrdoNotInOrder)
        };
        if late {
            self.report_error(slot, CopKernel::SrdoSctTimeout, q);
        }
        if let Some(code) = error {
            self.report_error(slot, code, q);
        }
    }

    #[inline(always)]
    fn on_inverted<const FIRST: bool>(
        &mut self,
        slot: usize,
        rx: &RxFrame,
        q: &mut ActionQueue,
    ) -> Option<Event> {
        let s = self.slots.get_mut(slot)?;
        if s.flags & flag::HOLDING == 0 {
            self.report_error(slot, CopKernel::SrdoNotInOrder, q);
            return None;
        }
        s.flags &= !flag::HOLDING;
        let mask = wire::payload_mask(s.dlc);
        let inverted = u64::from_le_bytes(rx.frame.data) & mask;
        let code = if rx.time.since(s.held_at) > u32::from(s.srvt) {
            CopKernel::SrdoSrvtTimeout
        } else if rx.frame.len != s.dlc {
            CopKernel::SrdoDlcNotValid
        } else if (u64::from_le_bytes(s.held) ^ inverted) & mask != mask {
            // Not the complement of the held frame in every bit of the DLC.
            CopKernel::SrdoDataError
        } else {
            let normal = u64::from_le_bytes(s.held) & mask;
            let (first_at, dlc) = (s.held_at, s.dlc);
            if !self.scatter(slot, normal, inverted, dlc) {
                self.report_error(slot, CopKernel::SrdoErrorMapp, q);
                return None;
            }
            if let Some(s) = self.slots.get_mut(slot) {
                s.deadline = first_at.plus(s.sct);
                s.flags |= flag::ARMED;
                if !SRDO_USE_PROGMONITOR && self.due.is_after(s.deadline) {
                    self.due = s.deadline;
                }
            }
            return self.report_ok(slot, ProgMonEvent::SrdoReceived, q, FIRST);
        };
        self.report_error(slot, code, q);
        None
    }

    // ----------------------------------------------------------------- timers

    /// Starts a new processing cycle (resets the resumable timer cursor).
    pub fn begin_cycle(&mut self) {
        self.cursor = 0;
        self.not_operational_reported = false;
    }

    /// The timer phase of a cycle (SCT, SRVT, refresh time, program
    /// monitor). Resumable: each call handles SRDOs until one of them
    /// queued something (at most five actions), and returns `true` once
    /// every SRDO of this cycle has been handled.
    pub fn poll(&mut self, state: NmtState, now: Ticks, q: &mut ActionQueue) -> bool {
        self.poll_with(state, now, q, crate::config::SRDO_CHECK_SRVT_BEFORE_1STRX)
    }

    /// True when [`Srdo::poll`] at `now` would do nothing: the same
    /// conditions as its early returns.
    #[inline]
    pub fn at_rest(&self, state: NmtState, now: Ticks) -> bool {
        if self.count == 0 {
            return true;
        }
        if state != NmtState::Operational {
            return !SRDO_USE_PROGMONITOR || self.not_operational_reported;
        }
        let watch_srvt = crate::config::SRDO_CHECK_SRVT_BEFORE_1STRX && self.holding_seen;
        !SRDO_USE_PROGMONITOR && self.cursor == 0 && !(watch_srvt || now.is_after(self.due))
    }

    /// [`Srdo::poll`] with `SRDO_CHECK_SRVT_BEFORE_1STRX` as a parameter
    /// (so both settings are testable in one build).
    fn poll_with(
        &mut self,
        state: NmtState,
        now: Ticks,
        q: &mut ActionQueue,
        srvt_before_1st: bool,
    ) -> bool {
        if self.count == 0 {
            return true;
        }
        if state != NmtState::Operational {
            if SRDO_USE_PROGMONITOR && !self.not_operational_reported {
                self.not_operational_reported = true;
                q.emit(Event::ProgMon(ProgMonEvent::SctNotCheckedNotOperational));
            }
            return true;
        }
        // Without the program monitor a pass only acts on a deadline that
        // has passed or (SRVT checked before the second frame) on a held
        // first frame; until then the whole pass is one comparison.
        if !SRDO_USE_PROGMONITOR && self.cursor == 0 {
            let watch_srvt = srvt_before_1st && self.holding_seen;
            if !(watch_srvt || now.is_after(self.due)) {
                return true;
            }
        }
        while self.cursor < self.count {
            let slot = usize::from(self.cursor);
            self.cursor += 1;
            let before = q.len();
            let quiet = self.timer_step(slot, now, q, srvt_before_1st);
            // A step that only reported its check to the program monitor
            // does not end the pass while the queue has room for the worst
            // step: the application gets the same events in the same
            // order, without a return to the cycle per SRDO. A step with
            // an error ends it, so that its callback runs before the next
            // SRDO is looked at.
            if (quiet && q.len() <= QUEUE_CAPACITY - STEP_ACTIONS_MAX) || q.len() == before {
                continue;
            }
            let done = self.cursor >= self.count;
            if done && !SRDO_USE_PROGMONITOR {
                self.plan_timers(now);
            }
            return done;
        }
        if !SRDO_USE_PROGMONITOR {
            self.plan_timers(now);
        }
        true
    }

    /// Finds the earliest armed SCT deadline of the running receive SRDOs
    /// ([`Srdo::due`]; `now` + 2^30 ticks when none is armed, which only
    /// causes an idle pass after 1.2 days) and whether a first frame is
    /// held.
    fn plan_timers(&mut self, now: Ticks) {
        let mut earliest = 1i32 << 30;
        let mut holding = false;
        for s in self.slots.iter().take(self.count()) {
            holding |= s.flags & flag::HOLDING != 0;
            let armed = flag::ACTIVE | flag::ARMED;
            if s.flags & armed == armed && s.direction == Direction::Receive as u8 {
                earliest = earliest.min(s.deadline.since(now) as i32);
            }
        }
        self.due = now.plus(earliest as u32);
        self.holding_seen = holding;
    }

    /// One SRDO's part of the timer pass: SRVT and SCT checks of a
    /// receive SRDO, the refresh of a transmit one, the program monitor's
    /// event. `true` when it reported nothing but that event (no error).
    fn timer_step(
        &mut self,
        slot: usize,
        now: Ticks,
        q: &mut ActionQueue,
        srvt_before_1st: bool,
    ) -> bool {
        let Some(s) = self.slots.get_mut(slot) else {
            return true;
        };
        if s.flags & flag::ACTIVE == 0 {
            Self::progmon(q, ProgMonEvent::SctNotCheckedItIsInvalid);
            return true;
        }
        if s.direction == Direction::Transmit as u8 {
            // The refresh time only feeds the program monitor.
            let mut quiet = true;
            if SRDO_USE_PROGMONITOR {
                Self::progmon(q, ProgMonEvent::SctNotCheckedItIsTx);
                if s.flags & flag::ARMED != 0 && now.is_after(s.deadline) {
                    s.flags &= !flag::ARMED;
                    Self::progmon(q, ProgMonEvent::SrdoError);
                    quiet = false;
                }
            }
            // Every pass steps the transmit SRDOs, and a pass comes at
            // least every 2^30 ticks: the first-send delay is settled long
            // before `tx_from` could be compared beyond 2^31 ticks.
            self.first_send_delay_over(now);
            return quiet;
        }
        // A first frame held longer than any SRVT is dated back to
        // HELD_LIMIT at each pass, so that its age, counted modulo 2^32,
        // never looks recent again: a lone inverted frame days later is a
        // SRVT timeout, not a pair with stale data. (`held_at` means
        // nothing while no frame is held; the HOLDING test only keeps the
        // idle pass short.)
        if s.flags & flag::HOLDING != 0 && now.since(s.held_at) > HELD_LIMIT {
            s.held_at = Ticks(now.0.wrapping_sub(HELD_LIMIT));
        }
        // Fast path of an idle cycle: no deadline passed, nothing to watch.
        let deadline_over = s.flags & flag::ARMED != 0 && now.is_after(s.deadline);
        let watch_srvt = srvt_before_1st && s.flags & flag::HOLDING != 0;
        if !(deadline_over || watch_srvt) {
            Self::progmon(q, ProgMonEvent::SctChecked);
            return true;
        }
        let holding = s.flags & flag::HOLDING != 0;
        let held_for = now.since(s.held_at);
        let srvt_over = holding && held_for > u32::from(s.srvt);
        let srvt_error = srvt_before_1st && srvt_over;
        if srvt_error {
            s.flags &= !flag::HOLDING;
        }
        // A first frame that came in time may still complete its pair
        // within SRVT; until then the SCT is not over.
        let pair_pending = holding && !srvt_over && !s.held_at.is_after(s.deadline);
        let sct_error = deadline_over && !pair_pending;
        if sct_error {
            s.flags &= !flag::ARMED;
        }
        if srvt_error {
            self.report_error(slot, CopKernel::SrdoSrvtTimeout, q);
        }
        if sct_error {
            self.report_error(slot, CopKernel::SrdoSctTimeout, q);
        }
        Self::progmon(q, ProgMonEvent::SctChecked);
        !(srvt_error || sct_error)
    }

    // ----------------------------------------------------------- transmission

    /// True once the first-send delay after entering OPERATIONAL has
    /// passed at `now`; settles [`Srdo::tx_open`] the first time.
    fn first_send_delay_over(&mut self, now: Ticks) -> bool {
        if !self.tx_open && now.reached(self.tx_from) {
            self.tx_open = true;
        }
        self.tx_open
    }

    /// `CcmSendSrdo` for one SRDO. Checks, in this order: `kCopSrdoNotExist`
    /// (no such SRDO), `kCopSrdoNmtError` (not OPERATIONAL),
    /// `kCopSrdoInvalidCfg` (0x13FE not 0xA5 or the configuration check
    /// failed when the node entered OPERATIONAL), `kCopSrdoInvalid`
    /// (direction 0), `kCopSrdoRxTxConflict` (a receive SRDO),
    /// `kCopSrdoNmtError` (the first-send delay of 0.5 ms × node-ID after
    /// entering OPERATIONAL has not passed). These refusals send nothing and
    /// leave the status byte alone.
    ///
    /// Then the normal and inverted variables are read; if frame 2 would not
    /// be the exact complement of frame 1 nothing is sent and
    /// `kCopSrdoDataError` is reported (status error, `Event::SrdoError`) and
    /// returned. Otherwise frame 1 and then frame 2 are queued on the high
    /// priority buffer. A driver refusal is reported and returned with the
    /// driver's code (if frame 2 is refused, frame 1 has already gone).
    /// Success: status ok, `Event::SrdoEvent`, `ProgMon(SrdoTransmitted)`.
    ///
    /// With `first` and an empty queue the success event is not queued but
    /// returned as `Some(commu_index)` (the event the queue would hand out
    /// first; the program monitor's event is queued after it), so that the
    /// caller can hand it to the application at once; else `None`.
    #[allow(clippy::too_many_arguments)]
    pub fn send(
        &mut self,
        port: &mut impl CanPort,
        state: NmtState,
        commu_index: u16,
        now: Ticks,
        q: &mut ActionQueue,
        first: bool,
    ) -> CopResult<Option<u16>> {
        let slot = self.slot_for(commu_index)?;
        if state != NmtState::Operational || !self.operational {
            return Err(CopKernel::SrdoNmtError);
        }
        if !self.running {
            return Err(CopKernel::SrdoInvalidCfg);
        }
        let s = *self.slots.get(slot).ok_or(CopKernel::SrdoNotExist)?;
        if s.flags & flag::ACTIVE == 0 {
            return Err(CopKernel::SrdoInvalid);
        }
        if s.direction != Direction::Transmit as u8 {
            return Err(CopKernel::SrdoRxTxConflict);
        }
        if !self.first_send_delay_over(now) {
            return Err(CopKernel::SrdoNmtError);
        }
        let Some((normal, inverted)) = self.gather(slot, s.dlc) else {
            self.report_error(slot, CopKernel::SrdoErrorMapp, q);
            return Err(CopKernel::SrdoErrorMapp);
        };
        if !wire::is_complement(normal, inverted, s.dlc) {
            self.report_error(slot, CopKernel::SrdoDataError, q);
            return Err(CopKernel::SrdoDataError);
        }
        let ids = SrdoCobIds::new(u32::from(s.cob1), u32::from(s.cob1) + 1)
            .map_err(|_| CopKernel::SrdoInvalidCfg)?;
        let (f1, f2) = wire::encode(ids, normal, inverted, s.dlc);
        for f in [&f1, &f2] {
            if let Err(code) = port.send(f, Priority::High) {
                self.report_error(slot, code, q);
                return Err(code);
            }
        }
        if let Some(s) = self.slots.get_mut(slot) {
            s.deadline = now.plus(s.sct);
            s.flags |= flag::ARMED;
        }
        let direct = first && q.is_empty();
        let e = self.report_ok(slot, ProgMonEvent::SrdoTransmitted, q, direct);
        Ok(e.map(|_| commu_index))
    }

    /// `CcmSendGfc`: sends the GFC (id 0x001, DLC 0). `kCopSrdoNmtError`
    /// when not OPERATIONAL, `kCopSrdoInvalid` when 0x1300 is not 1, the
    /// driver's code when it refuses the frame.
    #[cfg(srdo_use_gfc)]
    pub fn send_gfc(&mut self, port: &mut impl CanPort, state: NmtState) -> CopResult {
        if state != NmtState::Operational {
            return Err(CopKernel::SrdoNmtError);
        }
        if !self.gfc_enabled {
            return Err(CopKernel::SrdoInvalid);
        }
        port.send(&wire::encode_gfc(), Priority::High)
    }

    // -------------------------------------------------------------------- API

    /// `CcmGetSrdoState`: the status byte; `kCopSrdoNotExist` for an index
    /// that is not an SRDO of this dictionary.
    pub fn get_state(&self, commu_index: u16) -> CopResult<u8> {
        // 0x1300 + n gives n; any other index more than 64 (or 0: absent).
        match self.state.get(usize::from(commu_index ^ COMMU_BASE)) {
            Some(&st) if st != status::ABSENT => Ok(st),
            _ => Err(CopKernel::SrdoNotExist),
        }
    }

    /// `CcmSetSrdoState`: sets bits 4-7 of the status byte; the reserved
    /// bits 0-3 keep their value (0). `kCopSrdoNotExist` for a bad index.
    pub fn set_state(&mut self, commu_index: u16, value: u8) -> CopResult {
        let s = self
            .status_mut(commu_index)
            .ok_or(CopKernel::SrdoNotExist)?;
        *s = merge_state(*s, value);
        Ok(())
    }

    /// The status byte of an SRDO of this dictionary, `None` for any other
    /// index: one table look-up and one bounds check.
    #[inline(always)]
    pub fn status_mut(&mut self, commu_index: u16) -> Option<&mut u8> {
        // 0x1300 + n gives n; any other index more than 64 (or 0: absent).
        self.state
            .get_mut(usize::from(commu_index ^ COMMU_BASE))
            .filter(|st| **st != status::ABSENT)
    }

    /// The table of status bytes (SRDO n at offset n, [`status::ABSENT`]
    /// at 0 and for a number without SRDO), for the C API's `CcmGetSrdoState` /
    /// `CcmSetSrdoState`, which reach a byte through it while the stack is
    /// not borrowed (`src/ffi/global.rs` says when the pointer is valid).
    pub fn status_table(&mut self) -> *mut [u8; MAX_SRDO_NUMBER + 1] {
        &mut self.state
    }

    /// `SrdoGetCommuParam`: direction and refresh time / SCT as they are in
    /// the dictionary now.
    pub fn commu_param(&self, od: &ObjectDictionary, commu_index: u16) -> CopResult<CommuParam> {
        self.slot_for(commu_index)?;
        Ok(CommuParam {
            direction: read_u8(od, commu_index, 1).ok_or(CopKernel::SrdoNotExist)?,
            sct_ms: read_u16(od, commu_index, 2).ok_or(CopKernel::SrdoNotExist)?,
        })
    }

    /// `SrdoGetMappParam` (dynamic mapping): the number of mapped objects
    /// and the variable of each. `kCopSrdoErrorMapp` when an entry cannot
    /// be read.
    #[cfg(not(srdo_static_mapping))]
    pub fn mapp_param(&self, od: &ObjectDictionary, commu_index: u16) -> CopResult<MappParam> {
        use crate::od::Storage;
        self.slot_for(commu_index)?;
        let mapp_index = commu_index + MAPP_OFFSET;
        let count = read_u8(od, mapp_index, 0).ok_or(CopKernel::SrdoErrorMapp)?;
        let mut out = MappParam {
            count,
            vars: [None; SRDO_MAX_MAPPENTRIES],
        };
        for (sub, var) in (1..=count).zip(out.vars.iter_mut()) {
            let e = MappingEntry::decode(
                read_u32(od, mapp_index, sub).ok_or(CopKernel::SrdoErrorMapp)?,
            );
            if e.dummy_bits().is_some() {
                continue;
            }
            *var = match od.find(e.index, e.sub).and_then(|o| o.storage()) {
                Ok(Storage::Ram(m)) => Some(m),
                Ok(Storage::Var(v)) => v.data(),
                _ => None,
            };
        }
        Ok(out)
    }

    /// `CcmCalcSrdoCrc`: the CRC over the SRDO's parameters as they are in
    /// the dictionary now (also for disabled SRDOs; nothing is compared).
    pub fn calc_crc(&self, od: &ObjectDictionary, commu_index: u16) -> CopResult<u16> {
        self.slot_for(commu_index)?;
        crc::calc(od, commu_index)
    }

    /// Length in bytes of one frame of the SRDO (sum of the normal mapped
    /// entries), e.g. to size the variable fields of static mapping.
    pub fn mapped_len(&self, od: &ObjectDictionary, commu_index: u16) -> CopResult<u8> {
        self.slot_for(commu_index)?;
        check::mapped_len(od, commu_index)
    }

    /// `CcmStaticDefineSrdoVarFields` (static mapping): hands the SRDO its
    /// two contiguous variable fields. Each normal entry of the (constant)
    /// mapping must be the variable at its byte offset in `normal`, each
    /// inverted entry the variable at the same offset in `inverted` (same
    /// address and size), else `kCopSrdoErrorMapp`; more than 8 bytes of
    /// data give `kCopSrdoLengthExceeded`; an unknown index
    /// `kCopSrdoNotExist`; a call while OPERATIONAL `kCopSrdoNmtError`
    /// (define the fields at reset communication, before 0x13FE = 0xA5).
    /// The fields may be longer than the mapping; only the mapped bytes are
    /// used. Frames are copied to and from the fields unchanged.
    #[cfg(srdo_static_mapping)]
    pub fn static_define_var_fields(
        &mut self,
        od: &ObjectDictionary,
        commu_index: u16,
        normal: &'static [core::sync::atomic::AtomicU8],
        inverted: &'static [core::sync::atomic::AtomicU8],
    ) -> CopResult {
        let slot = self.slot_for(commu_index)?;
        if self.operational {
            return Err(CopKernel::SrdoNmtError);
        }
        let len = usize::from(check::mapped_len(od, commu_index)?);
        if len > wire::MAX_DATA {
            return Err(CopKernel::SrdoLengthExceeded);
        }
        plan::match_fields(od, commu_index, normal, inverted)?;
        let (Some(n), Some(i)) = (normal.get(..len), inverted.get(..len)) else {
            return Err(CopKernel::SrdoErrorMapp);
        };
        let dst = self.fields.get_mut(slot).ok_or(CopKernel::SrdoNotExist)?;
        *dst = Some(plan::Fields {
            normal: n,
            inverted: i,
        });
        Ok(())
    }
}
