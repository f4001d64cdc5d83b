//! The configuration check (`CcmCheckSrdoConfig`) on dictionaries the
//! manual's macros cannot produce but a hand-written C dictionary can: the
//! transmission type (0x1301 sub 4) as writable RAM, a mapping entry that
//! names a VISIBLE_STRING, a mapping parameter whose default count exceeds
//! SRDO_MAX_MAPPENTRIES. Each SRDO is sealed (its CRC written to 0x13FF)
//! first, so the check gets past the CRC step to the step under test.

use core::sync::atomic::AtomicU8;

use cop::CopKernel;
use cop::ccm::Stack;
use cop::config::SRDO_MAX_MAPPENTRIES;
use cop::od::{Access, ByteOrder, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl};
use cop::port::Ticks;
use cop::sim::SimBus;
use std::sync::{Mutex, MutexGuard};

/// Normal data 0x6200 sub 1 (U16), inverted data 0x6300 sub 1 (U16).
static NORMAL: [AtomicU8; 2] = decl::zeroed();
static INVERTED: [AtomicU8; 2] = decl::zeroed();
static S6200: [ObdSubEntry; 2] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
    ObdSubEntry::ram(1, DataType::UInt16, Access::PRW, &NORMAL, Some(&[0, 0])),
];
static S6300: [ObdSubEntry; 2] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
    ObdSubEntry::ram(1, DataType::UInt16, Access::PRW, &INVERTED, Some(&[0, 0])),
];
/// Two bytes of VISIBLE_STRING, readable and flagged mappable: only its
/// type makes it unfit for an SRDO.
static S2000: [ObdSubEntry; 1] = [ObdSubEntry::rom(0, DataType::VString, Access::PR, b"ab")];
static DEVICE: [ObdEntry; 2] = [
    ObdEntry::new(0x6200, &S6200, None),
    ObdEntry::new(0x6300, &S6300, None),
];
static MANUFACTURER: [ObdEntry; 1] = [ObdEntry::new(0x2000, &S2000, None)];

cop::obd_create_srdo_gfc_param!(mod gfc);
cop::obd_create_srdo_cfg_valid!(mod cfg_valid);
cop::obd_create_srdo_crc!(mod crcs, [0]);
// SRDO 1 as the manual's macros give it (transmit, 25 ms, 20 ms, 0x101/0x102).
cop::obd_create_srdo_commu!(mod commu, 0x1301, 1, 25, 20, 0x101, 0x102);
// The good mapping: 0x6200 sub 1 / 0x6300 sub 1, 16 bits each.
cop::obd_create_srdo_mapp!(mod mapp, 0x1381, [0x6200_0110, 0x6300_0110]);
// A mapping whose normal entry names the string (16 bits, its length).
cop::obd_create_srdo_mapp!(mod mapp_string, 0x1381, [0x2000_0010, 0x6300_0110]);

/// 0x1301 with sub 4 (transmission type) as a RAM variable, default 253.
mod commu_ttype {
    use super::*;
    static DIRECTION: [AtomicU8; 1] = decl::zeroed();
    static SCT: [AtomicU8; 2] = decl::zeroed();
    static SRVT: [AtomicU8; 1] = decl::zeroed();
    static TTYPE: [AtomicU8; 1] = decl::zeroed();
    static COB1: [AtomicU8; 4] = decl::zeroed();
    static COB2: [AtomicU8; 4] = decl::zeroed();
    static SCT_DEFAULT: [u8; 2] = 25u16.to_ne_bytes();
    static COB1_DEFAULT: [u8; 4] = 0x101u32.to_ne_bytes();
    static COB2_DEFAULT: [u8; 4] = 0x102u32.to_ne_bytes();
    pub static SUBS: [ObdSubEntry; 7] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[6]),
        ObdSubEntry::param(1, DataType::UInt8, &DIRECTION, &[1]),
        ObdSubEntry::param(2, DataType::UInt16, &SCT, &SCT_DEFAULT),
        ObdSubEntry::param(3, DataType::UInt8, &SRVT, &[20]),
        ObdSubEntry::param(4, DataType::UInt8, &TTYPE, &[253]),
        ObdSubEntry::param(5, DataType::UInt32, &COB1, &COB1_DEFAULT),
        ObdSubEntry::param(6, DataType::UInt32, &COB2, &COB2_DEFAULT),
    ];
}

/// 0x1381 with SRDO_MAX_MAPPENTRIES + 2 entry subindices and that count
/// as its constant sub 0 (the write hook refuses such a count; a
/// dictionary default is not written through it).
mod mapp_long {
    use super::*;
    pub const COUNT: usize = SRDO_MAX_MAPPENTRIES + 2;
    static COUNT_VALUE: [u8; 1] = [COUNT as u8];
    /// Pairs of 0x6200 sub 1 / 0x6300 sub 1, 8 bits each (CPU order).
    static NORMAL_ENTRY: [u8; 4] = 0x6200_0108u32.to_ne_bytes();
    static INVERTED_ENTRY: [u8; 4] = 0x6300_0108u32.to_ne_bytes();
    const fn subs() -> [ObdSubEntry; COUNT + 1] {
        const FILL: ObdSubEntry = ObdSubEntry::rom(0, DataType::UInt8, Access::R, &COUNT_VALUE);
        let mut s = [FILL; COUNT + 1];
        let mut sub = 1;
        while sub <= COUNT {
            let entry: &'static [u8; 4] = if sub % 2 == 1 {
                &NORMAL_ENTRY
            } else {
                &INVERTED_ENTRY
            };
            s[sub] = ObdSubEntry::rom(sub as u8, DataType::UInt32, Access::R, entry);
            sub += 1;
        }
        s
    }
    pub static SUBS: [ObdSubEntry; COUNT + 1] = subs();
}

/// The SRDO objects of one dictionary: SRDO 1 with `commu` and `mapp`.
const fn generic(commu: &'static [ObdSubEntry], mapp: &'static [ObdSubEntry]) -> [ObdEntry; 5] {
    [
        ObdEntry::new(0x1300, &gfc::SUBS, None),
        ObdEntry::new(0x1301, commu, None),
        ObdEntry::new(0x1381, mapp, None),
        ObdEntry::new(0x13FE, &cfg_valid::SUBS, None),
        ObdEntry::new(0x13FF, &crcs::SUBS, None),
    ]
}
static GENERIC_TTYPE: [ObdEntry; 5] = generic(&commu_ttype::SUBS, &mapp::SUBS);
static GENERIC_STRING: [ObdEntry; 5] = generic(&commu::SUBS, &mapp_string::SUBS);
static GENERIC_LONG: [ObdEntry; 5] = generic(&commu::SUBS, &mapp_long::SUBS);

/// The dictionaries share the variables of 0x1300, 0x1301, 0x13FE and
/// 0x13FF: one test at a time.
static SERIAL: Mutex<()> = Mutex::new(());

/// The result of the configuration check.
type Checked = Result<(), (CopKernel, u16)>;

/// A node (node-ID 1) on `generic`, connected, with the CRC of SRDO 1
/// written to 0x13FF sub 1; returns it (and the lock over the shared
/// variables) with the result of the check.
fn sealed(generic: &'static [ObdEntry]) -> (MutexGuard<'static, ()>, Stack, Checked) {
    let guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let od = ObjectDictionary::new(generic, &MANUFACTURER, &DEVICE).unwrap();
    let mut s = Stack::new(od, 1).unwrap();
    // The start-up (reset communication loads the defaults) runs in the
    // stack's pending work.
    let bus = SimBus::new();
    let mut port = bus.attach(8);
    while s.drain(&mut port, Ticks(0)).is_some() {}
    s.connect().unwrap();
    while s.drain(&mut port, Ticks(0)).is_some() {}
    let mut sct = [0u8; 2];
    s.read_object(0x1301, 2, ByteOrder::Wire, &mut sct).unwrap();
    assert_eq!(sct, 25u16.to_le_bytes(), "the defaults are loaded");
    #[cfg(feature = "srdo-static-mapping")]
    {
        // Refused for the mappings the check refuses too; what counts is
        // the check's verdict below.
        let od = *s.od();
        let _ = s
            .srdo_mut()
            .static_define_var_fields(&od, 0x1301, &NORMAL, &INVERTED);
    }
    let crc = s.srdo().calc_crc(s.od(), 0x1301).unwrap();
    s.write_object(0x13FF, 1, ByteOrder::Wire, &crc.to_le_bytes(), Ticks(0))
        .unwrap();
    let r = s.srdo().check_config(s.od());
    (guard, s, r)
}

// req: SB-1-TTYPE, M-2.8.2-CHECK
#[test]
fn a_writable_transmission_type_other_than_254_fails_the_check() {
    let (_g, mut s, r) = sealed(&GENERIC_TTYPE);
    assert_eq!(r, Err((CopKernel::SrdoInvalidCfg, 0x1301)));
    // The hook holds a write to the same value: 254 only.
    assert_eq!(
        s.write_object(0x1301, 4, ByteOrder::Wire, &[253], Ticks(0))
            .map_err(|e| e.kernel),
        Err(CopKernel::SrdoInvalidCfg)
    );
    s.write_object(0x1301, 4, ByteOrder::Wire, &[254], Ticks(0))
        .unwrap();
    let crc = s.srdo().calc_crc(s.od(), 0x1301).unwrap();
    s.write_object(0x13FF, 1, ByteOrder::Wire, &crc.to_le_bytes(), Ticks(0))
        .unwrap();
    assert_eq!(s.srdo().check_config(s.od()), Ok(()), "254 passes");
}

// req: SB-2-MAPPING
#[test]
fn a_mapped_visible_string_fails_the_check() {
    let (_g, _s, r) = sealed(&GENERIC_STRING);
    assert_eq!(r, Err((CopKernel::SrdoErrorMapp, 0x1301)));
}

// req: SB-2-MAPPING
#[test]
fn a_default_count_above_the_capacity_fails_the_check() {
    let (_g, s, r) = sealed(&GENERIC_LONG);
    assert_eq!(r, Err((CopKernel::SrdoErrorMapp, 0x1301)));
    // The CRC stream covers every listed entry (13 bytes, then sub and
    // entry, 5 bytes each); the diagnostic copy stops at its buffer.
    let mut out = [0u8; cop::srdo::crc::MAX_STREAM];
    let n = cop::srdo::crc::stream_bytes(s.od(), 0x1301, &mut out).unwrap();
    let full = 13 + 5 * mapp_long::COUNT;
    // The buffer holds the longest stream of CiA 304 (16 entries).
    let longest = 13 + 5 * 16;
    assert_eq!(n, full.min(longest));
    // The last whole entry in the buffer, in CANopen byte order: odd subs
    // 0x6200 sub 1, even subs 0x6300 sub 1, 8 bits.
    let last = (n - 13) / 5;
    let index_high = if last % 2 == 1 { 0x62 } else { 0x63 };
    assert_eq!(out[n - 5..n], [last as u8, 0x08, 0x01, 0x00, index_high]);
}

// The count-bound test and its dictionaries, only where
// the mapping is written (dynamic mapping) and SRDO_MAX_MAPPENTRIES exceeds 4
// (not with 32 or 64 bits of granularity).
#[cfg(not(any(
    feature = "srdo-static-mapping",
    feature = "srdo-granularity-32",
    feature = "srdo-granularity-64"
)))]
mod count_bound {
    use super::*;

    // SRDO 1 disabled (its mapping may be written).
    cop::obd_create_srdo_commu!(mod commu_off, 0x1301, 0, 25, 20, 0x101, 0x102);

    /// 0x1381 with 4 entry subindices only (RAM, default count 2).
    mod mapp_short {
        use super::*;
        static COUNT: [AtomicU8; 1] = decl::zeroed();
        static ENTRIES: [[AtomicU8; 4]; 4] = [const { decl::zeroed() }; 4];
        static DEFAULT: [u8; 4] = 0x6200_0110u32.to_ne_bytes();
        pub static SUBS: [ObdSubEntry; 5] = [
            ObdSubEntry::param(0, DataType::UInt8, &COUNT, &[2]),
            ObdSubEntry::param(1, DataType::UInt32, &ENTRIES[0], &DEFAULT),
            ObdSubEntry::param(2, DataType::UInt32, &ENTRIES[1], &DEFAULT),
            ObdSubEntry::param(3, DataType::UInt32, &ENTRIES[2], &DEFAULT),
            ObdSubEntry::param(4, DataType::UInt32, &ENTRIES[3], &DEFAULT),
        ];
    }

    static GENERIC_SHORT: [ObdEntry; 5] = generic(&commu_off::SUBS, &mapp_short::SUBS);
    static GENERIC_OFF: [ObdEntry; 5] = generic(&commu_off::SUBS, &mapp::SUBS);

    /// A write's verdict: the kernel code and the SDO abort code.
    type Verdict = Result<(), (CopKernel, u32)>;

    /// `CcmWriteObject` of the mapping count 0x1381 sub 0 on `generic`:
    /// the kernel code and the SDO abort code.
    fn write_count(generic: &'static [ObdEntry], counts: &[(u8, Verdict)]) {
        let (_g, mut s, _) = sealed(generic);
        for &(count, expected) in counts {
            let r = s
                .write_object(0x1381, 0, ByteOrder::Wire, &[count], Ticks(0))
                .map_err(|e| (e.kernel, e.abort));
            assert_eq!(r, expected, "count {count}");
        }
    }

    // req: SB-2-MAPPING
    #[test]
    fn the_mapping_count_is_bounded_by_the_capacity_and_the_subindices() {
        // CiA 301 table 22: 0x06040042, the number of mapped objects would
        // exceed the PDO (here: SRDO) length.
        let bound = Err((CopKernel::SrdoErrorMapp, 0x0604_0042));
        // 4 entry subindices, fewer than SRDO_MAX_MAPPENTRIES: 4 at most.
        write_count(&GENERIC_SHORT, &[(5, bound), (4, Ok(())), (0, Ok(()))]);
        // SRDO_MAX_MAPPENTRIES subindices: up to the capacity, where the
        // entries decide (0x06040041: entries 3.. are empty).
        let max = SRDO_MAX_MAPPENTRIES as u8;
        write_count(
            &GENERIC_OFF,
            &[
                (max + 1, bound),
                (max, Err((CopKernel::SrdoErrorMapp, 0x0604_0041))),
                (2, Ok(())),
            ],
        );
    }
}
