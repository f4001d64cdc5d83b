//! Fault-injection campaign for SRDO reception (see `cop::sim::faults` for
//! the fault model, the expected reactions and what is counted).
//!
//! ```text
//! cargo run --release --example fault_injection -- --cycles 10000000 --seed 1
//! ```
//! Prints the table (class, injected, detected, missed, false alarms,
//! expected codes) and exits with 1 unless every fault was detected and
//! nothing else was reported.

use std::process::ExitCode;
use std::time::Instant;

use cop::sim::faults::{Config, run};

fn usage() -> ExitCode {
    eprintln!("usage: fault_injection [--cycles N] [--seed N] [--fault-one-in N]");
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
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let Some(v) = args.next().as_deref().and_then(number) else {
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
    println!("wall time {:.1} s", started.elapsed().as_secs_f64());
    if report.passed() {
        println!("PASS: every injected fault detected, no false alarm");
        ExitCode::SUCCESS
    } else {
        println!("FAIL");
        ExitCode::FAILURE
    }
}
