//! `--check`: what `DynBuildOd` does with a container on a given node,
//! found out by doing it: the node's static dictionary ([`crate::node`]) is
//! built as a `cop` dictionary in this process, a stack runs on it on the
//! simulated bus, and the container is applied with the library's own
//! build ([`cop::od::dynamic::DynPool::build`], the code behind
//! `DynBuildOd`). The report says whether it builds, which objects it
//! creates, which values it changes and which it leaves (read-only on the
//! node), the PDOs it reconfigures, the SRDO configuration check
//! afterwards, and the pool it takes; a refusal comes with the lines of the
//! file that cause it, as far as they can be named.
//!
//! The library is the one this tool was built with: its configuration
//! switches (PDO mapping rules and counts, object size, SRDO rules) must be
//! the node's. For a node folder whose `copcfg.h`/`obdcfg.h` differ in one
//! of them, the command line builds a `dcf2bin` for that configuration
//! (`COP_CONFIG_DIR`, once per folder) and lets it answer. The pool is not
//! such a switch: the build runs in a large pool and the need is compared
//! with the node's `OBD_DYNAMIC_POOL_SIZE`.

use std::collections::BTreeMap;
use std::sync::atomic::AtomicU8;

use cop::CopKernel;
use cop::ccm::Stack;
use cop::od::dynamic::DynPool;
use cop::od::{ByteOrder, ObjectDictionary};
use cop::sim::SimBus;

use crate::Dcf;
use crate::container::{PoolNeed, pool_need};
use crate::node::Node;

/// The pool of the in-process build (`.bss`; only the bytes a build uses
/// are touched).
static POOL: DynPool<{ 64 << 20 }> = DynPool::new();

/// One check at a time uses the pool.
static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// The C name of a result code.
pub fn kernel_name(k: CopKernel) -> String {
    format!("kCop{k:?} (0x{:04X})", k.code())
}

/// The configuration values of the library this tool was built with, by
/// their `copcfg.h` names: the switches that change what `DynBuildOd`
/// accepts.
pub fn built_config() -> BTreeMap<&'static str, i64> {
    use cop::config as c;
    let b = |v: bool| i64::from(v);
    BTreeMap::from([
        (
            "OBD_SUPPORTED_OBJ_SIZE",
            i64::from(c::OBD_SUPPORTED_OBJ_SIZE),
        ),
        ("SRDO_GRANULARITY", i64::from(c::SRDO_GRANULARITY)),
        ("SRDO_USE_STATIC_MAPPING", b(c::SRDO_USE_STATIC_MAPPING)),
        ("SRDO_USE_DUMMY_MAPPING", b(c::SRDO_USE_DUMMY_MAPPING)),
        ("SRDO_ALLOW_GAPS_IN_OD", b(c::SRDO_ALLOW_GAPS_IN_OD)),
        ("SRDO_USE_GFC", b(c::SRDO_USE_GFC)),
        ("SRDO_USE_PROGMONITOR", b(c::SRDO_USE_PROGMONITOR)),
        ("SRDO_MAX_SRDO_IN_OBD", c::SRDO_MAX_SRDO_IN_OBD as i64),
        ("PDO_GRANULARITY", i64::from(c::PDO_GRANULARITY)),
        ("PDO_USE_BIT_MAPPING", b(c::PDO_USE_BIT_MAPPING)),
        ("PDO_USE_DUMMY_MAPPING", b(c::PDO_USE_DUMMY_MAPPING)),
        ("PDO_MAX_MAPPENTRIES", c::PDO_MAX_MAPPENTRIES as i64),
        ("PDO_MAX_RXPDO_IN_OBD", c::PDO_MAX_RXPDO_IN_OBD as i64),
        ("PDO_MAX_TXPDO_IN_OBD", c::PDO_MAX_TXPDO_IN_OBD as i64),
        ("SDO_MAX_CLIENT_IN_OBD", c::SDO_MAX_CLIENT_IN_OBD as i64),
        ("HBC_MAX_CONSUMER_IN_OBD", c::HBC_MAX_CONSUMER_IN_OBD as i64),
        ("NMTS_USE_LIFEGUARDING", b(c::NMTS_USE_LIFEGUARDING)),
    ])
}

/// The objects a switch matters for (`None`: every container).
fn relevant(key: &str) -> Option<std::ops::RangeInclusive<u16>> {
    Some(match key {
        k if k.starts_with("SRDO_") => 0x1300..=0x13FF,
        k if k.starts_with("PDO_") => 0x1400..=0x1BFF,
        "SDO_MAX_CLIENT_IN_OBD" => 0x1280..=0x12FF,
        "HBC_MAX_CONSUMER_IN_OBD" => 0x1016..=0x1016,
        "NMTS_USE_LIFEGUARDING" => 0x100C..=0x100D,
        _ => return None,
    })
}

/// The switches in which `node` differs from this tool's library, among
/// those that matter for the objects of `dcf`.
pub fn config_mismatch(node: &Node, dcf: &Dcf) -> Vec<String> {
    built_config()
        .iter()
        .filter(|(k, _)| match relevant(k) {
            Some(r) => dcf.objects.iter().any(|o| r.contains(&o.index)),
            None => true,
        })
        .filter_map(|(k, built)| {
            let theirs = node.config.get(*k)?;
            (theirs != built).then(|| format!("{k} {theirs} (this dcf2bin: {built})"))
        })
        .collect()
}

/// What the check found.
#[derive(Debug, Clone, Default)]
pub struct Report {
    /// True when the container builds.
    pub builds: bool,
    /// The report, one line each.
    pub lines: Vec<String>,
    /// The pool the build takes (when it was computed).
    pub pool: Option<PoolNeed>,
}

/// A value for the report: numbers as numbers, text as text, else hex.
fn shown(t: cop::od::DataType, b: &[u8]) -> String {
    use crate::value::Number;
    match (t, crate::value::number(t, b)) {
        (cop::od::DataType::VString, _) => format!("\"{}\"", String::from_utf8_lossy(b)),
        (t, Some(Number::Int(v))) if t.wire_size() == Some(b.len()) && !t.is_signed() => {
            format!("0x{v:0w$X}", w = 2 * b.len())
        }
        (t, Some(n)) if t.wire_size() == Some(b.len()) && t.is_numeric() => n.to_string(),
        _ if b.is_empty() => "(empty)".into(),
        _ => hex(b),
    }
}

fn hex(b: &[u8]) -> String {
    let mut s: String = b.iter().take(32).map(|x| format!("{x:02X}")).collect();
    if b.len() > 32 {
        s.push_str(&format!("... ({} bytes)", b.len()));
    }
    s
}

fn peek(od: &ObjectDictionary, index: u16, sub: u8) -> Option<Vec<u8>> {
    let o = od.find(index, sub).ok()?;
    let mut b = vec![0u8; 4096];
    let n = od.peek(&o, ByteOrder::Wire, &mut b).ok()?;
    b.truncate(n);
    Some(b)
}

/// Names the entries a node refuses one by one (before the build): a
/// subindex the node's object lacks, a value its object does not take.
fn entry_problems(dcf: &Dcf, od: &ObjectDictionary) -> Vec<String> {
    let mut out = Vec::new();
    let at = |o: &crate::Object| format!("{}:{}: [{}]", dcf.file.display(), o.line, o.section);
    for o in &dcf.objects {
        if od.find_entry(o.index).is_none() {
            continue;
        }
        let Ok(obj) = od.find(o.index, o.sub) else {
            out.push(format!(
                "{} the node's object 0x{:04X} has no subindex {} ({})",
                at(o),
                o.index,
                o.sub,
                kernel_name(CopKernel::ObdSubindexNotExist)
            ));
            continue;
        };
        if !obj.access().writable() {
            continue;
        }
        if let Err(e) = od.stage(&obj, ByteOrder::Wire, &o.data) {
            out.push(format!(
                "{}:{}: [{}] the node's 0x{:04X} sub {} ({}) refuses the value {}: {}",
                dcf.file.display(),
                o.value_line,
                o.section,
                o.index,
                o.sub,
                crate::value::type_name(obj.data_type()),
                shown(o.typ(), &o.data),
                kernel_name(e.kernel)
            ));
        }
    }
    out
}

/// A stack on `node`, connected, on its own simulated bus.
fn start(node: &Node, node_id: u8) -> Result<(Stack, SimBus, cop::sim::SimPort), String> {
    let od = node.dictionary()?;
    let bus = SimBus::new();
    let mut port = bus.attach(64);
    let mut stack = Stack::new(od, node_id).map_err(|e| {
        format!(
            "the node's dictionary does not start a stack: {}",
            kernel_name(e)
        )
    })?;
    while stack.drain(&mut port, bus.now()).is_some() {}
    stack
        .connect()
        .map_err(|e| format!("the node does not connect: {}", kernel_name(e)))?;
    while stack.drain(&mut port, bus.now()).is_some() {}
    Ok((stack, bus, port))
}

fn image_of(len: usize) -> Option<&'static [AtomicU8]> {
    (len > 0).then(|| {
        let v: Vec<AtomicU8> = (0..len).map(|_| AtomicU8::new(0)).collect();
        &*Box::leak(v.into_boxed_slice())
    })
}

/// Builds the container of `objects` alone on a fresh `node`.
fn attempt(
    dcf: &Dcf,
    objects: Vec<crate::Object>,
    node: &Node,
    image_len: usize,
) -> Result<(), CopKernel> {
    let part = Dcf {
        objects,
        warnings: Vec::new(),
        ..dcf.clone()
    };
    let bytes = part.container().map_err(|_| CopKernel::DynInvalidConfig)?;
    let (mut stack, bus, mut port) =
        start(node, dcf.node_id.unwrap_or(1)).map_err(|_| CopKernel::InvalidParam)?;
    POOL.build(
        &mut stack,
        &mut port,
        bus.now(),
        &bytes,
        image_of(image_len),
    )?;
    POOL.release(stack);
    Ok(())
}

/// The PDO an index belongs to: (0 RPDO / 1 TPDO, number from 1).
fn pdo_of(index: u16) -> Option<(u8, u16)> {
    match index {
        0x1400..=0x15FF => Some((0, index - 0x1400 + 1)),
        0x1600..=0x17FF => Some((0, index - 0x1600 + 1)),
        0x1800..=0x19FF => Some((1, index - 0x1800 + 1)),
        0x1A00..=0x1BFF => Some((1, index - 0x1A00 + 1)),
        _ => None,
    }
}

/// What is wrong with the mapping `mapp` of the file against the node's
/// objects and the file's own (the PDO rules of this build).
fn mapping_problems(dcf: &Dcf, node: &Node, mapp: u16, receive: bool) -> Vec<String> {
    let mut out = Vec::new();
    let Some(count) = dcf.get(mapp, 0).and_then(|o| o.data.first().copied()) else {
        return out;
    };
    let at =
        |o: &crate::Object| format!("{}:{}: [{}]", dcf.file.display(), o.value_line, o.section);
    if usize::from(count) > cop::config::PDO_MAX_MAPPENTRIES {
        if let Some(o) = dcf.get(mapp, 0) {
            out.push(format!(
                "{} {count} mapping entries, PDO_MAX_MAPPENTRIES is {}",
                at(o),
                cop::config::PDO_MAX_MAPPENTRIES
            ));
        }
    }
    let mut bits_total = 0u32;
    for s in 1..=count {
        let Some(e) = dcf.get(mapp, s) else {
            continue;
        };
        let mut w = [0u8; 4];
        for (d, b) in w.iter_mut().zip(&e.data) {
            *d = *b;
        }
        let v = u32::from_le_bytes(w);
        let (index, sub, bits) = ((v >> 16) as u16, (v >> 8) as u8, v as u8);
        bits_total += u32::from(bits);
        if index < 0x1000 {
            if !(receive && cop::config::PDO_USE_DUMMY_MAPPING) {
                out.push(format!(
                    "{} dummy entry 0x{index:04X} only in RPDOs with PDO_USE_DUMMY_MAPPING",
                    at(e)
                ));
            }
            continue;
        }
        let in_node = node
            .objects
            .iter()
            .find(|o| o.index == index && o.sub == sub);
        let in_file = dcf.get(index, sub);
        let (typ, mappable) = match (in_node, in_file) {
            (Some(o), _) => (o.typ, o.access & cop::od::Access::PDO != 0),
            (None, Some(o)) if node.objects.iter().all(|n| n.index != index) => {
                (o.typ(), o.pdo_mapping)
            }
            _ => {
                out.push(format!(
                    "{} maps 0x{index:04X} sub {sub}, which neither the node nor the file has",
                    at(e)
                ));
                continue;
            }
        };
        if !mappable {
            out.push(format!(
                "{} maps 0x{index:04X} sub {sub}, which is not PDO-mappable",
                at(e)
            ));
            continue;
        }
        let want = typ.wire_size().map(|n| 8 * n as u32);
        let bit_ok =
            typ == cop::od::DataType::Bool && bits == 1 && cop::config::PDO_USE_BIT_MAPPING;
        if want != Some(u32::from(bits)) && !bit_ok {
            out.push(format!(
                "{} maps 0x{index:04X} sub {sub} with {bits} bits; it is {}{}",
                at(e),
                crate::value::type_name(typ),
                if typ == cop::od::DataType::Bool {
                    " (one bit needs PDO_USE_BIT_MAPPING)"
                } else {
                    ""
                }
            ));
        }
    }
    if bits_total > 64 {
        if let Some(o) = dcf.get(mapp, 0) {
            out.push(format!(
                "{} {bits_total} bits mapped, a PDO carries 64",
                at(o)
            ));
        }
    }
    out
}

/// Finds the part of the file a container-level refusal `code` comes
/// from: when the objects outside the PDOs are refused without them, each
/// such object refused alone; else each PDO whose entries are refused
/// (with the other objects).
fn blame(dcf: &Dcf, node: &Node, image_len: usize, code: CopKernel) -> Vec<String> {
    let plain: Vec<crate::Object> = dcf
        .objects
        .iter()
        .filter(|o| pdo_of(o.index).is_none())
        .cloned()
        .collect();
    let mut pdos: BTreeMap<(u8, u16), Vec<crate::Object>> = BTreeMap::new();
    for o in &dcf.objects {
        if let Some(p) = pdo_of(o.index) {
            pdos.entry(p).or_default().push(o.clone());
        }
    }
    let lines = |objs: &[crate::Object]| -> String {
        let first = objs.iter().map(|o| o.line).min().unwrap_or(0);
        let last = objs.iter().map(|o| o.line).max().unwrap_or(0);
        format!("{}:{first}..{last}", dcf.file.display())
    };
    let mut out = Vec::new();
    // The other objects first: when they are refused without any PDO,
    // every PDO tried with them would be refused too.
    if attempt(dcf, plain.clone(), node, image_len) == Err(code) {
        let mut by_index: BTreeMap<u16, Vec<crate::Object>> = BTreeMap::new();
        for o in plain {
            by_index.entry(o.index).or_default().push(o);
        }
        for (index, objs) in by_index {
            if attempt(dcf, objs.clone(), node, image_len) == Err(code) {
                out.push(format!(
                    "{} 0x{index:04X} is refused on its own: {}",
                    lines(&objs),
                    kernel_name(code)
                ));
            }
        }
        return out;
    }
    for ((dir, n), objs) in &pdos {
        let mut with = plain.clone();
        with.extend(objs.iter().cloned());
        with.sort_by_key(|o| (o.index, o.sub));
        if attempt(dcf, with, node, image_len) == Err(code) {
            let what = if *dir == 0 { "RPDO" } else { "TPDO" };
            let (c, m) = if *dir == 0 {
                (0x1400 + n - 1, 0x1600 + n - 1)
            } else {
                (0x1800 + n - 1, 0x1A00 + n - 1)
            };
            let specific = mapping_problems(dcf, node, m, *dir == 0);
            if !specific.is_empty() {
                out.extend(specific.into_iter().map(|p| format!("{what} {n}: {p}")));
                continue;
            }
            out.push(format!(
                "{} {what} {n} (0x{c:04X}/0x{m:04X}) is refused on its own: {} (its mapping against the node's objects and the PDO rules of this build: PDO_USE_BIT_MAPPING {}, PDO_MAX_MAPPENTRIES {})",
                lines(objs),
                kernel_name(code),
                cop::config::PDO_USE_BIT_MAPPING,
                cop::config::PDO_MAX_MAPPENTRIES
            ));
        }
    }
    out
}

/// Applies `container` (made from `dcf`) to `node` and reports. The
/// process image is `image_len` bytes (default: what the container's
/// parameter segment reports). `pool_size` is the node's
/// `OBD_DYNAMIC_POOL_SIZE`.
pub fn check(
    dcf: &Dcf,
    container: &[u8],
    node: &Node,
    image_len: Option<usize>,
    pool_size: usize,
) -> Result<Report, String> {
    check_and_export(dcf, container, node, image_len, pool_size, None)
}

/// [`check`], and when the container builds, the EDS of the node after
/// the build written to `eds` (`cop::od::eds::write_eds`, with the data
/// types the file gives the objects the build created).
pub fn check_and_export(
    dcf: &Dcf,
    container: &[u8],
    node: &Node,
    image_len: Option<usize>,
    pool_size: usize,
    eds: Option<&std::path::Path>,
) -> Result<Report, String> {
    let _one = LOCK
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let mut r = Report::default();
    let image_len = image_len.unwrap_or_else(|| dcf.pi_params().map_or(0, |p| p.total as usize));
    let (mut stack, bus, mut port) = start(node, dcf.node_id.unwrap_or(1))?;
    let problems = entry_problems(dcf, stack.od());
    let before: Vec<Option<Vec<u8>>> = dcf
        .objects
        .iter()
        .map(|o| peek(stack.od(), o.index, o.sub))
        .collect();
    let existed: Vec<bool> = dcf
        .objects
        .iter()
        .map(|o| stack.od().find_entry(o.index).is_some())
        .collect();
    let need = pool_need(container, stack.od(), image_len);
    let built = POOL.build(
        &mut stack,
        &mut port,
        bus.now(),
        container,
        image_of(image_len),
    );
    match (&built, &need) {
        (Ok(info), Ok(need)) if need.target32() <= pool_size => {
            r.builds = true;
            r.pool = Some(*need);
            r.lines.push(format!(
                "DynBuildOd builds the container: {} objects ({} subindices) created",
                info.new_indices, info.new_subs
            ));
        }
        (Ok(_), Ok(need)) => {
            r.pool = Some(*need);
            r.lines.push(format!(
                "DynBuildOd refuses the container: {}: the node's pool (OBD_DYNAMIC_POOL_SIZE {pool_size}) is smaller than the {} bytes the build takes on 32-bit targets (with a large enough pool it builds)",
                kernel_name(CopKernel::DynNoMemory),
                need.target32()
            ));
        }
        (Err(e), _) | (Ok(_), Err(e)) => {
            r.lines.push(format!(
                "DynBuildOd refuses the container: {}",
                kernel_name(*e)
            ));
            if problems.is_empty() {
                let found = blame(dcf, node, image_len, *e);
                if found.is_empty() {
                    r.lines.push(
                        "  no single object or PDO of the file is refused alone: the combination is (two TPDOs with one COB-ID, variables sharing the process image)".into(),
                    );
                }
                for f in found {
                    r.lines.push(format!("  {f}"));
                }
            }
        }
    }
    for p in &problems {
        r.lines.push(format!("  {p}"));
    }
    if built.is_err() {
        return Ok(r);
    }
    // What changed.
    let mut created: BTreeMap<u16, usize> = BTreeMap::new();
    for (o, ex) in dcf.objects.iter().zip(&existed) {
        if !ex {
            *created.entry(o.index).or_default() += 1;
        }
    }
    for (index, n) in &created {
        let subs = if *n == 1 { "subindex" } else { "subindices" };
        r.lines.push(format!(
            "  created 0x{index:04X} ({n} {subs} from the file)"
        ));
    }
    // A created object takes the file's value as its default without the
    // stack's write rules (0x1029 sub 1 = 0x80, for example); say where a
    // write of the same value would be refused. A refusal for the state
    // the object is in (abort 0x08000022: a mapping entry or count of a
    // valid PDO, CiA 301 7.5.2.36) is the write procedure's, not the
    // value's: the build follows that procedure, so it is no note.
    for (o, ex) in dcf.objects.iter().zip(&existed) {
        let writable = stack
            .od()
            .find(o.index, o.sub)
            .is_ok_and(|obj| obj.access().writable());
        if *ex || !writable {
            continue;
        }
        let now = bus.now();
        let refused = stack
            .write_object(o.index, o.sub, ByteOrder::Wire, &o.data, now)
            .err()
            .filter(|e| e.abort != cop::error::SdoAbort::DeviceState.code());
        if let Some(e) = refused {
            r.lines.push(format!(
                "  note: {}:{}: [{}] 0x{:04X} sub {} is created with {}, which the stack refuses on a write ({}): the node runs with it as a default (README, Behaviour decisions)",
                dcf.file.display(),
                o.value_line,
                o.section,
                o.index,
                o.sub,
                shown(o.typ(), &o.data),
                kernel_name(e.kernel)
            ));
        }
    }
    for ((o, was), ex) in dcf.objects.iter().zip(&before).zip(&existed) {
        if !ex {
            continue;
        }
        let now = peek(stack.od(), o.index, o.sub);
        let place = format!("{}:{}", dcf.file.display(), o.value_line);
        // Domains keep their size: a shorter value is followed by zeros.
        let same = |a: &[u8], file: &[u8]| {
            a == file
                || (o.typ().wire_size().is_none()
                    && a.starts_with(file)
                    && a[file.len()..].iter().all(|b| *b == 0))
        };
        match (was, now) {
            (Some(a), Some(b)) if *a != b => r.lines.push(format!(
                "  changed 0x{:04X} sub {}: {} -> {} ({place})",
                o.index,
                o.sub,
                shown(o.typ(), a),
                shown(o.typ(), &b)
            )),
            (Some(a), Some(b)) if a == &b && !same(&b, &o.data) => r.lines.push(format!(
                "  kept 0x{:04X} sub {}: the node's {} (read-only there), the file says {} ({place})",
                o.index,
                o.sub,
                shown(o.typ(), &b),
                shown(o.typ(), &o.data)
            )),
            _ => {}
        }
    }
    let pdos: std::collections::BTreeSet<u16> = dcf
        .objects
        .iter()
        .filter(|o| (0x1400..=0x1BFF).contains(&o.index))
        .map(|o| o.index & !0x0200)
        .collect();
    for p in pdos {
        let (what, n) = match p {
            0x1400..=0x15FF => ("RPDO", p - 0x1400 + 1),
            _ => ("TPDO", p - 0x1800 + 1),
        };
        r.lines.push(format!(
            "  reconfigured {what} {n} (0x{p:04X}/0x{:04X})",
            p + 0x200
        ));
    }
    if stack.srdo().count() > 0 {
        match stack.srdo().check_config(stack.od()) {
            Ok(()) => r
                .lines
                .push("  SRDO configuration check (CcmCheckSrdoConfig): passes".into()),
            Err((k, i)) => r.lines.push(format!(
                "  SRDO configuration check (CcmCheckSrdoConfig): {} at 0x{i:04X}",
                kernel_name(k)
            )),
        }
    }
    if let Some(need) = r.pool {
        let verdict = if need.target32() <= pool_size {
            "fits"
        } else {
            "too small: DynBuildOd answers kCopDynNoMemory (0x00A0)"
        };
        r.lines.push(format!(
            "  pool: {} bytes on 32-bit targets ({} with room for the build-time index, {} on this host); OBD_DYNAMIC_POOL_SIZE {pool_size}: {verdict}",
            need.target32(),
            need.target32_linear(),
            need.host()
        ));
    }
    if image_len > 0 {
        r.lines.push(format!(
            "  process image: {image_len} bytes handed to DynBuildOd"
        ));
    }
    if let Some(path) = eds {
        let types = dcf.types();
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or("node.eds");
        let info = cop::od::eds::EdsInfo {
            file_name: name,
            description: "the node after DynBuildOd (dcf2bin --check)",
            types: &types,
            ..cop::od::eds::EdsInfo::default()
        };
        let mut text = String::new();
        cop::od::eds::write_eds(stack.od(), &info, &mut text).map_err(|e| e.to_string())?;
        crate::write_atomically(path, text.as_bytes())
            .map_err(|e| format!("{}: {e}", path.display()))?;
        r.lines.push(format!(
            "  EDS of the node after the build: {}",
            path.display()
        ));
    }
    POOL.release(stack);
    Ok(r)
}
