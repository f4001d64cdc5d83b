//! The CANopen device: the CCM layer that ties the object dictionary and
//! the protocol modules together (`CcmInitCANopen`, `CcmConnectToNet`,
//! `CcmProcess`, `CcmReadObject`, `CcmWriteObject`, NMT).
//!
//! # Driving the stack
//! ```text
//! let mut stack = Stack::new(od, node_id)?;      // CcmInitCANopen
//! stack.connect();                               // CcmConnectToNet
//! loop {
//!     stack.begin_cycle(&mut port);              // CcmProcess ...
//!     while let Some(ev) = stack.poll(&mut port, clock.now()) {
//!         handle(ev);                            // ... calls the callbacks
//!     }
//! }
//! ```
//! `poll` hands out one [`Event`] at a time; the caller handles it before
//! the next `poll`, so callbacks always observe the state the event
//! describes and may call back into the stack.
//!
//! # One processing cycle
//! 1. receive overrun reported by the driver (SRDO: `kCopSrdoOverrun`);
//! 2. every received frame, oldest first (NMT, SRDO/GFC, SDO, guarding);
//! 3. timers: SRDO (SCT, SRVT, program monitor), SYNC producer (then the
//!    synchronous PDOs it triggers), SDO timeout, heartbeat, life guarding,
//!    delayed emergencies.

use crate::emcy::{self, EmcyConsumer, EmcyProducer};
use crate::error::{CopKernel, CopResult, OdError};
use crate::event::{Action, ActionQueue, Event, Internal, NmtEvent, NmtState};
use crate::heartbeat::{self, HeartbeatConsumer, HeartbeatProducer};
use crate::nmt::lss::{self, LssSlave};
use crate::nmt::slave::{self, Transition};
use crate::nmt::{LifeGuardSlave, NmtMaster, error_behaviour, lifeguard};
use crate::od::{ByteOrder, Object, ObjectDictionary, Staged, WriteHooks};
use crate::pdo::Pdo;
use crate::port::{CanFrame, CanId, CanPort, Priority, RxFrame, Ticks};
use crate::sdo::{SdoClient, SdoServer, SdoServers};
use crate::srdo::{Received, Srdo};
use crate::store::{self, StoreRestore};
use crate::sync::{self, SyncProducer};
use crate::wire::emcy::Emergency;
use crate::wire::nmt::{self, NmtCs};
use crate::wire::srdo::{COB_ID_COUNT, COB_ID_MIN, GFC_ID};

mod dynod;
mod pdo;
mod services;

/// True for the identifiers the SRDO module receives: the GFC (0x001) and
/// the SRDO range 0x101..=0x180, 11-bit (an extended identifier has its
/// flag bit in [`CanId::raw`] and is never in the range).
#[inline(always)]
const fn srdo_or_gfc_id(id: CanId) -> bool {
    let raw = id.raw();
    raw == GFC_ID as u32 || raw.wrapping_sub(COB_ID_MIN as u32) < COB_ID_COUNT as u32
}

pub use crate::nmt::NmtCommand;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    Overrun,
    OverrunReport,
    Receive,
    /// SRDO timers (resumable).
    SrdoTimers,
    /// This node's SYNC, before the PDOs it triggers.
    SyncProducer,
    /// PDO and SYNC work (resumable).
    PdoTimers,
    /// Heartbeat consumer (resumable).
    HbcTimers,
    /// NMT master guarding (resumable).
    NmtmTimers,
    /// SDO client timeouts (resumable).
    SdocTimers,
    /// SDO timeout, heartbeat producer, delayed emergencies.
    Timers,
    Idle,
}

/// A CANopen device.
#[derive(Debug)]
pub struct Stack {
    od: ObjectDictionary,
    node_id: u8,
    state: NmtState,
    connected: bool,
    queue: ActionQueue,
    phase: Phase,
    guard_toggle: bool,
    /// The request COB-ID the driver receives for each SDO server.
    sdo_subscribed: [Option<CanId>; crate::config::SDO_MAX_SERVER_IN_OBD],
    /// Identifiers changed outside a cycle; subscribe at the next one.
    resubscribe: bool,
    /// The driver's bus-off flag at the last cycle (a communication error
    /// counts when it is raised).
    bus_off: bool,
    hb: HeartbeatProducer,
    hbc: HeartbeatConsumer,
    nmtm: NmtMaster,
    emcy: EmcyProducer,
    sdo: SdoServers,
    sdoc: SdoClient,
    srdo: Srdo,
    pdo: Pdo,
    emcc: EmcyConsumer,
    lgs: LifeGuardSlave,
    syncp: SyncProducer,
    store: StoreRestore,
    /// The LSS slave, where the build serves LSS (`Stack::with_lss`).
    lss: Option<LssSlave>,
    /// The dynamic object dictionary in force (`DynBuildOd`).
    dynamic: Option<crate::od::dynamic::Installed>,
}

/// The module reactions to dictionary writes.
///
/// Made with [`hooks!`], which borrows the modules field by field, so that
/// the dictionary and the SDO server stay usable beside them.
struct Hooks<'a> {
    state: NmtState,
    node: u8,
    now: Ticks,
    srdo: &'a mut Srdo,
    pdo: &'a mut Pdo,
    hb: &'a mut HeartbeatProducer,
    hbc: &'a mut HeartbeatConsumer,
    emcy: &'a mut EmcyProducer,
    lgs: &'a mut LifeGuardSlave,
    syncp: &'a mut SyncProducer,
    store: &'a mut StoreRestore,
    sdo_changed: bool,
}

/// The [`Hooks`] of a stack (`$stack`) at `$now`.
macro_rules! hooks {
    ($stack:expr, $now:expr) => {
        Hooks {
            state: $stack.state,
            node: $stack.node_id,
            now: $now,
            srdo: &mut $stack.srdo,
            pdo: &mut $stack.pdo,
            hb: &mut $stack.hb,
            hbc: &mut $stack.hbc,
            emcy: &mut $stack.emcy,
            lgs: &mut $stack.lgs,
            syncp: &mut $stack.syncp,
            store: &mut $stack.store,
            sdo_changed: false,
        }
    };
}

impl WriteHooks for Hooks<'_> {
    fn check(
        &mut self,
        od: &ObjectDictionary,
        obj: &Object,
        value: &Staged,
    ) -> Result<(), OdError> {
        if (0x1300..=0x13FF).contains(&obj.index()) {
            self.srdo.check_write(od, obj, value, self.state)?;
        }
        if crate::pdo::handles(obj.index()) {
            self.pdo.check_write(od, obj, value)?;
        }
        emcy::producer::check_write(obj, value)?;
        crate::sdo::check_write(od, obj, value)?;
        error_behaviour::check_write(obj, value)?;
        self.syncp.check_write(obj, value)?;
        self.store.check_write(od, obj, value, self.state)?;
        Ok(())
    }

    fn before_store(&mut self, od: &ObjectDictionary, obj: &Object, value: &Staged) {
        if (0x1300..=0x13FF).contains(&obj.index()) {
            self.srdo.before_store(od, obj, value);
        }
    }

    fn after_store(&mut self, od: &ObjectDictionary, obj: &Object) {
        match obj.index() {
            heartbeat::PRODUCER_TIME_INDEX => self.hb.reconfigure(od, self.now),
            heartbeat::CONSUMER_TIME_INDEX => self.hbc.reconfigure(od),
            emcy::producer::COB_ID_INDEX | emcy::producer::INHIBIT_INDEX => {
                self.emcy.reconfigure(od, self.node)
            }
            emcy::producer::ERROR_FIELD_INDEX if obj.sub() == 0 => {
                emcy::producer::clear_error_field(od)
            }
            lifeguard::GUARD_TIME_INDEX | lifeguard::LIFE_TIME_FACTOR_INDEX => {
                self.lgs.reconfigure(od)
            }
            sync::producer::COB_ID_SYNC_INDEX | sync::producer::CYCLE_PERIOD_INDEX => {
                self.syncp.reconfigure(od, self.now);
                self.pdo.after_store(od, obj, self.now);
            }
            sync::producer::COUNTER_OVERFLOW_INDEX => self.syncp.reconfigure(od, self.now),
            store::LOAD_INDEX | store::SAVE_INDEX => self.store.after_store(od, obj),
            // SDO server 0x1200..0x127F, SDO client 0x1280..0x12FF.
            0x1200..=0x12FF => self.sdo_changed = true,
            0x1300..=0x13FF => self.srdo.after_store(od, obj),
            i if crate::pdo::handles(i) => self.pdo.after_store(od, obj, self.now),
            _ => {}
        }
    }
}

impl Stack {
    /// Creates the device (`CcmInitCANopen`): checks the node-ID (1..=127,
    /// else `kCopInvalidNodeId`), lets the modules find their objects, and
    /// queues the start-up sequence: kNmtEvEnterInitialising, then the reset
    /// of application and communication objects with their NMT events. The
    /// node stays in INITIALISATION until [`Stack::connect`].
    pub fn new(od: ObjectDictionary, node_id: u8) -> CopResult<Stack> {
        Stack::create(od, node_id, None)
    }

    /// [`Stack::new`] with the LSS slave (CiA 305, [`crate::nmt::lss`]):
    /// `node_id` may also be 0xFF, a node without node-ID, which answers
    /// only LSS until a master gives it one ([`Stack::lss_init_state`]).
    /// Only in builds with the LSS slave (`CCM_MODULE_LSSS`, feature
    /// `lss-slave`): without it no LSS code is in the image.
    #[cfg(ccm_module_lsss)]
    pub fn with_lss(od: ObjectDictionary, node_id: u8) -> CopResult<Stack> {
        Stack::create(od, node_id, Some(LssSlave::new(node_id)))
    }

    fn create(od: ObjectDictionary, node_id: u8, lss: Option<LssSlave>) -> CopResult<Stack> {
        let without_node_id = lss.is_some() && node_id == lss::UNCONFIGURED;
        if !(1..=127).contains(&node_id) && !without_node_id {
            return Err(CopKernel::InvalidNodeId);
        }
        let mut s = Stack {
            od,
            node_id,
            state: NmtState::Initialisation,
            connected: false,
            queue: ActionQueue::new(),
            phase: Phase::Idle,
            guard_toggle: false,
            sdo_subscribed: [None; crate::config::SDO_MAX_SERVER_IN_OBD],
            resubscribe: false,
            bus_off: false,
            hb: HeartbeatProducer::new(),
            hbc: HeartbeatConsumer::new(),
            nmtm: NmtMaster::new(),
            emcy: EmcyProducer::new(),
            sdo: SdoServers::new(),
            sdoc: SdoClient::new(),
            srdo: Srdo::new(),
            pdo: Pdo::new(),
            emcc: EmcyConsumer::new(),
            lgs: LifeGuardSlave::new(),
            syncp: SyncProducer::new(),
            store: StoreRestore::new(),
            lss,
            dynamic: None,
        };
        s.srdo.init(&s.od)?;
        s.queue.emit(Event::Nmt(NmtEvent::EnterInitialising));
        s.queue_reset(true);
        Ok(s)
    }

    /// `CcmProcessLssInitState`'s answer after a cycle: `kCopLsssInvalidNodeId`
    /// while the node has no node-ID (0xFF), success once it has one.
    pub fn lss_init_state(&self) -> CopResult {
        if self.node_id == lss::UNCONFIGURED {
            Err(CopKernel::LsssInvalidNodeId)
        } else {
            Ok(())
        }
    }

    /// The LSS slave, where the stack has one.
    pub fn lss(&self) -> Option<&LssSlave> {
        self.lss.as_ref()
    }

    /// `CcmConnectToNet`: leave INITIALISATION (boot-up message, then
    /// PRE-OPERATIONAL). `kCopNmtStateError` when already connected,
    /// `kCopLsssInvalidNodeId` while the node has no node-ID (LSS).
    pub fn connect(&mut self) -> CopResult {
        if self.connected {
            return Err(CopKernel::NmtStateError);
        }
        self.lss_init_state()?;
        self.connected = true;
        if self.queue.is_empty() && self.state == NmtState::Initialisation {
            self.queue_state(NmtState::PreOperational);
        }
        // Otherwise the reset sequence still queued ends in PRE-OPERATIONAL
        // because `connected` is now set (see `run`).
        Ok(())
    }

    /// The dictionary.
    pub fn od(&self) -> &ObjectDictionary {
        &self.od
    }

    /// Mutable access to the dictionary (dynamic OD). What the PDOs
    /// resolved in it is resolved again.
    pub fn od_mut(&mut self) -> &mut ObjectDictionary {
        self.pdo.dictionary_changed();
        &mut self.od
    }

    /// Mutable access to the PDO module (dynamic OD: its pooled channels).
    pub(crate) fn pdo_mut(&mut self) -> &mut Pdo {
        &mut self.pdo
    }

    /// This node's ID.
    pub fn node_id(&self) -> u8 {
        self.node_id
    }

    /// Current NMT state.
    pub fn nmt_state(&self) -> NmtState {
        self.state
    }

    /// True after [`Stack::connect`].
    pub fn is_connected(&self) -> bool {
        self.connected
    }

    /// The SRDO module.
    pub fn srdo(&self) -> &Srdo {
        &self.srdo
    }

    /// The SRDO module, mutable.
    pub fn srdo_mut(&mut self) -> &mut Srdo {
        &mut self.srdo
    }

    /// The PDO module.
    pub fn pdo(&self) -> &Pdo {
        &self.pdo
    }

    /// The PDO module with what its API needs of the stack.
    pub(crate) fn pdo_parts(&mut self) -> crate::pdo::Parts<'_> {
        crate::pdo::Parts {
            od: &self.od,
            pdo: &mut self.pdo,
            state: self.state,
            queue: &mut self.queue,
        }
    }

    /// The heartbeat consumer.
    pub fn hbc(&self) -> &HeartbeatConsumer {
        &self.hbc
    }

    /// The heartbeat consumer, mutable.
    pub fn hbc_mut(&mut self) -> &mut HeartbeatConsumer {
        &mut self.hbc
    }

    /// The NMT master.
    pub fn nmtm(&self) -> &NmtMaster {
        &self.nmtm
    }

    /// The NMT master, mutable.
    pub fn nmtm_mut(&mut self) -> &mut NmtMaster {
        &mut self.nmtm
    }

    /// `CcmSendNmtCommand`: NMT module control to `node` (0 = all).
    /// The command also applies to this node when it is addressed, as
    /// CiA 301 requires of a master that is itself an NMT slave.
    pub fn send_nmt_command(&mut self, port: &mut impl CanPort, node: u8, cs: NmtCs) -> CopResult {
        if !self.connected {
            return Err(CopKernel::NmtStateError);
        }
        NmtMaster::send_command(port, node, cs)?;
        if node == 0 || node == self.node_id {
            self.nmt_command(cs);
        }
        Ok(())
    }

    /// The SDO client.
    pub fn sdoc(&self) -> &SdoClient {
        &self.sdoc
    }

    /// Defines an SDO client channel and subscribes its response COB-ID; a
    /// transfer running on it is aborted first ([`SdoClient::define`]).
    pub fn define_sdo_client(
        &mut self,
        port: &mut impl CanPort,
        index: u16,
        p: crate::sdo::client::ClientParam,
    ) -> CopResult {
        self.sdoc.define(port, index, p, &mut self.queue)?;
        self.subscribe(port);
        Ok(())
    }

    /// Starts an SDO client transfer (`CcmSdocStartTransfer`).
    #[allow(clippy::too_many_arguments)]
    pub fn sdo_client_start(
        &mut self,
        port: &mut impl CanPort,
        now: Ticks,
        index: u16,
        dir: crate::sdo::client::Direction,
        mux: crate::wire::sdo::Multiplexer,
        buf: &'static [core::sync::atomic::AtomicU8],
        len: usize,
        timeout_ticks: u32,
    ) -> CopResult {
        if !self.connected || self.state == NmtState::Stopped {
            return Err(CopKernel::NmtStateError);
        }
        self.sdoc
            .start(port, now, index, dir, mux, buf, len, timeout_ticks)
    }

    /// Aborts an SDO client transfer (`CcmSdocAbort`).
    pub fn sdo_client_abort(
        &mut self,
        port: &mut impl CanPort,
        index: u16,
        code: u32,
    ) -> CopResult {
        self.sdoc.abort(port, index, code, &mut self.queue)
    }

    /// The heartbeat producer.
    pub fn heartbeat(&self) -> &HeartbeatProducer {
        &self.hb
    }

    /// The emergency producer.
    pub fn emcy_mut(&mut self) -> &mut EmcyProducer {
        &mut self.emcy
    }

    /// Starts a processing cycle (`CcmProcess`); then call [`Stack::poll`]
    /// until it returns `None`.
    pub fn begin_cycle(&mut self) {
        self.phase = Phase::Overrun;
        self.srdo.begin_cycle();
        self.pdo.begin_cycle();
    }

    /// Runs the stack until it has an event for the application or nothing
    /// left to do in this cycle.
    #[inline(always)]
    pub fn poll(&mut self, port: &mut impl CanPort, now: Ticks) -> Option<Event> {
        // The usual re-entry after the application handled an event: the
        // next one is already queued and goes out without entering the
        // cycle's state machine.
        if let Some(e) = self.queue.pop_event() {
            return Some(e);
        }
        // The front of the cycle (overrun check, received frames) without
        // the phase machine: a received SRDO's event goes out from there,
        // and the poll after the application handled it comes back there,
        // so only the cycle's last poll enters `poll_work`.
        if self.queue.is_empty()
            && matches!(
                self.phase,
                Phase::Overrun | Phase::OverrunReport | Phase::Receive
            )
        {
            if let Some(e) = self.poll_front(port, now) {
                return Some(e);
            }
        }
        self.poll_work(port, now)
    }

    /// The phases up to `Receive` (also for `poll_work`, so that the
    /// receive path exists once): returns the first event of a received
    /// frame, or `None` when the phase machine has to go on (the timer
    /// phases, or actions queued).
    #[inline(never)]
    fn poll_front(&mut self, port: &mut impl CanPort, now: Ticks) -> Option<Event> {
        if self.phase == Phase::Overrun {
            self.check_overrun(port, now);
        }
        if self.phase == Phase::OverrunReport && (!self.report_overrun() || !self.queue.is_empty())
        {
            return None;
        }
        self.receive_frames(port, now)
    }

    /// Phase `Overrun`: identifiers changed outside a cycle, the driver's
    /// overrun and bus-off flags.
    #[inline(always)]
    fn check_overrun(&mut self, port: &mut impl CanPort, now: Ticks) {
        if core::mem::take(&mut self.resubscribe) {
            self.subscribe(port);
        }
        let status = port.status();
        if status.rx_overrun && self.connected {
            self.srdo.on_rx_overrun();
        }
        if status.rx_overrun_other && self.connected {
            self.can_overrun(port, now);
        }
        // Followed once connected, so that a controller already bus-off
        // when the node connects counts at its first cycle.
        if self.connected && status.bus_off != self.bus_off {
            self.bus_off = status.bus_off;
            if status.bus_off {
                self.communication_error();
            }
        }
        self.phase = Phase::OverrunReport;
    }

    /// Phase `OverrunReport`: one SRDO per step keeps the action queue
    /// small; `true` when none is left (the phase is then `Receive`).
    #[inline(always)]
    fn report_overrun(&mut self) -> bool {
        let done = self.srdo.report_overrun(&mut self.queue);
        if done {
            self.phase = Phase::Receive;
        }
        done
    }

    /// Phase `Receive`: frame after frame while they queue nothing. Returns
    /// the first event a frame queued; `None` with the next timer phase
    /// (`SrdoTimers`, or `PdoTimers` when the SRDOs and the SYNC producer
    /// are at rest) when the driver has no frame left, or with internal
    /// work queued.
    #[inline(always)]
    fn receive_frames(&mut self, port: &mut impl CanPort, now: Ticks) -> Option<Event> {
        while let Some(f) = port.receive() {
            if let Some(e) = self.on_frame(port, &f, now) {
                return Some(e);
            }
            if let Some(e) = self.queue.pop_event() {
                return Some(e);
            }
            if !self.queue.is_empty() {
                return None;
            }
        }
        // Phases with nothing to do at `now` are skipped (see
        // `early_at_rest`).
        self.phase = if self.early_at_rest(now) {
            Phase::PdoTimers
        } else {
            Phase::SrdoTimers
        };
        None
    }

    /// [`Stack::poll`]: internal work, the cycle's phases (out of line, so
    /// that taking a queued event does not pay for its register saves).
    #[inline(never)]
    fn poll_work(&mut self, port: &mut impl CanPort, now: Ticks) -> Option<Event> {
        loop {
            if let Some(a) = self.queue.pop() {
                match a {
                    Action::Emit(e) => return Some(e),
                    Action::Do(i) => {
                        self.run(i, port, now);
                        continue;
                    }
                }
            }
            match self.phase {
                Phase::Overrun | Phase::OverrunReport | Phase::Receive => {
                    if let Some(e) = self.poll_front(port, now) {
                        return Some(e);
                    }
                }
                Phase::SrdoTimers => {
                    if self.srdo.poll(self.state, now, &mut self.queue) {
                        self.phase = Phase::SyncProducer;
                    }
                }
                Phase::SyncProducer => {
                    self.produce_sync(port, now);
                    self.phase = Phase::PdoTimers;
                }
                Phase::PdoTimers => {
                    let (od, q, emcy) = (&self.od, &mut self.queue, &mut self.emcy);
                    if self.pdo.poll(od, self.state, port, now, q, emcy) {
                        self.phase = if self.late_at_rest(now) {
                            Phase::Idle
                        } else {
                            Phase::HbcTimers
                        };
                    }
                }
                Phase::HbcTimers => {
                    if !self.connected || self.hbc.poll(now, &mut self.queue) {
                        self.phase = Phase::NmtmTimers;
                    } else {
                        // A producer was reported lost.
                        self.communication_error();
                    }
                }
                Phase::NmtmTimers => {
                    if !self.connected || self.nmtm.poll(port, now, &mut self.queue) {
                        self.phase = Phase::SdocTimers;
                    }
                }
                Phase::SdocTimers => {
                    if self.sdoc.poll(port, now, &mut self.queue) {
                        self.phase = Phase::Timers;
                    }
                }
                Phase::Timers => {
                    self.timers(port, now);
                    self.phase = Phase::Idle;
                }
                Phase::Idle => return None,
            }
        }
    }

    /// Runs a whole cycle, handing each event to `handle`.
    pub fn process(
        &mut self,
        port: &mut impl CanPort,
        now: Ticks,
        mut handle: impl FnMut(&mut Stack, Event),
    ) {
        self.begin_cycle();
        while let Some(e) = self.poll(port, now) {
            handle(self, e);
        }
    }

    /// The event at the front of the action queue, if one waits there:
    /// what [`Stack::poll`] and [`Stack::drain`] would hand out first, with
    /// no time needed. The C API's pump takes it without reading the clock.
    #[inline(always)]
    pub fn queued_event(&mut self) -> Option<Event> {
        self.queue.pop_event()
    }

    /// Whether a program monitor event waits at the front of the action
    /// queue ([`Stack::queued_progmon`] would take it).
    #[inline(always)]
    pub fn progmon_queued(&self) -> bool {
        self.queue.front_is_progmon()
    }

    /// The program monitor event at the front of the action queue, if one
    /// waits there (a run of them follows a timer pass over the SRDOs).
    #[inline(always)]
    pub fn queued_progmon(&mut self) -> Option<crate::event::ProgMonEvent> {
        self.queue.pop_progmon()
    }

    /// Hands out queued events without starting a cycle (after API calls
    /// such as [`Stack::send_srdo`] or [`Stack::connect`]).
    pub fn drain(&mut self, port: &mut impl CanPort, now: Ticks) -> Option<Event> {
        let saved = self.phase;
        self.phase = Phase::Idle;
        let e = self.poll(port, now);
        if self.phase == Phase::Idle {
            self.phase = saved;
        }
        e
    }

    /// The SRDO timers and the SYNC producer would do nothing at `now`, so
    /// their phases can be left out of this cycle. Each module answers
    /// from its current state with the conditions of its own `poll`, so a
    /// deadline is acted upon at the same tick as without the skip, and
    /// whatever changed a module since its last pass (an API call, a
    /// frame, an event handled) is taken into account.
    #[inline]
    fn early_at_rest(&self, now: Ticks) -> bool {
        self.srdo.at_rest(self.state, now) && self.syncp.at_rest(self.operating(), now)
    }

    /// The phases after the PDOs would do nothing at `now` (the heartbeat
    /// consumer, the NMT master's node guarding, the SDO client and
    /// server, the heartbeat producer, life guarding, the EMCY producer;
    /// the conditions of [`Stack::timers`] and of each `poll`), so the
    /// cycle can end after the PDOs. Evaluated when the PDO phase is
    /// done, so that what the application did in the callbacks of this
    /// cycle counts.
    #[inline]
    fn late_at_rest(&self, now: Ticks) -> bool {
        let supervising = self.connected;
        let beating = self.connected && self.state != NmtState::Initialisation;
        (!supervising || (self.hbc.at_rest(now) && self.nmtm.at_rest(now)))
            && self.sdoc.at_rest()
            && self.sdo.at_rest()
            && (!beating || self.hb.at_rest(now))
            && (!supervising || self.lgs.at_rest(now, self.hb.period_ms() > 0))
            && self.emcy.at_rest(now)
    }

    #[inline(never)] // its frame stays out of poll_work (worst-case stack, docs/tms570.md)
    fn timers(&mut self, port: &mut impl CanPort, now: Ticks) {
        for s in self.sdo.channels_mut() {
            let f = s.poll(&self.od, now);
            send_server_frame(s, port, f);
        }
        self.send_sdo_segments(port, now);
        if self.connected && self.state != NmtState::Initialisation {
            self.hb.poll(port, self.node_id, self.state as u8, now);
        }
        self.poll_life_guarding(port, now);
        self.emcy.poll(port, now);
    }

    /// A received frame. SRDO and GFC identifiers first, with one range
    /// test, inlined into the receive loop: NMT (0x000), error control and
    /// guarding (0x701..=0x77F) and the emergencies of the consumer
    /// (0x081..=0x0FF) cannot have them, so their decoding is skipped. A
    /// frame the SRDO module does not take goes on to the PDO and SDO
    /// services as before.
    /// Called with an empty queue; returns the first event the frame
    /// reports when it comes without the queue (a completed SRDO pair).
    #[inline(always)]
    fn on_frame(&mut self, port: &mut impl CanPort, rx: &RxFrame, now: Ticks) -> Option<Event> {
        if srdo_or_gfc_id(rx.frame.id)
            && self.connected
            && matches!(self.state, NmtState::Operational | NmtState::PreOperational)
        {
            match self.srdo.on_frame_first(self.state, rx, &mut self.queue) {
                Received::Event(e) => return Some(e),
                Received::Taken => {}
                Received::NotSrdo => self.on_service_frame(port, rx, now),
            }
            return None;
        }
        self.on_other_frame(port, rx, now);
        None
    }

    /// [`Stack::on_frame`] for every frame but an SRDO or GFC frame while
    /// the node is PRE-OPERATIONAL or OPERATIONAL.
    #[inline(never)]
    fn on_other_frame(&mut self, port: &mut impl CanPort, rx: &RxFrame, now: Ticks) {
        let f = &rx.frame;
        #[cfg(ccm_module_lsss)]
        if self.lss.is_some() && f.id == CanId::std_masked(crate::wire::lss::MASTER_TO_SLAVE) {
            self.on_lss_frame(port, f);
            return;
        }
        if !self.connected || self.state == NmtState::Initialisation {
            return;
        }
        if srdo_or_gfc_id(f.id) {
            // STOPPED: neither the SRDO module nor the services take it.
            return;
        }
        if let Some(cmd) = nmt::decode_command(f) {
            if cmd.node == 0 || cmd.node == self.node_id {
                self.nmt_command(cmd.cs);
            }
            return;
        }
        if !f.rtr {
            if let Some(ec) = nmt::decode_error_control(f) {
                if !self.nmtm.on_error_control(f, &mut self.queue) {
                    self.hbc.on_heartbeat(ec, rx.time, &mut self.queue);
                }
                return;
            }
        }
        if f.rtr && f.id == nmt::error_control_id(self.node_id) {
            let reply = nmt::encode_guard_reply(self.node_id, self.state as u8, self.guard_toggle);
            if port.send(&reply, Priority::Low).is_ok() {
                self.guard_toggle = !self.guard_toggle;
            }
            self.lgs.on_guard_request(rx.time);
            return;
        }
        if self.state == NmtState::Stopped {
            return;
        }
        if self.emcc.on_frame(f, &mut self.queue) {
            return;
        }
        // (The SRDO module takes only the identifiers handled above.)
        self.on_service_frame(port, rx, now);
    }

    /// An LSS request (CiA 305), in every NMT state and before
    /// `CcmConnectToNet`.
    #[cfg(ccm_module_lsss)]
    #[inline(never)]
    fn on_lss_frame(&mut self, port: &mut impl CanPort, f: &crate::port::CanFrame) {
        let (Some(lss), Some(req)) = (self.lss.as_mut(), crate::wire::lss::decode_request(f))
        else {
            return;
        };
        let address = [1, 2, 3, 4].map(|sub| self.od.read_or(lss::IDENTITY_INDEX, sub, 0u32));
        let outcome = lss.on_request(req, address, self.node_id);
        if let Some(answer) = outcome.answer {
            let _ = port.send(&answer, Priority::Low);
        }
        if outcome.take_node_id {
            // The reset communication takes the pending node-ID.
            self.queue_reset(false);
        }
    }

    /// The rest of [`Stack::on_frame`]: PDO, SDO client and SDO server.
    #[inline(never)]
    fn on_service_frame(&mut self, port: &mut impl CanPort, rx: &RxFrame, now: Ticks) {
        let f = &rx.frame;
        let (od, q, emcy) = (&self.od, &mut self.queue, &mut self.emcy);
        if self.pdo.on_frame(od, self.state, rx, port, now, q, emcy) {
            return;
        }
        if self.sdoc.on_frame(port, f, now, &mut self.queue) {
            return;
        }
        if let Some(server) = self.sdo.receiving(f.id) {
            let mut hooks = hooks!(self, now);
            let reply = server.on_frame(&self.od, &mut hooks, f, now);
            let changed = hooks.sdo_changed;
            if reply.is_some() {
                send_server_frame(server, port, reply);
            }
            self.send_sdo_segments(port, now);
            if changed {
                self.sdo.reconfigure(&self.od, self.node_id);
                self.sdoc.reconfigure(&self.od);
                self.subscribe(port);
            }
        }
    }

    /// Hands the segments of the block uploads to the driver until it
    /// refuses one (a full transmit buffer); the rest goes in the next
    /// cycle.
    fn send_sdo_segments(&mut self, port: &mut impl CanPort, now: Ticks) {
        for s in self.sdo.channels_mut() {
            while let Some(f) = s.pending_segment() {
                if port.send(&f, Priority::Low).is_err() {
                    return;
                }
                s.segment_sent(now);
            }
        }
    }

    fn nmt_command(&mut self, cs: NmtCs) {
        match Transition::of(cs) {
            Transition::Enter(s) => self.queue_state(s),
            Transition::Reset { node } => self.queue_reset(node),
        }
    }

    /// `CcmNmtsExecCommand`: a local NMT command.
    pub fn exec_command(&mut self, cmd: NmtCommand) -> CopResult {
        if !self.connected {
            return Err(CopKernel::NmtStateError);
        }
        let cs = cmd.specifier().ok_or(CopKernel::NmtUnknownCommand)?;
        self.nmt_command(cs);
        Ok(())
    }

    fn queue_state(&mut self, target: NmtState) {
        slave::queue_state(&mut self.queue, self.state, target);
    }

    /// Queues a reset ([`slave::queue_reset`]).
    fn queue_reset(&mut self, node: bool) {
        slave::queue_reset(&mut self.queue, node);
    }

    #[inline(never)] // its frame stays out of poll_work (worst-case stack, docs/tms570.md)
    fn run(&mut self, i: Internal, port: &mut impl CanPort, now: Ticks) {
        match i {
            Internal::RestoreApplication => {
                self.restore_defaults(0x2000, 0x9FFF);
                self.store.restored(store::part::APP);
                self.store.load_parts(&self.od, store::part::APP);
            }
            Internal::RestoreCommunication => {
                #[cfg(ccm_module_lsss)]
                if let Some(lss) = &self.lss {
                    // CiA 305: the pending node-ID becomes the node's now.
                    self.node_id = lss.pending_node_id();
                }
                self.restore_defaults(0x1000, 0x1FFF);
                self.store.restored(store::part::GEN);
                self.store.load_parts(&self.od, store::part::GEN);
                self.lgs.reset_communication();
                self.syncp.reset_communication();
                self.emcy.reset_communication();
            }
            Internal::Reconfigure => {
                self.reconfigure_modules(port, now);
                if self.connected && self.state == NmtState::Initialisation {
                    self.queue_state(NmtState::PreOperational);
                }
            }
            Internal::EnterState(s) => self.enter_state(s, port, now),
            Internal::SrdoCheckHandled(slot) => self.srdo.check_handled(slot, &mut self.queue),
            Internal::SrdoOk(slot) => self.srdo.deliver_ok(slot, &mut self.queue),
        }
    }

    /// Restores the defaults of `from..=to`; a dynamic OD then puts its
    /// values back (it stays in force until `DynDestroyOd`).
    #[inline(never)] // out of `run`: its frame stays off the store path (docs/tms570.md)
    fn restore_defaults(&mut self, from: u16, to: u16) {
        self.od.restore_defaults(from, to);
        if let Some(d) = &self.dynamic {
            crate::od::dynamic::reapply(&self.od, d, from, to);
        }
    }

    /// The dynamic object dictionary in force, if any.
    pub fn dynamic_od(&self) -> Option<&crate::od::dynamic::Installed> {
        self.dynamic.as_ref()
    }

    /// Records (`Some`) or forgets (`None`) the dynamic OD in force.
    pub(crate) fn set_dynamic_od(&mut self, d: Option<crate::od::dynamic::Installed>) {
        self.dynamic = d;
    }

    /// Lets every module take over its parameters from the dictionary again,
    /// as after reset communication but without NMT transition: after a
    /// dynamic OD was built, rolled back or destroyed. PDOs keep running
    /// when the node is OPERATIONAL.
    pub fn reload_configuration(&mut self, port: &mut impl CanPort, now: Ticks) {
        self.reconfigure_modules(port, now);
        self.pdo.on_state(self.state, now);
    }

    /// The PDO part of `DynDestroyOd` (seed manual L-1087d 5.2): the PDO
    /// module sees kNmtEvPreResetCommunication (every PDO stops), the
    /// dynamic tables leave the dictionary (`original_user` becomes the
    /// user part again), the PDO parameters of the static dictionary get
    /// their defaults, and the PDO module takes them over in PRE-OPERATIONAL,
    /// whatever the node's NMT state (an NMT start makes the PDOs run
    /// again). The other modules re-read their parameters.
    pub(crate) fn destroy_dynamic_od(
        &mut self,
        original_user: &'static [crate::od::ObdEntry],
        port: &mut impl CanPort,
        now: Ticks,
    ) {
        self.pdo.on_state(NmtState::Initialisation, now);
        self.dynamic = None;
        // The previous user part passed the checks once already.
        let _ = self.od.set_user_part(original_user);
        self.pdo.dictionary_changed();
        self.od.restore_defaults(0x1400, 0x1BFF);
        self.sdo.cancel();
        self.reconfigure_modules(port, now);
        if self.pdo.has_pooled() {
            // The pooled channels have let go of their identifiers (their
            // PDOs are gone); the fixed ones serve again.
            self.pdo.detach_pooled(port);
            self.pdo.reconfigure(&self.od, self.node_id, port);
        }
        self.pdo.on_state(NmtState::PreOperational, now);
    }

    /// Lets every module take over its parameters from the dictionary and
    /// tells the driver the identifiers (after reset communication, and
    /// after a dynamic OD changed the dictionary).
    #[inline(never)] // out of `run`: its frame stays off the store path (docs/tms570.md)
    fn reconfigure_modules(&mut self, port: &mut impl CanPort, now: Ticks) {
        self.reconfigure_services(now);
        self.hb.reconfigure(&self.od, now);
        self.hbc.reconfigure(&self.od);
        self.emcy.reconfigure(&self.od, self.node_id);
        self.sdo.reconfigure(&self.od, self.node_id);
        self.sdoc.reconfigure(&self.od);
        self.subscribe(port);
        self.srdo.reconfigure(&self.od, port);
        self.pdo.reconfigure(&self.od, self.node_id, port);
    }

    /// Tells the driver which identifiers to receive (`CdrvDefineCanId`):
    /// NMT, node guarding requests and the SDO server. The SRDO module
    /// subscribes its own COB-IDs.
    fn subscribe(&mut self, port: &mut impl CanPort) {
        let _ = port.subscribe(CanId::std_masked(nmt::NMT_COB_ID), Priority::High);
        #[cfg(ccm_module_lsss)]
        if self.lss.is_some() {
            let _ = port.subscribe(
                CanId::std_masked(crate::wire::lss::MASTER_TO_SLAVE),
                Priority::Low,
            );
        }
        // Error control of every other node: guarding requests to this node,
        // heartbeats for the consumer, boot-ups and guard answers for the
        // master.
        for node in 1..=127u8 {
            let _ = port.subscribe(nmt::error_control_id(node), Priority::Low);
        }
        for id in self.sdoc.rx_ids() {
            let _ = port.subscribe(id, Priority::Low);
        }
        for (s, subscribed) in self.sdo.channels().iter().zip(&mut self.sdo_subscribed) {
            let sdo = s.rx_id();
            if sdo != *subscribed {
                if let Some(old) = *subscribed {
                    let _ = port.unsubscribe(old);
                }
                if let Some(new) = sdo {
                    let _ = port.subscribe(new, Priority::Low);
                }
                *subscribed = sdo;
            }
        }
    }

    #[inline(never)] // out of `run`: its frame stays off the store path (docs/tms570.md)
    fn enter_state(&mut self, s: NmtState, port: &mut impl CanPort, now: Ticks) {
        let from = self.state;
        self.state = s;
        match s {
            NmtState::Initialisation => {
                self.hb.stop();
                self.sdo.cancel();
                self.sdoc.cancel_all();
            }
            NmtState::Stopped => self.sdo.cancel(),
            _ => {}
        }
        if from == NmtState::Initialisation && s == NmtState::PreOperational {
            // CiA 301: boot-up is 0x700 + node-ID with one byte 0x00.
            let _ = port.send(&nmt::encode_bootup(self.node_id), Priority::High);
            self.hb.start(now);
        }
        if s == NmtState::Operational && from != NmtState::Operational {
            self.srdo.subscribe(&self.od, port);
        }
        self.srdo.on_state(&self.od, s, self.node_id, now);
        self.pdo.on_state(s, now);
    }

    /// `CcmReadObject` / SDO-independent read.
    pub fn read_object(
        &self,
        index: u16,
        sub: u8,
        order: ByteOrder,
        out: &mut [u8],
    ) -> Result<usize, OdError> {
        self.od.read(index, sub, order, out)
    }

    /// `CcmWriteObject`: writes through the same checks and hooks as SDO.
    pub fn write_object(
        &mut self,
        index: u16,
        sub: u8,
        order: ByteOrder,
        data: &[u8],
        now: Ticks,
    ) -> Result<(), OdError> {
        let mut hooks = hooks!(self, now);
        let r = self.od.write(index, sub, order, data, &mut hooks);
        if hooks.sdo_changed {
            self.sdo.reconfigure(&self.od, self.node_id);
            self.sdoc.reconfigure(&self.od);
            // No port here: the driver learns the new identifiers at the
            // start of the next cycle.
            self.resubscribe = true;
        }
        r
    }

    /// `CcmSendEmergency`.
    pub fn send_emergency(
        &mut self,
        port: &mut impl CanPort,
        now: Ticks,
        e: Emergency,
    ) -> CopResult {
        if !self.connected || self.state == NmtState::Stopped {
            return Err(CopKernel::NmtStateError);
        }
        self.emcy.send(&self.od, port, now, e)
    }

    /// `CcmSendSrdo` for one SRDO (0 is handled by the caller, which
    /// iterates so that each SRDO's events are handled in turn).
    pub fn send_srdo(
        &mut self,
        port: &mut impl CanPort,
        commu_index: u16,
        now: Ticks,
    ) -> CopResult {
        self.srdo
            .send(port, self.state, commu_index, now, &mut self.queue, false)
            .map(|_| ())
    }

    /// [`Stack::send_srdo`] that, with `first`, returns the SRDO's success
    /// event (`Some(commu_index)` for `Event::SrdoEvent(commu_index)`)
    /// instead of queueing it when nothing else is queued (see
    /// [`crate::srdo::Srdo::send`]): the caller hands it to the
    /// application, then takes whatever [`Stack::has_queued`] says is left.
    pub fn send_srdo_first(
        &mut self,
        port: &mut impl CanPort,
        commu_index: u16,
        now: Ticks,
        first: bool,
    ) -> CopResult<Option<u16>> {
        self.srdo
            .send(port, self.state, commu_index, now, &mut self.queue, first)
    }

    /// True when events or internal work are queued (what [`Stack::drain`]
    /// would take).
    pub fn has_queued(&self) -> bool {
        !self.queue.is_empty()
    }
}

#[cfg(test)]
mod tests;

/// Sends the frame SDO server `s` holds, then `f`. One the driver refuses
/// (a full transmit buffer), or one that would overtake a frame still
/// waiting, is kept and goes in the next cycle ([`SdoServer::hold`]).
fn send_server_frame(s: &mut SdoServer, port: &mut impl CanPort, f: Option<CanFrame>) {
    for f in [s.take_held(), f].into_iter().flatten() {
        if s.holding() || port.send(&f, Priority::Low).is_err() {
            s.hold(f);
        }
    }
}
