//! Command line of `dcf2bin` (see the library documentation for what the
//! container holds).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use dcf2bin::container::{pool_need_alone, verify};
use dcf2bin::{Dcf, Options, check, node};

const HELP: &str = "\
dcf2bin - CANopen DCF/EDS to the binary DCF container of the cop dynamic
object dictionary (SYS TEC CcmDyn format: header, index segment (CiA 302
concise DCF), process-image address segment, extended info segment,
process-image parameter segment)

USAGE:
    dcf2bin [OPTIONS] <INPUT.dcf|INPUT.eds>
    dcf2bin --check <NODE> [--objdict FILE] [--image N] [--eds FILE] <INPUT.dcf>
    dcf2bin --srdo-crc [--write] <INPUT.dcf>
    dcf2bin --verify <CONTAINER.bin>

OPTIONS:
    -o, --output <FILE>  where to write the container
                         (default: INPUT with the extension .bin)
        --c-array <NAME> write C source instead (default: INPUT.h), a
                         `static const unsigned char NAME[]` holding the
                         container, to #include where DynBuildOd is called
        --node-id <N>    node-ID for $NODEID (default: [DeviceComissioning]
                         NodeID of the file)
        --strict         refuse what would be skipped or tolerated with a
                         warning (unsupported data types, forms outside
                         CiA 306)
        --dump           print the objects (index, subindex, data type,
                         attribute, value in hex) instead of writing
        --check <NODE>   build the container in this process on the node
                         and report what DynBuildOd does: whether it
                         builds, what it creates and changes, the pool.
                         NODE is the node's C folder (copcfg.h, obdcfg.h,
                         objdict.h) or the node's EDS (then the
                         configuration is the one dcf2bin was built with)
        --objdict <FILE> with --check: the node's objdict.h, when it is not
                         in the folder
        --image <N>      with --check: bytes of the process image handed to
                         DynBuildOd (default: what the container reports)
        --eds <FILE>     with --check: write the EDS of the node after the
                         build (the library's export, with the data types
                         the input gives the objects the build created)
        --srdo-crc       print the configuration CRC (object 0x13FF) of
                         every SRDO the file configures, the stored value
                         and the pairs of its mapping, and run the
                         library's SRDO configuration check on the file
                         (exit status 1 when the file declares the
                         configuration valid, 0x13FE = 0xA5, and a stored
                         0x13FF value is not the CRC)
        --write          with --srdo-crc: store the CRCs in the file
                         (0x13FF sub n ParameterValue)
        --verify <BIN>   check a container (from any tool): what DynBuildOd
                         refuses, process-image windows that do not cover
                         the variables; lists subindices written twice
    -q, --quiet          no summary (warnings are still printed)
    -v, --verbose        every warning (default: of many of one kind, the
                         first three and their number)
    -h, --help           this text

A conversion prints the size of the container and the pool
(OBD_DYNAMIC_POOL_SIZE) it needs. Nothing is written when the input has an
error; errors name the file, the line, the section and the key. Output
files are written to a temporary file and renamed.
";

#[derive(Default)]
struct Args {
    input: PathBuf,
    output: Option<PathBuf>,
    c_array: Option<String>,
    node_id: Option<u8>,
    strict: bool,
    dump: bool,
    srdo_crc: bool,
    write: bool,
    check: Option<PathBuf>,
    objdict: Option<PathBuf>,
    image: Option<usize>,
    eds: Option<PathBuf>,
    verify: bool,
    quiet: bool,
    verbose: bool,
}

fn parse_args() -> Result<Option<Args>, String> {
    let mut it = std::env::args().skip(1);
    let mut a = Args::default();
    let mut input = None;
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().ok_or(format!("{name} needs a value"));
        match arg.as_str() {
            "-h" | "--help" => return Ok(None),
            "-o" | "--output" => a.output = Some(PathBuf::from(value("--output")?)),
            "--c-array" => {
                let n = value("--c-array")?;
                if n.is_empty()
                    || !n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                    || n.starts_with(|c: char| c.is_ascii_digit())
                {
                    return Err(format!("--c-array: `{n}` is not a C identifier"));
                }
                a.c_array = Some(n);
            }
            "--node-id" => {
                let v = value("--node-id")?;
                let n = dcf2bin::parse_int(&v, None).map_err(|e| format!("--node-id: {e}"))?;
                a.node_id = Some(
                    u8::try_from(n)
                        .ok()
                        .filter(|n| (1..=127).contains(n))
                        .ok_or(format!("--node-id: {n} is not 1..127"))?,
                );
            }
            "--image" => {
                let v = value("--image")?;
                let n = dcf2bin::parse_int(&v, None).map_err(|e| format!("--image: {e}"))?;
                a.image = Some(
                    usize::try_from(n)
                        .ok()
                        .filter(|n| *n <= 1 << 24)
                        .ok_or(format!("--image: {n} is not 0..16 MiB"))?,
                );
            }
            "--check" => a.check = Some(PathBuf::from(value("--check")?)),
            "--objdict" => a.objdict = Some(PathBuf::from(value("--objdict")?)),
            "--eds" => a.eds = Some(PathBuf::from(value("--eds")?)),
            "--strict" => a.strict = true,
            "--dump" => a.dump = true,
            "--srdo-crc" => a.srdo_crc = true,
            "--write" => a.write = true,
            "--verify" => a.verify = true,
            "-q" | "--quiet" => a.quiet = true,
            "-v" | "--verbose" => a.verbose = true,
            s if s.starts_with('-') && s.len() > 1 => {
                return Err(format!("unknown option {s} (see --help)"));
            }
            s => {
                if input.replace(PathBuf::from(s)).is_some() {
                    return Err("more than one input file (see --help)".into());
                }
            }
        }
    }
    a.input = input.ok_or("no input file (see --help)")?;
    if a.write && !a.srdo_crc {
        return Err("--write belongs to --srdo-crc".into());
    }
    if (a.objdict.is_some() || a.image.is_some() || a.eds.is_some()) && a.check.is_none() {
        return Err("--objdict, --image and --eds belong to --check".into());
    }
    let modes = [a.dump, a.srdo_crc, a.check.is_some(), a.verify];
    if modes.iter().filter(|m| **m).count() > 1 {
        return Err("--dump, --srdo-crc, --check and --verify exclude each other".into());
    }
    Ok(Some(a))
}

fn c_source(name: &str, input: &Path, bytes: &[u8]) -> String {
    let mut s = format!(
        "/* Generated by dcf2bin from {}: the binary DCF container for DynBuildOd. Do not edit. */\n\
         static const unsigned char {name}[{}] = {{\n",
        input.file_name().and_then(|n| n.to_str()).unwrap_or("?"),
        bytes.len()
    );
    for chunk in bytes.chunks(12) {
        s.push_str("   ");
        for b in chunk {
            s.push_str(&format!(" 0x{b:02X},"));
        }
        s.push('\n');
    }
    s.push_str("};\n");
    s
}

/// The pool figure printed after a conversion.
fn pool_line(dcf: &Dcf, bytes: &[u8]) -> String {
    let image = dcf.pi_params().map_or(0, |p| p.total as usize);
    match pool_need_alone(bytes, image) {
        Ok(n) => {
            let mut s = format!(
                "pool (OBD_DYNAMIC_POOL_SIZE) on a node without any of these objects: {} bytes on 32-bit targets, {} with room for the build-time index (linear build), {} on this host",
                n.target32(),
                n.target32_linear(),
                n.host()
            );
            if n.container_channels.total() > 0 {
                s.push_str(&format!(
                    "; on a node whose obdcfg.h counts 0 RPDOs and 0 TPDOs (the container's {} RPDO and {} TPDO channels from the pool, at most {} and {} bytes each): at most {} bytes on 32-bit targets",
                    n.container_channels.rx,
                    n.container_channels.tx,
                    n.channel_bytes.rx,
                    n.channel_bytes.tx,
                    n.target32_pdos_from_pool()
                ));
            }
            if image > 0 {
                if let Ok(w) = pool_need_alone(bytes, 0) {
                    s.push_str(&format!(
                        "; with a process image of {image} bytes (without one: {})",
                        w.target32()
                    ));
                }
            }
            s.push_str("; --check NODE gives the figure for a node");
            s
        }
        Err(e) => format!(
            "pool: not computed, DynBuildOd refuses the container on any node: {}",
            check::kernel_name(e)
        ),
    }
}

fn run_verify(a: &Args) -> Result<bool, String> {
    let bytes = std::fs::read(&a.input).map_err(|e| format!("{}: {e}", a.input.display()))?;
    let v = verify(&bytes).map_err(|e| format!("{}: {e}", a.input.display()))?;
    println!(
        "{}: {} entries, {} variables placed in the process image{}",
        a.input.display(),
        v.entries,
        v.placed,
        v.pi.map_or(String::new(), |p| format!(
            " ({} bytes; inputs {}+{}, outputs {}+{})",
            p.total, p.input_offset, p.input_size, p.output_offset, p.output_size
        ))
    );
    for (i, s, n) in &v.repeated {
        println!(
            "0x{i:04X} sub {s} written {n} times: DynBuildOd keeps the last value (a concise DCF is a sequence of writes; PDOs are reconfigured as a unit)"
        );
    }
    println!("{}", pool_line_of(&bytes));
    Ok(true)
}

fn pool_line_of(bytes: &[u8]) -> String {
    match pool_need_alone(bytes, 0) {
        Ok(n) => format!(
            "pool (OBD_DYNAMIC_POOL_SIZE) on a node without any of these objects and without process image: {} bytes on 32-bit targets; at most {} when its obdcfg.h counts 0 RPDOs and 0 TPDOs ({} PDO channels from the pool)",
            n.target32(),
            n.target32_pdos_from_pool(),
            n.container_channels.total()
        ),
        Err(e) => format!(
            "DynBuildOd refuses it on any node: {}",
            check::kernel_name(e)
        ),
    }
}

/// Builds a `dcf2bin` whose library has the configuration of `dir`
/// (`COP_CONFIG_DIR`, its own target folder per configuration folder) and
/// runs it with this command line.
fn rebuild_and_run(dir: &Path, mismatch: &[String]) -> Result<bool, String> {
    let dir = dir
        .canonicalize()
        .map_err(|e| format!("{}: {e}", dir.display()))?;
    let manual = format!(
        "COP_CONFIG_DIR={} cargo build --manifest-path tools/dcf2bin/Cargo.toml",
        dir.display()
    );
    if std::env::var_os("DCF2BIN_BUILT_FOR").is_some_and(|d| Path::new(&d) == dir) {
        return Err(format!(
            "{}: built for this folder and still different ({}): the folder changed while building?",
            dir.display(),
            mismatch.join("; ")
        ));
    }
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml");
    if !manifest.is_file() {
        return Err(format!(
            "{}: the library of this dcf2bin has another configuration ({}) and its sources are not here to build one: {manual}",
            dir.display(),
            mismatch.join("; ")
        ));
    }
    // One build folder per configuration folder, next to the library's.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in dir.as_os_str().as_encoded_bytes() {
        h = (h ^ u64::from(*b)).wrapping_mul(0x0100_0000_01b3);
    }
    let target = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../target/dcf2bin-for")
        .join(format!("{h:016x}"));
    eprintln!(
        "dcf2bin: the node's configuration differs from this build ({}): building dcf2bin for {} (once)",
        mismatch.join("; "),
        dir.display()
    );
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = std::process::Command::new(&cargo)
        .args(["build", "-q", "--manifest-path"])
        .arg(&manifest)
        .env("COP_CONFIG_DIR", &dir)
        .env("CARGO_TARGET_DIR", &target)
        .status()
        .map_err(|e| format!("{cargo}: {e} (build it yourself: {manual})"))?;
    if !status.success() {
        return Err(format!("the build for {} failed: {manual}", dir.display()));
    }
    let exe = target
        .join("debug")
        .join(format!("dcf2bin{}", std::env::consts::EXE_SUFFIX));
    let status = std::process::Command::new(&exe)
        .args(std::env::args_os().skip(1))
        .env("DCF2BIN_BUILT_FOR", &dir)
        .status()
        .map_err(|e| format!("{}: {e}", exe.display()))?;
    Ok(status.success())
}

fn run_check(a: &Args, node_path: &Path, dcf: &Dcf, bytes: &[u8]) -> Result<bool, String> {
    let (node, pool_size, config) = if node_path.is_dir() {
        let node = node::from_c_folder(node_path, a.objdict.as_deref())?;
        let mismatch = check::config_mismatch(&node, dcf);
        if !mismatch.is_empty() {
            return rebuild_and_run(node_path, &mismatch);
        }
        if node.config.get("OBD_USE_DYNAMIC_OD") == Some(&0) {
            println!(
                "DynBuildOd refuses the container: kCopDynNoMemory (0x00A0): OBD_USE_DYNAMIC_OD is FALSE in {}",
                node_path.display()
            );
            return Ok(false);
        }
        let pool = node
            .config
            .get("OBD_DYNAMIC_POOL_SIZE")
            .map_or(cop::config::OBD_DYNAMIC_POOL_SIZE, |v| *v as usize);
        (node, pool, format!("{}", node_path.display()))
    } else {
        let (_, nd) = dcf2bin::load_with(
            node_path,
            Options {
                node_id: a.node_id.or(dcf.node_id),
                strict: false,
            },
        )
        .map_err(|e| e.to_string())?;
        (
            node::from_eds(&nd),
            cop::config::OBD_DYNAMIC_POOL_SIZE,
            "the library dcf2bin was built with".to_string(),
        )
    };
    println!(
        "check: {} on the node of {} (configuration: {config}; {} objects in its static dictionary)",
        a.input.display(),
        node_path.display(),
        node.objects.len()
    );
    let r = check::check_and_export(dcf, bytes, &node, a.image, pool_size, a.eds.as_deref())?;
    for l in &r.lines {
        println!("{l}");
    }
    Ok(r.builds)
}

/// Prints the warnings; unless `all`, of a run of warnings of one kind
/// (the same message but for quoted values and numbers) the first three
/// and how many more there are.
fn print_warnings(ws: &[dcf2bin::Warning], all: bool) {
    let kind = |w: &dcf2bin::Warning| -> String {
        let mut quoted = false;
        w.at.msg
            .chars()
            .filter(|c| {
                if *c == '`' {
                    quoted = !quoted;
                }
                !quoted && !c.is_ascii_digit()
            })
            .take(40)
            .collect()
    };
    let mut i = 0;
    while let Some(w) = ws.get(i) {
        let run = ws[i..]
            .iter()
            .take_while(|x| x.kind == w.kind && kind(x) == kind(w))
            .count();
        let shown = if all { run } else { run.min(3) };
        for x in &ws[i..i + shown] {
            eprintln!("dcf2bin: {x}");
        }
        if run > shown {
            eprintln!(
                "dcf2bin: ... and {} more of this kind (--verbose lists them)",
                run - shown
            );
        }
        i += run;
    }
}

fn run(a: &Args) -> Result<bool, String> {
    if a.verify {
        return run_verify(a);
    }
    let opts = Options {
        node_id: a.node_id,
        strict: a.strict,
    };
    let (text, dcf) = dcf2bin::load_with(&a.input, opts).map_err(|e| e.to_string())?;
    print_warnings(&dcf.warnings, a.verbose);
    if a.srdo_crc {
        let reports = dcf.srdo_reports().map_err(|e| e.to_string())?;
        for r in &reports {
            let stored = match r.stored {
                Some(s) if s == r.crc => "stored: the same".to_string(),
                Some(s) => format!("stored: 0x{s:04X}, differs"),
                None => "no 0x13FF value in the file".to_string(),
            };
            println!(
                "SRDO {} (0x{:04X}): 0x13FF sub {} = 0x{:04X} ({stored})",
                r.n,
                0x1300 + u16::from(r.n),
                r.n,
                r.crc
            );
            for ((i, s), (ii, is)) in &r.pairs {
                println!("    0x{i:04X} sub {s} / inverted 0x{ii:04X} sub {is}");
            }
        }
        if !reports.is_empty() {
            let head = "SRDO configuration check (CcmCheckSrdoConfig, with these CRCs)";
            match dcf2bin::safety::library_check(&dcf) {
                Ok(None) => println!("{head}: passes"),
                Ok(Some((k, i))) => println!("{head}: {} at 0x{i:04X}", check::kernel_name(k)),
                Err(e) => println!("{head}: not run: {e}"),
            }
        }
        if a.write {
            let crcs: Vec<(u8, u16)> = reports.iter().map(|r| (r.n, r.crc)).collect();
            let updated =
                dcf2bin::safety::write_crcs(&text, &a.input, &crcs).map_err(|e| e.to_string())?;
            dcf2bin::write_atomically(&a.input, updated.as_bytes())
                .map_err(|e| format!("{}: {e}", a.input.display()))?;
            return Ok(true);
        }
        // A file that declares its configuration valid (0x13FE = 0xA5) must
        // hold the CRCs of it: a node would refuse it (kCopSrdoCfgCrcError).
        let declared_valid = dcf
            .get(0x13FE, 0)
            .is_some_and(|o| o.data.first() == Some(&0xA5));
        let mut agree = true;
        for r in reports.iter().filter(|_| declared_valid) {
            let stored = match r.stored {
                Some(s) if s == r.crc => continue,
                Some(s) => format!("is 0x{s:04X}"),
                None => "has no value".to_string(),
            };
            eprintln!(
                "dcf2bin: {}: 0x13FE = 0xA5 declares the configuration valid, but 0x13FF sub {} {stored}, not the CRC 0x{:04X} of SRDO {} (--write stores the CRCs)",
                a.input.display(),
                r.n,
                r.crc,
                r.n
            );
            agree = false;
        }
        return Ok(agree);
    }
    if a.dump {
        for o in &dcf.objects {
            let hex: String = o.data.iter().map(|b| format!("{b:02X}")).collect();
            println!(
                "{:04X} {:02X} {:04X} {:02X} {hex}",
                o.index, o.sub, o.data_type, o.attr
            );
        }
        return Ok(true);
    }
    let bytes = dcf.container().map_err(|e| e.to_string())?;
    if let Some(node) = &a.check {
        return run_check(a, node, &dcf, &bytes);
    }
    let (out, content) = match &a.c_array {
        Some(name) => (
            a.output
                .clone()
                .unwrap_or_else(|| a.input.with_extension("h")),
            c_source(name, &a.input, &bytes).into_bytes(),
        ),
        None => (
            a.output
                .clone()
                .unwrap_or_else(|| a.input.with_extension("bin")),
            bytes.clone(),
        ),
    };
    dcf2bin::write_atomically(&out, &content).map_err(|e| format!("{}: {e}", out.display()))?;
    if !a.quiet {
        let pi = dcf.pi_params().map_or(String::new(), |p| {
            format!(
                ", network variables in a process image of {} bytes",
                p.total
            )
        });
        println!(
            "{}: container of {} bytes, {} entries{pi}",
            out.display(),
            bytes.len(),
            dcf.objects.len()
        );
        println!("{}", pool_line(&dcf, &bytes));
    }
    Ok(true)
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(Some(a)) => a,
        Ok(None) => {
            print!("{HELP}");
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("dcf2bin: {e}");
            return ExitCode::from(2);
        }
    };
    match run(&args) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("dcf2bin: {e}");
            ExitCode::FAILURE
        }
    }
}
