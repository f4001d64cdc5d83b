//! Fault-injection campaign for SRDO reception: evidence that every fault
//! of the EN 50325-5 / CiA 304 fault model is detected with the SYS TEC
//! error code the library documents, at the moment it has to be, and that
//! legal traffic never raises an alarm.
//!
//! # Set-up
//! Three [`Device`]s of [`super::srdo_net`] on one [`SimBus`]: the producer
//! (node 1) sends SRDO 1 (two UNSIGNED16 pairs, DLC 4) with
//! `CcmSendSrdo`; the consumer (node 2) receives it with SCT 50 ms and SRVT
//! 20 ms, its receive queue holds 16 frames; the rogue (node 3) transmits
//! on the same COB-IDs with a mapping of one pair (DLC 2). Each device is a
//! complete stack configured the way a tool does it (CRC into 0x13FF, 0xA5
//! into 0x13FE) and started with NMT.
//!
//! The producer's and the rogue's frames are taken off the bus by the fault
//! filter, checked against the expected encoding (frame 2 = complement of
//! frame 1) and put back on the bus by the campaign at the planned times,
//! lost, changed, repeated or reordered. The consumer runs `CcmProcess`
//! every 0.5..3 ms (random); its application answers as manual 2.9.1 /
//! 2.9.2 ask and calls `CcmCheckSrdoConfig` in every 16th cycle (the
//! diagnostic interval of manual 2.8.2, about 28 ms). Time is simulated (100 µs ticks)
//! and the whole run follows from the seed.
//!
//! # Episodes
//! The run is a sequence of episodes. A fault-free episode is one producer
//! cycle with legal jitter: frame 1 anywhere between the end of the
//! previous pair and SCT after the first frame of the previous valid pair
//! (exactly SCT with probability 1/16), frame 2 0..SRVT after frame 1
//! (exactly SRVT with probability 1/16, together in the same tick with
//! 1/16). A fault episode (probability 1/5) injects one fault of a class
//! chosen uniformly, followed by one fault-free recovery cycle whose frame 1
//! comes within SCT of the last valid pair, so that a fault's consequences
//! are exactly the documented ones.
//!
//! Before an episode runs, the campaign writes down what the consumer must
//! report and in which of its processing cycles: every `AppSrdoEvent` with
//! the data of the pair, every `AppSrdoError` with its code, every failed
//! `CcmCheckSrdoConfig`, every SDO answer and every producer program-monitor
//! event. Each processing cycle's observations must equal the expectation
//! for that cycle, in order (overrun first, then the received frames, then
//! the timer phase, then the diagnostic check). An injected fault is
//! *detected* when everything expected of its episode was observed in the
//! expected cycles and nothing else was; an error event in a fault-free
//! episode is a *false alarm*.
//!
//! Checked in every cycle besides: inside `AppSrdoError` the status byte is
//! 0x50 (bits 4-5 = 01, bits 6-7 = 01) and `kSrdoPMEvSrdoError` follows the
//! callback; inside `AppSrdoEvent` bits 4-5 are 00 and
//! `kSrdoPMEvSrdoReceived` follows; `kCopSrdoNotHandledInApp` never occurs
//! (the application answers); the consumer's mapped variables change only
//! with a valid pair and then hold its normal data and their complement.
//! A breach is a *violation* and fails the run.
//!
//! # Fault classes and expected reactions
//! "Frame 1" is the normal frame (COB-ID 0x101), "frame 2" the inverted one
//! (0x102); "next cycle" is the consumer's first `CcmProcess` at or after
//! the instant named. With `SRDO_CHECK_SRVT_BEFORE_1STRX` the timer phase
//! finds an expired SRVT itself when a consumer cycle falls between SRVT
//! expiry and the next frame; the campaign knows the cycle times and
//! expects whichever applies.
//!
//! | class | what is injected | expected (default build) | with `SRDO_CHECK_SRVT_BEFORE_1STRX` |
//! |---|---|---|---|
//! | bit flip, frame 1 | one random data bit of frame 1 inverted | `kCopSrdoDataError` (0x0111) when frame 2 is processed; data not taken | same |
//! | bit flip, frame 2 | one random data bit of frame 2 inverted | `kCopSrdoDataError` | same |
//! | loss of frame 1 | frame 1 lost | `kCopSrdoNotInOrder` (0x010B) on frame 2 | same |
//! | loss of frame 2 | frame 2 lost | `kCopSrdoNotInOrder` on the next frame 1 (which is kept and completes the next pair) | `kCopSrdoSrvtTimeout` (0x010D) in the first cycle after SRVT, if it comes before the next frame 1 |
//! | reordering | frame 2 before frame 1 | `kCopSrdoNotInOrder` on frame 2, then as loss of frame 2 for the held frame 1 | same, with the SRVT rule for the held frame |
//! | repetition | frame 1 or frame 2 delivered twice (CAN retransmission) | frame 1 twice: `kCopSrdoNotInOrder`, then the pair is valid (same data); frame 2 twice: pair valid, then `kCopSrdoNotInOrder` | same |
//! | wrong DLC | frame 1 or frame 2 with a DLC other than 4 (0..8) | frame 1: `kCopSrdoDlcNotValid` (0x010F), then `kCopSrdoNotInOrder` on frame 2; frame 2: `kCopSrdoDlcNotValid` | same |
//! | frame 2 later than SRVT | frame 2 SRVT + 1..10 ms after frame 1 | `kCopSrdoSrvtTimeout` on frame 2 | `kCopSrdoSrvtTimeout` in the first cycle after SRVT, then `kCopSrdoNotInOrder` on the late frame 2 (or only the first when no cycle lies between) |
//! | producer silence | no pair for SCT + 0.1..100 ms | `kCopSrdoSctTimeout` (0x010C) once, in the first cycle after SCT (or on the late frame 1 when no cycle lies between); the producer's program monitor reports `kSrdoPMEvSrdoError` at its late send | same |
//! | masquerade | the rogue (same COB-IDs, one mapped pair, DLC 2) sends a complete, correctly inverted pair between two pairs of the producer, or inside one | between: `kCopSrdoDlcNotValid`, `kCopSrdoNotInOrder`; inside: `kCopSrdoDlcNotValid`, `kCopSrdoNotInOrder`, `kCopSrdoNotInOrder` (the producer's pair is lost) | same |
//! | configuration CRC | PRE-OPERATIONAL by NMT, SDO download of a changed SCT (0x1301 sub 2), SDO download 0xA5 to 0x13FE, NMT start; later repaired the same way | SCT write accepted (0x13FE becomes 0), 0xA5 refused with SDO abort 0x08000020, after the start the SRDO does not run, and `CcmCheckSrdoConfig` returns `kCopSrdoCfgCrcError` (0x0104) for 0x1301 at every diagnostic check from the write until the repair | same |
//! | tick-counter wrap | the 32-bit 100 µs counter wraps between frame 1 and frame 2 (a legal pair, or frame 2 later than SRVT), or between the start of the SCT and its expiry | legal pair: accepted, no error; late frame 2: as "frame 2 later than SRVT"; SCT: as "producer silence" | as in those classes |
//! | driver overrun | unrelated frames (0x181) overflow the consumer's queue after a pair, in front of a pair (the pair is lost) or in front of frame 2 (frame 2 is lost) | `kCopSrdoOverrun` (0x0114) first in the next cycle; frame 2 lost: then as loss of frame 2 | same |
//!
//! Modelled, and why it is enough: bit flips are in the data field of a
//! frame the CAN CRC did not catch (a corrupted identifier or DLC is the
//! masquerade or DLC class). The masquerade is a device with another
//! configuration whose frames differ in length; a rogue whose mapping has
//! the same length and which sends correctly inverted pairs cannot be told
//! apart at run time by any SRDO consumer (there is no sender field or
//! sequence counter in CiA 304) and is excluded by the configuration
//! process (CRC over the parameters, unique COB-IDs); the same holds for
//! the repetition of a complete pair. The tick-counter wrap is produced by
//! taking both nodes to PRE-OPERATIONAL, moving the simulated clock so that
//! the wrap falls where wanted, and starting them again; this happens only
//! while no SRDO runs, as after any restart.
//!
//! # Timing limits
//! Exactly at a limit is valid, one tick (100 µs) later is an error: frame
//! 2 exactly SRVT after frame 1 completes the pair, SRVT + 1 tick is
//! `kCopSrdoSrvtTimeout`; frame 1 exactly SCT after the previous valid
//! pair's frame 1 is in time, SCT + 1 tick is `kCopSrdoSctTimeout`. The
//! legal jitter hits both limits exactly (1/16 of the pairs each) and the
//! faults use one tick beyond them (1/8 of their cases); the report counts
//! these hits.

use std::cell::RefCell;
use std::collections::{BTreeMap, VecDeque};
use std::fmt::Write as _;
use std::rc::Rc;

use super::srdo_net::{
    COB_INVERTED, COB_NORMAL, DATA_LEN, Device, ROGUE_DATA_LEN, Role, SCT_MS, SRDO, SRVT_MS,
    answer_as_manual,
};
use super::{Delivery, SimBus};
use crate::ccm::NmtCommand;
use crate::config::{SRDO_CHECK_SRVT_BEFORE_1STRX, SRDO_USE_PROGMONITOR};
use crate::error::CopKernel;
use crate::event::{Event, ProgMonEvent};
use crate::port::{CanFrame, CanId, Ticks};
use crate::wire::nmt::{self, NmtCs};

/// SCT of the consumer (= refresh time of the producer) in ticks.
const SCT: u64 = SCT_MS as u64 * 10;
/// SRVT in ticks.
const SRVT: u64 = SRVT_MS as u64 * 10;
/// Shortest and longest distance between two consumer cycles, in ticks.
const POLL_MIN: u64 = 5;
const POLL_MAX: u64 = 30;
/// Every n-th consumer cycle runs the diagnostic `CcmCheckSrdoConfig`.
const DIAG_EVERY: u64 = 16;
/// Frames the consumer's driver queue holds.
const RX_CAPACITY: usize = 16;
/// First-send delay of a node after entering OPERATIONAL, per node-ID.
const FIRST_SEND_TICKS_PER_NODE: u64 = 5;
/// A fault cycle starts within this many ticks of the end of the previous
/// pair, so that its recovery pair still fits into the SCT.
const COMPACT: u64 = 100;
/// Identifier of the unrelated traffic that overflows the queue.
const FOREIGN_ID: u16 = 0x181;
/// SDO server of the consumer (CiA 301 default connection set).
const SDO_REQUEST: u16 = 0x602;
const SDO_RESPONSE: u16 = 0x582;

/// Order of the reports within one consumer cycle.
const PH_OVERRUN: u8 = 0;
const PH_FRAME: u8 = 1;
const PH_TIMER: u8 = 2;
const PH_DIAG: u8 = 3;

/// A small deterministic generator (SplitMix64: a 64-bit counter through a
/// fixed mixing function; every seed gives a full-period, well-spread
/// sequence, enough for choosing faults and jitter).
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator started from `seed`.
    pub const fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `lo..=hi` (`lo` when `hi < lo`); the modulo bias is below
    /// 2^-40 for the small ranges used here.
    pub fn range(&mut self, lo: u64, hi: u64) -> u64 {
        if hi <= lo {
            return lo;
        }
        lo + self.next_u64() % (hi - lo + 1)
    }

    /// True with probability 1/n.
    pub fn one_in(&mut self, n: u64) -> bool {
        self.range(1, n) == 1
    }
}

/// The fault classes (see the module documentation for each one).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Class {
    /// One data bit of the normal frame inverted.
    BitFlipNormal,
    /// One data bit of the inverted frame inverted.
    BitFlipInverted,
    /// The normal frame lost.
    LossNormal,
    /// The inverted frame lost.
    LossInverted,
    /// The inverted frame before the normal frame.
    Reordering,
    /// One frame of the pair delivered twice.
    Repetition,
    /// One frame of the pair with a wrong DLC.
    WrongDlc,
    /// The inverted frame later than SRVT.
    LateInverted,
    /// No pair for longer than SCT.
    ProducerSilence,
    /// A pair from a device with another configuration on the same COB-IDs.
    Masquerade,
    /// A parameter changed over SDO without a new CRC.
    ConfigCrc,
    /// The 32-bit tick counter wraps during a pair or an SCT.
    TickWrap,
    /// The consumer's receive queue overflows.
    Overrun,
}

impl Class {
    /// Every class, in table order.
    pub const ALL: [Class; 13] = [
        Class::BitFlipNormal,
        Class::BitFlipInverted,
        Class::LossNormal,
        Class::LossInverted,
        Class::Reordering,
        Class::Repetition,
        Class::WrongDlc,
        Class::LateInverted,
        Class::ProducerSilence,
        Class::Masquerade,
        Class::ConfigCrc,
        Class::TickWrap,
        Class::Overrun,
    ];

    /// Short name for the table.
    pub const fn name(self) -> &'static str {
        match self {
            Class::BitFlipNormal => "bit flip, normal frame",
            Class::BitFlipInverted => "bit flip, inverted frame",
            Class::LossNormal => "loss of normal frame",
            Class::LossInverted => "loss of inverted frame",
            Class::Reordering => "reordering",
            Class::Repetition => "repetition",
            Class::WrongDlc => "wrong DLC",
            Class::LateInverted => "inverted frame > SRVT",
            Class::ProducerSilence => "producer silence > SCT",
            Class::Masquerade => "masquerade",
            Class::ConfigCrc => "configuration CRC",
            Class::TickWrap => "tick-counter wrap",
            Class::Overrun => "driver overrun",
        }
    }

    /// The expected reaction in short (the module documentation has it in
    /// full).
    pub const fn expected(self) -> &'static str {
        match self {
            Class::BitFlipNormal | Class::BitFlipInverted => "DataError",
            Class::LossNormal => "NotInOrder",
            Class::LossInverted => "NotInOrder (next frame 1) | SrvtTimeout*",
            Class::Reordering => "NotInOrder, then NotInOrder | SrvtTimeout*",
            Class::Repetition => "NotInOrder (+ valid pair)",
            Class::WrongDlc => "DlcNotValid (+ NotInOrder)",
            Class::LateInverted => "SrvtTimeout (* + NotInOrder)",
            Class::ProducerSilence => "SctTimeout once (+ producer PM)",
            Class::Masquerade => "DlcNotValid, NotInOrder (x1|x2)",
            Class::ConfigCrc => "abort 0x08000020, CfgCrcError",
            Class::TickWrap => "none | SrvtTimeout | SctTimeout",
            Class::Overrun => "Overrun (+ loss consequences)",
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// Counts of one fault class.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClassStats {
    /// Episodes with this fault.
    pub injected: u64,
    /// Episodes in which everything expected was observed in time and
    /// nothing else.
    pub detected: u64,
    /// Expected observations that did not come (or not in their cycle).
    pub missed: u64,
    /// Error events in these episodes that were not expected.
    pub false_alarms: u64,
}

/// What a campaign found.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// Seed of the run.
    pub seed: u64,
    /// Producer cycles simulated (each planned pair or silent slot).
    pub cycles: u64,
    /// Consumer processing cycles (`CcmProcess`).
    pub consumer_cycles: u64,
    /// Simulated time in ticks of 100 µs.
    pub simulated_ticks: u64,
    /// Fault-free episodes (one cycle each).
    pub fault_free: u64,
    /// Error events during fault-free episodes.
    pub false_alarms: u64,
    /// Valid pairs of fault-free episodes that were not accepted in time.
    pub lost_pairs: u64,
    /// Per class, in the order of [`Class::ALL`].
    pub classes: [ClassStats; 13],
    /// Status byte, callback order, variable or producer check breaches.
    pub violations: u64,
    /// Legal pairs whose frame 2 came exactly SRVT after frame 1.
    pub at_srvt: u64,
    /// Legal pairs whose frame 1 came exactly SCT after the previous valid
    /// pair's frame 1.
    pub at_sct: u64,
    /// Faults exactly one tick beyond SRVT.
    pub srvt_plus_one: u64,
    /// Faults exactly one tick beyond SCT.
    pub sct_plus_one: u64,
    /// Wraps of the bus's 32-bit tick counter during the run.
    pub counter_wraps: u64,
    /// The first few failures, described.
    pub failures: Vec<String>,
    /// Timing of every planned pair, in planning order (only with
    /// [`Config::record_pairs`]).
    pub pairs: Vec<PairTiming>,
}

/// Timing of one SRDO pair of the campaign, in ticks of 100 µs (the
/// evidence report's timing plot): the legal pairs the consumer had to
/// accept and the pairs that broke SRVT or SCT on purpose. A passing run
/// has checked every one: each legal pair was accepted in the cycle that
/// processed its frame 2, each late one reported.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PairTiming {
    /// From frame 1 to frame 2 (limit: SRVT).
    pub gap_ticks: u64,
    /// From frame 1 of the previous valid pair to this frame 1 (limit: SCT).
    pub period_ticks: u64,
    /// `None`: accepted without error. `SrdoSrvtTimeout`: frame 2 later
    /// than SRVT, reported. `SrdoSctTimeout`: frame 1 later than SCT, the
    /// timeout reported, then the pair accepted.
    pub reported: Option<CopKernel>,
}

impl PairTiming {
    /// SRVT of the campaign in ticks.
    pub const SRVT_TICKS: u64 = SRVT;
    /// SCT of the campaign in ticks.
    pub const SCT_TICKS: u64 = SCT;
}

impl Report {
    /// Stats of one class.
    pub fn class(&self, c: Class) -> ClassStats {
        self.classes.get(c.index()).copied().unwrap_or_default()
    }

    /// True when every injected fault was detected, nothing else was
    /// reported and no check was breached.
    pub fn passed(&self) -> bool {
        self.false_alarms == 0
            && self.lost_pairs == 0
            && self.violations == 0
            && self.classes.iter().all(|c| c.detected == c.injected)
            && self.failures.is_empty()
    }

    /// The table: class, injected, detected, false alarms, expected codes.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "| {:<26} | {:>9} | {:>9} | {:>6} | {:>12} | {:<41} |",
            "class", "injected", "detected", "missed", "false alarms", "expected (kCopSrdo...)"
        );
        let _ = writeln!(
            s,
            "|{:-<28}|{:->11}|{:->11}|{:->8}|{:->14}|{:-<43}|",
            "", "", "", "", "", ""
        );
        for c in Class::ALL {
            let st = self.class(c);
            let _ = writeln!(
                s,
                "| {:<26} | {:>9} | {:>9} | {:>6} | {:>12} | {:<41} |",
                c.name(),
                st.injected,
                st.detected,
                st.missed,
                st.false_alarms,
                c.expected()
            );
        }
        let _ = writeln!(
            s,
            "| {:<26} | {:>9} | {:>9} | {:>6} | {:>12} | {:<41} |",
            "fault-free cycles",
            self.fault_free,
            "-",
            self.lost_pairs,
            self.false_alarms,
            "valid pair accepted, nothing else"
        );
        let _ = writeln!(
            s,
            "* SRDO_CHECK_SRVT_BEFORE_1STRX: {}; program monitor: {}",
            SRDO_CHECK_SRVT_BEFORE_1STRX, SRDO_USE_PROGMONITOR
        );
        let _ = writeln!(
            s,
            "seed {:#x}: {} producer cycles, {} consumer cycles, {:.1} s simulated, \
             {} counter wraps; limits hit: frame 2 at SRVT {}, frame 1 at SCT {}, \
             SRVT + 1 tick {}, SCT + 1 tick {}; violations {}",
            self.seed,
            self.cycles,
            self.consumer_cycles,
            self.simulated_ticks as f64 / 10_000.0,
            self.counter_wraps,
            self.at_srvt,
            self.at_sct,
            self.srvt_plus_one,
            self.sct_plus_one,
            self.violations
        );
        for f in &self.failures {
            let _ = writeln!(s, "FAILURE: {f}");
        }
        s
    }
}

/// Parameters of a campaign.
#[derive(Clone, Copy, Debug)]
pub struct Config {
    /// Producer cycles to simulate (at least).
    pub cycles: u64,
    /// Seed of the generator.
    pub seed: u64,
    /// One episode in this many injects a fault.
    pub fault_one_in: u64,
    /// Keep the timing of every pair in [`Report::pairs`].
    pub record_pairs: bool,
}

impl Config {
    /// `cycles` with `seed` and one fault episode in five.
    pub const fn new(cycles: u64, seed: u64) -> Config {
        Config {
            cycles,
            seed,
            fault_one_in: 5,
            record_pairs: false,
        }
    }
}

/// Runs a campaign. `Err` when the devices cannot be set up (a defect of
/// the set-up, not a finding).
pub fn run(cfg: &Config) -> Result<Report, String> {
    let _guard = super::srdo_net::lock();
    let mut sim = Sim::new(cfg)?;
    while sim.report.cycles < cfg.cycles {
        sim.plan_episode(cfg.fault_one_in);
        sim.run_actions();
    }
    sim.finish();
    Ok(sim.report)
}

/// An observation of the consumer's application.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Obs {
    /// `AppSrdoEvent`; the normal data the variables then held.
    Accept([u8; DATA_LEN]),
    /// `AppSrdoError` with this code.
    Error(CopKernel),
    /// `CcmCheckSrdoConfig` failed with (code, communication index).
    Config(CopKernel, u16),
}

/// An SDO answer of the consumer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SdoReply {
    Done(u16, u8),
    Abort(u16, u8, u32),
    Other([u8; 8]),
}

#[derive(Clone, Copy, Debug)]
enum Act {
    ProducerSend {
        data: [u8; DATA_LEN],
        late: bool,
    },
    RogueSend {
        data: [u8; ROGUE_DATA_LEN],
    },
    Deliver(CanFrame),
    /// Unrelated frames: this many, or (None) exactly as many as the
    /// consumer's queue still takes.
    Burst(Option<usize>),
    Nmt(NmtCs),
    Local(Role, NmtCommand),
    Sdo([u8; 8]),
    Jump(u32),
    Check {
        running: bool,
        valid: u8,
    },
}

#[derive(Clone, Copy, Debug)]
struct Action {
    t: u64,
    late: bool,
    seq: u64,
    ep: u64,
    kind: Act,
}

#[derive(Clone, Copy, Debug)]
struct Poll {
    t: u64,
    diag: bool,
}

#[derive(Clone, Debug)]
struct Episode {
    id: u64,
    class: Option<Class>,
    variant: &'static str,
    remaining: u64,
    missed: u64,
    unexpected: u64,
    broken: bool,
}

#[derive(Default)]
struct Capture {
    /// Frames the producer and the rogue sent (taken off the bus).
    tx: Vec<CanFrame>,
    /// SDO answers of the consumer.
    sdo: Vec<CanFrame>,
}

type Key = (u64, u8, u64);

struct Sim {
    rng: Rng,
    bus: SimBus,
    producer: Device,
    consumer: Device,
    rogue: Device,
    capture: Rc<RefCell<Capture>>,
    /// Simulated time in ticks since the start (never wraps).
    abs: u64,
    /// Bus ticks = `abs` + `offset` (mod 2^32).
    offset: u32,
    polls: VecDeque<Poll>,
    last_poll: u64,
    poll_count: u64,
    actions: Vec<Action>,
    seq: u64,
    expected: BTreeMap<Key, (Obs, u64)>,
    sdo_expected: VecDeque<(SdoReply, u64)>,
    episodes: VecDeque<Episode>,
    next_ep: u64,
    current_ep: u64,
    // Planning state.
    last_valid: u64,
    free_from: u64,
    prod_ref: u64,
    rogue_ready: u64,
    last_data: [u8; DATA_LEN],
    // Observation state.
    values: ([u8; DATA_LEN], [u8; DATA_LEN]),
    report: Report,
    record_pairs: bool,
}

fn complement<const N: usize>(d: [u8; N]) -> [u8; N] {
    d.map(|b| !b)
}

fn frame(id: u16, data: &[u8]) -> CanFrame {
    CanFrame::new(CanId::std_masked(id), data)
}

fn describe(v: &[Obs]) -> String {
    let parts: Vec<String> = v
        .iter()
        .map(|o| match o {
            Obs::Accept(d) => format!("Accept({d:02X?})"),
            Obs::Error(c) => format!("{c:?}"),
            Obs::Config(c, i) => format!("Config({c:?}, {i:#06x})"),
        })
        .collect();
    format!("[{}]", parts.join(", "))
}

impl Sim {
    fn new(cfg: &Config) -> Result<Sim, String> {
        let mut rng = Rng::new(cfg.seed);
        let bus = SimBus::new();
        // Any epoch: long runs may cross the counter wrap on their own.
        let start = rng.next_u64() as u32;
        bus.set_time(Ticks(start));
        let setup = |e: String| format!("set-up: {e}");
        let mut producer =
            Device::new(&bus, Role::Producer, 0).map_err(|e| setup(format!("{e:?}")))?;
        let mut consumer =
            Device::new(&bus, Role::Consumer, RX_CAPACITY).map_err(|e| setup(format!("{e:?}")))?;
        let mut rogue = Device::new(&bus, Role::Rogue, 0).map_err(|e| setup(format!("{e:?}")))?;
        for d in [&mut producer, &mut consumer, &mut rogue] {
            d.seal().map_err(|e| setup(format!("seal: {e:?}")))?;
        }
        consumer.process(|_, _| {});
        let capture = Rc::new(RefCell::new(Capture::default()));
        let cap = Rc::clone(&capture);
        let (p, c, r) = (
            producer.port.node(),
            consumer.port.node(),
            rogue.port.node(),
        );
        bus.set_filter(Some(Box::new(move |from, f: &mut CanFrame| {
            if from == p || from == r {
                cap.borrow_mut().tx.push(*f);
                return Delivery::Drop;
            }
            if from == c && f.id == CanId::std_masked(SDO_RESPONSE) {
                cap.borrow_mut().sdo.push(*f);
            }
            Delivery::Deliver
        })));
        for d in [&mut producer, &mut consumer, &mut rogue] {
            d.command(NmtCommand::StartRemoteNode)
                .map_err(|e| setup(format!("start: {e:?}")))?;
        }
        if !consumer.stack.srdo().is_running() || !producer.stack.srdo().is_running() {
            return Err(setup("SRDOs not running".into()));
        }
        consumer.process(|_, _| {});
        capture.borrow_mut().tx.clear();
        bus.clear_trace();
        let report = Report {
            seed: cfg.seed,
            ..Report::default()
        };
        Ok(Sim {
            rng,
            bus,
            producer,
            consumer,
            rogue,
            capture,
            abs: 0,
            offset: start,
            polls: VecDeque::new(),
            last_poll: 0,
            poll_count: 0,
            actions: Vec::new(),
            seq: 0,
            expected: BTreeMap::new(),
            sdo_expected: VecDeque::new(),
            episodes: VecDeque::new(),
            next_ep: 0,
            current_ep: 0,
            last_valid: 0,
            free_from: FIRST_SEND_TICKS_PER_NODE,
            prod_ref: FIRST_SEND_TICKS_PER_NODE,
            rogue_ready: FIRST_SEND_TICKS_PER_NODE * 3,
            last_data: [0; DATA_LEN],
            values: ([0; DATA_LEN], [0; DATA_LEN]),
            report,
            record_pairs: cfg.record_pairs,
        })
    }

    // ------------------------------------------------------------ polls

    /// Plans consumer cycles at least up to `t`.
    fn ensure_polls(&mut self, t: u64) {
        while self.polls.back().map_or(self.last_poll, |p| p.t) < t {
            let prev = self.polls.back().map_or(self.last_poll, |p| p.t);
            self.poll_count += 1;
            let p = Poll {
                t: prev + self.rng.range(POLL_MIN, POLL_MAX),
                diag: self.poll_count % DIAG_EVERY == 0,
            };
            self.polls.push_back(p);
        }
    }

    /// The first consumer cycle at or after `t` (a frame delivered at `t`
    /// is processed in it).
    fn cycle_at(&mut self, t: u64) -> u64 {
        self.ensure_polls(t);
        self.polls.iter().find(|p| p.t >= t).map_or(t, |p| p.t)
    }

    /// The first consumer cycle strictly after `t` (a timer that expires
    /// at `t` is found in it).
    fn cycle_after(&mut self, t: u64) -> u64 {
        self.cycle_at(t + 1)
    }

    // --------------------------------------------------------- planning

    fn act_at(&mut self, t: u64, late: bool, kind: Act) -> u64 {
        // Steps of 4 leave room for several reports caused by one action.
        self.seq += 4;
        self.actions.push(Action {
            t,
            late,
            seq: self.seq,
            ep: self.current_ep,
            kind,
        });
        self.seq
    }

    fn act(&mut self, t: u64, kind: Act) -> u64 {
        self.act_at(t, false, kind)
    }

    fn expect(&mut self, cycle: u64, phase: u8, seq: u64, obs: Obs) {
        let mut key = (cycle, phase, seq);
        while self.expected.contains_key(&key) {
            key.2 += 1;
        }
        self.expected.insert(key, (obs, self.current_ep));
        self.count_expectation();
    }

    fn count_expectation(&mut self) {
        let id = self.current_ep;
        if let Some(e) = self.episode_mut(id) {
            e.remaining += 1;
        }
    }

    fn episode_mut(&mut self, id: u64) -> Option<&mut Episode> {
        let front = self.episodes.front()?.id;
        let pos = usize::try_from(id.checked_sub(front)?).ok()?;
        self.episodes.get_mut(pos)
    }

    fn fresh_data(&mut self) -> [u8; DATA_LEN] {
        loop {
            let d = (self.rng.next_u64() as u32).to_le_bytes();
            if d != self.last_data {
                self.last_data = d;
                return d;
            }
        }
    }

    /// The producer sends a pair at `t`; returns its data and frames. Its
    /// program monitor reports lateness when the refresh time has passed.
    fn send_pair(&mut self, t: u64) -> ([u8; DATA_LEN], CanFrame, CanFrame) {
        let data = self.fresh_data();
        let late = SRDO_USE_PROGMONITOR && t.saturating_sub(self.prod_ref) > SCT;
        self.prod_ref = t;
        self.act(t, Act::ProducerSend { data, late });
        (
            data,
            frame(COB_NORMAL, &data),
            frame(COB_INVERTED, &complement(data)),
        )
    }

    /// A legal gap between frame 1 and frame 2: 0..=SRVT, both limits
    /// with probability 1/16.
    fn legal_gap(&mut self) -> u64 {
        match self.rng.range(0, 15) {
            0 => SRVT,
            1 => 0,
            _ => self.rng.range(0, SRVT),
        }
    }

    /// A valid pair with frame 1 at `tn` and frame 2 `gap` later; returns
    /// the sequence number of frame 1.
    fn valid_pair_at(&mut self, tn: u64, gap: u64) -> u64 {
        if gap == SRVT {
            self.report.at_srvt += 1;
        }
        if tn == self.last_valid + SCT {
            self.report.at_sct += 1;
        }
        let reported = (tn > self.last_valid + SCT).then_some(CopKernel::SrdoSctTimeout);
        self.record_pair(tn, gap, reported);
        let pair = self.send_pair(tn);
        let n_seq = self.deliver_accepted(tn, gap, pair);
        self.free_from = tn + gap;
        self.report.cycles += 1;
        n_seq
    }

    /// Delivers the frames of `pair` (as `send_pair` returns it) at `tn`
    /// and `gap` later, the consumer accepting the pair; returns the
    /// sequence number of frame 1.
    fn deliver_accepted(
        &mut self,
        tn: u64,
        gap: u64,
        (data, n, i): ([u8; DATA_LEN], CanFrame, CanFrame),
    ) -> u64 {
        let n_seq = self.act(tn, Act::Deliver(n));
        let i_seq = self.act(tn + gap, Act::Deliver(i));
        let c = self.cycle_at(tn + gap);
        self.expect(c, PH_FRAME, i_seq, Obs::Accept(data));
        self.last_valid = tn;
        n_seq
    }

    fn record_pair(&mut self, tn: u64, gap: u64, reported: Option<CopKernel>) {
        if self.record_pairs {
            self.report.pairs.push(PairTiming {
                gap_ticks: gap,
                period_ticks: tn.saturating_sub(self.last_valid),
                reported,
            });
        }
    }

    /// A fault-free cycle with legal jitter, frame 1 not before `earliest`
    /// and not later than SCT after the last valid pair. Returns (time of
    /// frame 1, its sequence number).
    fn legal_pair(&mut self, earliest: u64) -> (u64, u64) {
        let deadline = self.last_valid + SCT;
        let tn = if self.rng.one_in(16) {
            deadline.max(earliest)
        } else {
            self.rng.range(earliest, deadline)
        };
        let gap = self.legal_gap();
        (tn, self.valid_pair_at(tn, gap))
    }

    /// A normal frame received at `held_at` is still held when the next
    /// normal frame (`next_seq`, at `next_at`) arrives: either the timer
    /// phase drops it after SRVT (only with SRDO_CHECK_SRVT_BEFORE_1STRX
    /// and a consumer cycle in between), or the next frame finds it.
    fn held_until_next_normal(&mut self, held_at: u64, held_seq: u64, next_at: u64, next_seq: u64) {
        if SRDO_CHECK_SRVT_BEFORE_1STRX {
            let q = self.cycle_after(held_at + SRVT);
            if q < next_at {
                self.expect(
                    q,
                    PH_TIMER,
                    held_seq,
                    Obs::Error(CopKernel::SrdoSrvtTimeout),
                );
                return;
            }
        }
        let c = self.cycle_at(next_at);
        self.expect(c, PH_FRAME, next_seq, Obs::Error(CopKernel::SrdoNotInOrder));
    }

    /// Frame 2 `SRVT + extra` after frame 1 at `tn`.
    fn late_inverted(&mut self, tn: u64, extra: u64) {
        if extra == 1 {
            self.report.srvt_plus_one += 1;
        }
        self.record_pair(tn, SRVT + extra, Some(CopKernel::SrdoSrvtTimeout));
        let (_, n, i) = self.send_pair(tn);
        let n_seq = self.act(tn, Act::Deliver(n));
        let ti = tn + SRVT + extra;
        let i_seq = self.act(ti, Act::Deliver(i));
        self.report.cycles += 1;
        let c = self.cycle_at(ti);
        if SRDO_CHECK_SRVT_BEFORE_1STRX {
            let q = self.cycle_after(tn + SRVT);
            if q < ti {
                self.expect(q, PH_TIMER, n_seq, Obs::Error(CopKernel::SrdoSrvtTimeout));
                self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoNotInOrder));
                self.free_from = ti;
                return;
            }
        }
        self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoSrvtTimeout));
        self.free_from = ti;
    }

    /// After no valid pair since `last_valid`, the next pair comes
    /// `extra` ticks after the SCT deadline: one SCT timeout, found by the
    /// timer phase or by the late frame 1.
    fn sct_expiry(&mut self, extra: u64) {
        if extra == 1 {
            self.report.sct_plus_one += 1;
        }
        let deadline = self.last_valid + SCT;
        let t2 = deadline + extra;
        let q = self.cycle_after(deadline);
        let gap = self.legal_gap();
        let n2_seq = self.valid_pair_at(t2, gap);
        if q < t2 {
            self.expect(q, PH_TIMER, n2_seq, Obs::Error(CopKernel::SrdoSctTimeout));
        } else {
            self.expect(q, PH_FRAME, n2_seq, Obs::Error(CopKernel::SrdoSctTimeout));
        }
    }

    fn sdo_download(&mut self, t: u64, index: u16, sub: u8, value: u32, len: u8, reply: SdoReply) {
        // CiA 301 7.2.4.3.3, initiate download, expedited, size indicated:
        // ccs = 1, n = 4 - len, e = 1, s = 1.
        let cmd = 0x20 | ((4 - len) << 2) | 0x03;
        let [i0, i1] = index.to_le_bytes();
        let [v0, v1, v2, v3] = value.to_le_bytes();
        self.act(t, Act::Sdo([cmd, i0, i1, sub, v0, v1, v2, v3]));
        self.sdo_expected.push_back((reply, self.current_ep));
        self.count_expectation();
    }

    fn nmt_all(&mut self, t: u64, cs: NmtCs, cmd: NmtCommand) {
        self.act(t, Act::Local(Role::Producer, cmd));
        self.act(t, Act::Local(Role::Rogue, cmd));
        self.act(t, Act::Nmt(cs));
    }

    fn plan_episode(&mut self, fault_one_in: u64) {
        let class = if self.rng.one_in(fault_one_in) {
            let i = self.rng.range(0, Class::ALL.len() as u64 - 1) as usize;
            Class::ALL.get(i).copied()
        } else {
            None
        };
        self.current_ep = self.next_ep;
        self.next_ep += 1;
        self.episodes.push_back(Episode {
            id: self.current_ep,
            class,
            variant: "",
            remaining: 0,
            missed: 0,
            unexpected: 0,
            broken: false,
        });
        match class {
            None => {
                let e = self.free_from;
                self.legal_pair(e);
            }
            Some(c) => {
                let variant = self.plan_fault(c);
                let id = self.current_ep;
                if let Some(e) = self.episode_mut(id) {
                    e.variant = variant;
                }
            }
        }
    }

    /// Plans the fault cycle and its recovery; returns the variant name.
    fn plan_fault(&mut self, class: Class) -> &'static str {
        let deadline = self.last_valid + SCT;
        let tn = self.free_from + self.rng.range(0, COMPACT);
        let gap = self.rng.range(0, SRVT);
        match class {
            Class::BitFlipNormal | Class::BitFlipInverted => {
                let (_, mut n, mut i) = self.send_pair(tn);
                let bit = self.rng.range(0, DATA_LEN as u64 * 8 - 1) as usize;
                let f = if class == Class::BitFlipNormal {
                    &mut n
                } else {
                    &mut i
                };
                if let Some(b) = f.data.get_mut(bit / 8) {
                    *b ^= 1 << (bit % 8);
                }
                self.act(tn, Act::Deliver(n));
                let i_seq = self.act(tn + gap, Act::Deliver(i));
                let c = self.cycle_at(tn + gap);
                self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoDataError));
                self.report.cycles += 1;
                self.free_from = tn + gap;
                self.legal_pair(tn + gap);
                "data bit"
            }
            Class::LossNormal => {
                let (_, _, i) = self.send_pair(tn);
                let i_seq = self.act(tn + gap, Act::Deliver(i));
                let c = self.cycle_at(tn + gap);
                self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoNotInOrder));
                self.report.cycles += 1;
                self.legal_pair(tn + gap);
                "frame 1 lost"
            }
            Class::LossInverted => {
                let (_, n, _) = self.send_pair(tn);
                let n_seq = self.act(tn, Act::Deliver(n));
                self.report.cycles += 1;
                let (t2, n2_seq) = self.legal_pair(tn + gap);
                self.held_until_next_normal(tn, n_seq, t2, n2_seq);
                "frame 2 lost"
            }
            Class::Reordering => {
                let (_, n, i) = self.send_pair(tn);
                let i_seq = self.act(tn, Act::Deliver(i));
                let n_seq = self.act(tn + gap, Act::Deliver(n));
                let c = self.cycle_at(tn);
                self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoNotInOrder));
                self.report.cycles += 1;
                let (t2, n2_seq) = self.legal_pair(tn + gap);
                self.held_until_next_normal(tn + gap, n_seq, t2, n2_seq);
                "frame 2 first"
            }
            Class::Repetition => {
                let (data, n, i) = self.send_pair(tn);
                self.report.cycles += 1;
                if self.rng.one_in(2) {
                    let again = self.rng.range(tn, tn + gap);
                    self.act(tn, Act::Deliver(n));
                    let n2_seq = self.act(again, Act::Deliver(n));
                    let i_seq = self.act(tn + gap, Act::Deliver(i));
                    let c = self.cycle_at(again);
                    self.expect(c, PH_FRAME, n2_seq, Obs::Error(CopKernel::SrdoNotInOrder));
                    let c = self.cycle_at(tn + gap);
                    self.expect(c, PH_FRAME, i_seq, Obs::Accept(data));
                    // The repeated frame 1 completes the pair: SCT runs
                    // from it.
                    self.last_valid = again;
                    self.legal_pair(tn + gap);
                    "frame 1 twice"
                } else {
                    let again = tn + gap + self.rng.range(0, COMPACT / 2);
                    self.act(tn, Act::Deliver(n));
                    let i_seq = self.act(tn + gap, Act::Deliver(i));
                    let i2_seq = self.act(again, Act::Deliver(i));
                    let c = self.cycle_at(tn + gap);
                    self.expect(c, PH_FRAME, i_seq, Obs::Accept(data));
                    let c = self.cycle_at(again);
                    self.expect(c, PH_FRAME, i2_seq, Obs::Error(CopKernel::SrdoNotInOrder));
                    self.last_valid = tn;
                    self.legal_pair(again);
                    "frame 2 twice"
                }
            }
            Class::WrongDlc => {
                let (_, mut n, mut i) = self.send_pair(tn);
                let dlc = loop {
                    let d = self.rng.range(0, 8) as u8;
                    if usize::from(d) != DATA_LEN {
                        break d;
                    }
                };
                let on_normal = self.rng.one_in(2);
                let f = if on_normal { &mut n } else { &mut i };
                // Bytes beyond the data are whatever the faulty sender had.
                for b in f.data.iter_mut().skip(DATA_LEN) {
                    *b = self.rng.next_u64() as u8;
                }
                for b in f.data.iter_mut().skip(usize::from(dlc)) {
                    *b = 0;
                }
                f.len = dlc;
                let n_seq = self.act(tn, Act::Deliver(n));
                let i_seq = self.act(tn + gap, Act::Deliver(i));
                self.report.cycles += 1;
                if on_normal {
                    let c = self.cycle_at(tn);
                    self.expect(c, PH_FRAME, n_seq, Obs::Error(CopKernel::SrdoDlcNotValid));
                    let c = self.cycle_at(tn + gap);
                    self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoNotInOrder));
                } else {
                    let c = self.cycle_at(tn + gap);
                    self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoDlcNotValid));
                }
                self.legal_pair(tn + gap);
                if on_normal { "frame 1" } else { "frame 2" }
            }
            Class::LateInverted => {
                // Room for frame 2 and the recovery pair before the SCT.
                let room = deadline.saturating_sub(self.free_from + SRVT + 1);
                let tn = self.free_from + self.rng.range(0, COMPACT.min(room));
                let extra = if self.rng.one_in(8) {
                    1
                } else {
                    self.rng
                        .range(1, deadline.saturating_sub(tn + SRVT).min(COMPACT))
                };
                self.late_inverted(tn, extra);
                let e = self.free_from;
                self.legal_pair(e);
                "late frame 2"
            }
            Class::ProducerSilence => {
                self.report.cycles += 1;
                let extra = if self.rng.one_in(8) {
                    1
                } else {
                    self.rng.range(1, 2 * SCT)
                };
                self.sct_expiry(extra);
                "silence"
            }
            Class::Masquerade => self.plan_masquerade(tn.max(self.rogue_ready), gap),
            Class::ConfigCrc => self.plan_config_crc(),
            Class::TickWrap => self.plan_tick_wrap(),
            Class::Overrun => self.plan_overrun(tn, gap),
        }
    }

    fn plan_masquerade(&mut self, tn: u64, gap: u64) -> &'static str {
        let rogue = (self.rng.next_u64() as u16).to_le_bytes();
        let (nr, ir) = (
            frame(COB_NORMAL, &rogue),
            frame(COB_INVERTED, &complement(rogue)),
        );
        let (data, n, i) = self.send_pair(tn);
        self.report.cycles += 1;
        if self.rng.one_in(2) {
            // Between two pairs of the producer.
            self.deliver_accepted(tn, gap, (data, n, i));
            let tr = tn + gap + self.rng.range(0, COMPACT / 2);
            let tir = tr + self.rng.range(0, SRVT);
            self.act(tr, Act::RogueSend { data: rogue });
            let nr_seq = self.act(tr, Act::Deliver(nr));
            let ir_seq = self.act(tir, Act::Deliver(ir));
            let c = self.cycle_at(tr);
            self.expect(c, PH_FRAME, nr_seq, Obs::Error(CopKernel::SrdoDlcNotValid));
            let c = self.cycle_at(tir);
            self.expect(c, PH_FRAME, ir_seq, Obs::Error(CopKernel::SrdoNotInOrder));
            self.legal_pair(tir);
            "between pairs"
        } else {
            // Inside a pair of the producer.
            let tr = self.rng.range(tn, tn + gap);
            let tir = self.rng.range(tr, tn + gap);
            self.act(tn, Act::Deliver(n));
            self.act(tr, Act::RogueSend { data: rogue });
            let nr_seq = self.act(tr, Act::Deliver(nr));
            let ir_seq = self.act(tir, Act::Deliver(ir));
            let i_seq = self.act(tn + gap, Act::Deliver(i));
            let c = self.cycle_at(tr);
            self.expect(c, PH_FRAME, nr_seq, Obs::Error(CopKernel::SrdoDlcNotValid));
            let c = self.cycle_at(tir);
            self.expect(c, PH_FRAME, ir_seq, Obs::Error(CopKernel::SrdoNotInOrder));
            let c = self.cycle_at(tn + gap);
            self.expect(c, PH_FRAME, i_seq, Obs::Error(CopKernel::SrdoNotInOrder));
            self.legal_pair(tn + gap);
            "inside a pair"
        }
    }

    fn plan_overrun(&mut self, tn: u64, gap: u64) -> &'static str {
        let (data, n, i) = self.send_pair(tn);
        self.report.cycles += 1;
        match self.rng.range(0, 2) {
            0 => {
                self.deliver_accepted(tn, gap, (data, n, i));
                let tb = tn + gap + self.rng.range(0, COMPACT / 2);
                let n_burst = RX_CAPACITY + 1 + self.rng.range(0, 7) as usize;
                let b_seq = self.act(tb, Act::Burst(Some(n_burst)));
                let c = self.cycle_at(tb);
                self.expect(c, PH_OVERRUN, b_seq, Obs::Error(CopKernel::SrdoOverrun));
                // The next frame must find room again.
                self.legal_pair(c + 1);
                "after a pair"
            }
            1 => {
                let b_seq = self.act(tn, Act::Burst(None));
                self.act(tn, Act::Deliver(n));
                self.act(tn, Act::Deliver(i));
                let c = self.cycle_at(tn);
                self.expect(c, PH_OVERRUN, b_seq, Obs::Error(CopKernel::SrdoOverrun));
                self.legal_pair(c + 1);
                "pair lost"
            }
            _ => {
                // The cycle that reports the overrun still lies within the
                // SCT, so the recovery pair can come in time.
                let room = (self.last_valid + SCT).saturating_sub(tn + POLL_MAX + 1);
                let gap = gap.min(room);
                let n_seq = self.act(tn, Act::Deliver(n));
                let b_seq = self.act(tn + gap, Act::Burst(None));
                self.act(tn + gap, Act::Deliver(i));
                let c = self.cycle_at(tn + gap);
                self.expect(c, PH_OVERRUN, b_seq, Obs::Error(CopKernel::SrdoOverrun));
                let (t2, n2_seq) = self.legal_pair(c + 1);
                self.held_until_next_normal(tn, n_seq, t2, n2_seq);
                "frame 2 lost"
            }
        }
    }

    /// A moment 1..29 ticks after `after` (the steps of a reconfiguration).
    fn soon_after(&mut self, after: u64) -> u64 {
        after + self.rng.range(1, 30)
    }

    /// The NMT command `cs` soon after `after`; the cycle that handles it.
    fn nmt_soon_after(&mut self, after: u64, cs: NmtCs) -> u64 {
        let t = self.soon_after(after);
        self.act(t, Act::Nmt(cs));
        self.cycle_at(t)
    }

    /// The write of 0x13FE soon after `after` and its `reply`; the cycle
    /// that handles it.
    fn config_valid_soon_after(&mut self, after: u64, reply: SdoReply) -> u64 {
        let t = self.soon_after(after);
        self.sdo_download(t, 0x13FE, 0, 0xA5, 1, reply);
        self.cycle_at(t)
    }

    /// Checks, at the end of cycle `p`, whether the consumer's SRDO runs
    /// and what 0x13FE holds.
    fn check_late(&mut self, p: u64, running: bool, valid: u8) {
        self.act_at(p, true, Act::Check { running, valid });
    }

    fn plan_config_crc(&mut self) -> &'static str {
        let crc_error = Obs::Config(CopKernel::SrdoCfgCrcError, SRDO);
        let p1 = self.nmt_soon_after(self.free_from, NmtCs::EnterPreOperational);
        let t2 = self.soon_after(p1);
        let changed = u32::from(SCT_MS) + self.rng.range(1, 50) as u32;
        self.sdo_download(t2, SRDO, 2, changed, 2, SdoReply::Done(SRDO, 2));
        let p2 = self.cycle_at(t2);
        let refused = SdoReply::Abort(0x13FE, 0, 0x0800_0020);
        let p3 = self.config_valid_soon_after(p2, refused);
        let p4 = self.nmt_soon_after(p3, NmtCs::Start);
        self.check_late(p4, false, 0);
        // The producer goes on; the consumer's SRDO does not run and must
        // ignore the pair.
        let tx = self.soon_after(p4);
        let (_, n, i) = self.send_pair(tx);
        self.act(tx, Act::Deliver(n));
        let txi = tx + self.legal_gap();
        self.act(txi, Act::Deliver(i));
        self.report.cycles += 1;
        // The bad configuration stays for at least one diagnostic check.
        self.ensure_polls(p2);
        let first_diag = loop {
            if let Some(p) = self.polls.iter().find(|p| p.t >= p2 && p.diag) {
                break p.t;
            }
            let last = self.polls.back().map_or(p2, |p| p.t);
            self.ensure_polls(last + POLL_MAX);
        };
        let p5 = self.nmt_soon_after(first_diag.max(txi), NmtCs::EnterPreOperational);
        let t6 = self.soon_after(p5);
        self.sdo_download(t6, SRDO, 2, u32::from(SCT_MS), 2, SdoReply::Done(SRDO, 2));
        let p6 = self.cycle_at(t6);
        let diag: Vec<u64> = self
            .polls
            .iter()
            .filter(|p| p.diag && p.t >= p2 && p.t < p6)
            .map(|p| p.t)
            .collect();
        for t in diag {
            self.expect(t, PH_DIAG, 0, crc_error);
        }
        let p7 = self.config_valid_soon_after(p6, SdoReply::Done(0x13FE, 0));
        let p8 = self.nmt_soon_after(p7, NmtCs::Start);
        self.check_late(p8, true, 0xA5);
        // The SCT runs from entering OPERATIONAL.
        self.last_valid = p8;
        self.legal_pair(p8 + 1);
        "SCT changed by SDO"
    }

    fn plan_tick_wrap(&mut self) -> &'static str {
        let t = self.free_from + self.rng.range(1, COMPACT);
        self.nmt_all(
            t,
            NmtCs::EnterPreOperational,
            NmtCommand::EnterPreOperational,
        );
        let p1 = self.cycle_at(t);
        let jump_seq = self.act_at(p1, true, Act::Jump(0));
        let ts = p1 + 1;
        self.nmt_all(ts, NmtCs::Start, NmtCommand::StartRemoteNode);
        let p2 = self.cycle_at(ts);
        self.last_valid = p2;
        self.prod_ref = ts + FIRST_SEND_TICKS_PER_NODE;
        self.rogue_ready = ts + 3 * FIRST_SEND_TICKS_PER_NODE;
        let earliest = self.prod_ref.max(p2 + 1);
        let deadline = p2 + SCT;
        let (wrap_at, variant) = match self.rng.range(0, 2) {
            0 => {
                let gap = self.rng.range(1, SRVT);
                let tn = self.rng.range(earliest, deadline);
                self.valid_pair_at(tn, gap);
                let e = self.free_from;
                self.legal_pair(e);
                (tn + self.rng.range(1, gap), "legal pair across the wrap")
            }
            1 => {
                let tn = self.rng.range(earliest, deadline - SRVT - 1);
                let extra = self.rng.range(1, (deadline - tn - SRVT).min(COMPACT));
                self.late_inverted(tn, extra);
                let e = self.free_from;
                self.legal_pair(e);
                (
                    tn + self.rng.range(1, SRVT + extra),
                    "late frame 2 across the wrap",
                )
            }
            _ => {
                // The slot of the pair that does not come.
                self.report.cycles += 1;
                let extra = self.rng.range(1, SCT);
                self.sct_expiry(extra);
                (p2 + self.rng.range(1, SCT), "SCT across the wrap")
            }
        };
        // Bus ticks = abs + offset: put the counter's wrap at `wrap_at`.
        let offset = 0u32.wrapping_sub(wrap_at as u32);
        if let Some(a) = self.actions.iter_mut().find(|a| a.seq == jump_seq) {
            a.kind = Act::Jump(offset);
        }
        variant
    }

    // -------------------------------------------------------- execution

    fn goto(&mut self, t: u64) {
        if t > self.abs {
            let before = self.bus.now();
            self.bus.advance_ticks((t - self.abs) as u32);
            if self.bus.now().0 < before.0 {
                self.report.counter_wraps += 1;
            }
            self.abs = t;
        }
    }

    fn run_actions(&mut self) {
        let mut actions = std::mem::take(&mut self.actions);
        actions.sort_by_key(|a| (a.t, a.late, a.seq));
        for a in &actions {
            self.run_polls_until(a.t, a.late);
            self.goto(a.t);
            self.execute(a);
        }
        actions.clear();
        self.actions = actions;
        self.bus.clear_trace();
        self.close_episodes();
    }

    /// Runs the consumer cycles before `t` (and at `t` when `inclusive`).
    fn run_polls_until(&mut self, t: u64, inclusive: bool) {
        while let Some(p) = self.polls.front().copied() {
            if p.t < t || (inclusive && p.t == t) {
                self.polls.pop_front();
                self.last_poll = p.t;
                self.consumer_cycle(p);
            } else {
                break;
            }
        }
    }

    fn fail(&mut self, ep: u64, what: String) {
        if let Some(e) = self.episode_mut(ep) {
            e.broken = true;
        }
        self.note(what);
    }

    fn note(&mut self, what: String) {
        if self.report.failures.len() < 10 {
            let t = format!("t={} ({:#010x})", self.abs, self.bus.now().0);
            self.report.failures.push(format!("{t}: {what}"));
        }
    }

    fn take_tx(&mut self) -> Vec<CanFrame> {
        std::mem::take(&mut self.capture.borrow_mut().tx)
    }

    fn execute(&mut self, a: &Action) {
        match a.kind {
            Act::ProducerSend { data, late } => {
                let mut late_seen = false;
                let mut errors = 0u32;
                self.producer.process(|_, e| match e {
                    Event::ProgMon(ProgMonEvent::SrdoError) => late_seen = true,
                    Event::SrdoError(..) => errors += 1,
                    _ => {}
                });
                self.producer.set_data(&data);
                let mut sent = false;
                let r = self.producer.send(|_, e| match e {
                    Event::SrdoEvent(_) => sent = true,
                    Event::SrdoError(..) => errors += 1,
                    _ => {}
                });
                let frames = self.take_tx();
                let want = [
                    frame(COB_NORMAL, &data),
                    frame(COB_INVERTED, &complement(data)),
                ];
                if r.is_err() || !sent || errors > 0 || frames != want {
                    self.report.violations += 1;
                    self.fail(
                        a.ep,
                        format!("producer send: {r:?}, event {sent}, frames {frames:02X?}"),
                    );
                }
                if late_seen != late {
                    self.fail(
                        a.ep,
                        format!("producer program monitor: late {late_seen}, expected {late}"),
                    );
                }
            }
            Act::RogueSend { data } => {
                self.rogue.set_data(&data);
                let r = self.rogue.send(|_, _| {});
                let frames = self.take_tx();
                let want = [
                    frame(COB_NORMAL, &data),
                    frame(COB_INVERTED, &complement(data)),
                ];
                if r.is_err() || frames != want {
                    self.fail(a.ep, format!("rogue send: {r:?} {frames:02X?}"));
                }
            }
            Act::Deliver(f) => self.bus.inject(f),
            Act::Burst(n) => {
                let n = n.unwrap_or(RX_CAPACITY.saturating_sub(self.consumer.port.pending()));
                for _ in 0..n {
                    let bytes = self.rng.next_u64().to_le_bytes();
                    self.bus.inject(frame(FOREIGN_ID, &bytes));
                }
            }
            Act::Nmt(cs) => self
                .bus
                .inject(nmt::encode_command(cs, Role::Consumer.node_id())),
            Act::Local(role, cmd) => {
                let d = match role {
                    Role::Producer => &mut self.producer,
                    Role::Rogue => &mut self.rogue,
                    Role::Consumer => &mut self.consumer,
                };
                let r = d.command(cmd);
                self.take_tx();
                if r.is_err() {
                    self.fail(a.ep, format!("{role:?} {cmd:?}: {r:?}"));
                }
            }
            Act::Sdo(data) => self.bus.inject(frame(SDO_REQUEST, &data)),
            Act::Jump(offset) => {
                self.offset = offset;
                let t = (self.abs as u32).wrapping_add(offset);
                self.bus.set_time(Ticks(t));
            }
            Act::Check { running, valid } => {
                let is = self.consumer.stack.srdo().is_running();
                let v = self.consumer.read(0x13FE, 0);
                if is != running || v != u32::from(valid) {
                    self.fail(
                        a.ep,
                        format!(
                            "consumer running {is} 0x13FE {v:#x}, expected {running} {valid:#x}"
                        ),
                    );
                }
            }
        }
    }

    /// One `CcmProcess` of the consumer and its application's checks.
    fn consumer_cycle(&mut self, p: Poll) {
        self.goto(p.t);
        self.report.consumer_cycles += 1;
        let mut obs: Vec<Obs> = Vec::new();
        let mut breaches: Vec<String> = Vec::new();
        let mut follow: Option<ProgMonEvent> = None;
        let fields = self.consumer.fields();
        self.consumer.process(|stack, e| {
            if let Some(want) = follow.take() {
                if e == Event::ProgMon(want) {
                    return;
                }
                breaches.push(format!("{want:?} expected after the callback, got {e:?}"));
            }
            match e {
                Event::SrdoError(SRDO, CopKernel::SrdoNotHandledInApp) => {
                    breaches.push("kCopSrdoNotHandledInApp".into());
                }
                Event::SrdoError(SRDO, code) => {
                    let st = answer_as_manual(stack, &e);
                    if st != Some(0x50) {
                        breaches.push(format!("status {st:02X?} inside AppSrdoError({code:?})"));
                    }
                    obs.push(Obs::Error(code));
                    if SRDO_USE_PROGMONITOR {
                        follow = Some(ProgMonEvent::SrdoError);
                    }
                }
                Event::SrdoEvent(SRDO) => {
                    let st = answer_as_manual(stack, &e);
                    if st.map(|s| s & 0x30) != Some(0) {
                        breaches.push(format!("status {st:02X?} inside AppSrdoEvent"));
                    }
                    let (n, i) = (fields.normal(), fields.inverted());
                    if i != complement(n) {
                        breaches.push(format!("variables {n:02X?} / {i:02X?} not complements"));
                    }
                    obs.push(Obs::Accept(n));
                    if SRDO_USE_PROGMONITOR {
                        follow = Some(ProgMonEvent::SrdoReceived);
                    }
                }
                Event::SrdoEvent(_) | Event::SrdoError(..) => {
                    breaches.push(format!("event of another SRDO: {e:?}"));
                }
                _ => {}
            }
        });
        if let Some(want) = follow {
            breaches.push(format!("{want:?} missing at the end of the cycle"));
        }
        if p.diag {
            if let Err((code, idx)) = self
                .consumer
                .stack
                .srdo()
                .check_config(self.consumer.stack.od())
            {
                obs.push(Obs::Config(code, idx));
            }
        }
        // The variables change only with a valid pair.
        for o in &obs {
            if let Obs::Accept(d) = o {
                self.values = (*d, complement(*d));
            }
        }
        let now = (fields.normal(), fields.inverted());
        if now != self.values {
            breaches.push(format!(
                "variables changed without a valid pair: {now:02X?}"
            ));
        }
        if !breaches.is_empty() {
            self.report.violations += breaches.len() as u64;
            let ep = self.current_ep;
            for b in breaches {
                self.fail(ep, b);
            }
        }
        self.compare(p.t, &obs);
        self.compare_sdo();
    }

    /// Compares one consumer cycle's observations with the expectation.
    fn compare(&mut self, t: u64, obs: &[Obs]) {
        let keys: Vec<Key> = self
            .expected
            .range(..=(t, u8::MAX, u64::MAX))
            .map(|(k, _)| *k)
            .collect();
        let mut want: Vec<(Obs, u64)> = Vec::with_capacity(keys.len());
        for k in &keys {
            if let Some(v) = self.expected.remove(k) {
                want.push(v);
            }
        }
        for (_, ep) in &want {
            if let Some(e) = self.episode_mut(*ep) {
                e.remaining = e.remaining.saturating_sub(1);
            }
        }
        let same = want.len() == obs.len()
            && want.iter().zip(obs).all(|((w, _), o)| w == o)
            && keys.iter().all(|k| k.0 == t);
        if same {
            return;
        }
        // Which expected observations came, which did not, which came
        // without being expected.
        let mut rest: Vec<Obs> = obs.to_vec();
        let mut missed_eps = Vec::new();
        for (w, ep) in &want {
            match rest.iter().position(|o| o == w) {
                Some(i) => {
                    rest.remove(i);
                }
                None => missed_eps.push(*ep),
            }
        }
        let blame = want.first().map_or(self.current_ep, |(_, ep)| *ep);
        for ep in &missed_eps {
            if let Some(e) = self.episode_mut(*ep) {
                e.missed += 1;
                e.broken = true;
            }
        }
        let unexpected = rest.len() as u64;
        if let Some(e) = self.episode_mut(blame) {
            e.unexpected += unexpected;
            e.broken = true;
        }
        let wanted: Vec<Obs> = want.iter().map(|(o, _)| *o).collect();
        let class = self
            .episode_mut(blame)
            .map(|e| format!("{:?} {}", e.class, e.variant))
            .unwrap_or_default();
        self.note(format!(
            "episode {blame} ({class}), cycle {t}: expected {}, observed {}",
            describe(&wanted),
            describe(obs)
        ));
    }

    fn compare_sdo(&mut self) {
        let replies = std::mem::take(&mut self.capture.borrow_mut().sdo);
        for f in replies {
            let [cmd, i0, i1, sub, c0, c1, c2, c3] = f.data;
            let index = u16::from_le_bytes([i0, i1]);
            // CiA 301 7.2.4.3.4 (scs = 3) and 7.2.4.3.17 (cs = 4).
            let got = match cmd {
                0x60 => SdoReply::Done(index, sub),
                0x80 => SdoReply::Abort(index, sub, u32::from_le_bytes([c0, c1, c2, c3])),
                _ => SdoReply::Other(f.data),
            };
            match self.sdo_expected.pop_front() {
                Some((want, ep)) => {
                    if let Some(e) = self.episode_mut(ep) {
                        e.remaining = e.remaining.saturating_sub(1);
                    }
                    if want != got {
                        self.fail(ep, format!("SDO answer {got:X?}, expected {want:X?}"));
                    }
                }
                None => {
                    let ep = self.current_ep;
                    self.fail(ep, format!("unexpected SDO answer {got:X?}"));
                }
            }
        }
    }

    /// Counts the episodes whose expectations are all settled (never the
    /// one being planned and run, which may still be blamed).
    fn close_episodes(&mut self) {
        while self.episodes.len() > 1 {
            match self.episodes.front() {
                Some(e) if e.remaining == 0 => {}
                _ => break,
            }
            if let Some(e) = self.episodes.pop_front() {
                self.account(&e);
            }
        }
    }

    fn account(&mut self, e: &Episode) {
        match e.class {
            None => {
                self.report.fault_free += 1;
                self.report.false_alarms += e.unexpected;
                self.report.lost_pairs += e.missed;
                if e.broken && e.unexpected == 0 && e.missed == 0 {
                    // A breach of another check in a fault-free episode.
                    self.report.lost_pairs += 1;
                }
            }
            Some(c) => {
                if let Some(s) = self.report.classes.get_mut(c.index()) {
                    s.injected += 1;
                    s.missed += e.missed;
                    s.false_alarms += e.unexpected;
                    if !e.broken {
                        s.detected += 1;
                    }
                }
            }
        }
    }

    /// Runs the consumer until every expectation is settled, then counts.
    fn finish(&mut self) {
        let last = self.expected.keys().next_back().map_or(self.abs, |k| k.0);
        self.ensure_polls(last);
        self.run_polls_until(last, true);
        let left: Vec<(Obs, u64)> = std::mem::take(&mut self.expected).into_values().collect();
        for (o, ep) in left {
            if let Some(e) = self.episode_mut(ep) {
                e.missed += 1;
                e.broken = true;
                e.remaining = e.remaining.saturating_sub(1);
            }
            self.note(format!("episode {ep}: {o:?} never observed"));
        }
        while let Some(e) = self.episodes.pop_front() {
            self.account(&e);
        }
        self.report.simulated_ticks = self.abs;
    }
}
