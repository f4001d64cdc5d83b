//! Build-time configuration.
//!
//! The SYS TEC stack is configured by the application's `copcfg.h` (switches)
//! and `obdcfg.h` (capacities). This script resolves every switch the library
//! needs, in this order of precedence:
//!
//! 1. the application's own headers, when `COP_CONFIG_DIR` names the folder
//!    holding `copcfg.h` (and optionally `obdcfg.h`; `COP_OBDCFG_DIR` names
//!    another folder for `obdcfg.h`, as ODBuilder projects keep it beside
//!    `objdict.h`): they are run through the C preprocessor together with
//!    `include/copdef.h`, so the values are exactly what the application's C
//!    compiler sees;
//! 2. otherwise Cargo features (`srdo-static-mapping`, ...) and `COP_*`
//!    environment variables for capacities;
//! 3. otherwise the documented defaults (manual L-1077d section 2.4).
//!
//! The result is written to `$OUT_DIR/config.rs` (constants) and
//! `$OUT_DIR/abi_symbol.rs` (the link-time configuration signature, see
//! `include/cop_config.h`), and a few `cfg` flags select code.

use std::collections::BTreeMap;
use std::env;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

/// Every value the library takes from the configuration.
struct Config {
    obj_size: u32,
    srdo_granularity: u32,
    srdo_static_mapping: bool,
    srdo_dummy_mapping: bool,
    srdo_allow_gaps: bool,
    srdo_use_gfc: bool,
    srdo_use_progmonitor: bool,
    srdo_check_srvt_before_1strx: bool,
    srdo_max_srdo_in_obd: u32,
    cdrv_timestamp: bool,
    cdrv_can20b: bool,
    cdrv_use_highbuff: bool,
    pdo_static_mapping: bool,
    pdo_granularity: u32,
    pdo_bit_mapping: bool,
    pdo_dummy_mapping: bool,
    pdo_max_mappentries: u32,
    sdos_default_timeout: u32,
    sdos_buffer_size: u32,
    sdo_blocksize_download: u32,
    sdo_blocksize_upload: u32,
    sdo_max_server_in_obd: u32,
    sdo_max_client_in_obd: u32,
    hbc_max_consumer_in_obd: u32,
    pdo_max_rxpdo_in_obd: u32,
    pdo_max_txpdo_in_obd: u32,
    nmtm_max_slave_entries: u32,
    emcc_max_consumer: u32,
    nmts_use_lifeguarding: bool,
    ccm_use_pdo_check_var: bool,
    dyn_od_pool_size: u32,
    obd_use_dynamic_od: bool,
    cob_more_than_128_entries: bool,
    ccm_module_lsss: bool,
    max_instances: u32,
}

const KEYS: &[&str] = &[
    "OBD_SUPPORTED_OBJ_SIZE",
    "SRDO_GRANULARITY",
    "SRDO_USE_STATIC_MAPPING",
    "SRDO_USE_DUMMY_MAPPING",
    "SRDO_ALLOW_GAPS_IN_OD",
    "SRDO_USE_GFC",
    "SRDO_USE_PROGMONITOR",
    "SRDO_CHECK_SRVT_BEFORE_1STRX",
    "SRDO_MAX_SRDO_IN_OBD",
    "CDRV_TIMESTAMP",
    "CDRV_CAN_SPEC",
    "CDRV_USE_HIGHBUFF",
    "PDO_USE_STATIC_MAPPING",
    "PDO_GRANULARITY",
    "PDO_USE_BIT_MAPPING",
    "PDO_USE_DUMMY_MAPPING",
    "PDO_MAX_MAPPENTRIES",
    "SDOS_DEFAULT_TIMEOUT",
    "SDOS_BUFFER_SIZE",
    "SDO_BLOCKSIZE_DOWNLOAD",
    "SDO_BLOCKSIZE_UPLOAD",
    "SDO_MAX_SERVER_IN_OBD",
    "SDO_MAX_CLIENT_IN_OBD",
    "HBC_MAX_CONSUMER_IN_OBD",
    "PDO_MAX_RXPDO_IN_OBD",
    "PDO_MAX_TXPDO_IN_OBD",
    "NMTM_MAX_SLAVE_ENTRIES",
    "EMCC_MAX_CONSUMER",
    "NMTS_USE_LIFEGUARDING",
    "CCM_USE_PDO_CHECK_VAR",
    "OBD_DYNAMIC_POOL_SIZE",
    "OBD_USE_DYNAMIC_OD",
    "COP_USE_SMALL_TIME",
    "COP_MAX_INSTANCES",
    "COB_MORE_THAN_128_ENTRIES",
    "CCM_MODULE_INTEGRATION",
];

fn feature(name: &str) -> bool {
    env::var_os(format!(
        "CARGO_FEATURE_{}",
        name.to_uppercase().replace('-', "_")
    ))
    .is_some()
}

fn env_u32(name: &str, default: u32) -> u32 {
    println!("cargo:rerun-if-env-changed={name}");
    match env::var(name) {
        Ok(v) => parse_c_int(&v).unwrap_or_else(|| panic!("{name}={v} is not a number")),
        Err(_) => default,
    }
}

/// Parses a preprocessed C integer expression of the simple kinds that
/// configuration headers use: `8`, `0x01`, `(5000L)`, `(0x00)`.
fn parse_c_int(text: &str) -> Option<u32> {
    let t: String = text
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '(' && *c != ')')
        .collect();
    let t = t.trim_end_matches(['u', 'U', 'l', 'L']);
    if let Some(hex) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        u32::from_str_radix(hex, 16).ok()
    } else {
        t.parse().ok()
    }
}

fn from_features() -> Config {
    let granularity = if feature("srdo-granularity-64") {
        64
    } else if feature("srdo-granularity-32") {
        32
    } else if feature("srdo-granularity-16") {
        16
    } else {
        8
    };
    let obj_size = if feature("obd-obj-size-big") {
        2
    } else if feature("obd-obj-size-middle") {
        1
    } else {
        0
    };
    let pdo_granularity = if feature("pdo-granularity-64") { 64 } else { 8 };
    let pdo_bit_mapping = feature("pdo-bit-mapping");
    Config {
        obj_size,
        srdo_granularity: granularity,
        srdo_static_mapping: feature("srdo-static-mapping"),
        srdo_dummy_mapping: feature("srdo-dummy-mapping"),
        srdo_allow_gaps: feature("srdo-allow-gaps"),
        srdo_use_gfc: feature("srdo-gfc"),
        srdo_use_progmonitor: feature("srdo-progmonitor"),
        srdo_check_srvt_before_1strx: feature("srdo-check-srvt-before-1strx"),
        srdo_max_srdo_in_obd: env_u32("COP_SRDO_MAX_SRDO_IN_OBD", 64),
        cdrv_timestamp: feature("cdrv-timestamp"),
        cdrv_can20b: feature("cdrv-can20b"),
        // SYS TEC default TRUE; COP_CDRV_USE_HIGHBUFF=0 switches it off.
        cdrv_use_highbuff: env_u32("COP_CDRV_USE_HIGHBUFF", 1) != 0,
        pdo_static_mapping: false,
        pdo_granularity,
        pdo_bit_mapping,
        // SYS TEC default TRUE; COP_PDO_USE_DUMMY_MAPPING=0 switches it off.
        pdo_dummy_mapping: env_u32("COP_PDO_USE_DUMMY_MAPPING", 1) != 0,
        pdo_max_mappentries: pdo_max_mappentries(pdo_granularity, pdo_bit_mapping),
        sdos_default_timeout: env_u32("COP_SDOS_DEFAULT_TIMEOUT", 5000),
        sdos_buffer_size: env_u32("COP_SDOS_BUFFER_SIZE", 256),
        sdo_blocksize_download: env_u32("COP_SDO_BLOCKSIZE_DOWNLOAD", 6),
        sdo_blocksize_upload: env_u32("COP_SDO_BLOCKSIZE_UPLOAD", 6),
        // SYS TEC default 1 (copdef.h): the default server 0x1200 only.
        sdo_max_server_in_obd: env_u32("COP_SDO_MAX_SERVER_IN_OBD", 1),
        sdo_max_client_in_obd: env_u32("COP_SDO_MAX_CLIENT_IN_OBD", 4),
        hbc_max_consumer_in_obd: env_u32("COP_HBC_MAX_CONSUMER_IN_OBD", 8),
        pdo_max_rxpdo_in_obd: env_u32("COP_PDO_MAX_RXPDO_IN_OBD", 8),
        pdo_max_txpdo_in_obd: env_u32("COP_PDO_MAX_TXPDO_IN_OBD", 8),
        nmtm_max_slave_entries: env_u32("COP_NMTM_MAX_SLAVE_ENTRIES", 16),
        emcc_max_consumer: env_u32("COP_EMCC_MAX_CONSUMER", 10),
        // SYS TEC default TRUE; COP_NMTS_USE_LIFEGUARDING=0 switches it off.
        nmts_use_lifeguarding: env_u32("COP_NMTS_USE_LIFEGUARDING", 1) != 0,
        // SYS TEC default TRUE (copdef.h).
        ccm_use_pdo_check_var: env_u32("COP_CCM_USE_PDO_CHECK_VAR", 1) != 0,
        dyn_od_pool_size: env_u32("COP_OBD_DYNAMIC_POOL_SIZE", 8192),
        // The dynamic OD is part of the Rust build unless switched off.
        obd_use_dynamic_od: env_u32("COP_OBD_USE_DYNAMIC_OD", 1) != 0,
        cob_more_than_128_entries: env_u32("COP_COB_MORE_THAN_128_ENTRIES", 0) != 0,
        // Not in the SYS TEC default CCM_MODULE_INTEGRATION (copdef.h), but
        // a default feature of the Rust build.
        ccm_module_lsss: feature("lss-slave") || env_u32("COP_CCM_MODULE_LSSS", 0) != 0,
        // SYS TEC default CDRV_MAX_INSTANCES = 1; more gives the
        // multi-instance ABI (every Ccm* function takes the handle).
        max_instances: env_u32("COP_MAX_INSTANCES", 1),
    }
}

/// Runs the application's copcfg.h/obdcfg.h through the C preprocessor after
/// include/copdef.h has filled in every default, and reads back the values.
fn from_headers(dir: &Path, obd_dir: &Path, include: &Path) -> Config {
    let out = PathBuf::from(env::var("OUT_DIR").unwrap());
    let probe = out.join("cop_config_probe.c");
    let mut src = String::new();
    src.push_str("#include \"copcfg.h\"\n");
    if obd_dir.join("obdcfg.h").exists() {
        src.push_str("#include \"obdcfg.h\"\n");
    }
    src.push_str("#include \"copdef.h\"\n");
    for k in KEYS {
        // The key is glued to the marker so that the preprocessor leaves the
        // name alone and expands only the value.
        let _ = writeln!(src, "COP_PROBE_{k} = {k}");
    }
    fs::write(&probe, src).unwrap();
    let expanded = cc::Build::new()
        .file(&probe)
        .include(dir)
        .include(obd_dir)
        .include(include)
        .cargo_metadata(false)
        .expand();
    let text = String::from_utf8_lossy(&expanded);
    let mut values = BTreeMap::new();
    for line in text.lines() {
        if let Some(rest) = line.trim().strip_prefix("COP_PROBE_") {
            if let Some((k, v)) = rest.split_once(" = ") {
                values.insert(k.trim().to_string(), v.trim().to_string());
            }
        }
    }
    let num = |k: &str| -> u32 {
        let v = values
            .get(k)
            .unwrap_or_else(|| panic!("{k} missing from preprocessed configuration"));
        parse_c_int(v).unwrap_or_else(|| {
            panic!(
                "{k} = `{v}` in {}: not an integer constant after preprocessing",
                dir.display()
            )
        })
    };
    let flag = |k: &str| num(k) != 0;
    // A mask of module bits: a number (`0x00000935`) or, as copdef.h's
    // default, an `|` of the CCM_MODULE_* names, which the probe leaves as
    // names (their values are in cop_types.h); only the LSS slave's bit is
    // read from them.
    let bits = |k: &str| -> u32 {
        let v = &values[k];
        v.split('|').fold(0, |acc, part| {
            let name = part.trim().trim_matches(|c| c == '(' || c == ')').trim();
            acc | match parse_c_int(part) {
                Some(n) => n,
                None if name == "CCM_MODULE_LSSS" => CCM_MODULE_LSSS,
                None if name.starts_with("CCM_MODULE_") => 0,
                None => panic!(
                    "{k} = `{v}` in {}: not a mask of module bits",
                    dir.display()
                ),
            }
        })
    };
    if flag("COP_USE_SMALL_TIME") {
        panic!(
            "COP_USE_SMALL_TIME != FALSE in {}: this library keeps tTime 32 bits wide (README, ABI)",
            dir.display()
        );
    }
    Config {
        obj_size: num("OBD_SUPPORTED_OBJ_SIZE"),
        srdo_granularity: num("SRDO_GRANULARITY"),
        srdo_static_mapping: flag("SRDO_USE_STATIC_MAPPING"),
        srdo_dummy_mapping: flag("SRDO_USE_DUMMY_MAPPING"),
        srdo_allow_gaps: flag("SRDO_ALLOW_GAPS_IN_OD"),
        srdo_use_gfc: flag("SRDO_USE_GFC"),
        srdo_use_progmonitor: flag("SRDO_USE_PROGMONITOR"),
        srdo_check_srvt_before_1strx: flag("SRDO_CHECK_SRVT_BEFORE_1STRX"),
        srdo_max_srdo_in_obd: num("SRDO_MAX_SRDO_IN_OBD"),
        cdrv_timestamp: flag("CDRV_TIMESTAMP"),
        cdrv_can20b: num("CDRV_CAN_SPEC") == 2,
        cdrv_use_highbuff: flag("CDRV_USE_HIGHBUFF"),
        pdo_static_mapping: flag("PDO_USE_STATIC_MAPPING"),
        pdo_granularity: num("PDO_GRANULARITY"),
        pdo_bit_mapping: flag("PDO_USE_BIT_MAPPING"),
        pdo_dummy_mapping: flag("PDO_USE_DUMMY_MAPPING"),
        // Read back rather than derived: copcfg.h may set it itself, and
        // tPdoParam is sized by exactly this value.
        pdo_max_mappentries: num("PDO_MAX_MAPPENTRIES"),
        sdos_default_timeout: num("SDOS_DEFAULT_TIMEOUT"),
        sdos_buffer_size: num("SDOS_BUFFER_SIZE"),
        sdo_blocksize_download: num("SDO_BLOCKSIZE_DOWNLOAD"),
        sdo_blocksize_upload: num("SDO_BLOCKSIZE_UPLOAD"),
        sdo_max_server_in_obd: num("SDO_MAX_SERVER_IN_OBD"),
        sdo_max_client_in_obd: num("SDO_MAX_CLIENT_IN_OBD"),
        hbc_max_consumer_in_obd: num("HBC_MAX_CONSUMER_IN_OBD"),
        pdo_max_rxpdo_in_obd: num("PDO_MAX_RXPDO_IN_OBD"),
        pdo_max_txpdo_in_obd: num("PDO_MAX_TXPDO_IN_OBD"),
        nmtm_max_slave_entries: num("NMTM_MAX_SLAVE_ENTRIES"),
        emcc_max_consumer: num("EMCC_MAX_CONSUMER"),
        nmts_use_lifeguarding: flag("NMTS_USE_LIFEGUARDING"),
        ccm_use_pdo_check_var: flag("CCM_USE_PDO_CHECK_VAR"),
        dyn_od_pool_size: num("OBD_DYNAMIC_POOL_SIZE"),
        obd_use_dynamic_od: flag("OBD_USE_DYNAMIC_OD"),
        cob_more_than_128_entries: flag("COB_MORE_THAN_128_ENTRIES"),
        ccm_module_lsss: bits("CCM_MODULE_INTEGRATION") & CCM_MODULE_LSSS != 0,
        max_instances: num("COP_MAX_INSTANCES"),
    }
}

/// `CCM_MODULE_LSSS` of cop_types.h: the LSS slave's bit of
/// `CCM_MODULE_INTEGRATION`.
const CCM_MODULE_LSSS: u32 = 0x0000_0001;

/// `PDO_MAX_MAPPENTRIES` as copdef.h derives it: 64 one-bit entries need
/// bit mapping and a granularity other than 8.
fn pdo_max_mappentries(granularity: u32, bit_mapping: bool) -> u32 {
    if granularity != 8 && bit_mapping {
        64
    } else {
        8
    }
}

fn check(c: &Config) {
    // The handle is a BYTE with 0xFF as CCM_ILLINSTANCE_HDL; the registry
    // keeps one bit per instance.
    assert!(
        (1..=8).contains(&c.max_instances),
        "COP_MAX_INSTANCES must be 1..=8, got {}",
        c.max_instances
    );
    assert!(
        matches!(c.srdo_granularity, 8 | 16 | 32 | 64),
        "SRDO_GRANULARITY must be 8, 16, 32 or 64 (manual 2.4), got {}",
        c.srdo_granularity
    );
    assert!(
        matches!(c.pdo_granularity, 8 | 64),
        "PDO_GRANULARITY must be 8 or 64 (dynamic OD manual L-1087d, chapter 4), got {}",
        c.pdo_granularity
    );
    assert!(
        matches!(c.pdo_max_mappentries, 8 | 64),
        "PDO_MAX_MAPPENTRIES must be 8 or 64 (copdef.h), got {}",
        c.pdo_max_mappentries
    );
    assert!(c.obj_size <= 2, "OBD_SUPPORTED_OBJ_SIZE must be 0, 1 or 2");
    assert!(
        c.srdo_max_srdo_in_obd <= 64,
        "SRDO_MAX_SRDO_IN_OBD must be at most 64 (CiA 304: 0x1301..0x1340)"
    );
    assert!(
        c.sdos_buffer_size >= 8,
        "SDOS_BUFFER_SIZE must be at least 8 bytes"
    );
    for (k, v) in [
        ("SDO_BLOCKSIZE_DOWNLOAD", c.sdo_blocksize_download),
        ("SDO_BLOCKSIZE_UPLOAD", c.sdo_blocksize_upload),
    ] {
        assert!(
            (1..=127).contains(&v),
            "{k} must be 1..=127 (CiA 301: 0 < blksize < 128), got {v}"
        );
    }
    assert!(c.hbc_max_consumer_in_obd <= 127 && c.nmtm_max_slave_entries <= 127);
    assert!(
        c.emcc_max_consumer <= 127,
        "EMCC_MAX_CONSUMER must be at most 127 (one entry per node-ID), got {}",
        c.emcc_max_consumer
    );
    assert!(c.pdo_max_rxpdo_in_obd <= 512 && c.pdo_max_txpdo_in_obd <= 512);
    assert!(
        (1..=128).contains(&c.sdo_max_server_in_obd),
        "SDO_MAX_SERVER_IN_OBD must be 1..=128 (CiA 301: 0x1200..0x127F), got {}",
        c.sdo_max_server_in_obd
    );
    assert!(c.sdo_max_client_in_obd <= 128);
}

/// The name of the symbol that encodes every setting that changes the C ABI.
/// `include/cop_config.h` builds the same name from the application's
/// headers and objdef.h references it, so a mismatch fails to link.
fn abi_symbol(c: &Config) -> String {
    // The instance count only where it is more than one, so that a
    // single-instance build keeps the name it always had.
    let instances = if c.max_instances > 1 {
        format!("_in{}", c.max_instances)
    } else {
        String::new()
    };
    format!(
        "CopLibAbi_os{}_gr{}_sm{}_pm{}_ts{}_id{}_pe{}_ch{}{instances}",
        [1, 2, 4][c.obj_size as usize],
        c.srdo_granularity,
        u8::from(c.srdo_static_mapping),
        u8::from(c.pdo_static_mapping),
        u8::from(c.cdrv_timestamp),
        if c.cdrv_can20b { 29 } else { 11 },
        c.pdo_max_mappentries,
        if c.cob_more_than_128_entries { 16 } else { 8 },
    )
}

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    let include = manifest.join("include");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=include/copdef.h");
    println!("cargo:rerun-if-env-changed=COP_CONFIG_DIR");
    println!("cargo:rerun-if-env-changed=COP_OBDCFG_DIR");

    let cfg = match env::var_os("COP_CONFIG_DIR") {
        Some(dir) if !dir.is_empty() => {
            let dir = PathBuf::from(dir);
            // obdcfg.h from its own folder when COP_OBDCFG_DIR names one.
            let obd_dir = match env::var_os("COP_OBDCFG_DIR") {
                Some(d) if !d.is_empty() => PathBuf::from(d),
                _ => dir.clone(),
            };
            if !obd_dir.is_dir() {
                panic!("COP_OBDCFG_DIR={} is not a folder", obd_dir.display());
            }
            println!("cargo:rerun-if-changed={}", dir.join("copcfg.h").display());
            println!(
                "cargo:rerun-if-changed={}",
                obd_dir.join("obdcfg.h").display()
            );
            from_headers(&dir, &obd_dir, &include)
        }
        _ => from_features(),
    };
    check(&cfg);

    let obj_size_ty = ["u8", "u16", "u32"][cfg.obj_size as usize];
    let max_mapp = 128 / cfg.srdo_granularity;
    let mut rs = String::new();
    let _ = writeln!(rs, "// Generated by build.rs from the build configuration.");
    let b = |v: bool| if v { "true" } else { "false" };
    let lines: [(&str, String); 37] = [
        (
            "`OBD_SUPPORTED_OBJ_SIZE`: 0 small (BYTE), 1 middle (WORD), 2 big (DWORD).",
            format!("pub const OBD_SUPPORTED_OBJ_SIZE: u8 = {};", cfg.obj_size),
        ),
        (
            "Rust type of `tObdSize`.",
            format!("pub type ObdSizeRepr = {obj_size_ty};"),
        ),
        (
            "`SRDO_GRANULARITY` in bits (8, 16, 32, 64).",
            format!("pub const SRDO_GRANULARITY: u8 = {};", cfg.srdo_granularity),
        ),
        (
            "`SRDO_MAX_MAPPENTRIES`: mapping entries per SRDO (128 / granularity).",
            format!("pub const SRDO_MAX_MAPPENTRIES: usize = {max_mapp};"),
        ),
        (
            "`SRDO_USE_STATIC_MAPPING` (SRDOSTC module).",
            format!(
                "pub const SRDO_USE_STATIC_MAPPING: bool = {};",
                b(cfg.srdo_static_mapping)
            ),
        ),
        (
            "`SRDO_USE_DUMMY_MAPPING`.",
            format!(
                "pub const SRDO_USE_DUMMY_MAPPING: bool = {};",
                b(cfg.srdo_dummy_mapping)
            ),
        ),
        (
            "`SRDO_ALLOW_GAPS_IN_OD`.",
            format!(
                "pub const SRDO_ALLOW_GAPS_IN_OD: bool = {};",
                b(cfg.srdo_allow_gaps)
            ),
        ),
        (
            "`SRDO_USE_GFC`.",
            format!("pub const SRDO_USE_GFC: bool = {};", b(cfg.srdo_use_gfc)),
        ),
        (
            "`SRDO_USE_PROGMONITOR`.",
            format!(
                "pub const SRDO_USE_PROGMONITOR: bool = {};",
                b(cfg.srdo_use_progmonitor)
            ),
        ),
        (
            "`SRDO_CHECK_SRVT_BEFORE_1STRX`.",
            format!(
                "pub const SRDO_CHECK_SRVT_BEFORE_1STRX: bool = {};",
                b(cfg.srdo_check_srvt_before_1strx)
            ),
        ),
        (
            "`SRDO_MAX_SRDO_IN_OBD`: capacity of the SRDO table.",
            format!(
                "pub const SRDO_MAX_SRDO_IN_OBD: usize = {};",
                cfg.srdo_max_srdo_in_obd
            ),
        ),
        (
            "`CDRV_TIMESTAMP`: `tCdrvMsg` carries `m_Time`.",
            format!(
                "pub const CDRV_TIMESTAMP: bool = {};",
                b(cfg.cdrv_timestamp)
            ),
        ),
        (
            "`COP_MAX_INSTANCES`: stack instances of the C API (more than one: \
             every `Ccm*` function takes the instance handle).",
            format!(
                "pub const COP_MAX_INSTANCES: usize = {};",
                cfg.max_instances
            ),
        ),
        (
            "`CDRV_USE_HIGHBUFF`: the driver keeps the high-priority frames \
             (SRDO, GFC, NMT) in buffers of their own.",
            format!(
                "pub const CDRV_USE_HIGHBUFF: bool = {};",
                b(cfg.cdrv_use_highbuff)
            ),
        ),
        (
            "`CDRV_CAN_SPEC == CAN20B`: `tCanId` is a DWORD.",
            format!("pub const CDRV_CAN20B: bool = {};", b(cfg.cdrv_can20b)),
        ),
        (
            "`PDO_USE_STATIC_MAPPING`: `tObdVarEntry` without callback fields.",
            format!(
                "pub const PDO_USE_STATIC_MAPPING: bool = {};",
                b(cfg.pdo_static_mapping)
            ),
        ),
        (
            "`PDO_GRANULARITY` (8 or 64): with bit mapping, 64 gives every PDO \
             64 mapping entries, so BOOLEANs can fill all 64 bits.",
            format!("pub const PDO_GRANULARITY: u8 = {};", cfg.pdo_granularity),
        ),
        (
            "`PDO_USE_BIT_MAPPING`: BOOLEANs may be mapped as single bits and \
             entries need not start on a byte boundary.",
            format!(
                "pub const PDO_USE_BIT_MAPPING: bool = {};",
                b(cfg.pdo_bit_mapping)
            ),
        ),
        (
            "`PDO_USE_DUMMY_MAPPING`: RPDOs may map data type indices as place holders.",
            format!(
                "pub const PDO_USE_DUMMY_MAPPING: bool = {};",
                b(cfg.pdo_dummy_mapping)
            ),
        ),
        (
            "`PDO_MAX_MAPPENTRIES`: mapping entries per PDO (64 with bit mapping \
             at a granularity other than 8, otherwise 8). Sizes `tPdoParam`.",
            format!(
                "pub const PDO_MAX_MAPPENTRIES: usize = {};",
                cfg.pdo_max_mappentries
            ),
        ),
        (
            "`SDOS_DEFAULT_TIMEOUT` in ticks of 100 us.",
            format!(
                "pub const SDOS_DEFAULT_TIMEOUT: u32 = {};",
                cfg.sdos_default_timeout
            ),
        ),
        (
            "`SDOS_BUFFER_SIZE`: SDO transfer buffer (largest segmented object).",
            format!(
                "pub const SDOS_BUFFER_SIZE: usize = {};",
                cfg.sdos_buffer_size
            ),
        ),
        (
            "`SDO_BLOCKSIZE_DOWNLOAD`: segments per sub-block the SDO server accepts in a block download (1..=127).",
            format!(
                "pub const SDO_BLOCKSIZE_DOWNLOAD: u8 = {};",
                cfg.sdo_blocksize_download
            ),
        ),
        (
            "`SDO_BLOCKSIZE_UPLOAD`: segments per sub-block the SDO client accepts in a block upload (1..=127).",
            format!(
                "pub const SDO_BLOCKSIZE_UPLOAD: u8 = {};",
                cfg.sdo_blocksize_upload
            ),
        ),
        (
            "`SDO_MAX_SERVER_IN_OBD`: SDO servers, the default one (0x1200) included.",
            format!(
                "pub const SDO_MAX_SERVER_IN_OBD: usize = {};",
                cfg.sdo_max_server_in_obd
            ),
        ),
        (
            "`SDO_MAX_CLIENT_IN_OBD`.",
            format!(
                "pub const SDO_MAX_CLIENT_IN_OBD: usize = {};",
                cfg.sdo_max_client_in_obd
            ),
        ),
        (
            "`HBC_MAX_CONSUMER_IN_OBD`.",
            format!(
                "pub const HBC_MAX_CONSUMER_IN_OBD: usize = {};",
                cfg.hbc_max_consumer_in_obd
            ),
        ),
        (
            "`PDO_MAX_RXPDO_IN_OBD`.",
            format!(
                "pub const PDO_MAX_RXPDO_IN_OBD: usize = {};",
                cfg.pdo_max_rxpdo_in_obd
            ),
        ),
        (
            "`PDO_MAX_TXPDO_IN_OBD`.",
            format!(
                "pub const PDO_MAX_TXPDO_IN_OBD: usize = {};",
                cfg.pdo_max_txpdo_in_obd
            ),
        ),
        (
            "`NMTM_MAX_SLAVE_ENTRIES`.",
            format!(
                "pub const NMTM_MAX_SLAVE_ENTRIES: usize = {};",
                cfg.nmtm_max_slave_entries
            ),
        ),
        (
            "`EMCC_MAX_CONSUMER`: emergency producers the consumer can list.",
            format!(
                "pub const EMCC_MAX_CONSUMER: usize = {};",
                cfg.emcc_max_consumer
            ),
        ),
        (
            "`NMTS_USE_LIFEGUARDING`: life guarding slave (`CcmInitLgs`, `CcmConfigLgs`).",
            format!(
                "pub const NMTS_USE_LIFEGUARDING: bool = {};",
                b(cfg.nmts_use_lifeguarding)
            ),
        ),
        (
            "`CCM_USE_PDO_CHECK_VAR`: every `CcmProcess` compares the mapped data of the event-driven and acyclic TPDOs with what they sent last.",
            format!(
                "pub const CCM_USE_PDO_CHECK_VAR: bool = {};",
                b(cfg.ccm_use_pdo_check_var)
            ),
        ),
        (
            "`OBD_DYNAMIC_POOL_SIZE`: bytes of the dynamic OD pool.",
            format!(
                "pub const OBD_DYNAMIC_POOL_SIZE: usize = {};",
                cfg.dyn_od_pool_size
            ),
        ),
        (
            "`OBD_USE_DYNAMIC_OD`: `DynBuildOd` has a pool (else it answers kCopDynNoMemory).",
            format!(
                "pub const OBD_USE_DYNAMIC_OD: bool = {};",
                b(cfg.obd_use_dynamic_od)
            ),
        ),
        (
            "`CCM_MODULE_INTEGRATION & CCM_MODULE_LSSS`: `CcmInitCANopen` starts the LSS slave (CiA 305) and takes node-ID 0xFF.",
            format!(
                "pub const CCM_MODULE_LSSS: bool = {};",
                b(cfg.ccm_module_lsss)
            ),
        ),
        (
            "Name of the link-time configuration signature symbol.",
            format!("pub const ABI_SYMBOL: &str = \"{}\";", abi_symbol(&cfg)),
        ),
    ];
    for (doc, l) in lines {
        let _ = writeln!(rs, "/// {doc}");
        let _ = writeln!(rs, "{l}");
    }
    let out = PathBuf::from(env::var("OUT_DIR").unwrap());
    fs::write(out.join("config.rs"), rs).unwrap();
    fs::write(
        out.join("abi_symbol.rs"),
        format!(
            "/// Link-time configuration signature (see include/cop_config.h).\n\
             #[unsafe(export_name = \"{}\")]\n\
             pub static COP_LIB_ABI_SIGNATURE: u8 = 0;\n",
            abi_symbol(&cfg)
        ),
    )
    .unwrap();

    let flags = [
        ("srdo_static_mapping", cfg.srdo_static_mapping),
        ("srdo_use_gfc", cfg.srdo_use_gfc),
        ("srdo_use_progmonitor", cfg.srdo_use_progmonitor),
        ("cdrv_timestamp", cfg.cdrv_timestamp),
        ("cdrv_can20b", cfg.cdrv_can20b),
        ("nmts_use_lifeguarding", cfg.nmts_use_lifeguarding),
        ("cob_hdl_word", cfg.cob_more_than_128_entries),
        ("ccm_module_lsss", cfg.ccm_module_lsss),
        ("multi_instance", cfg.max_instances > 1),
    ];
    for (name, on) in flags {
        println!("cargo::rustc-check-cfg=cfg({name})");
        if on {
            println!("cargo:rustc-cfg={name}");
        }
    }
}
