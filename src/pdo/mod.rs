//! Process data objects (CiA 301 §7.2.2) and the SYNC consumer (§7.2.5):
//! the SYS TEC modules PDO, CCMDFPDO, CCMSNPDO, CCMSTPDO and CCMSYNC.
//!
//! # Where the configuration lives
//! The dictionary is the only source: communication parameters
//! 0x1400+n / 0x1800+n (sub 1 COB-ID, 2 transmission type, 3 inhibit time
//! in 100 µs, 5 event timer in ms), mapping parameters 0x1600+n / 0x1A00+n
//! (sub 0 count, subs 1.. entries) and the SYNC objects 0x1005–0x1007. The
//! module keeps a copy that it refreshes after reset communication
//! ([`Pdo::reconfigure`]) and after every accepted write
//! ([`Pdo::after_store`]); writes are judged by [`Pdo::check_write`]
//! against the CiA 301 rules, whoever writes (SDO, `CcmWriteObject`,
//! `CcmDefinePdoTab`).
//!
//! # Processing
//! * Received frames ([`Pdo::on_frame`]): SYNC, RPDOs and remote requests
//!   for TPDOs. Event-driven RPDOs reach their variables at once;
//!   synchronous ones on the next SYNC.
//! * Timers ([`Pdo::poll`], resumable): synchronous TPDOs after a SYNC,
//!   event-driven TPDOs after an event once the inhibit time has passed,
//!   event timers, RPDO deadline monitoring, `CcmSignalCheckVar`.
//! * PDOs are processed in OPERATIONAL only (CiA 301 §7.3.2.2, table of
//!   services per NMT state); in every other state received PDOs are
//!   dropped and nothing is sent.
//!
//! # Behaviour decisions
//! * An RPDO shorter than its mapping is not processed: no variable
//!   changes and an emergency 0x8210 is sent. A longer one is accepted and
//!   the surplus bytes are ignored (CiA 301 permits both reactions to a
//!   longer PDO; ignoring keeps producers with padded frames working).
//! * An RPDO's mapped values reach their variables all or none: every
//!   value is converted and range-checked before the first one is stored.
//!   A value outside an object's range makes the whole PDO be dropped.
//! * Event-driven TPDOs (254/255) are sent on an application event
//!   (`CcmSignalVar`, `CcmSignalStaticPdo`, a changed value found by
//!   `CcmSignalCheckVar`, and with `CCM_USE_PDO_CHECK_VAR` a changed value
//!   found in any cycle) or when the event timer runs out; never more
//!   often than the inhibit time allows. The event timer starts when the
//!   node enters OPERATIONAL and restarts with every transmission.
//! * A synchronous TPDO is discarded when the SYNC window (0x1007) has
//!   passed before it could be sent; an RPDO of a synchronous type that
//!   arrives after the window is discarded (CiA 301 §7.5.2.7).
//! * Remote requests are answered for valid TPDOs whose COB-ID has bit 30
//!   clear: type 252 with the data sampled at the last SYNC, every other
//!   type with data sampled when the request is handled.
//! * The RPDO event timer (sub 5) is deadline monitoring (CiA 301 §7.5.2.35):
//!   armed by a reception, it sends emergency 0x8250 once when the next
//!   RPDO does not arrive in time.
//! * A COB-ID default of exactly the predefined connection set base
//!   (0x180/0x280/0x380/0x480 for TPDO 1–4, 0x200/0x300/0x400/0x500 for
//!   RPDO 1–4) gets the node-ID added after reset communication, as the
//!   EMCY producer does with 0x80.
//! * The SYNC consumer is always active with the COB-ID of 0x1005 (0x80
//!   when the dictionary has no 0x1005). With bit 30 set this node is the
//!   SYNC producer ([`crate::sync`]); the stack passes each SYNC it sends
//!   to this module, which treats it like a received one.
//! * The SYNC counter byte (DLC 1) is accepted and not evaluated: the
//!   parameter objects end at sub 5, so there is no SYNC start value;
//!   cyclic types count SYNCs from entering OPERATIONAL. Frames on the SYNC
//!   COB-ID with DLC above 1 are not SYNC messages and are ignored.
//! * A TPDO the driver refuses stays pending when it is event-driven and is
//!   retried in the next cycle; a synchronous or remote transmission is
//!   bound to its trigger and is not repeated.
//! * `CcmEnterCriticalSectionPdoProcess` … `Leave`: in between, no RPDO data
//!   reach variables (the latest frame per RPDO is kept and applied in the
//!   first cycle after the section) and no TPDO is sampled; timers keep
//!   running, so due TPDOs go out right after the section.
//! * The application's attachments (callback wish, static data block of
//!   `CcmDefineStaticPdoTab`) survive NMT resets; the dictionary values are
//!   restored to their defaults as CiA 301 requires.

pub mod decl;
pub mod mapping;
mod param;
#[cfg(test)]
mod tests;
mod watch;

pub use param::{PdoParam, StaticPdoParam};
use watch::{NoWatch, Watch, Watching};

use core::sync::atomic::{AtomicU8, Ordering};

use crate::config::{PDO_MAX_RXPDO_IN_OBD, PDO_MAX_TXPDO_IN_OBD};
use crate::emcy::{self, EmcyProducer};
use crate::error::{CopKernel, CopResult, OdError};
use crate::event::{ActionQueue, Event, NmtState};
use crate::od::{ByteOrder, Object, ObjectDictionary, Staged, Storage, value};
use crate::port::{CanId, CanPort, Priority, RxFrame, Ticks};
use crate::wire::emcy::Emergency;
use crate::wire::pdo::{
    self as wire, COB_INVALID, MapEntry, PdoCobId, SYNC_DEFAULT_COB_ID, bytes_for_bits, tx_type,
};

// The mapping switches come from the build configuration (copcfg.h through
// `COP_CONFIG_DIR`, else the Cargo features `pdo-bit-mapping` and
// `pdo-granularity-64`); re-exported here where the PDO code uses them.
pub use crate::config::{
    PDO_GRANULARITY, PDO_MAX_MAPPENTRIES, PDO_USE_BIT_MAPPING, PDO_USE_DUMMY_MAPPING,
};

/// First RPDO communication parameter.
pub const RPDO_COMMU_BASE: u16 = 0x1400;
/// First RPDO mapping parameter.
pub const RPDO_MAPP_BASE: u16 = 0x1600;
/// First TPDO communication parameter.
pub const TPDO_COMMU_BASE: u16 = 0x1800;
/// First TPDO mapping parameter.
pub const TPDO_MAPP_BASE: u16 = 0x1A00;
/// COB-ID SYNC.
pub const SYNC_COB_ID_INDEX: u16 = 0x1005;
/// Communication cycle period (µs).
pub const SYNC_CYCLE_INDEX: u16 = 0x1006;
/// Synchronous window length (µs).
pub const SYNC_WINDOW_INDEX: u16 = 0x1007;

/// Emergency "PDO not processed due to length error" (CiA 301 table 21).
pub const EMCY_PDO_LENGTH: u16 = 0x8210;
/// Emergency "RPDO timeout" (CiA 301 table 21).
pub const EMCY_RPDO_TIMEOUT: u16 = 0x8250;

/// True for the indices this module checks and follows: 0x1005–0x1007 and
/// the PDO parameters 0x1400–0x1BFF.
pub const fn handles(index: u16) -> bool {
    matches!(index, 0x1005..=0x1007 | 0x1400..=0x1BFF)
}

/// Direction of a PDO.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// Receive PDO (consumer), 0x1400+ / 0x1600+.
    Rx,
    /// Transmit PDO (producer), 0x1800+ / 0x1A00+.
    Tx,
}

/// Which parameter object of a PDO an index is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Communication parameter.
    Commu,
    /// Mapping parameter.
    Mapp,
}

/// A PDO parameter index taken apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PdoIndex {
    /// Direction.
    pub dir: Direction,
    /// Communication or mapping object.
    pub role: Role,
    /// PDO number counted from 0 (0x1400 is RPDO 0).
    pub number: u16,
}

impl PdoIndex {
    /// Decodes an index of 0x1400–0x1BFF.
    pub const fn of(index: u16) -> Option<PdoIndex> {
        let (dir, role, base) = match index {
            0x1400..=0x15FF => (Direction::Rx, Role::Commu, RPDO_COMMU_BASE),
            0x1600..=0x17FF => (Direction::Rx, Role::Mapp, RPDO_MAPP_BASE),
            0x1800..=0x19FF => (Direction::Tx, Role::Commu, TPDO_COMMU_BASE),
            0x1A00..=0x1BFF => (Direction::Tx, Role::Mapp, TPDO_MAPP_BASE),
            _ => return None,
        };
        Some(PdoIndex {
            dir,
            role,
            number: index - base,
        })
    }

    /// The communication parameter index.
    pub const fn commu(self) -> u16 {
        self.number
            + match self.dir {
                Direction::Rx => RPDO_COMMU_BASE,
                Direction::Tx => TPDO_COMMU_BASE,
            }
    }

    /// The mapping parameter index.
    pub const fn mapp(self) -> u16 {
        self.number
            + match self.dir {
                Direction::Rx => RPDO_MAPP_BASE,
                Direction::Tx => TPDO_MAPP_BASE,
            }
    }
}

/// The payload of one PDO.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
struct Payload {
    data: [u8; 8],
    len: u8,
}

impl Payload {
    fn from_frame(f: &crate::port::CanFrame) -> Payload {
        Payload {
            data: f.data,
            len: f.len.min(8),
        }
    }

    fn bytes(&self) -> &[u8] {
        self.data.get(..usize::from(self.len)).unwrap_or(&self.data)
    }
}

/// A PDO's parameters as last read from the dictionary.
#[derive(Clone, Copy, Debug)]
struct Config {
    /// The communication object exists.
    present: bool,
    /// Raw COB-ID value (sub 1).
    cob_raw: u32,
    /// The identifier when the PDO is valid.
    cob: Option<CanId>,
    rtr_allowed: bool,
    tx_type: u8,
    /// Inhibit time; its unit (100 µs) is the tick.
    inhibit_ticks: u32,
    event_ms: u16,
    count: usize,
    entries: [u32; PDO_MAX_MAPPENTRIES],
    total_bits: u16,
    /// The mapping object exists and its entries are acceptable.
    mapping_ok: bool,
}

impl Config {
    const fn new() -> Config {
        Config {
            present: false,
            cob_raw: COB_INVALID,
            cob: None,
            rtr_allowed: false,
            tx_type: tx_type::EVENT_PROFILE,
            inhibit_ticks: 0,
            event_ms: 0,
            count: 0,
            entries: [0; PDO_MAX_MAPPENTRIES],
            total_bits: 0,
            mapping_ok: false,
        }
    }
}

/// One PDO: configuration, application attachments and run-time state;
/// `W` is its change watch ([`TxChannel`], [`RxChannel`]).
/// `pub(crate)` so that the dynamic OD can lay channels out in its pool
/// ([`Pdo::attach_pooled`]).
#[derive(Clone, Debug)]
pub(crate) struct Channel<W> {
    cfg: Config,
    /// `CcmDefineStaticPdoTab`: the payload is this byte block, not a
    /// mapping.
    static_data: Option<&'static [AtomicU8]>,
    /// The application wants `Event::Pdo` for this PDO.
    notify: bool,
    subscribed: Option<CanId>,
    // TPDO state.
    last_tx: Option<Ticks>,
    event_deadline: Option<Ticks>,
    event_pending: bool,
    sync_count: u8,
    sync_due: bool,
    rtr_pending: bool,
    sampled: Option<Payload>,
    last_sent: Option<Payload>,
    /// `CCM_USE_PDO_CHECK_VAR`: the resolved mapping and its bytes (a
    /// TPDO's; an RPDO has none).
    watch: W,
    // RPDO state.
    sync_buffer: Option<Payload>,
    pending: Option<Payload>,
    deadline: Option<Ticks>,
}

/// The channel of an RPDO: without change watch.
pub(crate) type RxChannel = Channel<NoWatch>;
/// The channel of a TPDO: with the change watch of `CCM_USE_PDO_CHECK_VAR`.
pub(crate) type TxChannel = Channel<Watch>;

impl<W: Watching> Channel<W> {
    /// A channel without configuration.
    pub(crate) const fn new() -> Channel<W> {
        Channel {
            cfg: Config::new(),
            static_data: None,
            notify: false,
            subscribed: None,
            last_tx: None,
            event_deadline: None,
            event_pending: false,
            sync_count: 0,
            sync_due: false,
            rtr_pending: false,
            sampled: None,
            last_sent: None,
            watch: W::NEW,
            sync_buffer: None,
            pending: None,
            deadline: None,
        }
    }

    /// Forgets everything that happened at run time (state changes,
    /// reconfiguration); the configuration and attachments stay.
    fn reset_runtime(&mut self) {
        self.last_tx = None;
        self.event_deadline = None;
        self.event_pending = false;
        self.sync_count = 0;
        self.sync_due = false;
        self.rtr_pending = false;
        self.sampled = None;
        self.last_sent = None;
        self.watch.forget();
        self.sync_buffer = None;
        self.pending = None;
        self.deadline = None;
    }

    /// Starts the timers of a TPDO (entering OPERATIONAL, becoming valid).
    fn start(&mut self, now: Ticks) {
        self.reset_runtime();
        if tx_type::is_event(self.cfg.tx_type) && self.cfg.event_ms > 0 {
            self.event_deadline = Some(now.plus_ms(u32::from(self.cfg.event_ms)));
        }
    }

    /// Takes over newly read parameters; the mapping may have changed.
    fn set_cfg(&mut self, cfg: Config) {
        self.cfg = cfg;
        self.watch.forget();
    }

    /// Takes over the parameters after a write to its objects: `cfg` as
    /// read again, `event_time` when the write was to the event time
    /// (communication sub 5). True when the identifiers to receive may have
    /// changed (the COB-ID, or whether remote requests are answered).
    fn after_store(
        &mut self,
        cfg: Config,
        event_time: bool,
        operational: bool,
        now: Ticks,
    ) -> bool {
        let was = self.cfg.cob;
        let was_type = self.cfg.tx_type;
        let was_rtr = self.cfg.rtr_allowed;
        self.set_cfg(cfg);
        let cob_changed = self.cfg.cob != was;
        if self.cfg.cob.is_none() {
            self.reset_runtime();
        } else if (cob_changed || self.cfg.tx_type != was_type) && operational {
            self.start(now);
        } else if event_time && operational {
            // A new event time takes effect from now on.
            self.event_deadline = (tx_type::is_event(self.cfg.tx_type) && self.cfg.event_ms > 0)
                .then(|| now.plus_ms(u32::from(self.cfg.event_ms)));
        }
        cob_changed || self.cfg.rtr_allowed != was_rtr
    }

    /// [`Pdo::attach`] for this channel.
    fn attach(
        &mut self,
        notify: Option<bool>,
        static_data: Option<Option<&'static [AtomicU8]>>,
    ) -> CopResult {
        if let Some(n) = notify {
            self.notify = n;
        }
        if let Some(d) = static_data {
            if d.is_some_and(|d| d.len() > 8) {
                return Err(CopKernel::PdoLengthExceeded);
            }
            self.static_data = d;
            self.watch.forget();
        }
        Ok(())
    }

    /// The PDO can carry data: valid and with a usable payload definition.
    fn usable(&self) -> bool {
        self.cfg.cob.is_some() && (self.static_data.is_some() || self.cfg.mapping_ok)
    }

    /// Payload length in bytes.
    fn len(&self) -> u8 {
        match self.static_data {
            Some(d) => d.len().min(8) as u8,
            None => bytes_for_bits(self.cfg.total_bits),
        }
    }
}

/// The SYNC consumer (0x1005–0x1007).
#[derive(Clone, Copy, Debug)]
struct SyncConsumer {
    cob: Option<CanId>,
    cycle_us: u32,
    window_us: u32,
    last: Option<Ticks>,
    subscribed: Option<CanId>,
}

impl SyncConsumer {
    const fn new() -> SyncConsumer {
        SyncConsumer {
            cob: Some(CanId::std_masked(SYNC_DEFAULT_COB_ID as u16)),
            cycle_us: 0,
            window_us: 0,
            last: None,
            subscribed: None,
        }
    }

    /// True while the synchronous window after the last SYNC is open (or
    /// no window is configured).
    fn window_open(&self, at: Ticks) -> bool {
        if self.window_us == 0 {
            return true;
        }
        match self.last {
            Some(t) => u64::from(at.since(t)) * 100 <= u64::from(self.window_us),
            None => true,
        }
    }
}

/// What the PDO API needs of the stack, borrowed at once
/// ([`crate::ccm::Stack`] hands it out).
pub(crate) struct Parts<'a> {
    /// The dictionary.
    pub od: &'a ObjectDictionary,
    /// The module.
    pub pdo: &'a mut Pdo,
    /// The NMT state.
    pub state: NmtState,
    /// The action queue (PDO events of API calls).
    pub queue: &'a mut ActionQueue,
}

/// Bytes of the state of one PDO of direction `dir`: what a dynamic OD's
/// pool holds per PDO channel it provides (`PDO_MAX_RXPDO_IN_OBD` /
/// `PDO_MAX_TXPDO_IN_OBD` 0). A TPDO's includes its change watch
/// (`CCM_USE_PDO_CHECK_VAR`), an RPDO's does not.
pub const fn channel_size(dir: Direction) -> usize {
    match dir {
        Direction::Rx => core::mem::size_of::<RxChannel>(),
        Direction::Tx => core::mem::size_of::<TxChannel>(),
    }
}

/// `$body` for channel `$n` of direction `$dir` of `$pdo`, taken with
/// `$get` (`get` / `get_mut`) and bound to `$ch`; `None` without that
/// channel. RPDO and TPDO channels are of different types, so each
/// direction is its own arm.
macro_rules! on_channel {
    ($pdo:expr, $dir:expr, $n:expr, $get:ident, |$ch:ident| $body:expr) => {
        match $dir {
            Direction::Rx => $pdo.rx.$get($n).map(|$ch| $body),
            Direction::Tx => $pdo.tx.$get($n).map(|$ch| $body),
        }
    };
}

/// The channels of one direction: the `N` of the build configuration, or
/// those a dynamic OD laid out in its pool for the PDOs its container
/// creates beyond them (then these replace the fixed ones).
#[derive(Debug)]
struct Channels<const N: usize, W: 'static> {
    fixed: [Channel<W>; N],
    pooled: Option<&'static mut [Channel<W>]>,
}

impl<const N: usize, W: Watching + 'static> Channels<N, W> {
    const fn new() -> Self {
        Channels {
            fixed: [const { Channel::new() }; N],
            pooled: None,
        }
    }
}

impl<const N: usize, W: 'static> core::ops::Deref for Channels<N, W> {
    type Target = [Channel<W>];
    fn deref(&self) -> &[Channel<W>] {
        match &self.pooled {
            Some(p) => p,
            None => &self.fixed,
        }
    }
}

impl<const N: usize, W: 'static> core::ops::DerefMut for Channels<N, W> {
    fn deref_mut(&mut self) -> &mut [Channel<W>] {
        match &mut self.pooled {
            Some(p) => p,
            None => &mut self.fixed,
        }
    }
}

/// The PDO module: `PDO_MAX_RXPDO_IN_OBD` RPDOs (0x1400+n) and
/// `PDO_MAX_TXPDO_IN_OBD` TPDOs (0x1800+n), and the SYNC consumer.
/// PDOs of the dictionary beyond these capacities are not served, except
/// those of a dynamic OD whose channels lie in its pool
/// (`Pdo::attach_pooled`).
#[derive(Debug)]
pub struct Pdo {
    rx: Channels<PDO_MAX_RXPDO_IN_OBD, NoWatch>,
    tx: Channels<PDO_MAX_TXPDO_IN_OBD, Watch>,
    sync: SyncConsumer,
    operational: bool,
    lock_depth: u8,
    check_var: bool,
    resubscribe: bool,
    cursor: usize,
    housekeeping_done: bool,
    /// A whole pass of [`Pdo::poll`] found nothing armed or pending (no
    /// RPDO deadline or data, no TPDO of a usable PDO with a timer or a
    /// trigger, no `CcmSignalCheckVar`), and nothing has changed since: the
    /// timer work of a cycle has nothing to do. Every method that changes
    /// the module's state clears it ([`Pdo::wake`]); time alone cannot make
    /// anything due while nothing is armed.
    quiet: bool,
}

impl Default for Pdo {
    fn default() -> Self {
        Self::new()
    }
}

impl Pdo {
    /// A module without configuration.
    pub const fn new() -> Pdo {
        Pdo {
            rx: Channels::new(),
            tx: Channels::new(),
            sync: SyncConsumer::new(),
            operational: false,
            lock_depth: 0,
            check_var: false,
            resubscribe: true,
            cursor: 0,
            housekeeping_done: false,
            quiet: false,
        }
    }

    /// Channels laid out elsewhere (a dynamic OD's pool) replace the fixed
    /// ones of a direction; `None` keeps that direction's. The state of
    /// the fixed channels is copied into the first ones. The caller
    /// reconfigures the module afterwards.
    pub(crate) fn attach_pooled(
        &mut self,
        rx: Option<&'static mut [RxChannel]>,
        tx: Option<&'static mut [TxChannel]>,
    ) {
        self.wake();
        self.cursor = 0;
        if let Some(rx) = rx {
            for (d, s) in rx.iter_mut().zip(self.rx.fixed.iter()) {
                *d = s.clone();
            }
            self.rx.pooled = Some(rx);
        }
        if let Some(tx) = tx {
            for (d, s) in tx.iter_mut().zip(self.tx.fixed.iter()) {
                *d = s.clone();
            }
            self.tx.pooled = Some(tx);
        }
        self.dictionary_changed();
    }

    /// Gives the channels of [`Pdo::attach_pooled`] back: the fixed ones
    /// serve again (the caller reconfigures the module).
    pub(crate) fn detach_pooled(&mut self, port: &mut impl CanPort) {
        self.wake();
        // The identifiers the pooled channels subscribed go with them.
        for ch in self.rx.iter_mut() {
            update_subscription(port, &mut ch.subscribed, None);
        }
        for ch in self.tx.iter_mut() {
            update_subscription(port, &mut ch.subscribed, None);
        }
        self.resubscribe = true;
        self.rx.pooled = None;
        self.tx.pooled = None;
        self.cursor = 0;
        self.dictionary_changed();
    }

    /// Whether channels of a dynamic OD's pool are in use.
    pub fn has_pooled(&self) -> bool {
        self.rx.pooled.is_some() || self.tx.pooled.is_some()
    }

    /// The dictionary was replaced or rebuilt: what the TPDOs' mappings
    /// resolved to for `CCM_USE_PDO_CHECK_VAR` is resolved again.
    pub fn dictionary_changed(&mut self) {
        self.wake();
        for ch in self.tx.iter_mut() {
            ch.watch.forget();
        }
    }

    /// Something may have become due: the next [`Pdo::poll`] looks at
    /// every PDO again.
    #[inline]
    fn wake(&mut self) {
        self.quiet = false;
    }

    /// The parameters of a PDO that has a channel.
    fn config(&self, p: PdoIndex) -> Option<&Config> {
        on_channel!(self, p.dir, usize::from(p.number), get, |c| &c.cfg)
    }

    /// The communication index of a PDO this module serves; `None` for
    /// anything else (kCopPdoNotExist).
    fn served(&self, commu_index: u16) -> Option<PdoIndex> {
        let p = PdoIndex::of(commu_index)?;
        if p.role != Role::Commu {
            return None;
        }
        self.config(p).filter(|c| c.present).map(|_| p)
    }

    /// The COB-ID of a served PDO when it is valid.
    pub fn cob_id(&self, commu_index: u16) -> Option<CanId> {
        self.served(commu_index)
            .and_then(|p| self.config(p))
            .and_then(|c| c.cob)
    }

    /// Identifier and frame length of PDO number `n` (0-based, in the
    /// order 0x1400+n / 0x1800+n) when it is served and valid
    /// (`CcmCobGetParam`).
    pub fn cob_entry(&self, dir: Direction, n: usize) -> Option<(CanId, u8)> {
        let (cfg, len) = on_channel!(self, dir, n, get, |c| (&c.cfg, c.len()))?;
        if !cfg.present {
            return None;
        }
        cfg.cob.map(|id| (id, len))
    }

    /// The SYNC COB-ID in use.
    pub fn sync_cob_id(&self) -> Option<CanId> {
        self.sync.cob
    }

    /// The synchronous window length in µs.
    pub fn sync_window_us(&self) -> u32 {
        self.sync.window_us
    }

    /// The communication cycle period (0x1006) in µs.
    pub fn sync_cycle_us(&self) -> u32 {
        self.sync.cycle_us
    }

    /// Depth of `CcmEnterCriticalSectionPdoProcess` nesting.
    pub fn lock_depth(&self) -> u8 {
        self.lock_depth
    }

    // ----------------------------------------------------------------
    // Configuration
    // ----------------------------------------------------------------

    /// Takes over the configuration after reset communication: reads every
    /// PDO and the SYNC objects, adds the node-ID to predefined connection
    /// set defaults and subscribes the identifiers.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, node: u8, port: &mut impl CanPort) {
        self.wake();
        for n in 0..self.rx.len() {
            predefined_node_id(od, Direction::Rx, n, node);
        }
        for n in 0..self.tx.len() {
            predefined_node_id(od, Direction::Tx, n, node);
        }
        for (n, ch) in self.rx.iter_mut().enumerate() {
            ch.set_cfg(load(od, Direction::Rx, n));
            ch.reset_runtime();
        }
        for (n, ch) in self.tx.iter_mut().enumerate() {
            ch.set_cfg(load(od, Direction::Tx, n));
            ch.reset_runtime();
        }
        self.load_sync(od);
        self.operational = false;
        self.subscribe(port);
    }

    fn load_sync(&mut self, od: &ObjectDictionary) {
        let cob = od
            .read_uint(SYNC_COB_ID_INDEX, 0)
            .map_or(SYNC_DEFAULT_COB_ID, |v| v as u32);
        self.sync.cob = wire::check_identifier(cob & !COB_INVALID, crate::config::CDRV_CAN20B)
            .ok()
            .map(|()| CanId::from_cob_id(cob));
        self.sync.cycle_us = od.read_uint(SYNC_CYCLE_INDEX, 0).map_or(0, |v| v as u32);
        self.sync.window_us = od.read_uint(SYNC_WINDOW_INDEX, 0).map_or(0, |v| v as u32);
    }

    /// Sets the SYNC consumer directly (`CcmConfigSyncConsumer` on a
    /// dictionary without 0x1005/0x1007).
    pub fn set_sync(&mut self, cob: u32, window_us: u32) -> CopResult {
        self.wake();
        wire::check_identifier(cob & !COB_INVALID, crate::config::CDRV_CAN20B)
            .map_err(|_| CopKernel::InvalidParam)?;
        if cob & wire::COB_NO_RTR != 0 {
            return Err(CopKernel::InvalidParam);
        }
        self.sync.cob = Some(CanId::from_cob_id(cob));
        self.sync.window_us = window_us;
        self.resubscribe = true;
        Ok(())
    }

    /// Re-reads the SYNC objects (`CcmInitSyncConsumer`).
    pub fn reload_sync(&mut self, od: &ObjectDictionary) {
        self.wake();
        self.load_sync(od);
        self.resubscribe = true;
    }

    /// Module hook: may refuse a write to 0x1005–0x1007 or 0x1400–0x1BFF.
    pub fn check_write(
        &self,
        od: &ObjectDictionary,
        obj: &Object,
        value: &Staged,
    ) -> Result<(), OdError> {
        mapping::check_write(od, obj, value, mapping::RULES)
    }

    /// Module hook: a write to one of this module's objects happened.
    pub fn after_store(&mut self, od: &ObjectDictionary, obj: &Object, now: Ticks) {
        self.wake();
        let index = obj.index();
        if matches!(index, 0x1005..=0x1007) {
            self.load_sync(od);
            self.resubscribe = true;
            return;
        }
        let Some(p) = PdoIndex::of(index) else {
            return;
        };
        let operational = self.operational;
        let n = usize::from(p.number);
        let event_time = p.role == Role::Commu && obj.sub() == 5;
        let ids_changed = on_channel!(self, p.dir, n, get_mut, |ch| {
            ch.after_store(load(od, p.dir, n), event_time, operational, now)
        });
        if ids_changed == Some(true) {
            self.resubscribe = true;
        }
    }

    /// The PDO of a communication index when the dictionary has it and the
    /// tables have room for it. Unlike the served PDOs this does not need a
    /// reconfiguration first: applications define their PDOs in the NMT
    /// callback at kNmtEvResetCommunication, before the module takes over
    /// the configuration.
    pub fn covers(&self, od: &ObjectDictionary, commu_index: u16) -> Option<PdoIndex> {
        let p = PdoIndex::of(commu_index).filter(|p| p.role == Role::Commu)?;
        self.config(p)?;
        od.find_entry(commu_index).map(|_| p)
    }

    /// Attaches (or with `None` detaches) the application callback flag
    /// and the static data block of a PDO. `kCopPdoNotExist` for a PDO
    /// the dictionary or the tables do not have.
    pub fn attach(
        &mut self,
        od: &ObjectDictionary,
        commu_index: u16,
        notify: Option<bool>,
        static_data: Option<Option<&'static [AtomicU8]>>,
    ) -> CopResult {
        self.wake();
        let p = self.covers(od, commu_index).ok_or(CopKernel::PdoNotExist)?;
        on_channel!(self, p.dir, usize::from(p.number), get_mut, |ch| {
            ch.attach(notify, static_data)
        })
        .unwrap_or(Err(CopKernel::PdoNotExist))
    }

    /// Reacts to an NMT state change: PDOs run in OPERATIONAL only.
    pub fn on_state(&mut self, state: NmtState, now: Ticks) {
        self.wake();
        let operational = state == NmtState::Operational;
        if operational && !self.operational {
            for ch in self.tx.iter_mut() {
                ch.start(now);
            }
            for ch in self.rx.iter_mut() {
                ch.reset_runtime();
            }
            self.sync.last = None;
        } else if !operational {
            for ch in self.tx.iter_mut() {
                ch.reset_runtime();
            }
            for ch in self.rx.iter_mut() {
                ch.reset_runtime();
            }
        }
        self.operational = operational;
    }

    /// Tells the driver which identifiers to receive: SYNC, valid RPDOs,
    /// valid TPDOs that answer remote requests.
    fn subscribe(&mut self, port: &mut impl CanPort) {
        self.resubscribe = false;
        update_subscription(port, &mut self.sync.subscribed, self.sync.cob);
        for ch in self.rx.iter_mut() {
            update_subscription(port, &mut ch.subscribed, ch.cfg.cob);
        }
        for ch in self.tx.iter_mut() {
            let want = ch.cfg.cob.filter(|_| ch.cfg.rtr_allowed);
            update_subscription(port, &mut ch.subscribed, want);
        }
    }

    // ----------------------------------------------------------------
    // Application signals
    // ----------------------------------------------------------------

    /// `CcmSignalStaticPdo`: an application event for one TPDO. Event-driven
    /// TPDOs are sent in the next cycle (inhibit time permitting), type 0
    /// with the next SYNC; other types ignore events.
    pub fn signal(&mut self, commu_index: u16) -> CopResult {
        self.wake();
        let p = self
            .served(commu_index)
            .filter(|p| p.dir == Direction::Tx)
            .ok_or(CopKernel::PdoNotExist)?;
        if let Some(ch) = self.tx.get_mut(usize::from(p.number)) {
            ch.event_pending = true;
        }
        Ok(())
    }

    /// `CcmSignalVar`: an application event for every TPDO that maps the
    /// variable `is_var` accepts. `kCopPdoVarNotFound` when no valid TPDO
    /// maps it.
    pub fn signal_where(
        &mut self,
        od: &ObjectDictionary,
        mut is_var: impl FnMut(&Object) -> bool,
    ) -> CopResult {
        self.wake();
        let mut found = false;
        for ch in self.tx.iter_mut() {
            if !ch.usable() || ch.static_data.is_some() {
                continue;
            }
            let maps = ch
                .cfg
                .entries
                .iter()
                .take(ch.cfg.count)
                .filter_map(|raw| {
                    let e = MapEntry::decode(*raw);
                    od.find(e.index, e.sub).ok()
                })
                .any(|obj| is_var(&obj));
            if maps {
                ch.event_pending = true;
                found = true;
            }
        }
        if found {
            Ok(())
        } else {
            Err(CopKernel::PdoVarNotFound)
        }
    }

    /// `CcmSignalCheckVar`: in the next cycle every event-driven or type 0
    /// TPDO whose data differ from what it sent last is signalled.
    pub fn signal_check_var(&mut self) {
        self.wake();
        self.check_var = true;
    }

    /// `CcmEnterCriticalSectionPdoProcess`: until the matching leave, the
    /// stack neither writes RPDO data into variables nor samples TPDO data
    /// (received RPDOs are kept, the latest per PDO, and applied afterwards;
    /// due TPDOs wait).
    pub fn enter_critical(&mut self) {
        self.wake();
        self.lock_depth = self.lock_depth.saturating_add(1);
    }

    /// `CcmLeaveCriticalSectionPdoProcess`.
    pub fn leave_critical(&mut self) {
        self.wake();
        self.lock_depth = self.lock_depth.saturating_sub(1);
    }

    /// `CcmSendPdo`: samples and sends a TPDO now, whatever its
    /// transmission type, inhibit time or event timer say; the inhibit time
    /// and event timer restart from this transmission.
    ///
    /// `kCopPdoNotExist` when `commu_index` is not a TPDO of the
    /// dictionary, `kCopNmtStateError` outside OPERATIONAL,
    /// `kCopPdoErrorSend` for an invalid PDO (COB-ID bit 31),
    /// `kCopPdoErrorPdoEncode` when a mapped object cannot be read, or the
    /// driver's code.
    pub fn send_now(
        &mut self,
        od: &ObjectDictionary,
        state: NmtState,
        port: &mut impl CanPort,
        commu_index: u16,
        now: Ticks,
        q: &mut ActionQueue,
    ) -> CopResult {
        self.wake();
        let p = self
            .served(commu_index)
            .filter(|p| p.dir == Direction::Tx)
            .ok_or(CopKernel::PdoNotExist)?;
        if state != NmtState::Operational {
            return Err(CopKernel::NmtStateError);
        }
        let ch = self
            .tx
            .get_mut(usize::from(p.number))
            .ok_or(CopKernel::PdoNotExist)?;
        if !ch.usable() {
            return Err(CopKernel::PdoErrorSend);
        }
        let payload = sample(od, ch)?;
        transmit(ch, port, payload, now)?;
        if ch.notify {
            q.emit(Event::Pdo(commu_index));
        }
        Ok(())
    }

    // ----------------------------------------------------------------
    // Received frames
    // ----------------------------------------------------------------

    /// Offers a received frame; `true` when it was a SYNC, an RPDO or a
    /// remote request for a TPDO of this node.
    #[allow(clippy::too_many_arguments)]
    pub fn on_frame(
        &mut self,
        od: &ObjectDictionary,
        state: NmtState,
        rx: &RxFrame,
        port: &mut impl CanPort,
        now: Ticks,
        q: &mut ActionQueue,
        emcy: &mut EmcyProducer,
    ) -> bool {
        // A taken frame wakes the module's timer pass (see `quiet`).
        let f = &rx.frame;
        if Some(f.id) == self.sync.cob && !f.rtr {
            // CiA 301 §7.2.5: DLC 0, or 1 with the counter; other lengths
            // are not SYNC messages and are ignored.
            if wire::decode_sync(f).is_some() && state == NmtState::Operational {
                self.on_sync(rx.time);
            }
            self.wake();
            return true;
        }
        if f.rtr {
            let Some(ch) = self
                .tx
                .iter_mut()
                .find(|c| c.cfg.cob == Some(f.id) && c.cfg.rtr_allowed)
            else {
                return false;
            };
            if state == NmtState::Operational && ch.usable() {
                ch.rtr_pending = true;
            }
            self.wake();
            return true;
        }
        let Some(n) = self.rx.iter().position(|c| c.cfg.cob == Some(f.id)) else {
            return false;
        };
        if state == NmtState::Operational {
            self.on_rpdo(n, od, rx, port, now, q, emcy);
        }
        self.wake();
        true
    }

    #[allow(clippy::too_many_arguments)]
    fn on_rpdo(
        &mut self,
        n: usize,
        od: &ObjectDictionary,
        rx: &RxFrame,
        port: &mut impl CanPort,
        now: Ticks,
        q: &mut ActionQueue,
        emcy: &mut EmcyProducer,
    ) {
        let window_open = self.sync.window_open(rx.time);
        let locked = self.lock_depth > 0;
        let Some(ch) = self.rx.get_mut(n) else {
            return;
        };
        if !ch.usable() {
            return;
        }
        let commu = RPDO_COMMU_BASE.wrapping_add(n as u16);
        if rx.frame.len < ch.len() {
            // CiA 301 §7.2.2.2: not processed; EMCY 0x8210.
            send_emcy(od, port, now, emcy, EMCY_PDO_LENGTH, commu, rx.frame.len);
            return;
        }
        let payload = Payload::from_frame(&rx.frame);
        if ch.cfg.event_ms > 0 {
            ch.deadline = Some(rx.time.plus_ms(u32::from(ch.cfg.event_ms)));
        }
        if tx_type::is_sync(ch.cfg.tx_type) {
            if window_open {
                ch.sync_buffer = Some(payload);
            }
            return;
        }
        if locked {
            ch.pending = Some(payload);
            return;
        }
        if apply(od, ch, &payload).is_ok() && ch.notify {
            q.emit(Event::Pdo(commu));
        }
    }

    /// A SYNC arrived: synchronous RPDO data become due, synchronous TPDOs
    /// count it. The work that may send frames or queue events is done in
    /// [`Pdo::poll`] so that one received frame never queues more than one
    /// event.
    pub(crate) fn on_sync(&mut self, at: Ticks) {
        self.wake();
        self.sync.last = Some(at);
        for ch in self.rx.iter_mut() {
            if tx_type::is_sync(ch.cfg.tx_type) {
                if let Some(b) = ch.sync_buffer.take() {
                    ch.pending = Some(b);
                }
            }
        }
        for ch in self.tx.iter_mut().filter(|c| c.usable()) {
            match ch.cfg.tx_type {
                tx_type::SYNC_ACYCLIC if ch.event_pending => {
                    ch.event_pending = false;
                    ch.sync_due = true;
                }
                t @ 1..=tx_type::SYNC_CYCLIC_MAX => {
                    ch.sync_count = ch.sync_count.saturating_add(1);
                    if ch.sync_count >= t {
                        ch.sync_count = 0;
                        ch.sync_due = true;
                    }
                }
                tx_type::SYNC_RTR => ch.sync_due = true,
                _ => {}
            }
        }
    }

    // ----------------------------------------------------------------
    // Timers
    // ----------------------------------------------------------------

    /// Starts a processing cycle (resets the resumable cursor of
    /// [`Pdo::poll`]).
    pub fn begin_cycle(&mut self) {
        self.cursor = 0;
        self.housekeeping_done = false;
    }

    /// Timer work of one cycle; resumable like the SRDO checks: returns
    /// `true` when the cycle's work is complete, `false` after queueing an
    /// event (call again once it was handled). At most one event is queued
    /// per call.
    #[inline]
    pub fn poll(
        &mut self,
        od: &ObjectDictionary,
        state: NmtState,
        port: &mut impl CanPort,
        now: Ticks,
        q: &mut ActionQueue,
        emcy: &mut EmcyProducer,
    ) -> bool {
        if !self.housekeeping_done {
            self.housekeeping_done = true;
            if self.resubscribe || (state == NmtState::Operational && !self.quiet) {
                self.housekeeping(od, state, port, now, emcy);
            }
            // `CCM_USE_PDO_CHECK_VAR`: the comparison runs in every cycle
            // (the application may change mapped data without telling, as
            // through a process image), also when nothing else is armed.
            if state == NmtState::Operational
                && self.lock_depth == 0
                && (self.check_var || crate::config::CCM_USE_PDO_CHECK_VAR)
            {
                let signalled = core::mem::take(&mut self.check_var);
                if self.check_vars(od, signalled) {
                    self.quiet = false;
                }
            }
        }
        if state != NmtState::Operational || self.lock_depth > 0 || self.quiet {
            return true;
        }
        self.poll_channels(od, port, now, q)
    }

    /// The first part of [`Pdo::poll`] in a cycle, before the comparison:
    /// identifiers changed, RPDO deadlines, event timers.
    #[inline(never)]
    fn housekeeping(
        &mut self,
        od: &ObjectDictionary,
        state: NmtState,
        port: &mut impl CanPort,
        now: Ticks,
        emcy: &mut EmcyProducer,
    ) {
        if self.resubscribe {
            self.subscribe(port);
        }
        if state == NmtState::Operational && !self.quiet {
            self.check_deadlines(od, port, now, emcy);
            self.event_timers(now);
        }
    }

    /// The channels' work of [`Pdo::poll`], from where the last call
    /// stopped.
    #[inline(never)]
    fn poll_channels(
        &mut self,
        od: &ObjectDictionary,
        port: &mut impl CanPort,
        now: Ticks,
        q: &mut ActionQueue,
    ) -> bool {
        let total = self.rx.len() + self.tx.len();
        while self.cursor < total {
            let i = self.cursor;
            self.cursor += 1;
            let emitted = match i.checked_sub(self.rx.len()) {
                None => self.poll_rpdo(i, od, q),
                Some(t) => self.poll_tpdo(t, od, port, now, q),
            };
            if emitted {
                return false;
            }
        }
        self.quiet = self.nothing_armed();
        true
    }

    /// True when no PDO has anything that can become due by itself: no
    /// RPDO deadline or data waiting, no usable TPDO with an event timer or
    /// a pending trigger, no `CcmSignalCheckVar` waiting.
    fn nothing_armed(&self) -> bool {
        !self.check_var
            && self
                .rx
                .iter()
                .all(|c| c.deadline.is_none() && c.pending.is_none())
            && self.tx.iter().all(|c| {
                !c.usable()
                    || (c.event_deadline.is_none()
                        && !c.event_pending
                        && !c.sync_due
                        && !c.rtr_pending)
            })
    }

    fn check_deadlines(
        &mut self,
        od: &ObjectDictionary,
        port: &mut impl CanPort,
        now: Ticks,
        emcy: &mut EmcyProducer,
    ) {
        for n in 0..self.rx.len() {
            let expired = self
                .rx
                .get(n)
                .and_then(|c| c.deadline)
                .is_some_and(|d| now.is_after(d));
            if expired {
                if let Some(ch) = self.rx.get_mut(n) {
                    ch.deadline = None;
                }
                let commu = RPDO_COMMU_BASE.wrapping_add(n as u16);
                send_emcy(od, port, now, emcy, EMCY_RPDO_TIMEOUT, commu, 0);
            }
        }
    }

    fn event_timers(&mut self, now: Ticks) {
        for ch in self.tx.iter_mut().filter(|c| c.usable()) {
            if let Some(d) = ch.event_deadline {
                if !d.is_after(now) {
                    ch.event_pending = true;
                    ch.event_deadline = None;
                }
            }
        }
    }

    /// Marks the event-driven and acyclic TPDOs whose data differ from
    /// what they sent last; true when one was marked. A TPDO that has not
    /// sent since entering OPERATIONAL is marked on `CcmSignalCheckVar`
    /// (`signalled`); the unsignalled comparison of every cycle takes its
    /// current data as the reference instead, so that it is sent when they
    /// change, not merely because the node started.
    fn check_vars(&mut self, od: &ObjectDictionary, signalled: bool) -> bool {
        let mut marked = false;
        for ch in self.tx.iter_mut() {
            // The cheapest test first: a settled watch whose bytes are
            // unchanged has nothing to compare, whatever else holds.
            if !ch.watch.quiet() {
                marked |= compare_with_last_sent(od, ch, signalled);
            }
        }
        marked
    }

    fn poll_rpdo(&mut self, n: usize, od: &ObjectDictionary, q: &mut ActionQueue) -> bool {
        let Some(ch) = self.rx.get_mut(n) else {
            return false;
        };
        let Some(p) = ch.pending.take() else {
            return false;
        };
        if apply(od, ch, &p).is_ok() && ch.notify {
            return q.emit(Event::Pdo(RPDO_COMMU_BASE.wrapping_add(n as u16)));
        }
        false
    }

    fn poll_tpdo(
        &mut self,
        n: usize,
        od: &ObjectDictionary,
        port: &mut impl CanPort,
        now: Ticks,
        q: &mut ActionQueue,
    ) -> bool {
        let sync_window_open = self.sync.window_open(now);
        let Some(ch) = self.tx.get_mut(n) else {
            return false;
        };
        if !ch.usable() {
            return false;
        }
        let mut sent = false;
        if ch.sync_due {
            ch.sync_due = false;
            if sync_window_open {
                if let Ok(p) = sample(od, ch) {
                    if ch.cfg.tx_type == tx_type::SYNC_RTR {
                        ch.sampled = Some(p);
                    } else {
                        sent |= transmit(ch, port, p, now).is_ok();
                    }
                }
            }
        }
        if ch.rtr_pending {
            ch.rtr_pending = false;
            let p = match ch.sampled {
                Some(p) if ch.cfg.tx_type == tx_type::SYNC_RTR => Ok(p),
                _ => sample(od, ch),
            };
            if let Ok(p) = p {
                sent |= transmit(ch, port, p, now).is_ok();
            }
        }
        if tx_type::is_event(ch.cfg.tx_type) && ch.event_pending && !inhibited(ch, now) {
            // A refused transmission leaves the event pending: it is retried
            // in the next cycle.
            if let Ok(p) = sample(od, ch) {
                sent |= transmit(ch, port, p, now).is_ok();
            }
        }
        if sent && ch.notify {
            return q.emit(Event::Pdo(TPDO_COMMU_BASE.wrapping_add(n as u16)));
        }
        false
    }
}

// --------------------------------------------------------------------
// Helpers without module state
// --------------------------------------------------------------------

fn update_subscription(port: &mut impl CanPort, slot: &mut Option<CanId>, want: Option<CanId>) {
    if *slot == want {
        return;
    }
    if let Some(old) = *slot {
        let _ = port.unsubscribe(old);
    }
    if let Some(new) = want {
        let _ = port.subscribe(new, Priority::Low);
    }
    *slot = want;
}

/// Reads one PDO's parameters from the dictionary.
fn load(od: &ObjectDictionary, dir: Direction, n: usize) -> Config {
    let mut cfg = Config::new();
    let Ok(number) = u16::try_from(n) else {
        return cfg;
    };
    let p = PdoIndex {
        dir,
        role: Role::Commu,
        number,
    };
    if od.find_entry(p.commu()).is_none() {
        return cfg;
    }
    cfg.present = true;
    cfg.cob_raw = mapping::cob_id_of(od, p.commu());
    if let Ok(c) = PdoCobId::decode(cfg.cob_raw, crate::config::CDRV_CAN20B) {
        cfg.cob = c.valid.then_some(c.id);
        cfg.rtr_allowed = c.rtr_allowed && dir == Direction::Tx;
    }
    cfg.tx_type = od
        .read_uint(p.commu(), 2)
        .map_or(tx_type::EVENT_PROFILE, |v| v as u8);
    cfg.inhibit_ticks = od.read_uint(p.commu(), 3).map_or(0, |v| v as u32);
    cfg.event_ms = od.read_uint(p.commu(), 5).map_or(0, |v| v as u16);
    if od.find_entry(p.mapp()).is_some() {
        let count = od.read_uint(p.mapp(), 0).unwrap_or(0) as usize;
        if count <= PDO_MAX_MAPPENTRIES
            && mapping::read_entries(od, p.mapp(), count, &mut cfg.entries).is_some()
        {
            cfg.count = count;
            if let Ok(bits) = mapping::check_mapping(
                od,
                dir,
                cfg.entries.get(..count).unwrap_or(&[]),
                mapping::RULES,
            ) {
                cfg.total_bits = bits;
                cfg.mapping_ok = true;
            }
        }
    }
    cfg
}

/// Adds the node-ID to a COB-ID default that is exactly the predefined
/// connection set base of PDO 1–4 (CiA 301 §7.3.4, predefined connection
/// set). Only a value still equal to its default is changed: what the
/// application or a configuration tool wrote stays as written.
fn predefined_node_id(od: &ObjectDictionary, dir: Direction, n: usize, node: u8) {
    if n >= 4 {
        return;
    }
    let base = match dir {
        Direction::Rx => 0x200 + 0x100 * n as u32,
        Direction::Tx => 0x180 + 0x100 * n as u32,
    };
    let p = PdoIndex {
        dir,
        role: Role::Commu,
        number: n as u16,
    };
    let Ok(obj) = od.find(p.commu(), 1) else {
        return;
    };
    let Some(default) = obj.desc().default_value().and_then(value::native_to_u64) else {
        return;
    };
    let Ok(current) = od.read_uint(p.commu(), 1) else {
        return;
    };
    let flags = wire::COB_INVALID | wire::COB_NO_RTR;
    if current == default && (current as u32) & !flags == base {
        let _ = od.poke_uint(p.commu(), 1, current + u64::from(node));
    }
}

/// Samples a TPDO's payload from its mapped objects (or static block).
fn sample(od: &ObjectDictionary, ch: &TxChannel) -> Result<Payload, CopKernel> {
    let mut p = Payload::default();
    if let Some(d) = ch.static_data {
        for (o, b) in p.data.iter_mut().zip(d.iter()) {
            *o = b.load(Ordering::Relaxed);
        }
        p.len = ch.len();
        return Ok(p);
    }
    let mut pos = 0u16;
    for raw in ch.cfg.entries.iter().take(ch.cfg.count) {
        let e = MapEntry::decode(*raw);
        let obj = od
            .find(e.index, e.sub)
            .map_err(|_| CopKernel::PdoErrorPdoEncode)?;
        let mut tmp = [0u8; crate::od::MAX_FIXED];
        let n = od
            .peek(&obj, ByteOrder::Wire, &mut tmp)
            .map_err(|_| CopKernel::PdoErrorPdoEncode)?;
        let v = value::le_to_u64(tmp.get(..n).unwrap_or(&[]));
        wire::insert_bits(&mut p.data, pos, e.bits, v).ok_or(CopKernel::PdoErrorPdoEncode)?;
        pos += u16::from(e.bits);
    }
    p.len = bytes_for_bits(pos);
    Ok(p)
}

/// The comparison of `CCM_USE_PDO_CHECK_VAR` for one TPDO whose watch is
/// not quiet: `true` when its payload differs from the last sent one and
/// a transmission was marked. Out of line, so that the pass over quiet
/// watches in every cycle stays small.
#[inline(never)]
fn compare_with_last_sent(od: &ObjectDictionary, ch: &mut TxChannel, signalled: bool) -> bool {
    let t = ch.cfg.tx_type;
    if !ch.usable() || ch.event_pending || !(tx_type::is_event(t) || t == tx_type::SYNC_ACYCLIC) {
        return false;
    }
    let Ok(p) = watched_sample(od, ch) else {
        return false;
    };
    if ch.last_sent.is_none() && !signalled {
        ch.last_sent = Some(p);
        ch.watch.settle();
        false
    } else if ch.last_sent != Some(p) {
        ch.event_pending = true;
        true
    } else {
        ch.watch.settle();
        false
    }
}

/// [`sample`] for the comparison of `CCM_USE_PDO_CHECK_VAR`: without
/// sampling while the watched bytes are unchanged.
#[inline]
fn watched_sample(od: &ObjectDictionary, ch: &mut TxChannel) -> Result<Payload, CopKernel> {
    if let Some(p) = ch.watch.unchanged() {
        return Ok(p);
    }
    if ch.static_data.is_some() {
        return sample(od, ch);
    }
    let count = ch.cfg.count;
    let watched = ch
        .watch
        .take_bytes(od, ch.cfg.entries.get(..count).unwrap_or(&[]));
    let p = sample(od, ch)?;
    if watched {
        ch.watch.take(p);
    }
    Ok(p)
}

/// Writes an RPDO's payload into its mapped objects: every value is
/// converted and checked first, then all are stored, so either all mapped
/// variables change or none.
fn apply(od: &ObjectDictionary, ch: &RxChannel, p: &Payload) -> Result<(), CopKernel> {
    if let Some(d) = ch.static_data {
        let src = p.bytes();
        if src.len() < d.len() {
            return Err(CopKernel::PdoErrorPdoDecode);
        }
        value::store(d, src);
        return Ok(());
    }
    let mut staged: [Option<(Object, Staged)>; PDO_MAX_MAPPENTRIES] = [None; PDO_MAX_MAPPENTRIES];
    let mut pos = 0u16;
    for (slot, raw) in staged
        .iter_mut()
        .zip(ch.cfg.entries.iter().take(ch.cfg.count))
    {
        let e = MapEntry::decode(*raw);
        let v = wire::extract_bits(p.bytes(), pos, e.bits).ok_or(CopKernel::PdoErrorPdoDecode)?;
        pos += u16::from(e.bits);
        if mapping::is_dummy(e) {
            continue;
        }
        let obj = od
            .find(e.index, e.sub)
            .map_err(|_| CopKernel::PdoErrorPdoDecode)?;
        let wire_len = obj
            .data_type()
            .wire_size()
            .ok_or(CopKernel::PdoErrorPdoDecode)?;
        let bytes = v.to_le_bytes();
        let src = bytes.get(..wire_len).ok_or(CopKernel::PdoErrorPdoDecode)?;
        let s = od
            .stage(&obj, ByteOrder::Wire, src)
            .map_err(|_| CopKernel::PdoErrorPdoDecode)?;
        *slot = Some((obj, s));
    }
    for (obj, s) in staged.iter().flatten() {
        // Staging checked storage and size, so storing cannot fail here.
        let _ = od.store(obj, s, &[]);
    }
    for (obj, _) in staged.iter().flatten() {
        if let Ok(Storage::Var(v)) = obj.storage() {
            v.notify(od.callback_handle());
        }
    }
    Ok(())
}

fn inhibited(ch: &TxChannel, now: Ticks) -> bool {
    match ch.last_tx {
        Some(t) if ch.cfg.inhibit_ticks > 0 => now.since(t) < ch.cfg.inhibit_ticks,
        _ => false,
    }
}

/// Puts a TPDO on the bus and restarts its timers.
fn transmit(ch: &mut TxChannel, port: &mut impl CanPort, p: Payload, now: Ticks) -> CopResult {
    let id = ch.cfg.cob.ok_or(CopKernel::PdoErrorSend)?;
    port.send(&wire::encode_pdo(id, &p.data, p.len), Priority::Low)?;
    ch.last_tx = Some(now);
    ch.last_sent = Some(p);
    ch.watch.unsettle();
    ch.event_pending = false;
    if tx_type::is_event(ch.cfg.tx_type) && ch.cfg.event_ms > 0 {
        ch.event_deadline = Some(now.plus_ms(u32::from(ch.cfg.event_ms)));
    }
    Ok(())
}

fn send_emcy(
    od: &ObjectDictionary,
    port: &mut impl CanPort,
    now: Ticks,
    emcy: &mut EmcyProducer,
    code: u16,
    commu: u16,
    dlc: u8,
) {
    // Error register: generic error (bit 0) and communication error (bit 4).
    let register = od
        .read_uint(emcy::producer::ERROR_REGISTER_INDEX, 0)
        .unwrap_or(0) as u8
        | 0x11;
    let i = commu.to_le_bytes();
    let e = Emergency {
        code,
        register,
        manufacturer: [i[0], i[1], dlc, 0, 0],
    };
    let _ = emcy.send(od, port, now, e);
}
