//! The numbers of the library are the numbers a C application compiles
//! against: every value enum and every C constant of the Rust side is read
//! here against its `#define` or enumerator in `include/cop_types.h`, the
//! header the application includes (through `cop.h`).
//!
//! `c_tests/test_constants.c` checks the header's values against the SYS TEC
//! reference; this file closes the other half, header against library, so a
//! code the library returns (`CopKernel::SrdoNmtError.code()`) is the code
//! the application's `if (Ret == kCopSrdoNmtError)` compares with. A value
//! written differently on the two sides, or a C name the library does not
//! know, fails here.

use std::collections::BTreeMap;
use std::fmt::Debug;

use cop::error::{CopKernel, SdoAbort};
use cop::event::{ErrCtrlEvent, NmtEvent, NmtState, ProgMonEvent};
use cop::ffi::pdo::{PDO_INVALID_INDEX, kPdoTypeRecv, kPdoTypeSend, pdo_valid};
use cop::ffi::types::{cdrv_status, msg_type};
use cop::nmt::NmtCommand;
use cop::nmt::master::slave_state;
use cop::od::{DataType, kind};
use cop::sdo::client::SdocState;

/// The `#define`d and enumerated names of a C header with their values.
struct Header {
    /// Name → the value text of every definition of the name.
    defs: BTreeMap<String, Vec<String>>,
}

impl Header {
    fn cop_types() -> Header {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/include/cop_types.h");
        let text = std::fs::read_to_string(path).expect("include/cop_types.h");
        let mut defs: BTreeMap<String, Vec<String>> = BTreeMap::new();
        for line in text.lines() {
            let code = line.split("/*").next().unwrap_or("").trim();
            let (name, value) = if let Some(rest) = code.strip_prefix("#define") {
                let mut words = rest.trim().splitn(2, char::is_whitespace);
                (
                    words.next().unwrap_or(""),
                    words.next().unwrap_or("").trim(),
                )
            } else if let Some((name, value)) = code.split_once('=') {
                // An enumerator: `kCopSuccessful = 0x0000,`.
                (name.trim(), value.trim().trim_end_matches(','))
            } else {
                continue;
            };
            if !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                defs.entry(name.to_string())
                    .or_default()
                    .push(value.to_string());
            }
        }
        Header { defs }
    }

    /// The value of `name`: numbers, other names and `|` of both. A name
    /// defined twice with different texts (two `#if` branches) is refused,
    /// since the check could not say which one the application sees.
    fn value(&self, name: &str) -> u64 {
        let texts = self
            .defs
            .get(name)
            .unwrap_or_else(|| panic!("{name} is not in cop_types.h"));
        assert!(
            texts.iter().all(|t| *t == texts[0]),
            "{name} has two definitions: {texts:?}"
        );
        texts[0]
            .split('|')
            .map(|part| {
                let t = part.trim().trim_matches(|c| c == '(' || c == ')').trim();
                let digits = t.trim_end_matches(['u', 'U', 'l', 'L']);
                let number = match digits
                    .strip_prefix("0x")
                    .or_else(|| digits.strip_prefix("0X"))
                {
                    Some(hex) => u64::from_str_radix(hex, 16).ok(),
                    None => digits.parse().ok(),
                };
                number.unwrap_or_else(|| self.value(t))
            })
            .fold(0, |acc, v| acc | v)
    }

    /// Every name that starts with `prefix`.
    fn names(&self, prefix: &str) -> Vec<&str> {
        self.defs
            .keys()
            .map(String::as_str)
            .filter(|n| n.starts_with(prefix))
            .collect()
    }
}

/// Both directions for a value enum whose C names are `prefix` + the Rust
/// variant's name: each variant has its C name with the same number, and
/// each C name of the prefix (aliases included) decodes to a variant.
fn same_enum<T: Copy + Debug>(
    header: &Header,
    prefix: &str,
    all: &[T],
    code: impl Fn(T) -> u64,
    decodes: impl Fn(u64) -> bool,
) {
    for &v in all {
        // Rust spells acronyms as words (`UserSdoAbort` for the C
        // `kCopUserSDOAbort`), so the name is matched without case.
        let rust = format!("{prefix}{v:?}");
        let mut names = header.defs.keys().filter(|n| n.eq_ignore_ascii_case(&rust));
        let name = names
            .next()
            .unwrap_or_else(|| panic!("{rust} is not in cop_types.h"));
        assert!(names.next().is_none(), "{rust} names two C constants");
        assert_eq!(
            header.value(name),
            code(v),
            "{name}: header and library differ"
        );
    }
    let names = header.names(prefix);
    assert!(!names.is_empty(), "no C name starts with {prefix}");
    for name in names {
        let value = header.value(name);
        assert!(
            decodes(value),
            "{name} = {value:#x} is a value the library does not know"
        );
    }
}

/// [`same_enum`] for a `c_enum!` type: its values, `code()` and its
/// decoder (`$decode`, taking `$arg`).
macro_rules! same_c_enum {
    ($h:expr, $prefix:literal, $enum:ident::$decode:ident($arg:ty)) => {
        same_enum(
            &$h,
            $prefix,
            $enum::ALL,
            |v| v.code().into(),
            |n| <$arg>::try_from(n).ok().and_then($enum::$decode).is_some(),
        )
    };
}

#[test]
fn result_codes() {
    let h = Header::cop_types();
    same_c_enum!(h, "kCop", CopKernel::from_code(u32));
}

#[test]
fn nmt_states_events_and_commands() {
    let h = Header::cop_types();
    same_c_enum!(h, "kNodeState", NmtState::from_u8(u8));
    same_c_enum!(h, "kNmtEv", NmtEvent::from_u8(u8));
    same_c_enum!(h, "kNmtErrCtrlEv", ErrCtrlEvent::from_u8(u8));
    same_c_enum!(h, "kNmtComm", NmtCommand::from_u16(u16));
}

#[test]
fn program_monitor_events_data_types_and_sdo_client_states() {
    let h = Header::cop_types();
    same_c_enum!(h, "kSrdoPMEv", ProgMonEvent::from_u8(u8));
    same_c_enum!(h, "kObdTyp", DataType::from_code(u16));
    same_c_enum!(h, "kSdocTransfer", SdocState::from_u8(u8));
}

/// The Rust names of the abort codes are not the sdoac.h names, so the
/// codes are compared by number: every `SDOAC_*` of the header is a code
/// the library knows, and the names the two share mean the same number.
#[test]
fn sdo_abort_codes() {
    let h = Header::cop_types();
    let names = h.names("SDOAC_");
    assert!(names.len() >= 20, "SDOAC_* names in cop_types.h: {names:?}");
    for name in names {
        let value = h.value(name);
        let known = u32::try_from(value).ok().and_then(SdoAbort::from_code);
        assert!(
            known.is_some(),
            "{name} = {value:#010x} is a code the library does not know"
        );
    }
    for (name, code) in [
        ("SDOAC_TOGGEL_BIT_ERROR", SdoAbort::ToggleBit),
        ("SDOAC_TIME_OUT", SdoAbort::Timeout),
        ("SDOAC_OBJECT_NOT_EXIST", SdoAbort::ObjectNotExist),
        ("SDOAC_SUB_INDEX_NOT_EXIST", SdoAbort::SubindexNotExist),
        ("SDOAC_WRITE_TO_READ_ONLY_OBJ", SdoAbort::WriteReadOnly),
        ("SDOAC_DATA_TYPE_LENGTH_NOT_MATCH", SdoAbort::LengthMismatch),
        ("SDOAC_VALUE_RANGE_EXCEEDED", SdoAbort::ValueRange),
        ("SDOAC_DATA_NOT_TRANSF_OR_STORED", SdoAbort::CannotStore),
        ("SDOAC_GENERAL_ERROR", SdoAbort::General),
    ] {
        assert_eq!(h.value(name), u64::from(code.code()), "{name}");
    }
}

/// Flag bits and constants the library declares one by one: each against
/// the C name its documentation gives.
#[test]
fn flags_and_constants() {
    let h = Header::cop_types();
    let pairs: &[(&str, u64)] = &[
        ("kPdoValidCanId", pdo_valid::CAN_ID.into()),
        ("kPdoValidTxType", pdo_valid::TX_TYPE.into()),
        ("kPdoValidInihibitTime", pdo_valid::INHIBIT_TIME.into()),
        ("kPdoValidEventTime", pdo_valid::EVENT_TIME.into()),
        ("kPdoValidNrOfEntries", pdo_valid::NR_OF_ENTRIES.into()),
        ("kPdoValidMappObjects", pdo_valid::MAPP_OBJECTS.into()),
        ("kPdoValidCallback", pdo_valid::CALLBACK.into()),
        ("kPdoValidCommunication", pdo_valid::COMMUNICATION.into()),
        ("kPdoValidMapping", pdo_valid::MAPPING.into()),
        ("kPdoValidAll", pdo_valid::ALL.into()),
        ("kPdoTypeSend", kPdoTypeSend.into()),
        ("kPdoTypeRecv", kPdoTypeRecv.into()),
        ("kMtbRecv", msg_type::RECV.into()),
        ("kMtbRtr", msg_type::RTR.into()),
        ("kMtbHighPrio", msg_type::HIGH_PRIO.into()),
        ("kMtbExtend", msg_type::EXTEND.into()),
        ("kCdrvBusOff", cdrv_status::BUS_OFF.into()),
        ("kCdrvOverrun", cdrv_status::OVERRUN.into()),
        (
            "kCdrvRxBuffHighOverrun",
            cdrv_status::RX_BUFF_HIGH_OVERRUN.into(),
        ),
        (
            "kCdrvRxBuffLowOverrun",
            cdrv_status::RX_BUFF_LOW_OVERRUN.into(),
        ),
        ("kObdKindRam", kind::RAM.into()),
        ("kObdKindRom", kind::ROM.into()),
        ("kObdKindRamVString", kind::RAM_VSTRING.into()),
        ("kObdKindRomVString", kind::ROM_VSTRING.into()),
        ("kObdKindVarEntry", kind::VAR_ENTRY.into()),
        ("kObdEvPreRead", cop::od::event::PRE_READ.into()),
        ("kObdEvPostRead", cop::od::event::POST_READ.into()),
        ("kObdEvPreWrite", cop::od::event::PRE_WRITE.into()),
        ("kObdEvPostWrite", cop::od::event::POST_WRITE.into()),
        ("kObdEvInitWrite", cop::od::event::INIT_WRITE.into()),
        ("kObdEvAbortSdo", cop::od::event::ABORT_SDO.into()),
        ("kObdEvCheckExist", cop::od::event::CHECK_EXIST.into()),
        (
            "kObdEvWrStringDomain",
            cop::od::event::WR_STRING_DOMAIN.into(),
        ),
        ("kObdPartGen", cop::store::part::GEN.into()),
        ("kObdPartMan", cop::store::part::MAN.into()),
        ("kObdPartDev", cop::store::part::DEV.into()),
        ("kObdPartUsr", cop::store::part::USR.into()),
        ("kNmtmStateUsed", slave_state::USED.into()),
        ("kNmtmBootupReceived", slave_state::BOOTUP_RECEIVED.into()),
        ("kNmtmStateLgActive", slave_state::LG_ACTIVE.into()),
        ("kNmtmLgReceived", slave_state::LG_RECEIVED.into()),
        ("kNmtmStateNgActive", slave_state::NG_ACTIVE.into()),
        ("kNmtmUpdate", slave_state::UPDATE.into()),
        ("kNmtmStateToggleBit", slave_state::TOGGLE_BIT.into()),
        ("PDO_INVALID_INDEX", PDO_INVALID_INDEX.into()),
    ];
    for &(name, value) in pairs {
        assert_eq!(h.value(name), value, "{name}: header and library differ");
    }
}

/// The reader itself: a name defined in two `#if` branches with different
/// values is refused, an alias and an `|` of names are followed.
#[test]
fn the_reader_follows_aliases_and_refuses_two_definitions() {
    let h = Header::cop_types();
    assert_eq!(
        h.value("kNmtCommEnterOperational"),
        h.value("kNmtCommStartRemoteNode")
    );
    let all = ["kObdPartGen", "kObdPartMan", "kObdPartDev", "kObdPartUsr"]
        .iter()
        .map(|n| h.value(n));
    assert_eq!(h.value("kObdPartAll"), all.fold(0, |a, v| a | v));
    let twice = Header {
        defs: BTreeMap::from([("kX".to_string(), vec!["1".to_string(), "2".to_string()])]),
    };
    assert!(std::panic::catch_unwind(|| twice.value("kX")).is_err());
}
