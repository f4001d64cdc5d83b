//! Benchmark scenarios of the cop library.
//!
//! `cop-bench <scenario> [argument] <iterations>` sets a scenario up and
//! then calls its measured function `iterations` times. Every measured
//! function is `#[inline(never)]` and named `measure_*`; `scripts/bench.sh`
//! runs this binary under `valgrind --tool=callgrind --collect-atstart=no
//! --toggle-collect=<that function>` at two iteration counts N and 2N and
//! reports (Ir(2N) - Ir(N)) / N, so that everything outside the measured
//! function, and any one-time cost inside it, cancels.
//!
//! Each scenario checks afterwards that the measured work really happened
//! (every SRDO pair accepted and written, every SDO answered correctly,
//! every lookup found); a failed check ends the program with exit code 1,
//! so a figure can never come from a scenario that silently did nothing.
//!
//! | scenario | measured function | one call is |
//! |---|---|---|
//! | `srdo-rx <n>` | `measure_cycle` | one `CcmProcess` cycle of a node with `n` running receive SRDOs that takes one valid pair (4 data bytes) of SRDO n from the driver |
//! | `srdo-idle <n>` | `measure_cycle` | the same cycle without a frame |
//! | `srdo-crc16` | `measure_crc` | `CcmCalcSrdoCrc` of an SRDO with 16 mapping entries (`Srdo::calc_crc`) |
//! | `od-find <n>` | `measure_find` | one `ObjectDictionary::find` in a dictionary of `n` objects |
//! | `sdo-upload`, `sdo-download` | `measure_cycle` | one cycle that answers an expedited SDO request |
//! | `sdo-idle` | `measure_cycle` | the same cycle without a request |
//! | `dyn-build <bytes>` | `measure_dyn_build` | `DynBuildOd` of a container of about that size ([`dyn_build`]) |

mod dict;
mod port;

use std::hint::black_box;
use std::process::ExitCode;

use cop::ccm::{NmtCommand, Stack};
use cop::event::{Event, NmtState};
use cop::od::{ByteOrder, ObjectDictionary};
use cop::port::{CanFrame, CanId, RxFrame, Ticks};
use cop::srdo::Srdo;

use port::BenchPort;

/// Node-ID of the measured node.
const NODE_ID: u8 = 5;

/// What the application callbacks saw.
#[derive(Default, Debug)]
struct Tally {
    srdo_ok: u64,
    srdo_errors: u64,
    progmon: u64,
    other: u64,
}

/// The application's reaction to an event, as a firmware does it:
/// `AppSrdoEvent` marks the SRDO processed (status bits 4-5 := 11, manual
/// 2.9.1), the other callbacks only count.
fn handle(stack: &mut Stack, e: Event, tally: &mut Tally) {
    match e {
        Event::SrdoEvent(idx) => {
            if let Ok(st) = stack.srdo().get_state(idx) {
                let _ = stack.srdo_mut().set_state(idx, st | 0x30);
            }
            tally.srdo_ok += 1;
        }
        Event::SrdoError(..) => tally.srdo_errors += 1,
        Event::ProgMon(_) => tally.progmon += 1,
        _ => tally.other += 1,
    }
}

/// One `CcmProcess`: a cycle of the stack with every event handed to the
/// application.
#[inline(never)]
fn measure_cycle(stack: &mut Stack, port: &mut BenchPort, now: Ticks, tally: &mut Tally) {
    stack.process(port, now, |s, e| handle(s, e, tally));
}

/// `Srdo::calc_crc`, the work of `CcmCalcSrdoCrc`.
#[inline(never)]
fn measure_crc(srdo: &Srdo, od: &ObjectDictionary, commu_index: u16) -> Option<u16> {
    srdo.calc_crc(od, commu_index).ok()
}

/// One dictionary lookup.
#[inline(never)]
fn measure_find(od: &ObjectDictionary, index: u16, sub: u8) -> bool {
    black_box(od.find(index, sub)).is_ok()
}

/// Runs cycles until the queue is empty (set-up only).
fn settle(stack: &mut Stack, port: &mut BenchPort, now: Ticks) {
    for _ in 0..4 {
        stack.process(port, now, |_, _| {});
    }
}

fn fail(msg: String) -> Result<(), String> {
    Err(msg)
}

// ------------------------------------------------------------------- SRDO

/// A node with `count` receive SRDOs (4 data bytes each, SCT 65.535 s so
/// that no deadline passes during the run, SRVT 20 ms), valid CRCs, 0x13FE
/// = 0xA5, OPERATIONAL with every SRDO running.
fn srdo_node(count: usize) -> Result<(Stack, BenchPort), String> {
    let od = dict::srdo_dict(count, 2, 65535, 4);
    let mut stack = Stack::new(od, NODE_ID).map_err(|e| format!("CcmInitCANopen: {e:?}"))?;
    let mut port = BenchPort::new();
    let now = Ticks(0);
    stack.connect().map_err(|e| format!("connect: {e:?}"))?;
    settle(&mut stack, &mut port, now);
    for n in 1..=count as u16 {
        let idx = 0x1300 + n;
        let crc = stack
            .srdo()
            .calc_crc(stack.od(), idx)
            .map_err(|e| format!("CRC of {idx:#06x}: {e:?}"))?;
        stack
            .write_object(0x13FF, n as u8, ByteOrder::Wire, &crc.to_le_bytes(), now)
            .map_err(|e| format!("0x13FF sub {n}: {e:?}"))?;
    }
    stack
        .write_object(0x13FE, 0, ByteOrder::Wire, &[0xA5], now)
        .map_err(|e| format!("0x13FE: {e:?}"))?;
    if let Err(e) = stack.srdo().check_config(stack.od()) {
        return Err(format!("configuration check: {e:?}"));
    }
    stack
        .exec_command(NmtCommand::StartRemoteNode)
        .map_err(|e| format!("start: {e:?}"))?;
    settle(&mut stack, &mut port, now);
    if stack.nmt_state() != NmtState::Operational || !stack.srdo().is_running() {
        return Err("node not OPERATIONAL with SRDOs running".into());
    }
    Ok((stack, port))
}

fn srdo_cycles(count: usize, iterations: u64, with_pair: bool) -> Result<(), String> {
    let (mut stack, mut port) = srdo_node(count)?;
    // The pair goes to the highest SRDO (worst case for any search).
    let cob1 = 0x101 + 2 * (count as u16 - 1);
    let mut tally = Tally::default();
    let mut now = Ticks(0);
    let mut last = [0u8; 4];
    for i in 0..iterations {
        now = now.plus(1);
        if with_pair {
            let v = (i as u32).wrapping_mul(0x9E37_79B9).to_le_bytes();
            let inv = v.map(|b| !b);
            port.inject(RxFrame {
                frame: CanFrame::new(CanId::std_masked(cob1), &v),
                time: now,
            });
            port.inject(RxFrame {
                frame: CanFrame::new(CanId::std_masked(cob1 + 1), &inv),
                time: now,
            });
            last = v;
        }
        measure_cycle(&mut stack, &mut port, now, &mut tally);
    }
    let expected = if with_pair { iterations } else { 0 };
    if tally.srdo_ok != expected || tally.srdo_errors != 0 || port.pending() != 0 {
        return fail(format!(
            "expected {expected} valid pairs and no error, got {tally:?}"
        ));
    }
    if with_pair && iterations > 0 {
        // Normal frame: subs 1 and 3; inverted frame: subs 2 and 4.
        let object = 0x6000 + count as u16 - 1;
        let mut got = [0u8; 8];
        for (k, sub) in [1u8, 3, 2, 4].into_iter().enumerate() {
            let mut b = [0u8; 2];
            stack
                .read_object(object, sub, ByteOrder::Wire, &mut b)
                .map_err(|e| format!("read {object:#06x}/{sub}: {e:?}"))?;
            got[2 * k..2 * k + 2].copy_from_slice(&b);
        }
        let inv = last.map(|b| !b);
        if got[..4] != last || got[4..] != inv {
            return fail(format!(
                "variables {got:02x?}, expected {last:02x?} {inv:02x?}"
            ));
        }
        let status = stack.srdo().get_state(0x1300 + count as u16).unwrap_or(0);
        if status & 0x30 != 0x30 {
            return fail(format!("status byte {status:#04x}: event not handled"));
        }
    }
    Ok(())
}

fn srdo_crc(iterations: u64) -> Result<(), String> {
    let od = dict::srdo_dict(1, 2, 25, 16);
    // The defaults (mapping) reach the variables as at reset communication.
    od.restore_defaults(0x1000, 0xFFFF);
    let mut srdo = Srdo::new();
    srdo.init(&od).map_err(|e| format!("SrdoInit: {e:?}"))?;
    let mut stream = [0u8; cop::srdo::crc::MAX_STREAM];
    let n = cop::srdo::crc::stream_bytes(&od, 0x1301, &mut stream)
        .map_err(|e| format!("stream: {e:?}"))?;
    if n != 13 + 5 * 16 {
        return fail(format!("CRC stream of {n} bytes, expected 93"));
    }
    let expected = cop::srdo::crc16(&stream[..n]);
    for _ in 0..iterations {
        if measure_crc(&srdo, &od, black_box(0x1301)) != Some(expected) {
            return fail("CRC differs from CRC-16/XMODEM of the stream".into());
        }
    }
    Ok(())
}

// ----------------------------------------------------------------- lookup

fn od_find(count: usize, iterations: u64) -> Result<(), String> {
    let (od, mut addresses) = dict::lookup_dict(count);
    // A fixed pseudo-random order, so that consecutive lookups do not walk
    // the table in order.
    let mut x = 0x2545_F491u32;
    for i in (1..addresses.len()).rev() {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        addresses.swap(i, x as usize % (i + 1));
    }
    let mut found = 0u64;
    for i in 0..iterations {
        let (index, sub) = addresses[i as usize % addresses.len()];
        found += u64::from(measure_find(&od, index, sub));
    }
    if found != iterations {
        return fail(format!("{found} of {iterations} lookups found"));
    }
    Ok(())
}

// -------------------------------------------------------------------- SDO

#[derive(Clone, Copy, PartialEq, Eq)]
enum SdoRequest {
    None,
    Upload,
    Download,
}

fn sdo_cycles(request: SdoRequest, iterations: u64) -> Result<(), String> {
    let od = cop::testod::dictionary();
    let mut stack = Stack::new(od, NODE_ID).map_err(|e| format!("CcmInitCANopen: {e:?}"))?;
    let mut port = BenchPort::new();
    stack.connect().map_err(|e| format!("connect: {e:?}"))?;
    settle(&mut stack, &mut port, Ticks(0));
    if stack.nmt_state() != NmtState::PreOperational {
        return fail("node not PRE-OPERATIONAL".into());
    }
    let rx_id = CanId::std_masked(0x600 + u16::from(NODE_ID));
    let tx_id = CanId::std_masked(0x580 + u16::from(NODE_ID));
    // CiA 301 expedited upload of 0x1018 sub 1 (vendor-ID 0x00000123) and
    // expedited download of 4 bytes to 0x2002 sub 0 (UNSIGNED32, RAM).
    let (req, resp): ([u8; 8], [u8; 8]) = match request {
        SdoRequest::Upload => (
            [0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0],
            [0x43, 0x18, 0x10, 0x01, 0x23, 0x01, 0, 0],
        ),
        SdoRequest::Download | SdoRequest::None => (
            [0x23, 0x02, 0x20, 0x00, 0x78, 0x56, 0x34, 0x12],
            [0x60, 0x02, 0x20, 0x00, 0, 0, 0, 0],
        ),
    };
    let mut tally = Tally::default();
    let mut now = Ticks(0);
    let sent_before = port.sent;
    for _ in 0..iterations {
        now = now.plus(1);
        if request != SdoRequest::None {
            port.inject(RxFrame {
                frame: CanFrame::new(rx_id, &req),
                time: now,
            });
        }
        measure_cycle(&mut stack, &mut port, now, &mut tally);
    }
    let answers = u64::from(port.sent - sent_before);
    let expected = if request == SdoRequest::None {
        0
    } else {
        iterations
    };
    if answers != expected {
        return fail(format!("{answers} frames sent, expected {expected}"));
    }
    if expected > 0 {
        match port.last_sent {
            Some(f) if f.id == tx_id && f.len == 8 && f.data == resp => {}
            other => return fail(format!("SDO response {other:02x?}, expected {resp:02x?}")),
        }
    }
    Ok(())
}

// ------------------------------------------------------------- dynamic OD

/// Entries of one group of the generated container: a new record
/// 0x3000 + g with an UNSIGNED32, an UNSIGNED16 and an UNSIGNED8 (numeric,
/// read-write; the build adds sub 0) and a write to the existing UNSIGNED32
/// 0x2002 of the reference dictionary (through the normal write path).
const DYN_GROUP_ENTRIES: usize = 4;
/// Bytes of one group: 4 entry headers (7 bytes), 11 data bytes, 4
/// attribute bytes.
const DYN_GROUP_BYTES: usize = 4 * cop::od::dcf::ENTRY_HEADER_SIZE + 11 + 4;

/// A container of `groups` groups (see [`DYN_GROUP_ENTRIES`]).
fn dyn_container(groups: usize) -> Result<Vec<u8>, String> {
    use cop::od::dcf::{EntrySpec, attr, encode, encoded_len};
    let rw = attr::NUMERIC | attr::READ | attr::WRITE;
    let values: Vec<[u8; 4]> = (0..groups as u32)
        .map(|g| (0x1234_0000 | g).to_le_bytes())
        .collect();
    let mut entries = Vec::with_capacity(groups * DYN_GROUP_ENTRIES);
    for (g, v) in values.iter().enumerate() {
        let index = 0x3000 + g as u16;
        for (sub, data) in [(1u8, &v[..4]), (2, &v[..2]), (3, &v[..1])] {
            entries.push(EntrySpec {
                index,
                sub,
                data,
                attr: rw,
            });
        }
        entries.push(EntrySpec {
            index: 0x2002,
            sub: 0,
            data: &v[..4],
            attr: rw,
        });
    }
    let len = encoded_len(&entries, None, true, None).ok_or("container too large")?;
    let mut out = vec![0u8; len];
    encode(&entries, None, true, None, &mut out).map_err(|e| format!("encode: {e:?}"))?;
    Ok(out)
}

static DYN_POOL: cop::od::dynamic::DynPool<65536> = cop::od::dynamic::DynPool::new();

/// `DynBuildOd` (the Rust entry point `DynPool::build` behind it).
#[inline(never)]
fn measure_dyn_build(
    stack: &mut Stack,
    port: &mut BenchPort,
    container: &[u8],
) -> Result<cop::od::dynamic::BuildInfo, cop::CopKernel> {
    DYN_POOL.build(stack, port, Ticks(0), container, None)
}

/// `DynBuildOd` of a generated container of about `bytes` bytes (groups of
/// [`DYN_GROUP_ENTRIES`] entries, `bytes / 45` groups, so 768 and 1536
/// give exactly 17 and 34 groups) on the reference dictionary, PRE-
/// OPERATIONAL; `DynDestroyOd` after each build, outside the measurement.
/// Prints the container's size and entry count.
fn dyn_build(bytes: usize, iterations: u64) -> Result<(), String> {
    let groups = bytes / (DYN_GROUP_BYTES + 2);
    let container = dyn_container(groups)?;
    println!(
        "container {} bytes {} entries",
        container.len(),
        groups * DYN_GROUP_ENTRIES
    );
    let od = cop::testod::dictionary();
    let mut stack = Stack::new(od, NODE_ID).map_err(|e| format!("CcmInitCANopen: {e:?}"))?;
    let mut port = BenchPort::new();
    stack.connect().map_err(|e| format!("connect: {e:?}"))?;
    settle(&mut stack, &mut port, Ticks(0));
    for _ in 0..iterations {
        let info = measure_dyn_build(&mut stack, &mut port, black_box(&container))
            .map_err(|e| format!("DynBuildOd: {e:?}"))?;
        if info.new_indices != groups {
            return fail(format!(
                "{} objects created, expected {groups}",
                info.new_indices
            ));
        }
        let mut b = [0u8; 4];
        let last = 0x3000 + groups as u16 - 1;
        stack
            .read_object(last, 1, ByteOrder::Wire, &mut b)
            .map_err(|e| format!("read {last:#06x}/1: {e:?}"))?;
        if u32::from_le_bytes(b) != 0x1234_0000 | (groups as u32 - 1) {
            return fail(format!("{last:#06x}/1 holds {b:02x?}"));
        }
        DYN_POOL
            .destroy(&mut stack, &mut port, Ticks(0))
            .map_err(|e| format!("DynDestroyOd: {e:?}"))?;
    }
    Ok(())
}

// ------------------------------------------------------------------- main

const USAGE: &str = "usage: cop-bench <scenario> [n] <iterations>
  srdo-rx <n> | srdo-idle <n>    n = 1, 8, 32 or 64 receive SRDOs
  srdo-crc16
  od-find <n>                    n objects (1..=16384)
  sdo-upload | sdo-download | sdo-idle
  dyn-build <bytes>              container of about that size";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let num = |s: Option<&String>| s.and_then(|v| v.parse::<u64>().ok());
    let (name, param, iterations) = match args.len() {
        2 => (args[0].as_str(), None, num(args.get(1))),
        3 => (args[0].as_str(), num(args.get(1)), num(args.get(2))),
        _ => (String::new().leak() as &str, None, None),
    };
    let Some(iterations) = iterations else {
        eprintln!("{USAGE}");
        return ExitCode::from(2);
    };
    let n = param.map(|p| p as usize);
    let result = match (name, n) {
        ("srdo-rx", Some(n)) => srdo_cycles(n, iterations, true),
        ("srdo-idle", Some(n)) => srdo_cycles(n, iterations, false),
        ("srdo-crc16", None) => srdo_crc(iterations),
        ("od-find", Some(n)) => od_find(n, iterations),
        ("sdo-upload", None) => sdo_cycles(SdoRequest::Upload, iterations),
        ("sdo-download", None) => sdo_cycles(SdoRequest::Download, iterations),
        ("sdo-idle", None) => sdo_cycles(SdoRequest::None, iterations),
        ("dyn-build", Some(bytes)) => dyn_build(bytes, iterations),
        _ => {
            eprintln!("{USAGE}");
            return ExitCode::from(2);
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("cop-bench {}: {e}", args.join(" "));
            ExitCode::from(1)
        }
    }
}
