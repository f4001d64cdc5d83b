//! Load campaign: nine stacks (a master and eight safety nodes) on the
//! physical model of the simulated bus (`SimBus::with_model`, 1 Mbit/s,
//! receive buffers high 16 / low 10), with SRDOs every 10 ms, continuous
//! SDO block uploads, SYNC with eight synchronous PDOs and heartbeats.
//!
//! An independent checker reads the bus log (start, end and queueing time
//! of every frame) and decides for every SRDO whether each SCT / SRVT
//! deadline was met, from the bus arrival times alone. Every
//! `AppSrdoError` a stack reports is then correct (a real miss or loss of
//! that SRDO lies just before it) or false; every real miss is reported
//! or missed. The table: offered load (stuff bits included), bus load,
//! frames, lost safety and other frames, CAN overrun emergencies, SDO
//! transfers and errors, correct / false / missed alarms, worst pair
//! latency (queueing of the normal frame to the end of the inverted
//! frame), refused transmissions.
//!
//! ```sh
//! cargo run --release --example load_campaign --features std -- --minutes 10
//! cargo run --example load_campaign --features std -- --quick
//! ```
//!
//! Options: `--quick` (3 simulated seconds, a short sweep), `--minutes N`
//! (the main run; 0 leaves it out), `--sweep N,N,..` (the SRDO counts of
//! the sweep, each with 4 and 8 bytes, empty for none), `--csv FILE` (one
//! line per run for the plot). Exit code 1 on a false alarm in any run; at
//! or below 100 % offered load on a lost safety frame, an unreported miss
//! or an SDO error (but in the run with too small receive buffers); on a
//! check run that shows nothing to check. `LOAD_VERBOSE=1` adds the frames
//! per kind, `LOAD_TRACE=n` the frames and alarms of SRDO n on stderr.

use core::sync::atomic::AtomicU8;
use std::collections::HashMap;
use std::io::Write;

use cop::ccm::{NmtCommand, Stack};
use cop::event::Event;
use cop::od::{ByteOrder, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
use cop::sdo::client::{ClientParam, Direction};
use cop::sim::{BusFrame, BusModel, Delivery, SimBus, SimPort};
use cop::wire::sdo::Multiplexer;

/// Stacks on the bus: index 0 the master (node 1), 1..=8 the safety nodes.
const STACKS: usize = 9;
/// SRDO slots per dictionary: up to 8 transmit and 8 receive.
const SLOTS: usize = 16;
const REFRESH_MS: u32 = 10;
const SCT_MS: u32 = 15;
const SRVT_MS: u32 = 10;
const SYNC_US: u32 = 10_000;
const HEARTBEAT_MS: u16 = 50;
/// Process cycle of every stack.
const CYCLE_TICKS: u32 = 10;
/// Length of the object the master uploads from the nodes.
const SDO_LEN: usize = 200;

macro_rules! node_od {
    ($m:ident, [$(($c:ident, $p:ident, $k:literal)),*]) => {
        mod $m {
            use super::*;
            cop::od_ram!(pub static S1017, HB: u16 = HEARTBEAT_MS => UInt16, RW);
            cop::pdo_commu!(pub static S1800, V1800 = 0x8000_0180, 1, 0, 0);
            cop::pdo_mapp!(pub static S1A00, V1A00 = [0x2100_0120, 0x2100_0220]);
            pub static TEXT: [AtomicU8; SDO_LEN + 1] = decl::zeroed();
            pub static S2000: [ObdSubEntry; 1] =
                [ObdSubEntry::ram_string(0, cop::od::Access::RW, &TEXT, c"")];
            pub static PDO_VARS: [AtomicU8; 8] = decl::zeroed();
            pub static S2100: [ObdSubEntry; 3] = [
                ObdSubEntry::rom(0, cop::od::DataType::UInt8, cop::od::Access::R, &[2]),
                ObdSubEntry::ram(1, cop::od::DataType::UInt32, cop::od::Access::PRW,
                    PDO_VARS.split_at(4).0, Some(&[0; 4])),
                ObdSubEntry::ram(2, cop::od::DataType::UInt32, cop::od::Access::PRW,
                    PDO_VARS.split_at(4).1, Some(&[0; 4])),
            ];
            cop::obd_create_srdo_gfc_param!(pub mod gfc);
            $(
                cop::obd_create_srdo_commu!(pub mod $c, 0x1300 + $k, 0, 15, 10,
                    0x0FF + 2 * $k, 0x100 + 2 * $k);
                cop::obd_create_srdo_mapp!(pub mod $p, 0x1380 + $k, [
                    ((0x6000 + $k) << 16) | 0x0120, ((0x6100 + $k) << 16) | 0x0120,
                    ((0x6000 + $k) << 16) | 0x0220, ((0x6100 + $k) << 16) | 0x0220
                ]);
            )*
            cop::obd_create_srdo_cfg_valid!(pub mod cfg_valid);
            cop::obd_create_srdo_crc!(pub mod crcs, [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
            pub static NORMAL: [AtomicU8; 8 * SLOTS] = decl::zeroed();
            pub static INVERTED: [AtomicU8; 8 * SLOTS] = decl::zeroed();
            const fn pair(buf: &'static [AtomicU8], k: usize) -> [ObdSubEntry; 3] {
                let field = buf.split_at(8 * (k - 1)).1.split_at(8).0;
                [
                    ObdSubEntry::rom(0, cop::od::DataType::UInt8, cop::od::Access::R, &[2]),
                    ObdSubEntry::ram(1, cop::od::DataType::UInt32, cop::od::Access::PRW,
                        field.split_at(4).0, Some(&[0; 4])),
                    ObdSubEntry::ram(2, cop::od::DataType::UInt32, cop::od::Access::PRW,
                        field.split_at(4).1, Some(&[0; 4])),
                ]
            }
            pub static COMM: [ObdEntry; 2 * SLOTS + 6] = [
                ObdEntry::new(0x1017, &S1017, None),
                cop::srdo_obd_entry!(gfc),
                $(cop::srdo_obd_entry!($c),)*
                $(cop::srdo_obd_entry!($p),)*
                cop::srdo_obd_entry!(cfg_valid),
                cop::srdo_obd_entry!(crcs),
                ObdEntry::new(0x1800, &S1800, None),
                ObdEntry::new(0x1A00, &S1A00, None),
            ];
            pub static MANUF: [ObdEntry; 2] = [
                ObdEntry::new(0x2000, &S2000, None),
                ObdEntry::new(0x2100, &S2100, None),
            ];
            pub static DEVICE: [ObdEntry; 2 * SLOTS] = [
                $(ObdEntry::new(0x6000 + $k, { static S: [ObdSubEntry; 3] = pair(&NORMAL, $k); &S }, None),)*
                $(ObdEntry::new(0x6100 + $k, { static S: [ObdSubEntry; 3] = pair(&INVERTED, $k); &S }, None),)*
            ];
            pub fn od() -> ObjectDictionary {
                ObjectDictionary::new(&COMM, &MANUF, &DEVICE).unwrap()
            }
        }
    };
}

macro_rules! nodes {
    ($($m:ident),*) => {
        $(node_od!($m, [
            (c1, p1, 1), (c2, p2, 2), (c3, p3, 3), (c4, p4, 4), (c5, p5, 5), (c6, p6, 6),
            (c7, p7, 7), (c8, p8, 8), (c9, p9, 9), (c10, p10, 10), (c11, p11, 11),
            (c12, p12, 12), (c13, p13, 13), (c14, p14, 14), (c15, p15, 15), (c16, p16, 16)
        ]);)*
        fn dictionaries() -> Vec<ObjectDictionary> {
            vec![$($m::od()),*]
        }
    };
}
nodes!(n1, n2, n3, n4, n5, n6, n7, n8, n9);

static SDO_BUF: [AtomicU8; SDO_LEN + 8] = decl::zeroed();

/// One campaign run.
#[derive(Clone, Copy, Debug, Default)]
struct Setup {
    srdos: usize,
    /// Data bytes of each SRDO frame (4 or 8).
    srdo_len: usize,
    seconds: u32,
    /// Every SRDO due in the same millisecond of the period (a burst of
    /// 2 × SRDOs frames) instead of spread over the period.
    burst: bool,
    /// The bus loses every n-th SRDO frame (0: none): the check of the
    /// checker, whose misses the stacks must all report.
    drop_every: u64,
    /// Frames every node's low receive buffer holds (10 in a SYS TEC
    /// driver configuration; fewer to make it overflow).
    rx_low: usize,
}

/// SRDO `s` (0-based): sent by stack `s % 9` in its slot `s / 9`, received
/// by stack `(s + 1) % 9` in its slot `8 + s / 9`, COB-IDs 0x101 + 2s and
/// 0x102 + 2s (CiA 304 default COB-IDs of SRDO s + 1).
fn tx_of(s: usize) -> (usize, u16) {
    (s % STACKS, 0x1301 + (s / STACKS) as u16)
}
fn rx_of(s: usize) -> (usize, u16) {
    ((s + 1) % STACKS, 0x1309 + (s / STACKS) as u16)
}
fn cobs(s: usize) -> (u32, u32) {
    (0x101 + 2 * s as u32, 0x102 + 2 * s as u32)
}

struct Node {
    stack: Stack,
    port: SimPort,
}

impl Node {
    fn write(&mut self, index: u16, sub: u8, value: u32, len: usize) {
        let now = self.port.bus().now();
        let b = value.to_le_bytes();
        self.stack
            .write_object(index, sub, ByteOrder::Wire, &b[..len], now)
            .unwrap_or_else(|e| panic!("write {index:04X}.{sub} = {value:X}: {e:?}"));
    }
}

/// What one run measured.
#[derive(Clone, Debug, Default)]
struct Outcome {
    offered: f64,
    bus_load: f64,
    frames: u64,
    lost_safety: u64,
    lost_other: u64,
    tx_refused: u64,
    /// EMCY frames with error code 0x8110 (CAN overrun) on the bus.
    overrun_emcy: u64,
    sdo_ok: u64,
    sdo_errors: u64,
    correct: u64,
    false_alarms: u64,
    missed: u64,
    real_misses: u64,
    worst_latency_us: f64,
    false_examples: Vec<String>,
    missed_examples: Vec<String>,
    /// Frames per kind.
    classes: Vec<String>,
}

/// The kind of a frame by its identifier (CiA 301 / CiA 304 defaults).
fn class(id: u32) -> &'static str {
    match id {
        0x000 => "NMT",
        0x001 => "GFC",
        0x080 => "SYNC",
        0x081..=0x0FF => "EMCY",
        0x101..=0x180 => "SRDO",
        0x181..=0x57F => "PDO",
        0x580..=0x67F => "SDO",
        0x700..=0x77F => "heartbeat",
        _ => "other",
    }
}

/// Bits of a frame on the bus without stuff bits, intermission included
/// (ISO 11898-1:2015 10.4.2: 44 + 8 n bits SOF to EOF, base format).
fn nominal_bits(data: usize) -> f64 {
    47.0 + 8.0 * data as f64
}

/// The periodic traffic: per kind of frame, the frames due per second and
/// their data bytes (SRDO pairs, SYNC, the eight synchronous PDOs of 8
/// bytes, a heartbeat of every stack).
fn periodic(setup: &Setup) -> [(&'static str, f64, usize); 4] {
    [
        (
            "SRDO",
            2.0 * setup.srdos as f64 * (1000.0 / REFRESH_MS as f64),
            setup.srdo_len,
        ),
        ("SYNC", 1e6 / SYNC_US as f64, 0),
        ("PDO", 8.0 * 1e6 / SYNC_US as f64, 8),
        (
            "heartbeat",
            STACKS as f64 * (1000.0 / HEARTBEAT_MS as f64),
            1,
        ),
    ]
}

/// The load the periodic traffic offers (SDO, which fills what is left,
/// not counted), in percent of the bit rate: the frames due per second of
/// each kind times the mean length of that kind's frames on the bus,
/// stuff bits and intermission included (`bits`: kind -> (frames, bits)
/// from the bus log; the nominal length for a kind not seen).
fn offered_percent(setup: &Setup, bits: &std::collections::BTreeMap<&str, (u64, u64)>) -> f64 {
    let per_s: f64 = periodic(setup)
        .iter()
        .map(|&(kind, rate, data)| {
            let mean = match bits.get(kind) {
                Some(&(n, b)) if n > 0 => b as f64 / n as f64,
                _ => nominal_bits(data),
            };
            rate * mean
        })
        .sum();
    per_s / 1e6 * 100.0
}

/// An EMCY frame with error code 0x8110, CAN overrun (CiA 301 table 21;
/// the code little-endian in bytes 0 and 1).
fn is_overrun_emcy(f: &cop::port::CanFrame) -> bool {
    class(f.id.id()) == "EMCY" && f.payload().get(..2) == Some(&[0x10, 0x81][..])
}

/// A deadline the checker found missed: SRDO, when (ns), what.
#[derive(Clone, Copy, Debug)]
struct Miss {
    srdo: usize,
    /// The deadline that passed (or the arrival of the frame out of order).
    at_ns: u64,
    /// When a receiver can know it: the arrival of the late frame for an
    /// SRVT miss (found then, SAFETY_BEHAVIOUR 5), else `at_ns`.
    seen_ns: u64,
    what: &'static str,
    /// Beyond the deadline by more than the stack's time resolution
    /// ([`resolution_ns`]): it must be reported. A miss within the
    /// resolution may be reported or not; an alarm for it is correct.
    clear: bool,
}

/// The resolution of the stack's receive times: the driver's timestamp
/// (one tick, 100 µs) with `CDRV_TIMESTAMP`, otherwise the stack's cycle
/// (the time it takes the frame from the driver).
fn resolution_ns() -> u64 {
    if cop::config::CDRV_TIMESTAMP {
        100_000
    } else {
        u64::from(CYCLE_TICKS) * 100_000
    }
}

/// The checker's state per SRDO.
#[derive(Default, Clone, Copy)]
struct Watch {
    /// End of the last valid pair's normal frame.
    last_pair_ns: Option<u64>,
    /// A normal frame waiting for its inverted frame: (end, queued).
    normal: Option<(u64, u64)>,
}

struct Checker {
    watch: Vec<Watch>,
    by_cob: HashMap<u32, (usize, bool)>,
    misses: Vec<Miss>,
    worst_latency_ns: u64,
    from_ns: u64,
}

impl Checker {
    fn new(srdos: usize, from_ns: u64) -> Checker {
        let mut by_cob = HashMap::new();
        for s in 0..srdos {
            let (a, b) = cobs(s);
            by_cob.insert(a, (s, true));
            by_cob.insert(b, (s, false));
        }
        Checker {
            watch: vec![Watch::default(); srdos],
            by_cob,
            misses: Vec::new(),
            worst_latency_ns: 0,
            from_ns,
        }
    }

    /// SCT: a valid pair at least every SCT; SRVT: the inverted frame at
    /// most SRVT after the normal one (CiA 304 / EN 50325-5), judged on
    /// the end-of-frame times.
    fn frame(&mut self, f: &BusFrame) {
        let Some(&(s, normal)) = self.by_cob.get(&f.frame.id.id()) else {
            return;
        };
        self.sct_until(f.end_ns);
        let res = resolution_ns();
        let sct = u64::from(SCT_MS) * 1_000_000;
        let w = &mut self.watch[s];
        // A first frame just after the SCT, within the resolution.
        if let (true, Some(t)) = (normal, w.last_pair_ns) {
            if f.end_ns > t + sct && f.end_ns <= t + sct + res {
                self.misses.push(Miss {
                    srdo: s,
                    at_ns: t + sct,
                    seen_ns: f.end_ns,
                    what: "SCT",
                    clear: false,
                });
            }
        }
        if normal {
            // A normal frame while the last one still waits for its
            // inverted frame: that inverted frame is lost.
            if w.normal.is_some() {
                self.misses.push(Miss {
                    srdo: s,
                    at_ns: f.end_ns,
                    seen_ns: f.end_ns,
                    what: "normal frame without inverted frame",
                    clear: true,
                });
            }
            w.normal = Some((f.end_ns, f.queued_ns));
        } else if w.normal.is_none() {
            // An inverted frame without its normal frame: that one is lost.
            self.misses.push(Miss {
                srdo: s,
                at_ns: f.end_ns,
                seen_ns: f.end_ns,
                what: "inverted frame without normal frame",
                clear: true,
            });
        } else if let Some((n_end, n_queued)) = w.normal.take() {
            let srvt = u64::from(SRVT_MS) * 1_000_000;
            let gap = f.end_ns - n_end;
            if gap > srvt {
                self.misses.push(Miss {
                    srdo: s,
                    at_ns: n_end + srvt,
                    seen_ns: f.end_ns,
                    what: "SRVT",
                    clear: gap > srvt + res,
                });
            }
            if gap <= srvt {
                w.last_pair_ns = Some(n_end);
                if n_end >= self.from_ns {
                    self.worst_latency_ns = self.worst_latency_ns.max(f.end_ns - n_queued);
                }
            }
        }
    }

    /// Records every SCT that expired before `now_ns`.
    fn sct_until(&mut self, now_ns: u64) {
        let sct = u64::from(SCT_MS) * 1_000_000;
        let res = resolution_ns();
        for (s, w) in self.watch.iter_mut().enumerate() {
            if let Some(t) = w.last_pair_ns {
                // SCT runs from the first frame of one valid pair to the
                // first frame of the next (SAFETY_BEHAVIOUR 5): a normal
                // frame in time whose inverted frame is still to come
                // decides later.
                let deadline = t + sct + res;
                let in_time = w.normal.is_some_and(|(n_end, _)| n_end <= deadline);
                if now_ns > deadline && !in_time {
                    self.misses.push(Miss {
                        srdo: s,
                        at_ns: t + sct,
                        seen_ns: t + sct,
                        what: "SCT",
                        clear: true,
                    });
                    // One report per silence: the next deadline counts
                    // from the next pair.
                    w.last_pair_ns = None;
                }
            }
        }
    }
}

fn run(setup: Setup, progress: bool) -> Outcome {
    let model = BusModel {
        rx_low: setup.rx_low,
        ..BusModel::new(1_000_000).unwrap()
    };
    let bus = SimBus::with_model(model).unwrap();
    bus.keep_bus_log(true);
    if setup.drop_every > 0 {
        let mut n = 0u64;
        let every = setup.drop_every;
        bus.set_filter(Some(Box::new(move |_, f: &mut cop::port::CanFrame| {
            if class(f.id.id()) == "SRDO" {
                n += 1;
                if n % every == 0 {
                    return Delivery::Drop;
                }
            }
            Delivery::Deliver
        })));
    }
    let ods = dictionaries();
    let mut nodes: Vec<Node> = ods
        .into_iter()
        .enumerate()
        .map(|(i, od)| {
            let port = bus.attach(0);
            let mut stack = Stack::new(od, i as u8 + 1).unwrap();
            stack.connect().unwrap();
            Node { stack, port }
        })
        .collect();
    let pump = |n: &mut Node| {
        let now = n.port.bus().now();
        while n.stack.drain(&mut n.port, now).is_some() {}
    };
    for n in nodes.iter_mut() {
        pump(n);
    }
    // Configuration: the SRDOs of the setup, every other slot off.
    for s in 0..setup.srdos {
        let (c1, c2) = cobs(s);
        let (t, ti) = tx_of(s);
        let (r, ri) = rx_of(s);
        for (node, idx, dir, time) in [(t, ti, 1, REFRESH_MS), (r, ri, 2, SCT_MS)] {
            let n = &mut nodes[node];
            let map = idx + 0x80;
            if setup.srdo_len == 4 {
                // One pair of UNSIGNED32 instead of the two of the default
                // (while the SRDO is still off).
                n.write(map, 0, 2, 1);
            }
            // The COB-IDs change only while the SRDO is off: direction last.
            n.write(idx, 5, c1, 4);
            n.write(idx, 6, c2, 4);
            n.write(idx, 2, time, 2);
            n.write(idx, 3, SRVT_MS, 1);
            n.write(idx, 1, dir, 1);
        }
    }
    for (i, n) in nodes.iter_mut().enumerate() {
        // The CRC of every SRDO, the unused ones too (0x13FF).
        for slot in 0..SLOTS as u16 {
            let idx = 0x1301 + slot;
            let od = *n.stack.od();
            let crc = n.stack.srdo().calc_crc(&od, idx).unwrap();
            n.write(0x13FF, (idx - 0x1300) as u8, u32::from(crc), 2);
        }
        n.write(0x13FE, 0, 0xA5, 1);
        if i > 0 {
            // Synchronous TPDO 1 on 0x180 + node-ID.
            n.write(0x1800, 1, 0x8000_0180 + i as u32 + 1, 4);
            n.write(0x1800, 1, 0x180 + i as u32 + 1, 4);
            n.stack.exec_command(NmtCommand::StartRemoteNode).unwrap();
        }
        pump(n);
    }
    {
        let now = bus.now();
        let m = &mut nodes[0];
        m.stack
            .config_sync_producer(0x4000_0080, SYNC_US, now)
            .unwrap();
        m.stack.exec_command(NmtCommand::StartRemoteNode).unwrap();
        pump(m);
    }
    let text: Vec<u8> = (0..SDO_LEN).map(|i| b'a' + (i % 26) as u8).collect();
    // The object the master uploads, on every safety node.
    for m in [
        &n2::TEXT,
        &n3::TEXT,
        &n4::TEXT,
        &n5::TEXT,
        &n6::TEXT,
        &n7::TEXT,
        &n8::TEXT,
        &n9::TEXT,
    ] {
        for (v, b) in m.iter().zip(&text) {
            v.store(*b, core::sync::atomic::Ordering::Relaxed);
        }
    }

    let warmup_ms = 500u64;
    let mut checker = Checker::new(setup.srdos, warmup_ms * 1_000_000);
    let mut alarms: Vec<(usize, u64, cop::CopKernel)> = Vec::new();
    let slot_to_srdo: HashMap<(usize, u16), usize> =
        (0..setup.srdos).map(|s| (rx_of(s), s)).collect();
    let mut out = Outcome::default();
    let mut sdo_target = 0usize;
    let mut sdo_busy = false;
    let mut sdo_retry_ms = 100u64;
    let mut counter: u32 = 0;
    let total_ms = u64::from(setup.seconds) * 1000;
    let mut last_report = std::time::Instant::now();
    let mut ms = 0u64;
    // LOAD_TRACE=n: the frames of SRDO n (1-based) and its alarms on stderr.
    let trace_srdo: Option<usize> = std::env::var("LOAD_TRACE")
        .ok()
        .and_then(|v| v.parse::<usize>().ok())
        .filter(|&n| n >= 1 && n <= setup.srdos)
        .map(|n| n - 1);
    // Frames and bits per kind.
    let mut classes: std::collections::BTreeMap<&str, (u64, u64)> = Default::default();
    while ms < total_ms {
        let now = bus.now();
        // The safety application of each node: its transmit SRDOs every
        // refresh time, fresh data each time.
        // SRDO s is due in millisecond s of each refresh period (mod 10),
        // so the transmitters do not all send in the same millisecond.
        if ms >= 100 {
            counter = counter.wrapping_add(1);
            let phase = (ms % u64::from(REFRESH_MS)) as usize;
            let due = |s: &usize| {
                if setup.burst {
                    phase == 0
                } else {
                    s % REFRESH_MS as usize == phase
                }
            };
            for s in (0..setup.srdos).filter(due) {
                let (t, idx) = tx_of(s);
                let n = &mut nodes[t];
                let k = usize::from(idx - 0x1300);
                let stat = [
                    &n1::NORMAL,
                    &n2::NORMAL,
                    &n3::NORMAL,
                    &n4::NORMAL,
                    &n5::NORMAL,
                    &n6::NORMAL,
                    &n7::NORMAL,
                    &n8::NORMAL,
                    &n9::NORMAL,
                ][t];
                let inv = [
                    &n1::INVERTED,
                    &n2::INVERTED,
                    &n3::INVERTED,
                    &n4::INVERTED,
                    &n5::INVERTED,
                    &n6::INVERTED,
                    &n7::INVERTED,
                    &n8::INVERTED,
                    &n9::INVERTED,
                ][t];
                let v = counter
                    .wrapping_mul(31)
                    .wrapping_add(s as u32)
                    .to_ne_bytes();
                for j in 0..8 {
                    let b = v[j % 4];
                    stat[8 * (k - 1) + j].store(b, core::sync::atomic::Ordering::Relaxed);
                    inv[8 * (k - 1) + j].store(!b, core::sync::atomic::Ordering::Relaxed);
                }
                let _ = n.stack.send_srdo(&mut n.port, idx, now);
                pump(n);
            }
        }
        // The master's continuous SDO block uploads, node after node.
        if !sdo_busy && ms >= sdo_retry_ms {
            sdo_target = sdo_target % (STACKS - 1) + 1;
            let node = sdo_target as u8 + 1;
            let m = &mut nodes[0];
            let p = ClientParam {
                tx_cob: 0x600 + u32::from(node),
                rx_cob: 0x580 + u32::from(node),
                server_node: node,
                timeout_ticks: 10_000,
            };
            if m.stack.define_sdo_client(&mut m.port, 0x1280, p).is_ok()
                && m.stack
                    .sdo_client_start(
                        &mut m.port,
                        now,
                        0x1280,
                        Direction::BlockUpload,
                        Multiplexer::new(0x2000, 0),
                        &SDO_BUF,
                        SDO_BUF.len(),
                        0,
                    )
                    .is_ok()
            {
                sdo_busy = true;
            } else {
                // Refused (a full transmit buffer): an error, tried again
                // 10 ms later.
                out.sdo_errors += 1;
                sdo_retry_ms = ms + 10;
            }
            pump(m);
        }
        for (i, n) in nodes.iter_mut().enumerate() {
            let t_ns = bus.now_ns();
            n.stack.process(&mut n.port, now, |stack, e| {
                match e {
                    Event::SrdoError(idx, code) if code != cop::CopKernel::SrdoNotHandledInApp => {
                        if let Some(&s) = slot_to_srdo.get(&(i, idx)) {
                            if trace_srdo == Some(s) {
                                eprintln!("trace alarm {code:?} at {:.4}", t_ns as f64 / 1e9);
                            }
                            alarms.push((s, t_ns, code));
                        }
                    }
                    Event::SdocFinished { abort, .. } if i == 0 => {
                        if abort == 0 {
                            out.sdo_ok += 1;
                        } else {
                            out.sdo_errors += 1;
                        }
                        sdo_busy = false;
                    }
                    _ => {}
                }
                if let Event::SrdoEvent(idx) | Event::SrdoError(idx, _) = e {
                    if let Ok(st) = stack.srdo().get_state(idx) {
                        let new = if matches!(e, Event::SrdoError(..)) && st & 0x30 == 0x10 {
                            (st | 0x30) ^ 0xC0
                        } else {
                            st | 0x30
                        };
                        let _ = stack.srdo_mut().set_state(idx, new);
                    }
                }
            });
        }
        bus.advance_ticks(CYCLE_TICKS);
        ms += 1;
        for f in bus.take_bus_log() {
            if let Some(t) = trace_srdo {
                let (a, b) = cobs(t);
                if f.frame.id.id() == a || f.frame.id.id() == b {
                    eprintln!(
                        "trace {:03X} queued {:.4} end {:.4}",
                        f.frame.id.id(),
                        f.queued_ns as f64 / 1e9,
                        f.end_ns as f64 / 1e9
                    );
                }
            }
            checker.frame(&f);
            let c = classes.entry(class(f.frame.id.id())).or_insert((0, 0));
            *c = (c.0 + 1, c.1 + u64::from(f.bits));
            out.overrun_emcy += u64::from(is_overrun_emcy(&f.frame));
        }
        // Progress: every simulated minute, at most every 5 s of real time.
        if progress && ms % 60_000 == 0 && last_report.elapsed().as_secs() >= 5 {
            last_report = std::time::Instant::now();
            let st = bus.stats().unwrap();
            // Alarms of the start-up (before any SRDO is sent) are not
            // judged.
            let judged = alarms
                .iter()
                .filter(|a| a.1 >= (warmup_ms + u64::from(SCT_MS)) * 1_000_000)
                .count();
            eprintln!(
                "  {:>5.1} of {} simulated s, bus {:.1} %, {} frames, {} alarms after the start-up",
                ms as f64 / 1000.0,
                setup.seconds,
                st.load_percent(),
                st.frames,
                judged
            );
        }
        // Keep memory flat on the long run.
        if ms % 1000 == 0 {
            bus.clear_trace();
        }
    }
    checker.sct_until(bus.now_ns());
    out.offered = offered_percent(&setup, &classes);
    out.classes = classes
        .into_iter()
        .map(|(k, (n, _))| format!("{k} {n}"))
        .collect();
    let st = bus.stats().unwrap();
    out.bus_load = st.load_percent();
    out.frames = st.frames;
    out.lost_safety = st.rx_lost_high;
    out.lost_other = st.rx_lost_low;
    out.tx_refused = st.tx_refused;
    out.worst_latency_us = checker.worst_latency_ns as f64 / 1000.0;
    // An alarm is correct when a real miss of its SRDO lies before it, no
    // more than one SCT after the receiver could know it (the stack's
    // cycle, and an SRVT miss that an SCT check finds first); a real miss
    // is reported when an alarm of its SRDO comes in that time. One
    // millisecond of slack before the deadline: the stack's cycle.
    let window = u64::from(SCT_MS) * 1_000_000;
    let slack = 1_000_000;
    let matches =
        |m: &Miss, s: usize, t: u64| m.srdo == s && t + slack >= m.at_ns && t <= m.seen_ns + window;
    let from = warmup_ms * 1_000_000;
    for &(s, t, code) in &alarms {
        if t < from + window {
            continue;
        }
        let real = checker.misses.iter().any(|m| matches(m, s, t));
        if real {
            out.correct += 1;
        } else {
            out.false_alarms += 1;
            if out.false_examples.len() < 5 {
                out.false_examples.push(format!(
                    "SRDO {} at {:.4} s: {code:?}",
                    s + 1,
                    t as f64 / 1e9
                ));
            }
        }
    }
    // Misses the stacks could not report before the end are left out.
    let end_ns = bus.now_ns();
    for m in checker
        .misses
        .iter()
        .filter(|m| m.clear && m.at_ns >= from && m.seen_ns + window <= end_ns)
    {
        out.real_misses += 1;
        let reported = alarms.iter().any(|&(s, t, _)| matches(m, s, t));
        if !reported {
            out.missed += 1;
            if out.missed_examples.len() < 5 {
                out.missed_examples.push(format!(
                    "SRDO {} at {:.4} s: {}",
                    m.srdo + 1,
                    m.at_ns as f64 / 1e9,
                    m.what
                ));
            }
        }
    }
    out
}

/// What the due column says about a run.
fn due(s: &Setup) -> String {
    match (s.burst, s.drop_every, s.rx_low) {
        (true, _, _) => "at once".to_string(),
        (_, 0, 10) => "spread".to_string(),
        (_, 0, n) => format!("spread with low receive buffers of {n}"),
        (_, n, _) => format!("spread with 1/{n} SRDO frames lost"),
    }
}

/// The columns of a run: the table's heading, the CSV key, the value.
fn columns(s: &Setup, o: &Outcome) -> [(&'static str, &'static str, String); 18] {
    [
        ("SRDOs", "srdos", s.srdos.to_string()),
        ("bytes", "bytes", s.srdo_len.to_string()),
        ("due", "due", due(s)),
        ("s", "seconds", s.seconds.to_string()),
        ("offered load %", "offered", format!("{:.1}", o.offered)),
        ("bus load %", "bus_load", format!("{:.1}", o.bus_load)),
        ("frames", "frames", o.frames.to_string()),
        (
            "lost safety frames",
            "lost_safety",
            o.lost_safety.to_string(),
        ),
        ("lost other frames", "lost_other", o.lost_other.to_string()),
        ("EMCY 0x8110", "overrun_emcy", o.overrun_emcy.to_string()),
        ("SDO ok", "sdo_ok", o.sdo_ok.to_string()),
        ("SDO errors", "sdo_errors", o.sdo_errors.to_string()),
        ("real misses", "real_misses", o.real_misses.to_string()),
        ("correct", "correct", o.correct.to_string()),
        ("false", "false", o.false_alarms.to_string()),
        ("missed", "missed", o.missed.to_string()),
        (
            "worst pair latency ms",
            "worst_latency_ms",
            format!("{:.2}", o.worst_latency_us / 1000.0),
        ),
        ("transmit refused", "tx_refused", o.tx_refused.to_string()),
    ]
}

fn header() {
    let c = columns(&Setup::default(), &Outcome::default());
    let names: Vec<&str> = c.iter().map(|(h, _, _)| *h).collect();
    println!("| {} |", names.join(" | "));
    println!("|{}", "---|".repeat(names.len()));
}

fn row(s: &Setup, o: &Outcome) {
    let values: Vec<String> = columns(s, o).into_iter().map(|(_, _, v)| v).collect();
    println!("| {} |", values.join(" | "));
    if std::env::var_os("LOAD_VERBOSE").is_some() {
        println!("  frames: {}", o.classes.join(", "));
    }
    for e in &o.false_examples {
        println!("  false alarm: {e}");
    }
    for e in &o.missed_examples {
        println!("  missed: {e}");
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let quick = args.iter().any(|a| a == "--quick");
    let minutes: u32 = args
        .iter()
        .position(|a| a == "--minutes")
        .and_then(|i| args.get(i + 1))
        .map(|v| v.parse().expect("--minutes N"))
        .unwrap_or(10);
    let csv = args
        .iter()
        .position(|a| a == "--csv")
        .and_then(|i| args.get(i + 1))
        .cloned();
    let (main_s, sweep_s, mut sweep): (u32, u32, Vec<usize>) = if quick {
        (3, 2, vec![40, 64])
    } else {
        (minutes * 60, 20, (32..=64).step_by(4).collect())
    };
    if let Some(list) = args
        .iter()
        .position(|a| a == "--sweep")
        .and_then(|i| args.get(i + 1))
    {
        sweep = list
            .split(',')
            .filter(|v| !v.is_empty())
            .map(|v| v.parse().expect("--sweep N,N,.. (SRDOs, 1..=64)"))
            .filter(|&n| (1..=64).contains(&n))
            .collect();
    }
    println!(
        "load campaign: 1 Mbit/s, receive buffers high 16 / low 10, timestamps {}",
        if cop::config::CDRV_TIMESTAMP {
            "from the driver (CDRV_TIMESTAMP)"
        } else {
            "at the stack's cycle"
        }
    );
    header();
    let mut runs = Vec::new();
    // The main network; all SRDOs due at once; the checks of the checker
    // (lost SRDO frames) and of the overrun report (low receive buffers
    // too small for the bursts after SYNC), a minute each.
    for (burst, drop_every, rx_low) in [
        (false, 0, 10),
        (true, 0, 10),
        (false, 1000, 10),
        (false, 0, 3),
    ] {
        let main = Setup {
            srdos: 45,
            srdo_len: 4,
            seconds: if drop_every > 0 || rx_low != 10 {
                main_s.min(60)
            } else {
                main_s
            },
            burst,
            drop_every,
            rx_low,
        };
        if main_s > 0 {
            if !quick {
                eprintln!("45 SRDOs, {}", due(&main));
            }
            let o = run(main, !quick);
            row(&main, &o);
            runs.push((main, o));
        }
    }
    for (len, n) in [4, 8]
        .into_iter()
        .flat_map(|len| sweep.iter().map(move |&n| (len, n)))
    {
        let s = Setup {
            srdos: n,
            srdo_len: len,
            seconds: sweep_s,
            burst: false,
            drop_every: 0,
            rx_low: 10,
        };
        if !quick {
            eprintln!("sweep: {n} SRDOs of {len} bytes");
        }
        let o = run(s, false);
        row(&s, &o);
        runs.push((s, o));
    }
    if let Some(path) = csv {
        let mut f = std::fs::File::create(&path).expect("csv file");
        for (i, (s, o)) in runs.iter().enumerate() {
            let c = columns(s, o);
            if i == 0 {
                let keys: Vec<&str> = c.iter().map(|(_, k, _)| *k).collect();
                writeln!(f, "{}", keys.join(",")).unwrap();
            }
            let values: Vec<String> = c.into_iter().map(|(_, _, v)| v).collect();
            writeln!(f, "{}", values.join(",")).unwrap();
        }
    }
    // The goal: no false alarm anywhere; at or below 100 % offered load no
    // lost safety frame, no missed deadline report and no SDO error (but
    // where the low receive buffers are made to lose frames).
    let bad = runs.iter().any(|(s, o)| {
        o.false_alarms > 0
            || (o.offered <= 100.0 && (o.lost_safety > 0 || o.missed > 0))
            || (o.offered <= 100.0 && s.rx_low == 10 && o.sdo_errors > 0)
            // Lost frames the checker does not see, or alarms it cannot
            // place, would make every other row worthless.
            || (s.drop_every > 0 && (o.real_misses == 0 || o.correct < o.real_misses))
            // Each low-buffer overrun the stack saw is an EMCY 0x8110, no
            // SRDO alarm (the false count above).
            || (s.rx_low != 10 && (o.lost_other == 0 || o.overrun_emcy == 0))
    });
    if bad {
        println!(
            "FAILED: a false alarm, or at or below 100 % offered load a lost safety frame, an unreported miss or an SDO error"
        );
        std::process::exit(1);
    }
    println!(
        "ok: no false alarm; at or below 100 % offered load no lost safety frame, every miss reported, no SDO error"
    );
}
