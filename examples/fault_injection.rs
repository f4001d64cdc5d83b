//! Fault-injection campaign for SRDO reception (see `cop::sim::faults` for
//! the fault model, the expected reactions and what is counted).
//!
//! ```text
//! cargo run --release --example fault_injection -- --cycles 10000000 --seed 1
//! ```
//! Prints the table (class, injected, detected, missed, false alarms,
//! expected codes) and exits with 1 unless every fault was detected and
//! nothing else was reported. `--pairs FILE` also writes the timing of every
//! pair (legal, or late on purpose) as CSV (ticks of 100 µs; `tools/srdo_plot` draws it).

use std::io::Write as _;
use std::process::ExitCode;
use std::time::Instant;

use cop::error::CopKernel;
use cop::sim::faults::{Config, PairTiming, Report, run};

fn usage() -> ExitCode {
    eprintln!("usage: fault_injection [--cycles N] [--seed N] [--fault-one-in N] [--pairs FILE]");
    ExitCode::from(2)
}

/// A number in decimal or with 0x.
fn number(s: &str) -> Option<u64> {
    match s.strip_prefix("0x") {
        Some(h) => u64::from_str_radix(h, 16).ok(),
        None => s.replace('_', "").parse().ok(),
    }
}

fn main() -> ExitCode {
    let mut cfg = Config::new(1_000_000, 1);
    let mut pairs = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let Some(value) = args.next() else {
            return usage();
        };
        if a == "--pairs" {
            cfg.record_pairs = true;
            pairs = Some(value);
            continue;
        }
        let Some(v) = number(&value) else {
            return usage();
        };
        match a.as_str() {
            "--cycles" => cfg.cycles = v,
            "--seed" => cfg.seed = v,
            "--fault-one-in" if v >= 1 => cfg.fault_one_in = v,
            _ => return usage(),
        }
    }
    let started = Instant::now();
    let report = match run(&cfg) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::from(2);
        }
    };
    print!("{}", report.table());
    if let Some(path) = pairs {
        if let Err(e) = write_pairs(&path, &report) {
            eprintln!("{path}: {e}");
            return ExitCode::from(2);
        }
    }
    println!("wall time {:.1} s", started.elapsed().as_secs_f64());
    if report.passed() {
        println!("PASS: every injected fault detected, no false alarm");
        ExitCode::SUCCESS
    } else {
        println!("FAIL");
        ExitCode::FAILURE
    }
}

/// The accepted pairs as CSV: the limits in the header, one pair a line.
fn write_pairs(path: &str, report: &Report) -> std::io::Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(
        w,
        "# seed {:#x}, {} producer cycles, ticks of 100 us, srvt_ticks {}, sct_ticks {}",
        report.seed,
        report.cycles,
        PairTiming::SRVT_TICKS,
        PairTiming::SCT_TICKS
    )?;
    writeln!(w, "gap_ticks,period_ticks,reported")?;
    for p in &report.pairs {
        let reported = match p.reported {
            None => "",
            Some(CopKernel::SrdoSrvtTimeout) => "srvt",
            Some(CopKernel::SrdoSctTimeout) => "sct",
            Some(_) => "other",
        };
        writeln!(w, "{},{},{reported}", p.gap_ticks, p.period_ticks)?;
    }
    w.flush()
}
