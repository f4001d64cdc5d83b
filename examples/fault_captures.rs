//! Writes one pcap capture per fault class of the fault-injection campaign
//! (`cop::sim::fault_captures`), the consumer's DCF and a manifest of what
//! an observer of the bus must report in each capture.
//!
//! ```text
//! cargo run --example fault_captures -- target/captures
//! tshark -2 -X lua_script:tools/wireshark/cop_srdo.lua \
//!     -o cop_srdo.dcf:target/captures/consumer.dcf -r target/captures/late_inverted.pcap
//! ```
//! Manifest lines (`manifest.txt`), one per capture:
//! `<file> frames=<n> expect=<frame>:<expert field>,... valid=<frame>,...
//! consumer=<frame>:<code>,...` (empty lists stay empty after `=`).

use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use cop::sim::fault_captures::{WIRE_CLASSES, consumer_dcf, file_stem, write};
use cop::sim::srdo_net::lock;

fn main() -> ExitCode {
    let Some(dir) = std::env::args_os().nth(1).map(PathBuf::from) else {
        eprintln!("usage: fault_captures DIR");
        return ExitCode::from(2);
    };
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("fault_captures: {}: {e}", dir.display());
        return ExitCode::from(1);
    }
    let _devices = lock();
    let mut manifest = String::new();
    for class in WIRE_CLASSES {
        let file = format!("{}.pcap", file_stem(class));
        let c = match write(class, &dir.join(&file)) {
            Ok(c) => c,
            Err(e) => {
                eprintln!("fault_captures: {}: {e}", class.name());
                return ExitCode::from(1);
            }
        };
        let join = |v: Vec<String>| v.join(",");
        let _ = writeln!(
            manifest,
            "{file} frames={} expect={} valid={} consumer={}",
            c.frames,
            join(
                c.expected
                    .iter()
                    .map(|e| format!("{}:{}", e.frame, e.expert))
                    .collect()
            ),
            join(c.valid_pair_frames.iter().map(u32::to_string).collect()),
            join(
                c.consumer_errors
                    .iter()
                    .map(|(f, k)| format!("{f}:{k:?}"))
                    .collect()
            ),
        );
        println!(
            "{:<26} {:>3} frames, {} report(s) expected -> {file}",
            class.name(),
            c.frames,
            c.expected.len()
        );
    }
    for (name, text) in [("consumer.dcf", consumer_dcf()), ("manifest.txt", manifest)] {
        if let Err(e) = std::fs::write(dir.join(name), text) {
            eprintln!("fault_captures: {name}: {e}");
            return ExitCode::from(1);
        }
    }
    ExitCode::SUCCESS
}
