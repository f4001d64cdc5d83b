//! Unit tests of the SRDO module on a small Rust dictionary. Whole-stack
//! scenarios on the simulated bus are in `tests/srdo_*.rs`.

use core::sync::atomic::AtomicU8;

use super::*;
use crate::od::{Access, DataType, ObdEntry, ObdSubEntry, ObdVarEntry, decl};
use crate::port::{CanFrame, CanId};

static NORMAL: [AtomicU8; 8] = decl::zeroed();
static INVERTED: [AtomicU8; 8] = decl::zeroed();
static RO_VAR: [AtomicU8; 2] = decl::zeroed();
static NOMAP_VAR: [AtomicU8; 2] = decl::zeroed();
static U32_VAR: [AtomicU8; 4] = decl::zeroed();
static U32_VAR_I: [AtomicU8; 4] = decl::zeroed();
static WIDE_N: [AtomicU8; 4] = decl::zeroed();
static WIDE_I: [AtomicU8; 4] = decl::zeroed();
#[cfg_attr(srdo_static_mapping, allow(dead_code))]
static ODD_N: [AtomicU8; 3] = decl::zeroed();
#[cfg_attr(srdo_static_mapping, allow(dead_code))]
static SHORT_N: [AtomicU8; 2] = decl::zeroed();
#[cfg_attr(srdo_static_mapping, allow(dead_code))]
static FIT_N: [AtomicU8; 4] = decl::zeroed();
#[cfg_attr(srdo_static_mapping, allow(dead_code))]
static FIT_I: [AtomicU8; 4] = decl::zeroed();
static E6600_1: ObdVarEntry = ObdVarEntry::new();
static E6600_2: ObdVarEntry = ObdVarEntry::new();

const fn part(buf: &'static [AtomicU8], from: usize, len: usize) -> &'static [AtomicU8] {
    buf.split_at(from).1.split_at(len).0
}

/// Subindex `sub`, a PRW variable of type `typ` over the bytes of `buf`
/// from `at` on, as many as `default` has.
const fn var_in(
    sub: u8,
    typ: DataType,
    buf: &'static [AtomicU8],
    at: usize,
    default: &'static [u8],
) -> ObdSubEntry {
    ObdSubEntry::ram(
        sub,
        typ,
        Access::PRW,
        part(buf, at, default.len()),
        Some(default),
    )
}

const fn u8_var(sub: u8, buf: &'static [AtomicU8], at: usize) -> ObdSubEntry {
    var_in(sub, DataType::UInt8, buf, at, &[0])
}

const fn u16_var(sub: u8, buf: &'static [AtomicU8], at: usize) -> ObdSubEntry {
    var_in(sub, DataType::UInt16, buf, at, &[0, 0])
}

/// Subindices 1..4: UNSIGNED8 over bytes 0..3 of `buf`.
const fn four_u8(buf: &'static [AtomicU8]) -> [ObdSubEntry; 5] {
    [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[4]),
        u8_var(1, buf, 0),
        u8_var(2, buf, 1),
        u8_var(3, buf, 2),
        u8_var(4, buf, 3),
    ]
}

/// Subindices 1..2: UNSIGNED16 over bytes 4..7 of `buf`.
const fn two_u16(buf: &'static [AtomicU8]) -> [ObdSubEntry; 3] {
    [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[2]),
        u16_var(1, buf, 4),
        u16_var(2, buf, 6),
    ]
}

static S6200: [ObdSubEntry; 5] = four_u8(&NORMAL);
static S6201: [ObdSubEntry; 3] = two_u16(&NORMAL);
static S6300: [ObdSubEntry; 5] = four_u8(&INVERTED);
static S6301: [ObdSubEntry; 3] = two_u16(&INVERTED);
static S6400: [ObdSubEntry; 5] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[4]),
    ObdSubEntry::ram(1, DataType::UInt16, Access::PR, &RO_VAR, Some(&[0, 0])),
    ObdSubEntry::ram(2, DataType::UInt16, Access::RW, &NOMAP_VAR, Some(&[0, 0])),
    ObdSubEntry::ram(3, DataType::UInt32, Access::PRW, &U32_VAR, Some(&[0; 4])),
    ObdSubEntry::ram(4, DataType::UInt32, Access::PRW, &U32_VAR_I, Some(&[0; 4])),
];
static S6500: [ObdSubEntry; 3] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[2]),
    ObdSubEntry::ram(1, DataType::Int24, Access::PRW, &WIDE_N, Some(&[0; 4])),
    ObdSubEntry::ram(2, DataType::Int24, Access::PRW, &WIDE_I, Some(&[0; 4])),
];
// Two UNSIGNED32 whose variables the application attaches (check.rs step 5).
static S6600: [ObdSubEntry; 3] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[2]),
    ObdSubEntry::var(1, DataType::UInt32, Access::PRW, &E6600_1, 4, None),
    ObdSubEntry::var(2, DataType::UInt32, Access::PRW, &E6600_2, 4, None),
];

// The mappings of the three SRDOs are those of SAFETY_BEHAVIOUR.md
// section 3, so that the CRC vectors hold with static mapping too.
crate::obd_create_srdo_gfc_param!(mod gfc);
crate::obd_create_srdo_commu!(mod c1, 0x1301, 0, 25, 20, 0x101, 0x102);
crate::obd_create_srdo_commu!(mod c2, 0x1302, 0, 25, 20, 0x103, 0x104);
crate::obd_create_srdo_commu!(mod c3, 0x1303, 0, 25, 20, 0x105, 0x106);
crate::obd_create_srdo_mapp!(mod m1, 0x1381, [0x6200_0108, 0x6200_0208]);
crate::obd_create_srdo_mapp!(
    mod m2,
    0x1382,
    [0x6200_0108, 0x6200_0208, 0x6200_0308, 0x6200_0408]
);
crate::obd_create_srdo_mapp!(
    mod m3,
    0x1383,
    [0x6300_0110, 0x6300_0210, 0x6200_0108, 0x6200_0208]
);
// SRDO 4: 4 + 4 + 3 = 11 bytes of data, more than one frame holds.
crate::obd_create_srdo_commu!(mod c4, 0x1304, 0, 25, 20, 0x107, 0x108);
crate::obd_create_srdo_mapp!(
    mod m4,
    0x1384,
    [0x6400_0320, 0x6400_0420, 0x6400_0320, 0x6400_0420, 0x6500_0118, 0x6500_0218]
);
crate::obd_create_srdo_cfg_valid!(mod cfg_valid);
crate::obd_create_srdo_crc!(mod crcs, [0, 0, 0, 0]);

static GENERIC: [ObdEntry; 11] =
    crate::srdo_obd_entries![gfc, c1, c2, c3, c4, m1, m2, m3, m4, cfg_valid, crcs];
static DEVICE: [ObdEntry; 7] = [
    ObdEntry::new(0x6200, &S6200, None),
    ObdEntry::new(0x6201, &S6201, None),
    ObdEntry::new(0x6300, &S6300, None),
    ObdEntry::new(0x6301, &S6301, None),
    ObdEntry::new(0x6400, &S6400, None),
    ObdEntry::new(0x6500, &S6500, None),
    ObdEntry::new(0x6600, &S6600, None),
];

// A dictionary with a gap: SRDO 1 and 3, no SRDO 2.
crate::obd_create_srdo_commu!(mod g1, 0x1301, 0, 25, 20, 0x101, 0x102);
crate::obd_create_srdo_commu!(mod g3, 0x1303, 0, 25, 20, 0x105, 0x106);
crate::obd_create_srdo_mapp!(mod gm1, 0x1381, []);
crate::obd_create_srdo_mapp!(mod gm3, 0x1383, []);
crate::obd_create_srdo_cfg_valid!(mod g_cfg_valid);
crate::obd_create_srdo_crc!(mod g_crcs, [0, 0, 0]);
static GAPPED: [ObdEntry; 6] = crate::srdo_obd_entries![g1, g3, gm1, gm3, g_cfg_valid, g_crcs];
static NO_CFG_VALID: [ObdEntry; 2] = crate::srdo_obd_entries![g1, gm1];
static NO_CFG_VALID_ONLY: [ObdEntry; 3] = crate::srdo_obd_entries![g1, gm1, g_crcs];

/// The dictionaries' variables are statics shared by all tests here; each
/// test holds this lock.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn setup() -> (std::sync::MutexGuard<'static, ()>, ObjectDictionary, Srdo) {
    setup_with(&GENERIC)
}

/// [`setup`] with the SRDO objects `generic` (and the device objects).
fn setup_with(
    generic: &'static [ObdEntry],
) -> (std::sync::MutexGuard<'static, ()>, ObjectDictionary, Srdo) {
    setup_parts(generic, &DEVICE)
}

/// [`setup_with`] with the device objects `device`.
fn setup_parts(
    generic: &'static [ObdEntry],
    device: &'static [ObdEntry],
) -> (std::sync::MutexGuard<'static, ()>, ObjectDictionary, Srdo) {
    let guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let od = ObjectDictionary::new(generic, &[], device).unwrap();
    od.restore_defaults(0x1000, 0x9FFF);
    let mut srdo = Srdo::new();
    srdo.init(&od).unwrap();
    (guard, od, srdo)
}

fn set(od: &ObjectDictionary, index: u16, sub: u8, v: u64) {
    od.poke_uint(index, sub, v).unwrap();
}

#[cfg_attr(srdo_static_mapping, allow(dead_code))]
fn get(od: &ObjectDictionary, index: u16, sub: u8) -> u64 {
    od.read_uint(index, sub).unwrap()
}

/// Writes every SRDO's CRC into 0x13FF and declares the configuration valid.
fn seal(od: &ObjectDictionary, srdo: &Srdo) {
    for idx in srdo.commu_indices() {
        let crc = srdo.calc_crc(od, idx).unwrap();
        set(od, CRC_INDEX, (idx - COMMU_BASE) as u8, u64::from(crc));
    }
    set(od, CONFIG_VALID_INDEX, 0, u64::from(CONFIG_VALID));
}

#[cfg_attr(srdo_static_mapping, allow(dead_code))]
/// Runs the queue like the stack does; `handler` plays the application
/// and returns the status byte to set in response to an event (or `None`).
fn run(
    srdo: &mut Srdo,
    q: &mut ActionQueue,
    mut handler: impl FnMut(&Srdo, &Event) -> Option<(u16, u8)>,
) -> Vec<Event> {
    let mut out = Vec::new();
    while let Some(a) = q.pop() {
        match a {
            Action::Emit(e) => {
                if let Some((idx, st)) = handler(srdo, &e) {
                    srdo.set_state(idx, st).unwrap();
                }
                out.push(e);
            }
            Action::Do(Internal::SrdoCheckHandled(slot)) => srdo.check_handled(slot, q),
            Action::Do(Internal::SrdoOk(slot)) => srdo.deliver_ok(slot, q),
            Action::Do(other) => panic!("unexpected internal action {other:?}"),
        }
    }
    out
}

#[cfg_attr(srdo_static_mapping, allow(dead_code))]
/// The application of manual 2.9.1 / 2.9.2: on success sets bits 4-5 to
/// 11, on error (bits 4-5 = 01) sets 11 and toggles bits 6-7 (01 -> 10).
fn manual_app(srdo: &Srdo, e: &Event) -> Option<(u16, u8)> {
    match *e {
        Event::SrdoEvent(idx) => Some((idx, srdo.get_state(idx).unwrap() | 0x30)),
        Event::SrdoError(idx, code) if code != CopKernel::SrdoNotHandledInApp => {
            let st = srdo.get_state(idx).unwrap();
            assert_eq!(st & 0x30, 0x10, "inside AppSrdoError bits 4-5 are 01");
            assert_eq!(st & 0xC0, 0x40, "inside AppSrdoError bits 6-7 are 01");
            Some((idx, (st | 0x30) ^ 0xC0))
        }
        _ => None,
    }
}

/// The overruns `on_rx_overrun` reports for a driver overrun (commu
/// indices in report order), one SRDO a step and at most two actions a
/// step, through [`manual_app`].
#[cfg_attr(srdo_static_mapping, allow(dead_code))]
fn overruns(srdo: &mut Srdo) -> Vec<u16> {
    srdo.on_rx_overrun();
    let mut q = ActionQueue::new();
    let mut out = Vec::new();
    loop {
        let done = srdo.report_overrun(&mut q);
        assert!(q.len() <= 2 && q.len() <= crate::event::QUEUE_CAPACITY);
        out.extend(
            run(srdo, &mut q, manual_app)
                .into_iter()
                .filter_map(|e| match e {
                    Event::SrdoError(idx, CopKernel::SrdoOverrun) => Some(idx),
                    _ => None,
                }),
        );
        if done {
            return out;
        }
    }
}

#[cfg_attr(srdo_static_mapping, allow(dead_code))]
fn pm(e: ProgMonEvent) -> Vec<Event> {
    if SRDO_USE_PROGMONITOR {
        vec![Event::ProgMon(e)]
    } else {
        vec![]
    }
}

#[cfg_attr(srdo_static_mapping, allow(dead_code))]
fn rx(id: u16, data: &[u8], t: u32) -> RxFrame {
    RxFrame {
        frame: CanFrame::new(CanId::std_masked(id), data),
        time: Ticks(t),
    }
}

#[test]
fn per_srdo_state_fits_64_bytes() {
    // Performance goal: at most 64 bytes of run-time state per SRDO.
    assert!(
        core::mem::size_of::<Slot>() <= 64,
        "Slot is {} bytes",
        core::mem::size_of::<Slot>()
    );
}

// req: SB-3-CRC-VECTORS, M-1.1.3-CRC, M-2.8.8-CALCCRC
#[test]
fn crc_vectors_through_calc_crc() {
    // Source: SAFETY_BEHAVIOUR.md section 3, table of public test vectors;
    // each row set up in the dictionary and computed by CcmCalcSrdoCrc.
    let (_g, od, srdo) = setup();
    let rows: [(u16, u8, u16); 5] = [
        (0x1301, 1, 0xD879),
        (0x1301, 2, 0x7764),
        (0x1302, 1, 0xE57E),
        (0x1303, 1, 0x25EA),
        (0x1303, 2, 0xA3AF),
    ];
    for (idx, dir, expected) in rows {
        set(&od, idx, 1, u64::from(dir));
        set(&od, idx, 2, 25);
        set(&od, idx, 3, 20);
        set(&od, idx, 5, 0x101);
        set(&od, idx, 6, 0x102);
        assert_eq!(
            srdo.calc_crc(&od, idx),
            Ok(expected),
            "SRDO {idx:#x} direction {dir}"
        );
    }
    // The transmission type is not part of the CRC and SRDOs with direction
    // 0 are computed too (manual 2.8.8).
    set(&od, 0x1301, 1, 0);
    assert_ne!(srdo.calc_crc(&od, 0x1301), Ok(0xD879));
    assert_eq!(srdo.calc_crc(&od, 0x1305), Err(CopKernel::SrdoNotExist));
}

// req: SB-3-CRC-VECTORS
#[test]
fn crc_byte_stream_of_row_1() {
    // Source: SAFETY_BEHAVIOUR.md section 3, "Byte stream of the first row".
    let (_g, od, _srdo) = setup();
    set(&od, 0x1301, 1, 1);
    set(&od, 0x1301, 2, 25);
    set(&od, 0x1301, 3, 20);
    set(&od, 0x1301, 5, 0x101);
    set(&od, 0x1301, 6, 0x102);
    let mut buf = [0u8; crc::MAX_STREAM];
    let n = crc::stream_bytes(&od, 0x1301, &mut buf).unwrap();
    assert_eq!(
        &buf[..n],
        &[
            0x01, 0x19, 0x00, 0x14, 0x01, 0x01, 0x00, 0x00, 0x02, 0x01, 0x00, 0x00, 0x02, 0x01,
            0x08, 0x01, 0x00, 0x62, 0x02, 0x08, 0x02, 0x00, 0x62
        ]
    );
    assert_eq!(crc16(&buf[..n]), 0xD879);
    // Sanity value of the same section.
    assert_eq!(crc16(b"123456789"), 0x31C3);
}

#[test]
fn init_finds_objects_and_refuses_bad_tables() {
    let (_g, od, srdo) = setup();
    assert_eq!(srdo.count(), 4);
    assert_eq!(
        srdo.commu_indices().collect::<Vec<_>>(),
        [0x1301, 0x1302, 0x1303, 0x1304]
    );
    let gapped = ObjectDictionary::new(&GAPPED, &[], &[]).unwrap();
    let mut s = Srdo::new();
    assert_eq!(
        s.discover(&gapped, 64, false),
        Err(CopKernel::SrdoNotExist),
        "gap refused while SRDO_ALLOW_GAPS_IN_OD is FALSE"
    );
    assert_eq!(s.discover(&gapped, 64, true), Ok(()));
    assert_eq!(s.commu_indices().collect::<Vec<_>>(), [0x1301, 0x1303]);
    assert_eq!(s.get_state(0x1302), Err(CopKernel::SrdoNotExist));
    assert_eq!(s.get_state(0x1303), Ok(0));
    assert_eq!(
        s.init(&gapped).is_ok(),
        crate::config::SRDO_ALLOW_GAPS_IN_OD,
        "init follows the build switch"
    );
    assert_eq!(
        s.discover(&od, 2, false),
        Err(CopKernel::NoResource),
        "more SRDOs than SRDO_MAX_SRDO_IN_OBD"
    );
    let no_cfg = ObjectDictionary::new(&NO_CFG_VALID, &[], &[]).unwrap();
    assert_eq!(
        s.discover(&no_cfg, 64, false),
        Err(CopKernel::ObdIndexNotExist),
        "0x13FF / 0x13FE missing"
    );
    // Manual 2.10.1: OBD_CREATE_SRDO_CFG_VALID() belongs to every
    // dictionary with SRDOs, also when their CRC object is there.
    let no_cfg_valid = ObjectDictionary::new(&NO_CFG_VALID_ONLY, &[], &[]).unwrap();
    assert_eq!(
        s.discover(&no_cfg_valid, 64, false),
        Err(CopKernel::ObdIndexNotExist),
        "0x13FE missing"
    );
    let no_srdo = ObjectDictionary::new(&[], &[], &[]).unwrap();
    assert_eq!(
        s.discover(&no_srdo, 64, false),
        Ok(()),
        "no SRDO, no 0x13FE needed"
    );
    assert_eq!(s.count(), 0);
}

// req: M-2.5.3-STATUS
#[test]
fn state_byte_api() {
    let (_g, _od, mut srdo) = setup();
    assert_eq!(srdo.get_state(0x1301), Ok(0));
    srdo.set_state(0x1301, 0xBF).unwrap();
    assert_eq!(
        srdo.get_state(0x1301),
        Ok(0xB0),
        "bits 0-3 stay reserved (0)"
    );
    for bad in [0x0000, 0x1300, 0x1305, 0x1340, 0x1381, 0xFFFF] {
        assert_eq!(srdo.get_state(bad), Err(CopKernel::SrdoNotExist));
        assert_eq!(srdo.set_state(bad, 0), Err(CopKernel::SrdoNotExist));
    }
}

#[test]
fn commu_param_and_mapped_len() {
    let (_g, od, srdo) = setup();
    set(&od, 0x1302, 1, 2);
    set(&od, 0x1302, 2, 40);
    assert_eq!(
        srdo.commu_param(&od, 0x1302),
        Ok(CommuParam {
            direction: 2,
            sct_ms: 40
        })
    );
    assert_eq!(srdo.mapped_len(&od, 0x1301), Ok(1));
    assert_eq!(srdo.mapped_len(&od, 0x1302), Ok(2));
    assert_eq!(srdo.mapped_len(&od, 0x1303), Ok(3));
    assert_eq!(srdo.mapped_len(&od, 0x1304), Ok(11));
    assert_eq!(srdo.commu_param(&od, 0x1305), Err(CopKernel::SrdoNotExist));
    set(&od, 0x1301, 1, 1);
    set(&od, 0x1303, 1, 1);
    assert_eq!(
        srdo.transmit_indices(&od).collect::<Vec<_>>(),
        [0x1301, 0x1303]
    );
}

#[test]
fn mapping_entry_format() {
    // Manual table 4: 0x20000310 = UNSIGNED16 at index 0x2000 sub 3.
    let e = MappingEntry::decode(0x2000_0310);
    assert_eq!(
        e,
        MappingEntry {
            index: 0x2000,
            sub: 3,
            bits: 16
        }
    );
    assert_eq!(e.encode(), 0x2000_0310);
    assert_eq!(MappingEntry::decode(0x0005_0008).dummy_bits(), Some(8));
    assert_eq!(MappingEntry::decode(0x0007_0020).dummy_bits(), Some(32));
    assert_eq!(e.dummy_bits(), None);
}

/// Object writes of a test case: (index, subindex, value).
#[cfg(not(srdo_static_mapping))]
type Writes = &'static [(u16, u8, u64)];
/// Frames of a test case: (COB-ID, data, receive tick).
#[cfg(not(srdo_static_mapping))]
type Frames = &'static [(u16, &'static [u8], u32)];

/// Tests that rewrite mappings (dynamic mapping only).
#[cfg(not(srdo_static_mapping))]
mod dynamic {
    use super::*;
    use crate::config::SRDO_GRANULARITY;
    use crate::event::QUEUE_CAPACITY;

    /// SRDO 0x1301: receive, SCT 25 ms, SRVT 20 ms, COB-IDs 0x101/0x102,
    /// normal 0x6201 sub 1 (U16), inverted 0x6301 sub 1 (U16); DLC 2.
    /// The other SRDOs are off.
    fn receive_config(od: &ObjectDictionary, srdo: &Srdo) {
        set(od, 0x1301, 1, 2);
        set(od, 0x1381, 0, 2);
        set(od, 0x1381, 1, 0x6201_0110);
        set(od, 0x1381, 2, 0x6301_0110);
        seal(od, srdo);
    }

    /// [`setup`] with [`receive_config`] applied.
    fn setup_receiving() -> (std::sync::MutexGuard<'static, ()>, ObjectDictionary, Srdo) {
        let (g, od, srdo) = setup();
        receive_config(&od, &srdo);
        (g, od, srdo)
    }

    fn operational(od: &ObjectDictionary, srdo: &mut Srdo, now: u32) {
        srdo.on_state(od, NmtState::Operational, 5, Ticks(now));
        assert!(srdo.is_running());
    }

    // req: M-2.8.2-CHECK, SB-2-ORDER, SB-2-MAPPING, SB-2-LENGTH, M-1.1-COBID
    #[test]
    fn configuration_check_codes_in_order() {
        let (_g, od, srdo) = setup_receiving();
        assert_eq!(srdo.check_config(&od), Ok(()));

        // CRC first: a changed parameter without a new CRC; disabled SRDOs
        // are CRC-checked too, and the first bad SRDO is named.
        for (index, sub, changed, sealed) in [(0x1301, 3, 21, 20), (0x1303, 2, 26, 25)] {
            set(&od, index, sub, changed);
            let crc_error = Err((CopKernel::SrdoCfgCrcError, index));
            assert_eq!(srdo.check_config(&od), crc_error);
            set(&od, index, sub, sealed);
            assert_eq!(srdo.check_config(&od), Ok(()));
        }

        // Dummy entries (index 0x0006) map only with the srdo-dummy-mapping switch.
        let dummy = if crate::config::SRDO_USE_DUMMY_MAPPING {
            CopKernel::Successful
        } else {
            CopKernel::SrdoErrorMapp
        };
        // Each code with the configurations (writes into a good one) that
        // give it.
        let cases: &[(CopKernel, &[Writes])] = &[
            (CopKernel::SrdoInvalidCfg, &[&[(0x1301, 1, 3)]]),
            (
                CopKernel::SrdoCfgTimingError,
                &[&[(0x1301, 2, 0)], &[(0x1301, 3, 0)], &[(0x1301, 2, 19)]],
            ),
            // SRVT equal to SCT is allowed (only SRVT > SCT is refused).
            (CopKernel::Successful, &[&[(0x1301, 3, 25)]]),
            (
                CopKernel::SrdoCfgIdError,
                &[
                    &[(0x1301, 5, 0x102), (0x1301, 6, 0x103)],
                    &[(0x1301, 5, 0x181), (0x1301, 6, 0x182)],
                    &[(0x1301, 6, 0x104)],
                ],
            ),
            (
                CopKernel::SrdoErrorMapp,
                &[
                    &[(0x1381, 0, 1)],
                    &[(0x1381, 0, 0)],
                    &[(0x1381, 2, 0x6300_0108)],
                    &[(0x1381, 1, 0x6202_0110)],
                    &[(0x1381, 1, 0x6201_0310)],
                    &[(0x1381, 1, 0x6400_0110), (0x1381, 2, 0x6301_0110)],
                    &[(0x1381, 1, 0x6400_0210)],
                    // Both entries of the pair of length 0 (equal lengths).
                    &[(0x1381, 1, 0x6300_0100), (0x1381, 2, 0x6301_0100)],
                    &[(0x1381, 1, 0x6400_0320), (0x1381, 2, 0x6301_0120)],
                ],
            ),
            (
                dummy,
                &[&[(0x1381, 1, 0x0006_0010), (0x1381, 2, 0x0006_0010)]],
            ),
            (
                CopKernel::SrdoLengthExceeded,
                &[&[
                    (0x1381, 0, 6),
                    (0x1381, 3, 0x6400_0320),
                    (0x1381, 4, 0x6400_0420),
                    (0x1381, 5, 0x6500_0118),
                    (0x1381, 6, 0x6500_0218),
                ]],
            ),
        ];
        for (code, configurations) in cases {
            for writes in configurations.iter() {
                od.restore_defaults(0x1000, 0x1FFF);
                receive_config(&od, &srdo);
                for (i, s, v) in writes.iter().copied() {
                    set(&od, i, s, v);
                }
                seal(&od, &srdo);
                let expected = if *code == CopKernel::Successful {
                    Ok(())
                } else {
                    Err((*code, 0x1301))
                };
                assert_eq!(srdo.check_config(&od), expected, "after {writes:x?}");
            }
        }
    }

    /// The limits of step 5 and 6 at their boundary: `SRDO_MAX_MAPPENTRIES`
    /// entries (manual 2.4: 128 / granularity) carrying exactly 8 bytes of
    /// normal data (CiA 304: one SRDO frame holds at most 8 bytes) pass.
    // req: SB-2-MAPPING, SB-2-LENGTH, M-2.4-GRANULARITY, SB-3-CRC-VECTORS
    #[test]
    fn full_mapping_at_the_limits_passes() {
        let (_g, od, srdo) = setup_receiving();
        let pairs = u8::try_from(SRDO_MAX_MAPPENTRIES / 2).unwrap();
        let bits = 64 / u32::from(pairs);
        assert_eq!(bits, u32::from(SRDO_GRANULARITY), "entries of one granule");
        set(&od, 0x1381, 0, u64::from(2 * pairs));
        for pair in 0..pairs {
            let sub = u32::from(pair % 4) + 1;
            let normal = 0x6200_0000 | (sub << 8) | bits;
            let inverted = 0x6300_0000 | (sub << 8) | bits;
            set(&od, 0x1381, 2 * pair + 1, u64::from(normal));
            set(&od, 0x1381, 2 * pair + 2, u64::from(inverted));
        }
        seal(&od, &srdo);
        assert_eq!(srdo.check_config(&od), Ok(()));
        // The CRC over the longest byte stream, built field by field as
        // SAFETY_BEHAVIOUR.md section 3 lays it out (direction, SCT, SRVT,
        // COB-IDs little-endian, count, then subindex + entry per entry).
        let mut bytes = vec![2u8, 25, 0, 20];
        bytes.extend_from_slice(&0x101u32.to_le_bytes());
        bytes.extend_from_slice(&0x102u32.to_le_bytes());
        bytes.push(2 * pairs);
        for sub in 1..=2 * pairs {
            bytes.push(sub);
            bytes.extend_from_slice(&u32::try_from(get(&od, 0x1381, sub)).unwrap().to_le_bytes());
        }
        assert_eq!(bytes.len(), 13 + 5 * SRDO_MAX_MAPPENTRIES);
        assert_eq!(srdo.calc_crc(&od, 0x1301), Ok(crc::crc16(&bytes)));
        let mut buf = [0u8; crc::MAX_STREAM];
        let n = crc::stream_bytes(&od, 0x1301, &mut buf).unwrap();
        assert_eq!(&buf[..n], &bytes[..], "the diagnostic copy holds all of it");
        assert_eq!(
            check::check_mapping(&od, 0x1301, Direction::Receive, SRDO_GRANULARITY),
            Ok(8),
            "the normal data length in bytes"
        );
        // One byte less: 7 bytes.
        set(&od, 0x1381, 0, u64::from(2 * pairs - 2));
        assert_eq!(
            check::check_mapping(&od, 0x1301, Direction::Receive, SRDO_GRANULARITY),
            Ok(7)
        );
        // One byte more than a frame (the first pair widened to 16 bits).
        set(&od, 0x1381, 0, u64::from(2 * pairs));
        set(&od, 0x1381, 1, 0x6201_0110);
        set(&od, 0x1381, 2, 0x6301_0110);
        seal(&od, &srdo);
        assert_eq!(
            srdo.check_config(&od),
            Err((CopKernel::SrdoLengthExceeded, 0x1301))
        );
    }

    /// SRDO 1's frames at tick `t`: `normal` on 0x101, its complement on
    /// 0x102 one tick later; the events, the application being
    /// [`manual_app`].
    fn receive_pair(srdo: &mut Srdo, normal: &[u8], t: u32) -> Vec<Event> {
        let mut q = ActionQueue::new();
        let inverted: Vec<u8> = normal.iter().map(|b| !b).collect();
        srdo.on_frame(NmtState::Operational, &rx(0x101, normal, t), &mut q);
        srdo.on_frame(NmtState::Operational, &rx(0x102, &inverted, t + 1), &mut q);
        run(srdo, &mut q, manual_app)
    }

    /// SAFETY_BEHAVIOUR.md section 9: *entering* OPERATIONAL starts the
    /// SRDOs with fresh timers. Being told OPERATIONAL again while in it
    /// (the stack reports changes only) is no entry: the held first frame,
    /// the status bytes and the SCT deadline stay.
    // req: SB-9-LEAVE, M-1.1-SCT
    #[test]
    fn operational_again_is_not_a_new_start() {
        let (_g, od, mut srdo) = setup_receiving();
        operational(&od, &mut srdo, 0);
        let ev = receive_pair(&mut srdo, &[1, 0], 100);
        assert_eq!(ev[0], Event::SrdoEvent(0x1301));
        assert_eq!(srdo.get_state(0x1301), Ok(0x30));
        let mut q = ActionQueue::new();
        srdo.on_frame(NmtState::Operational, &rx(0x101, &[2, 0], 300), &mut q);
        srdo.on_state(&od, NmtState::Operational, 5, Ticks(320));
        assert_eq!(srdo.get_state(0x1301), Ok(0x30), "status kept");
        srdo.on_frame(
            NmtState::Operational,
            &rx(0x102, &[0xFD, 0xFF], 321),
            &mut q,
        );
        let ev = run(&mut srdo, &mut q, manual_app);
        assert_eq!(ev[0], Event::SrdoEvent(0x1301), "the held frame completes");
        assert_eq!(get(&od, 0x6201, 1), 2);
        // SCT (25 ms) from the first frame at 300, not from tick 320.
        let errors = |srdo: &mut Srdo, t: u32| {
            let ev = timers(srdo, t, false);
            ev.into_iter()
                .filter(|e| matches!(e, Event::SrdoError(..)))
                .collect::<Vec<_>>()
        };
        assert_eq!(errors(&mut srdo, 550), []);
        let sct = Event::SrdoError(0x1301, CopKernel::SrdoSctTimeout);
        assert_eq!(errors(&mut srdo, 551), [sct]);
    }

    /// An attached variable must exist and be 1, 2, 4 or 8 bytes wide and
    /// at least as wide as the object's type (check.rs step 5).
    // req: SB-2-MAPPING
    #[test]
    fn attached_variables_of_the_wrong_size_are_refused() {
        let (_g, od, srdo) = setup_receiving();
        set(&od, 0x1381, 1, 0x6600_0120);
        set(&od, 0x1381, 2, 0x6600_0220);
        seal(&od, &srdo);
        let refused = Err((CopKernel::SrdoErrorMapp, 0x1301));
        // No variable attached yet.
        assert_eq!(srdo.check_config(&od), refused);
        assert!(E6600_2.attach(&FIT_I));
        // 2 bytes: a native size, but narrower than UNSIGNED32.
        assert!(E6600_1.attach(&SHORT_N));
        assert_eq!(srdo.check_config(&od), refused);
        // 3 bytes: wide enough, but no native size.
        assert!(E6600_1.attach(&ODD_N));
        assert_eq!(srdo.check_config(&od), refused);
        assert!(E6600_1.attach(&FIT_N));
        assert_eq!(srdo.check_config(&od), Ok(()));
        // A received pair lands in the attached variables (CPU order).
        let mut srdo = srdo;
        operational(&od, &mut srdo, 1000);
        let ev = receive_pair(&mut srdo, &[0x78, 0x56, 0x34, 0x12], 1010);
        assert_eq!(ev[0], Event::SrdoEvent(0x1301));
        let value = |v: &[AtomicU8; 4]| {
            u32::from_ne_bytes(
                v.each_ref()
                    .map(|b| b.load(core::sync::atomic::Ordering::Relaxed)),
            )
        };
        assert_eq!(value(&FIT_N), 0x1234_5678);
        assert_eq!(value(&FIT_I), !0x1234_5678);
        // SrdoGetMappParam names the attached variables.
        let p = srdo.mapp_param(&od, 0x1301).unwrap();
        assert_eq!(p.count, 2);
        assert!(core::ptr::eq(p.vars[0].unwrap().as_ptr(), FIT_N.as_ptr()));
        assert!(core::ptr::eq(p.vars[1].unwrap().as_ptr(), FIT_I.as_ptr()));
    }

    /// The application takes an attached variable away while OPERATIONAL
    /// (`CcmDefineVarTab` with `m_pData` NULL, which src/ffi/ccm.rs stores
    /// as given). SAFETY_BEHAVIOUR.md section 5: on every error the mapped
    /// variables are not changed, the status shows the error and
    /// `AppSrdoError` is called; the code is kCopSrdoErrorMapp (manual
    /// 2.9.2, the mapping). A transmit SRDO from such a variable sends
    /// nothing.
    // req: SB-5-NO-WRITE-ON-ERROR, M-2.8.1-SEND
    #[test]
    fn a_variable_detached_while_operational_is_a_mapping_error() {
        use core::sync::atomic::Ordering::Relaxed;
        let detach = || {
            for e in [&E6600_1, &E6600_2] {
                e.m_pData.store(core::ptr::null_mut(), Relaxed);
            }
        };
        let (_g, od, mut srdo) = setup_receiving();
        // SRDO 1 receives into the attached variables, SRDO 2 sends them.
        set(&od, 0x1381, 1, 0x6600_0120);
        set(&od, 0x1381, 2, 0x6600_0220);
        set(&od, 0x1302, 1, 1);
        set(&od, 0x1382, 0, 2);
        set(&od, 0x1382, 1, 0x6600_0120);
        set(&od, 0x1382, 2, 0x6600_0220);
        seal(&od, &srdo);
        assert!(E6600_1.attach(&FIT_N) && E6600_2.attach(&FIT_I));
        for (b, v) in FIT_N.iter().zip([0x11, 0x22, 0x33, 0x44]) {
            b.store(v, Relaxed);
        }
        let fit_n = || FIT_N.each_ref().map(|b| b.load(Relaxed));
        operational(&od, &mut srdo, 1000);
        E6600_2.m_pData.store(core::ptr::null_mut(), Relaxed);
        let normal = [0x78, 0x56, 0x34, 0x12];
        let inverted = normal.map(|b| !b);
        let ev = receive_pair(&mut srdo, &normal, 1010);
        assert_eq!(ev[0], Event::SrdoError(0x1301, CopKernel::SrdoErrorMapp));
        assert_eq!(fit_n(), [0x11, 0x22, 0x33, 0x44], "nothing written");
        assert!(!ev.contains(&Event::SrdoEvent(0x1301)));
        // Transmission gathers nothing from the missing variable.
        let mut q = ActionQueue::new();
        let mut port = crate::port::Recorder::default();
        let r = srdo.send(
            &mut port,
            NmtState::Operational,
            0x1302,
            Ticks(1100),
            &mut q,
            false,
        );
        assert_eq!(r, Err(CopKernel::SrdoErrorMapp));
        assert!(port.0.is_empty(), "no frame sent");
        let ev = run(&mut srdo, &mut q, manual_app);
        assert_eq!(ev[0], Event::SrdoError(0x1302, CopKernel::SrdoErrorMapp));
        // Attached again, both directions work.
        assert!(E6600_2.attach(&FIT_I));
        let ev = receive_pair(&mut srdo, &normal, 1200);
        assert_eq!(ev[0], Event::SrdoEvent(0x1301));
        assert_eq!(fit_n(), 0x1234_5678u32.to_ne_bytes());
        let r = srdo.send(
            &mut port,
            NmtState::Operational,
            0x1302,
            Ticks(1300),
            &mut q,
            false,
        );
        assert_eq!(r, Ok(None), "the success event is queued");
        // The variables' value in CANopen byte order on 0x103, then its
        // complement on 0x104 (SAFETY_BEHAVIOUR.md section 4).
        assert_eq!(
            port.0,
            [
                CanFrame::new(CanId::std_masked(0x103), &normal),
                CanFrame::new(CanId::std_masked(0x104), &inverted)
            ]
        );
        let ev = run(&mut srdo, &mut q, manual_app);
        assert_eq!(ev[0], Event::SrdoEvent(0x1302));
        detach();
    }

    /// Manual 2.5.1: the first transmission after entering OPERATIONAL
    /// waits 0.5 ms per node-ID (FIRST_SEND_DELAY_TICKS_PER_NODE, 5 ticks
    /// of 100 µs), for every node-ID, not only node 1.
    // req: M-2.5.1-FIRST-DELAY
    #[test]
    fn first_send_delay_grows_with_the_node_id() {
        for node in [1u8, 4, 127] {
            let (_g, od, mut srdo) = setup_receiving();
            set(&od, 0x1302, 1, 1);
            // SRDO 2 maps 0x6200 sub 1..4: normal, inverted, normal, inverted.
            for (sub, v) in [(1, 0x12), (2, 0xED), (3, 0x34), (4, 0xCB)] {
                set(&od, 0x6200, sub, v);
            }
            seal(&od, &srdo);
            srdo.on_state(&od, NmtState::Operational, node, Ticks(1000));
            assert!(srdo.is_running());
            let first = 1000 + 5 * u32::from(node);
            let mut q = ActionQueue::new();
            let mut port = crate::port::Recorder::default();
            let mut send_at = |srdo: &mut Srdo, t: u32| {
                let r = srdo.send(
                    &mut port,
                    NmtState::Operational,
                    0x1302,
                    Ticks(t),
                    &mut q,
                    false,
                );
                q = ActionQueue::new();
                r
            };
            assert_eq!(
                send_at(&mut srdo, first - 1),
                Err(CopKernel::SrdoNmtError),
                "node {node}: before the delay"
            );
            assert!(
                send_at(&mut srdo, first).is_ok(),
                "node {node}: at the delay"
            );
            assert_eq!(port.0.len(), 2, "node {node}: one pair");
        }
    }

    /// Dummy entries (CiA 301 data type indices 0x0001..0x0007): only sub 0,
    /// only the size of their type, only in receive SRDOs, only with
    /// `SRDO_USE_DUMMY_MAPPING` (manual 2.4).
    // req: M-2.4-DUMMY
    #[test]
    fn dummy_entries_only_as_the_manual_allows() {
        let (_g, od, srdo) = setup();
        let dummy = crate::config::SRDO_USE_DUMMY_MAPPING;
        let cases: &[(u8, u32, u32, bool)] = &[
            // direction, normal entry, inverted entry, accepted with dummies
            (2, 0x0006_0010, 0x0006_0010, true),
            (2, 0x0005_0008, 0x0002_0008, true),
            (2, 0x0006_0110, 0x0006_0110, false),
            (2, 0x0006_0008, 0x0006_0008, false),
            (2, 0x0007_0010, 0x0007_0010, false),
            (1, 0x0006_0010, 0x0006_0010, false),
        ];
        for &(direction, normal, inverted, ok) in cases {
            od.restore_defaults(0x1000, 0x1FFF);
            receive_config(&od, &srdo);
            set(&od, 0x1301, 1, u64::from(direction));
            set(&od, 0x1381, 1, u64::from(normal));
            set(&od, 0x1381, 2, u64::from(inverted));
            seal(&od, &srdo);
            let expected = if ok && dummy {
                Ok(())
            } else {
                Err((CopKernel::SrdoErrorMapp, 0x1301))
            };
            assert_eq!(
                srdo.check_config(&od),
                expected,
                "direction {direction}, {normal:#x}/{inverted:#x}"
            );
        }
    }

    // req: SB-2-DUPLICATE, M-2.4-GRANULARITY
    #[test]
    fn duplicate_cob_ids_and_granularity() {
        let (_g, od, srdo) = setup_receiving();
        // SRDO 0x1302 transmits 0x6200 sub 1/2 (U8) on the same COB-IDs.
        set(&od, 0x1302, 1, 1);
        set(&od, 0x1302, 5, 0x101);
        set(&od, 0x1302, 6, 0x102);
        set(&od, 0x1382, 0, 2);
        seal(&od, &srdo);
        assert_eq!(
            srdo.check_config_with(&od, 8),
            Err((CopKernel::SrdoCanIdAlreadyInUse, 0x1302)),
            "the later SRDO is the bad one"
        );
        set(&od, 0x1302, 5, 0x103);
        set(&od, 0x1302, 6, 0x104);
        seal(&od, &srdo);
        assert_eq!(srdo.check_config_with(&od, 8), Ok(()));
        // 8-bit objects at granularity 16 (SRDO_GRANULARITY, manual 2.4).
        assert_eq!(
            srdo.check_config_with(&od, 16),
            Err((CopKernel::SrdoGranularityMismatch, 0x1302))
        );
        assert_eq!(
            srdo.check_config(&od).is_ok(),
            crate::config::SRDO_GRANULARITY == 8
        );
        // A disabled SRDO's COB-IDs do not count as used.
        set(&od, 0x1302, 1, 0);
        set(&od, 0x1302, 5, 0x101);
        set(&od, 0x1302, 6, 0x102);
        seal(&od, &srdo);
        assert_eq!(srdo.check_config_with(&od, 8), Ok(()));
    }

    /// A write hook's verdict: the kernel code and the SDO abort code.
    type Verdict = Result<(), (CopKernel, u32)>;

    /// What the write hook gives for 8-bit entries: accepted at the
    /// granularity of 8 bits, else `kCopSrdoGranularityMismatch` with
    /// 0x06040043 (general parameter incompatibility, CiA 301 table 22).
    fn byte_entries() -> Verdict {
        if SRDO_GRANULARITY == 8 {
            Ok(())
        } else {
            Err((CopKernel::SrdoGranularityMismatch, 0x0604_0043))
        }
    }

    /// The result of the write hook for `index`/`sub` := `v`, as the
    /// kernel code and the CiA 301 abort code an SDO client receives.
    fn hook(od: &ObjectDictionary, srdo: &Srdo, index: u16, sub: u8, v: u64) -> Verdict {
        let obj = od.find(index, sub).unwrap();
        let len = obj.data_type().wire_size().unwrap();
        let bytes = v.to_le_bytes();
        let staged = od
            .stage(&obj, crate::od::ByteOrder::Wire, &bytes[..len])
            .unwrap();
        srdo.check_write(od, &obj, &staged, NmtState::PreOperational)
            .map_err(|e| (e.kernel, e.abort))
    }

    // A receive SRDO as `OBD_CREATE_SRDO_COMMU(0x1301, 1, 2, ...)` declares
    // it, with an empty mapping.
    crate::obd_create_srdo_commu!(mod rx1, 0x1301, 2, 25, 20, 0x101, 0x102);
    crate::obd_create_srdo_mapp!(mod rx1_mapp, 0x1381, []);
    crate::obd_create_srdo_cfg_valid!(mod rx_cfg_valid);
    crate::obd_create_srdo_crc!(mod rx_crcs, [0]);
    static RECEIVE: [ObdEntry; 4] = crate::srdo_obd_entries![rx1, rx1_mapp, rx_cfg_valid, rx_crcs];

    /// Manual 2.5: "Das SRDO Modul überprüft bei jeder Änderung des Mappings
    /// die gewählten Parameter": each entry written (while the direction is
    /// 0, the CiA 304 procedure) is checked at once against the object it
    /// names, with the CiA 301 abort codes of 7.5.2.36 / table 22
    /// (0x06020000 object does not exist, 0x06090011 subindex does not
    /// exist, 0x06040041 object cannot be mapped, 0x06040043 general
    /// parameter incompatibility).
    // req: SB-2-MAPPING-WRITE
    #[test]
    fn each_mapping_entry_is_checked_when_it_is_written() {
        use core::sync::atomic::Ordering::Relaxed;
        let (_g, od, srdo) = setup_with(&RECEIVE);
        assert_eq!(get(&od, 0x1301, 1), 2, "declared receive");
        set(&od, 0x1301, 1, 0);
        let bad = CopKernel::SrdoErrorMapp;
        E6600_1.m_pData.store(core::ptr::null_mut(), Relaxed);
        let byte = byte_entries();
        let cases: &[(u32, Verdict)] = &[
            (0x3000_0110, Err((bad, 0x0602_0000))), // no object 0x3000
            (0x6200_0908, Err((bad, 0x0609_0011))), // 0x6200 has no sub 9
            (0x6400_0110, Err((bad, 0x0604_0041))), // read-only, receive SRDO
            (0x6400_0210, Err((bad, 0x0604_0041))), // not mappable
            (0x6200_0110, Err((bad, 0x0604_0041))), // U8 mapped as 16 bits
            (0x6600_0120, Err((bad, 0x0604_0041))), // no variable attached
            (0x1301_0208, Err((bad, 0x0604_0041))), // SCT: not mappable
            (0x6200_0108, byte),
            (0x6400_0320, Ok(())),
            (0, Ok(())), // an empty entry
        ];
        for &(entry, expected) in cases {
            for sub in [1u8, 2] {
                let before = get(&od, 0x1381, sub);
                let r = hook(&od, &srdo, 0x1381, sub, u64::from(entry));
                assert_eq!(r, expected, "sub {sub} = {entry:#010x}");
                assert_eq!(get(&od, 0x1381, sub), before, "the hook only judges");
            }
        }
        // With its variable attached 0x6600 sub 1 may be mapped.
        assert!(E6600_1.attach(&FIT_N));
        assert_eq!(hook(&od, &srdo, 0x1381, 1, 0x6600_0120), Ok(()));
        E6600_1.m_pData.store(core::ptr::null_mut(), Relaxed);
        // A transmit SRDO may map the read-only object, and an SRDO
        // declared with direction 0 either kind (the check at 0xA5 judges
        // the direction in force).
        let (_g2, od, srdo) = {
            drop(_g);
            setup()
        };
        assert_eq!(get(&od, 0x1301, 1), 0, "declared off");
        assert_eq!(hook(&od, &srdo, 0x1381, 1, 0x6400_0110), Ok(()));
        assert_eq!(hook(&od, &srdo, 0x1381, 1, 0x6201_0210), Ok(()));
        assert_eq!(
            hook(&od, &srdo, 0x1381, 1, 0x6400_0210),
            Err((bad, 0x0604_0041))
        );
    }

    /// Sub 0 = n enables the n entries written before (while sub 0 was 0):
    /// an even count, pairs of equal length, every entry as above, at most
    /// 8 bytes of normal data (CiA 304; abort 0x06040042 "number and
    /// length of the objects to be mapped would exceed the PDO length",
    /// CiA 301 table 22) and each entry a multiple of the granularity.
    // req: SB-2-MAPPING-WRITE
    #[test]
    fn the_mapping_count_checks_the_entries_it_enables() {
        let (_g, od, srdo) = setup_with(&RECEIVE);
        set(&od, 0x1301, 1, 0);
        let put = |entries: &[u32]| {
            for (i, e) in entries.iter().enumerate() {
                set(&od, 0x1381, (i + 1) as u8, u64::from(*e));
            }
        };
        let bad = CopKernel::SrdoErrorMapp;
        put(&[0x6200_0108, 0x6300_0108, 0x6201_0110, 0x6300_0208]);
        assert_eq!(hook(&od, &srdo, 0x1381, 0, 0), Ok(()));
        assert_eq!(hook(&od, &srdo, 0x1381, 0, 2), byte_entries());
        assert_eq!(hook(&od, &srdo, 0x1381, 0, 3), Err((bad, 0x0604_0043)));
        assert_eq!(
            hook(&od, &srdo, 0x1381, 0, 4),
            Err((bad, 0x0604_0043)),
            "16 bits paired with 8 bits"
        );
        put(&[0x6200_0108, 0x3000_0108]);
        assert_eq!(hook(&od, &srdo, 0x1381, 0, 2), Err((bad, 0x0602_0000)));
        put(&[0x6200_0108, 0x6400_0108]);
        assert_eq!(hook(&od, &srdo, 0x1381, 0, 2), Err((bad, 0x0604_0041)));
        // Three pairs of 32 bits: 12 bytes of normal data.
        put(&[
            0x6400_0320,
            0x6400_0420,
            0x6400_0320,
            0x6400_0420,
            0x6400_0320,
            0x6400_0420,
        ]);
        assert_eq!(hook(&od, &srdo, 0x1381, 0, 4), Ok(()));
        assert_eq!(
            hook(&od, &srdo, 0x1381, 0, 6),
            Err((CopKernel::SrdoLengthExceeded, 0x0604_0042))
        );
        let max = crate::config::SRDO_MAX_MAPPENTRIES as u64;
        assert_eq!(
            hook(&od, &srdo, 0x1381, 0, max + 2),
            Err((bad, 0x0604_0042))
        );
        // Granularity (manual 2.4): 8-bit entries at 16 bits.
        put(&[0x6200_0108, 0x6300_0108]);
        assert_eq!(
            super::super::check::mapping_write(&od, 0x1301, 0, 2, 16)
                .map_err(|e| (e.kernel, e.abort)),
            Err((CopKernel::SrdoGranularityMismatch, 0x0604_0043))
        );
        assert_eq!(
            super::super::check::mapping_write(&od, 0x1301, 1, 0x6200_0108, 16)
                .map_err(|e| (e.kernel, e.abort)),
            Err((CopKernel::SrdoGranularityMismatch, 0x0604_0043))
        );
        assert_eq!(
            super::super::check::mapping_write(&od, 0x1301, 0, 2, 8)
                .map_err(|e| (e.kernel, e.abort)),
            Ok(())
        );
        // The full check still runs when 0xA5 is written.
        set(&od, 0x1381, 0, 2);
        set(&od, 0x1381, 2, 0x3000_0108);
        set(&od, 0x1301, 1, 2);
        seal(&od, &srdo);
        assert_eq!(
            srdo.check_config(&od),
            Err((CopKernel::SrdoErrorMapp, 0x1301))
        );
    }

    #[test]
    fn mapp_param_reports_the_variables() {
        let (_g, od, srdo) = setup_receiving();
        let p = srdo.mapp_param(&od, 0x1301).unwrap();
        assert_eq!(p.count, 2);
        assert!(core::ptr::eq(
            p.vars[0].unwrap().as_ptr(),
            NORMAL[4..].as_ptr()
        ));
        assert!(core::ptr::eq(
            p.vars[1].unwrap().as_ptr(),
            INVERTED[4..].as_ptr()
        ));
        assert!(p.vars[2].is_none());
    }

    // req: M-2.5.2-RECEIVE
    #[test]
    fn valid_pair_writes_both_variables_and_reports() {
        let (_g, od, mut srdo) = setup_receiving();
        operational(&od, &mut srdo, 1000);
        let mut q = ActionQueue::new();
        assert!(srdo.on_frame(
            NmtState::Operational,
            &rx(0x101, &[0x34, 0x12], 1010),
            &mut q
        ));
        assert!(q.is_empty(), "the first frame alone reports nothing");
        assert!(srdo.on_frame(
            NmtState::Operational,
            &rx(0x102, &[0xCB, 0xED], 1011),
            &mut q
        ));
        let ev = run(&mut srdo, &mut q, manual_app);
        let mut expected = vec![Event::SrdoEvent(0x1301)];
        expected.extend(pm(ProgMonEvent::SrdoReceived));
        assert_eq!(ev, expected);
        // CPU byte order in the variables, little-endian on the bus.
        assert_eq!(get(&od, 0x6201, 1), 0x1234);
        assert_eq!(get(&od, 0x6301, 1), 0xEDCB);
        assert_eq!(srdo.get_state(0x1301), Ok(0x30), "set by the application");
        // A frame of another id is not the module's.
        assert!(!srdo.on_frame(NmtState::Operational, &rx(0x103, &[1, 2], 1012), &mut q));
    }

    /// Every mapped variable of the test dictionary.
    fn mapped() -> [&'static [AtomicU8]; 8] {
        [
            &NORMAL, &INVERTED, &RO_VAR, &NOMAP_VAR, &U32_VAR, &U32_VAR_I, &WIDE_N, &WIDE_I,
        ]
    }

    /// Every mapped variable of the test dictionary, byte by byte.
    fn variables() -> Vec<u8> {
        mapped()
            .iter()
            .flat_map(|v| {
                v.iter()
                    .map(|b| b.load(core::sync::atomic::Ordering::Relaxed))
            })
            .collect()
    }

    fn clear_variables() {
        for v in mapped() {
            for b in v {
                b.store(0, core::sync::atomic::Ordering::Relaxed);
            }
        }
    }

    #[test]
    fn byte_plan_moves_data_as_the_general_plan() {
        let (_g, od, _srdo) = setup();
        // (mapping, byte plan expected)
        let cases: [(&[u32], bool); 5] = [
            (&[0x6201_0110, 0x6301_0110], true),
            (
                &[
                    0x6201_0110,
                    0x6301_0110,
                    0x6200_0108,
                    0x6300_0108,
                    0x6200_0208,
                    0x6300_0208,
                ],
                true,
            ),
            (
                &[
                    0x6400_0320,
                    0x6400_0420,
                    0x6201_0210,
                    0x6301_0210,
                    0x6200_0408,
                    0x6300_0408,
                    0x6200_0308,
                    0x6300_0308,
                ],
                true,
            ),
            // INTEGER24 in a 4-byte variable: sign extension.
            (&[0x6500_0118, 0x6500_0218], false),
            // One variable as normal and inverted entry: the order counts.
            (&[0x6200_0108, 0x6200_0108, 0x6201_0110, 0x6301_0110], false),
        ];
        let data = [
            (0x8877_6655_4433_2211u64, 0x0123_4567_89AB_CDEFu64),
            (0x0000_0000_00F1_80FF, 0xFFFF_FFFF_FF0E_7F00),
        ];
        for (mapping, bytes) in cases {
            set(&od, 0x1381, 0, mapping.len() as u64);
            for (sub, e) in (1u8..).zip(mapping) {
                set(&od, 0x1381, sub, u64::from(*e));
            }
            let dlc = check::mapped_len(&od, 0x1301).unwrap();
            let p = plan::Plan::build(&od, 0x1301).unwrap();
            let g = plan::General::build(&od, 0x1301).unwrap();
            assert_eq!(matches!(p, plan::Plan::Bytes { .. }), bytes, "{mapping:x?}");
            for (n, i) in data {
                let mask = crate::wire::srdo::payload_mask(dlc);
                clear_variables();
                assert!(g.scatter(n & mask, i & mask));
                let want = variables();
                assert_eq!(p.gather(dlc), g.gather(), "{mapping:x?}");
                clear_variables();
                assert!(p.scatter(n & mask, i & mask, dlc));
                assert_eq!(variables(), want, "{mapping:x?} {n:x} {i:x}");
                assert_eq!(p.gather(dlc), g.gather(), "{mapping:x?}");
                assert_ne!(want, vec![0; want.len()], "something was written");
            }
        }
    }

    fn store_u32(var: &[AtomicU8; 4], v: u32) {
        for (b, x) in var.iter().zip(v.to_ne_bytes()) {
            b.store(x, core::sync::atomic::Ordering::Relaxed);
        }
    }

    fn load_u32(var: &[AtomicU8; 4]) -> u32 {
        u32::from_ne_bytes(core::array::from_fn(|k| {
            var[k].load(core::sync::atomic::Ordering::Relaxed)
        }))
    }

    /// Variables wider than their mapped length (the general plan): the
    /// frame carries only the mapped low bytes of each, in mapping order,
    /// and a received value fills the whole variable, sign-extended for a
    /// signed type and zero-extended otherwise (manual 2.6: the data of
    /// the mapped objects, little-endian on the bus; CiA 301 7.4.7 for the
    /// mapping lengths).
    // req: M-2.5.2-RECEIVE, M-2.8.1-SEND
    #[test]
    fn wider_variables_carry_their_mapped_bytes_and_are_extended() {
        let (_g, od, _srdo) = setup();
        // Per frame: INTEGER24 in a 4-byte variable, an UNSIGNED8, 16 bits
        // of an UNSIGNED32: 3 + 1 + 2 = 6 bytes.
        let mapping = [
            0x6500_0118u32,
            0x6500_0218,
            0x6200_0108,
            0x6300_0108,
            0x6400_0310,
            0x6400_0410,
        ];
        set(&od, 0x1381, 0, mapping.len() as u64);
        for (sub, e) in (1u8..).zip(mapping) {
            set(&od, 0x1381, sub, u64::from(e));
        }
        assert_eq!(check::mapped_len(&od, 0x1301), Ok(6));
        let p = plan::Plan::build(&od, 0x1301).unwrap();
        assert!(matches!(p, plan::Plan::General(_)), "wider variables");
        // Frame bytes (little-endian): FF 80 F1 | 44 | FE FF and their
        // complement 00 7F 0E | BB | 01 00.
        let normal = 0xFFFE_44F1_80FFu64;
        let inverted = !normal & crate::wire::srdo::payload_mask(6);
        clear_variables();
        assert!(p.scatter(normal, inverted, 6));
        assert_eq!(load_u32(&WIDE_N), 0xFFF1_80FF, "negative INTEGER24");
        assert_eq!(load_u32(&WIDE_I), 0x000E_7F00, "positive INTEGER24");
        assert_eq!(load_u32(&U32_VAR), 0x0000_FFFE, "UNSIGNED32, 16 bits");
        assert_eq!(load_u32(&U32_VAR_I), 0x0000_0001, "UNSIGNED32, 16 bits");
        assert_eq!(get(&od, 0x6200, 1), 0x44);
        assert_eq!(get(&od, 0x6300, 1), 0xBB);
        // Sending: the bytes above the mapped length stay out of the frame.
        store_u32(&WIDE_N, 0x12F1_80FF);
        store_u32(&WIDE_I, 0xED0E_7F00);
        store_u32(&U32_VAR, 0xABCD_FFFE);
        store_u32(&U32_VAR_I, 0x5432_0001);
        assert_eq!(p.gather(6), Some((normal, inverted)));
    }

    /// The byte of significance k of an n-byte variable in either byte
    /// order, against the standard library's conversions.
    #[test]
    fn cpu_byte_in_both_byte_orders() {
        let v = 0x0102_0304_0506_0708u64;
        for n in [1usize, 2, 4, 8] {
            let low = v & crate::wire::srdo::payload_mask(n as u8);
            let (le, be) = (low.to_le_bytes(), low.to_be_bytes());
            for k in 0..n {
                let byte = (low >> (8 * k)) as u8;
                assert_eq!(le[plan::cpu_byte(k, n, true)], byte, "n {n} k {k}");
                assert_eq!(be[8 - n + plan::cpu_byte(k, n, false)], byte, "n {n} k {k}");
            }
        }
    }

    // req: SB-5-NO-WRITE-ON-ERROR, M-2.5.3-STATUS
    #[test]
    fn errors_leave_variables_untouched_and_set_status() {
        let (_g, od, mut srdo) = setup_receiving();
        set(&od, 0x6201, 1, 0x5555);
        set(&od, 0x6301, 1, 0xAAAA);
        operational(&od, &mut srdo, 0);
        let op = NmtState::Operational;
        let cases: &[(Frames, CopKernel)] = &[
            (&[(0x101, &[1], 10)], CopKernel::SrdoDlcNotValid),
            (
                &[(0x101, &[1, 2], 10), (0x102, &[0xFE], 11)],
                CopKernel::SrdoDlcNotValid,
            ),
            (&[(0x102, &[0xFE, 0xFD], 10)], CopKernel::SrdoNotInOrder),
            (
                &[(0x101, &[1, 2], 10), (0x101, &[1, 2], 11)],
                CopKernel::SrdoNotInOrder,
            ),
            (
                &[(0x101, &[1, 2], 10), (0x102, &[0xFE, 0xFC], 11)],
                CopKernel::SrdoDataError,
            ),
            (
                &[(0x101, &[1, 2], 10), (0x102, &[0xFE, 0xFD], 211)],
                CopKernel::SrdoSrvtTimeout,
            ),
        ];
        for (frames, code) in cases {
            srdo.on_state(&od, NmtState::PreOperational, 5, Ticks(0));
            operational(&od, &mut srdo, 0);
            let mut q = ActionQueue::new();
            let mut events = Vec::new();
            for (id, data, t) in frames.iter() {
                srdo.on_frame(op, &rx(*id, data, *t), &mut q);
                assert!(q.len() <= 4 && q.len() < QUEUE_CAPACITY);
                events.extend(run(&mut srdo, &mut q, |s, e| {
                    if let Event::SrdoError(idx, _) = e {
                        assert_eq!(s.get_state(*idx).unwrap() & 0xF0, 0x50);
                    }
                    None
                }));
            }
            let mut expected = vec![
                Event::SrdoError(0x1301, *code),
                Event::SrdoError(0x1301, CopKernel::SrdoNotHandledInApp),
            ];
            expected.extend(pm(ProgMonEvent::SrdoError));
            assert_eq!(events, expected, "{frames:x?}");
            assert_eq!(srdo.get_state(0x1301), Ok(0x50));
            assert_eq!(get(&od, 0x6201, 1), 0x5555, "normal variable untouched");
            assert_eq!(get(&od, 0x6301, 1), 0xAAAA, "inverted variable untouched");
        }
    }

    // req: M-1.1-SRVT, M-1.1-SCT
    #[test]
    fn srvt_boundary_and_sct_boundary() {
        let (_g, od, mut srdo) = setup_receiving();
        operational(&od, &mut srdo, 0);
        // Delivers frames one by one like the stack (queue drained between).
        let feed = |srdo: &mut Srdo, frames: &[(u16, [u8; 2], u32)]| {
            let mut out = Vec::new();
            for (id, data, t) in frames {
                let mut q = ActionQueue::new();
                srdo.on_frame(NmtState::Operational, &rx(*id, data, *t), &mut q);
                out.extend(run(srdo, &mut q, manual_app));
            }
            out
        };
        let mut ok = vec![Event::SrdoEvent(0x1301)];
        ok.extend(pm(ProgMonEvent::SrdoReceived));
        // Second frame exactly SRVT (20 ms = 200 ticks) after the first: valid.
        let ev = feed(
            &mut srdo,
            &[(0x101, [1, 0], 100), (0x102, [0xFE, 0xFF], 300)],
        );
        assert_eq!(ev, ok);
        // Next first frame exactly SCT (25 ms) after the previous first: valid.
        let ev = feed(
            &mut srdo,
            &[(0x101, [2, 0], 350), (0x102, [0xFD, 0xFF], 351)],
        );
        assert_eq!(ev, ok);
        // One tick later than SCT: SCT timeout before the frame is processed,
        // then the pair itself is valid.
        let ev = feed(
            &mut srdo,
            &[(0x101, [3, 0], 601), (0x102, [0xFC, 0xFF], 602)],
        );
        let mut expected = vec![Event::SrdoError(0x1301, CopKernel::SrdoSctTimeout)];
        expected.extend(pm(ProgMonEvent::SrdoError));
        expected.extend(ok.iter().copied());
        assert_eq!(ev, expected);
        // One tick past SRVT: timeout, nothing written.
        let ev = feed(
            &mut srdo,
            &[(0x101, [4, 0], 700), (0x102, [0xFB, 0xFF], 901)],
        );
        assert_eq!(ev[0], Event::SrdoError(0x1301, CopKernel::SrdoSrvtTimeout));
        assert_eq!(get(&od, 0x6201, 1), 3);
        assert_eq!(get(&od, 0x6301, 1), 0xFFFC);
    }

    /// SRDO `commu_index`: receive, SCT `sct_ms`, normal 0x6201 sub `sub`
    /// (U16), inverted 0x6301 sub `sub` (U16); DLC 2.
    fn receive_u16_pair(od: &ObjectDictionary, commu_index: u16, sct_ms: u64, sub: u8) {
        let mapp_index = commu_index + MAPP_OFFSET;
        let entry = |index: u32| u64::from(index << 16 | u32::from(sub) << 8 | 16);
        set(od, commu_index, 1, 2);
        set(od, commu_index, 2, sct_ms);
        set(od, mapp_index, 0, 2);
        set(od, mapp_index, 1, entry(0x6201));
        set(od, mapp_index, 2, entry(0x6301));
    }

    /// Runs the timer phase of one cycle with the SRVT switch given.
    fn timers(srdo: &mut Srdo, now: u32, srvt_before_1st: bool) -> Vec<Event> {
        srdo.begin_cycle();
        let mut q = ActionQueue::new();
        let mut out = Vec::new();
        loop {
            let done = srdo.poll_with(NmtState::Operational, Ticks(now), &mut q, srvt_before_1st);
            // A pass goes on over SRDOs that only report to the program
            // monitor and stops while the queue still has room for the
            // worst step (five actions), so it never fills up and loses one.
            assert!(
                q.len() < crate::event::QUEUE_CAPACITY,
                "a pass never fills the action queue ({} actions)",
                q.len()
            );
            out.extend(run(srdo, &mut q, manual_app));
            if done {
                return out;
            }
        }
    }

    /// SAFETY_BEHAVIOUR.md section 5: a driver overrun is reported for
    /// every running receive SRDO, also one whose SCT has just expired (it
    /// is waiting for its next pair and still running).
    // req: SB-5-OVERRUN
    #[test]
    fn overrun_reaches_a_receive_srdo_after_its_sct_timeout() {
        let (_g, od, mut srdo) = setup();
        receive_u16_pair(&od, 0x1302, 100, 2);
        receive_config(&od, &srdo);
        operational(&od, &mut srdo, 1000);
        let before = overruns(&mut srdo);
        assert_eq!(before, [0x1301, 0x1302]);
        // SRDO 1's SCT (25 ms) expires at 1251; SRDO 2 (100 ms) still runs.
        let errors: Vec<Event> = timers(&mut srdo, 1251, false)
            .into_iter()
            .filter(|e| matches!(e, Event::SrdoError(..)))
            .collect();
        assert_eq!(
            errors,
            [Event::SrdoError(0x1301, CopKernel::SrdoSctTimeout)]
        );
        assert_eq!(overruns(&mut srdo), before);
    }

    // req: M-1.1-SCT
    #[test]
    fn sct_timeouts_of_several_srdos_at_their_own_ticks() {
        for switch in [false, true] {
            let (_g, od, mut srdo) = setup();
            // SRDO 2: receive, SCT 100 ms, COB-IDs 0x103/0x104, 2 bytes.
            receive_u16_pair(&od, 0x1302, 100, 2);
            receive_config(&od, &srdo);
            operational(&od, &mut srdo, 1000);
            // Deadlines: SRDO 1 at 1250 (25 ms), SRDO 2 at 2000; the pair of
            // SRDO 2 at 1200 moves its deadline to 2200, the pair of SRDO 1
            // at 1300 after its timeout sets a deadline (1550) before every
            // other one.
            let frames: [(u32, u16, [u8; 2]); 4] = [
                (1200, 0x103, [1, 0]),
                (1200, 0x104, [0xFE, 0xFF]),
                (1300, 0x101, [2, 0]),
                (1301, 0x102, [0xFD, 0xFF]),
            ];
            // Under Miri (which looks for undefined behaviour) the ticks
            // near a frame or an expected timeout and every 100th: the same
            // calls in a fraction of the time; the other runs tick every
            // millisecond and so also show that no other tick reports.
            let near = |t: u32| {
                [1200, 1250, 1300, 1550, 2200]
                    .iter()
                    .any(|&at| (at - 2..=at + 2).contains(&t))
            };
            let mut errors = Vec::new();
            for t in (1001..=2400u32).filter(|&t| !cfg!(miri) || t % 100 == 0 || near(t)) {
                for (_, id, data) in frames.iter().filter(|f| f.0 == t) {
                    let mut q = ActionQueue::new();
                    srdo.on_frame(NmtState::Operational, &rx(*id, data, t), &mut q);
                    let ev = run(&mut srdo, &mut q, manual_app);
                    assert!(
                        matches!(ev.first(), None | Some(Event::SrdoEvent(_))),
                        "{ev:?}"
                    );
                }
                for e in timers(&mut srdo, t, switch) {
                    if let Event::SrdoError(idx, code) = e {
                        errors.push((t, idx, code));
                    }
                }
            }
            let sct = CopKernel::SrdoSctTimeout;
            assert_eq!(
                errors,
                [
                    (1251, 0x1301, sct),
                    (1551, 0x1301, sct),
                    (2201, 0x1302, sct)
                ],
                "SRVT switch {switch}"
            );
        }
    }

    /// SAFETY_BEHAVIOUR.md section 5: SCT timeout "once per expiry, re-armed
    /// by the next valid pair"; a cycle with nothing due does no timer pass
    /// (ARCHITECTURE.md, "A cycle with nothing due"). The expiry here is
    /// found at the last SRDO of the pass, so the pass that reports it is
    /// also the one that plans the next deadline.
    // req: M-1.1-SCT
    #[test]
    fn sct_timeout_of_the_last_srdo_plans_the_next_deadline() {
        let (_g, od, mut srdo) = setup();
        // SRDO 1: receive, SCT 100 ms; SRDO 4 (the last): receive, SCT 25 ms.
        receive_u16_pair(&od, 0x1301, 100, 1);
        receive_u16_pair(&od, 0x1304, 25, 2);
        seal(&od, &srdo);
        operational(&od, &mut srdo, 0);
        assert_eq!(srdo.count(), 4);
        let sct = CopKernel::SrdoSctTimeout;
        let errors = |ev: &[Event]| {
            ev.iter()
                .filter_map(|e| match *e {
                    Event::SrdoError(idx, code) => Some((idx, code)),
                    _ => None,
                })
                .collect::<Vec<_>>()
        };
        // Deadlines: SRDO 4 at 250 ticks (25 ms), SRDO 1 at 1000 (100 ms).
        assert_eq!(errors(&timers(&mut srdo, 250, false)), []);
        srdo.begin_cycle();
        assert!(
            !srdo.at_rest(NmtState::Operational, Ticks(251)),
            "the SCT of SRDO 4 has passed"
        );
        assert_eq!(
            errors(&timers(&mut srdo, 251, false)),
            [(0x1304, sct)],
            "reported by the pass that ends with SRDO 4"
        );
        // Once per expiry: the next deadline is that of SRDO 1, so without
        // the program monitor the cycles until then are at rest.
        srdo.begin_cycle();
        for t in [252, 600, 1000] {
            assert_eq!(
                srdo.at_rest(NmtState::Operational, Ticks(t)),
                !SRDO_USE_PROGMONITOR,
                "tick {t}"
            );
        }
        assert_eq!(errors(&timers(&mut srdo, 1000, false)), []);
        srdo.begin_cycle();
        assert!(!srdo.at_rest(NmtState::Operational, Ticks(1001)));
        // The report of SRDO 1 interrupts the pass; until the pass is over
        // the module is not at rest.
        let mut q = ActionQueue::new();
        let done = srdo.poll_with(NmtState::Operational, Ticks(1001), &mut q, false);
        assert!(!done, "SRDOs 2 to 4 still to check");
        assert!(!srdo.at_rest(NmtState::Operational, Ticks(1001)));
        assert_eq!(errors(&run(&mut srdo, &mut q, manual_app)), [(0x1301, sct)]);
        while !srdo.poll_with(NmtState::Operational, Ticks(1001), &mut q, false) {}
        assert_eq!(errors(&run(&mut srdo, &mut q, manual_app)), []);
        assert_eq!(errors(&timers(&mut srdo, 5000, false)), []);
    }

    // req: SB-5-SRVT-SWITCH
    #[test]
    fn srvt_checked_before_second_frame_both_settings() {
        for switch in [false, true] {
            let (_g, od, mut srdo) = setup_receiving();
            operational(&od, &mut srdo, 0);
            let mut q = ActionQueue::new();
            srdo.on_frame(NmtState::Operational, &rx(0x101, &[1, 0], 10), &mut q);
            assert!(q.is_empty());
            // At SRVT nothing happens with either setting.
            let at = timers(&mut srdo, 210, switch);
            assert!(
                !at.iter().any(|e| matches!(e, Event::SrdoError(..))),
                "{at:?}"
            );
            let ev = timers(&mut srdo, 211, switch);
            let mut expected = vec![];
            if switch {
                expected.push(Event::SrdoError(0x1301, CopKernel::SrdoSrvtTimeout));
                expected.extend(pm(ProgMonEvent::SrdoError));
            }
            expected.extend(pm(ProgMonEvent::SctChecked));
            expected.extend(pm(ProgMonEvent::SctNotCheckedItIsInvalid));
            expected.extend(pm(ProgMonEvent::SctNotCheckedItIsInvalid));
            expected.extend(pm(ProgMonEvent::SctNotCheckedItIsInvalid));
            assert_eq!(ev, expected, "SRDO_CHECK_SRVT_BEFORE_1STRX = {switch}");
            // With TRUE the half was dropped: its inverted frame is out of
            // order; with FALSE the late frame gives SRVT timeout.
            srdo.on_frame(
                NmtState::Operational,
                &rx(0x102, &[0xFE, 0xFF], 212),
                &mut q,
            );
            let ev = run(&mut srdo, &mut q, manual_app);
            let code = if switch {
                CopKernel::SrdoNotInOrder
            } else {
                CopKernel::SrdoSrvtTimeout
            };
            assert_eq!(ev[0], Event::SrdoError(0x1301, code));
            // SCT (250 ticks after entry) still expires once in both cases.
            let ev = timers(&mut srdo, 251, switch);
            assert_eq!(ev[0], Event::SrdoError(0x1301, CopKernel::SrdoSctTimeout));
        }
    }

    /// Outside OPERATIONAL no timer is checked. With the program monitor a
    /// cycle reports `SctNotCheckedNotOperational` at its first poll and
    /// nothing at the next; after that report (without the monitor: from
    /// the start) the module is at rest, so the stack need not poll it.
    // req: M-2.5.4-PROGMON
    #[test]
    fn outside_operational_a_cycle_reports_once_and_then_rests() {
        let (_g, _od, mut srdo) = setup_receiving();
        let pre = NmtState::PreOperational;
        for cycle in 0..2u32 {
            srdo.begin_cycle();
            let t = 10 * cycle;
            assert_eq!(srdo.at_rest(pre, Ticks(t)), !SRDO_USE_PROGMONITOR);
            let mut events = Vec::new();
            for poll in 0..3 {
                let mut q = ActionQueue::new();
                assert!(srdo.poll(pre, Ticks(t + poll), &mut q));
                events.extend(run(&mut srdo, &mut q, manual_app));
                assert!(
                    srdo.at_rest(pre, Ticks(t + poll)),
                    "cycle {cycle}, poll {poll}"
                );
            }
            assert_eq!(events, pm(ProgMonEvent::SctNotCheckedNotOperational));
        }
    }

    /// ARCHITECTURE.md "A cycle with nothing due": without the program
    /// monitor a poll before the planned deadline (and, with the SRVT
    /// switch, no first frame held) steps no SRDO; a pass that runs plans
    /// the next deadline from the SRDOs' timers, after which the module
    /// rests until that deadline; a pass ends at the end of the table.
    #[cfg(not(srdo_use_progmonitor))]
    #[test]
    fn polls_with_nothing_due_step_no_srdo_and_a_pass_plans_the_next() {
        for switch in [false, true] {
            let (_g, od, mut srdo) = setup_receiving();
            // SRDO 1's SCT (25 ms) runs from 0 to 250.
            operational(&od, &mut srdo, 0);
            let op = NmtState::Operational;
            assert_eq!(timers(&mut srdo, 100, switch), []);
            assert_eq!(srdo.cursor, 0, "tick 100, switch {switch}: no SRDO stepped");
            // A pair at 110/111 moves the SCT to 360; the plan still says 250.
            assert_eq!(
                receive_pair(&mut srdo, &[1, 0], 110),
                [Event::SrdoEvent(0x1301)]
            );
            // With the switch the first frame seen since the plan makes the
            // next poll a pass; without it the next pass is at 251.
            assert_eq!(timers(&mut srdo, 150, switch), []);
            let stepped = if switch { srdo.count() } else { 0 };
            assert_eq!(
                usize::from(srdo.cursor),
                stepped,
                "tick 150, switch {switch}"
            );
            assert_eq!(timers(&mut srdo, 251, switch), []);
            let stepped = if switch { 0 } else { srdo.count() };
            assert_eq!(
                usize::from(srdo.cursor),
                stepped,
                "tick 251, switch {switch}"
            );
            // Either pass planned 360: at rest until then.
            srdo.begin_cycle();
            for t in [252, 300, 360] {
                assert!(srdo.at_rest(op, Ticks(t)), "tick {t}, switch {switch}");
            }
            assert!(!srdo.at_rest(op, Ticks(361)));
            assert_eq!(
                timers(&mut srdo, 361, switch),
                [Event::SrdoError(0x1301, CopKernel::SrdoSctTimeout)]
            );
            assert_eq!(
                usize::from(srdo.cursor),
                srdo.count(),
                "the pass ends at the last SRDO"
            );
        }
    }
}

/// Static mapping: the variable fields must be the mapped variables.
#[cfg(srdo_static_mapping)]
mod static_mapping {
    use super::*;

    // req: M-2.12.1-STATIC-FIELDS
    #[test]
    fn var_fields_must_match_the_mapping() {
        let (_g, od, mut srdo) = setup();
        // SRDO 1 maps 0x6200 sub 1 (normal) and 0x6200 sub 2 (inverted):
        // NORMAL[0] and NORMAL[1].
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &NORMAL[0..1], &INVERTED[0..1]),
            Err(CopKernel::SrdoErrorMapp),
            "inverted field at the wrong address"
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &NORMAL[1..2], &NORMAL[1..2]),
            Err(CopKernel::SrdoErrorMapp),
            "normal field at the wrong address"
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &NORMAL[0..1], &NORMAL[1..2]),
            Ok(())
        );
        // SRDO 3 maps 0x6300 sub 1 with 16 bits, but the variable is 8 bits.
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1303, &INVERTED[0..3], &NORMAL[0..3]),
            Err(CopKernel::SrdoErrorMapp)
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1304, &NORMAL[0..8], &INVERTED[0..8]),
            Err(CopKernel::SrdoLengthExceeded)
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1305, &NORMAL[0..1], &NORMAL[1..2]),
            Err(CopKernel::SrdoNotExist)
        );
        srdo.on_state(&od, NmtState::Operational, 1, Ticks(0));
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &NORMAL[0..1], &NORMAL[1..2]),
            Err(CopKernel::SrdoNmtError)
        );
    }

    // SRDO 1 maps one UNSIGNED8 pair (0x6200 sub 1 / 0x6300 sub 1) and a
    // pair of UNSIGNED8 dummy entries (CiA 301 data type entry 0x0005).
    crate::obd_create_srdo_commu!(mod dc1, 0x1301, 0, 25, 20, 0x101, 0x102);
    crate::obd_create_srdo_mapp!(
        mod dm1,
        0x1381,
        [0x6200_0108, 0x6300_0108, 0x0005_0008, 0x0005_0008]
    );
    crate::obd_create_srdo_cfg_valid!(mod d_cfg_valid);
    crate::obd_create_srdo_crc!(mod d_crcs, [0]);
    static WITH_DUMMIES: [ObdEntry; 4] = crate::srdo_obd_entries![dc1, dm1, d_cfg_valid, d_crcs];

    /// SAFETY_BEHAVIOUR.md section 10 (the fields are the buffers the
    /// mapping points to) and section 11 / manual 2.4 (dummy entries only
    /// with SRDO_USE_DUMMY_MAPPING): a dummy entry has no variable, so it
    /// takes its bytes of the fields without naming a buffer; whether the
    /// SRDO may run with it is the configuration check's decision.
    // req: M-2.12.1-STATIC-FIELDS, M-2.4-DUMMY
    #[test]
    fn dummy_entries_take_field_bytes_without_a_variable() {
        let (_g, od, mut srdo) = setup_with(&WITH_DUMMIES);
        assert_eq!(srdo.mapped_len(&od, 0x1301), Ok(2));
        let bad = Err(CopKernel::SrdoErrorMapp);
        let fields: [(&'static [AtomicU8], &'static [AtomicU8], CopResult, &str); 3] = [
            (
                &NORMAL[0..1],
                &INVERTED[0..1],
                bad,
                "too short for the dummy bytes",
            ),
            (
                &NORMAL[1..3],
                &INVERTED[0..2],
                bad,
                "normal variable not at the start",
            ),
            (
                &NORMAL[0..2],
                &INVERTED[0..2],
                Ok(()),
                "variables at the start",
            ),
        ];
        for (normal, inverted, expected, why) in fields {
            let r = srdo.static_define_var_fields(&od, 0x1301, normal, inverted);
            assert_eq!(r, expected, "{why}");
        }
        set(&od, 0x1301, 1, 2);
        seal(&od, &srdo);
        let expected = if crate::config::SRDO_USE_DUMMY_MAPPING {
            Ok(())
        } else {
            Err((CopKernel::SrdoErrorMapp, 0x1301))
        };
        assert_eq!(srdo.check_config_with(&od, 8), expected);
    }

    // SRDO 1: an odd number of entries; SRDO 2: entries of 4 bits.
    crate::obd_create_srdo_commu!(mod oc1, 0x1301, 0, 25, 20, 0x101, 0x102);
    crate::obd_create_srdo_commu!(mod oc2, 0x1302, 0, 25, 20, 0x103, 0x104);
    crate::obd_create_srdo_mapp!(
        mod om1,
        0x1381,
        [0x6200_0108, 0x6300_0108, 0x6200_0208]
    );
    crate::obd_create_srdo_mapp!(mod om2, 0x1382, [0x6200_0104, 0x6300_0104]);
    crate::obd_create_srdo_cfg_valid!(mod o_cfg_valid);
    crate::obd_create_srdo_crc!(mod o_crcs, [0, 0]);
    static UNFIT: [ObdEntry; 6] = crate::srdo_obd_entries![oc1, oc2, om1, om2, o_cfg_valid, o_crcs];

    /// SAFETY_BEHAVIOUR.md section 10: the fields are accepted only for a
    /// mapping whose entries are the buffers' variables, and section 2: a
    /// mapping has normal/inverted pairs (an even count) of whole numeric
    /// objects. A constant mapping without pairs or with parts of bytes
    /// has no fields that could match it (kCopSrdoErrorMapp), even when the
    /// buffers start at the mapped variables.
    // req: M-2.12.1-STATIC-FIELDS, SB-2-MAPPING
    #[test]
    fn fields_for_a_mapping_without_pairs_or_whole_bytes_are_refused() {
        let (_g, od, mut srdo) = setup_with(&UNFIT);
        let bad = Err(CopKernel::SrdoErrorMapp);
        for idx in [0x1301, 0x1302] {
            let r = srdo.static_define_var_fields(&od, idx, &NORMAL[0..2], &INVERTED[0..2]);
            assert_eq!(r, bad, "{idx:#x}");
            set(&od, idx, 1, 2);
        }
        seal(&od, &srdo);
        assert_eq!(
            srdo.check_config_with(&od, 8),
            Err((CopKernel::SrdoErrorMapp, 0x1301))
        );
    }

    // Fields that hold variables of different sizes and attached ones.
    static MIX_N: [AtomicU8; 8] = decl::zeroed();
    static MIX_I: [AtomicU8; 8] = decl::zeroed();
    static ATT_N: [AtomicU8; 2] = decl::zeroed();
    static ATT_I: [AtomicU8; 2] = decl::zeroed();
    static E6710_1: ObdVarEntry = ObdVarEntry::new();
    static E6710_2: ObdVarEntry = ObdVarEntry::new();
    // 0x6700: an UNSIGNED16 and an UNSIGNED32 one after the other in each
    // field (bytes 0..2 and 2..6).
    static S6700: [ObdSubEntry; 5] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[4]),
        var_in(1, DataType::UInt16, &MIX_N, 0, &[0; 2]),
        var_in(2, DataType::UInt32, &MIX_N, 2, &[0; 4]),
        var_in(3, DataType::UInt16, &MIX_I, 0, &[0; 2]),
        var_in(4, DataType::UInt32, &MIX_I, 2, &[0; 4]),
    ];
    // 0x6710: two UNSIGNED16 whose variables the application attaches.
    static S6710: [ObdSubEntry; 3] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[2]),
        ObdSubEntry::var(1, DataType::UInt16, Access::PRW, &E6710_1, 2, None),
        ObdSubEntry::var(2, DataType::UInt16, Access::PRW, &E6710_2, 2, None),
    ];
    static MIX_DEVICE: [ObdEntry; 2] = [
        ObdEntry::new(0x6700, &S6700, None),
        ObdEntry::new(0x6710, &S6710, None),
    ];
    // SRDO 1: the UNSIGNED16 pair, then the UNSIGNED32 pair (6 bytes);
    // SRDO 2: the attached pair.
    crate::obd_create_srdo_commu!(mod xc1, 0x1301, 0, 25, 20, 0x101, 0x102);
    crate::obd_create_srdo_commu!(mod xc2, 0x1302, 0, 25, 20, 0x103, 0x104);
    crate::obd_create_srdo_mapp!(
        mod xm1,
        0x1381,
        [0x6700_0110, 0x6700_0310, 0x6700_0220, 0x6700_0420]
    );
    crate::obd_create_srdo_mapp!(mod xm2, 0x1382, [0x6710_0110, 0x6710_0210]);
    crate::obd_create_srdo_cfg_valid!(mod x_cfg_valid);
    crate::obd_create_srdo_crc!(mod x_crcs, [0, 0]);
    static MIXED: [ObdEntry; 6] = crate::srdo_obd_entries![xc1, xc2, xm1, xm2, x_cfg_valid, x_crcs];

    /// SAFETY_BEHAVIOUR.md section 10: each mapped variable must stand in
    /// the field at the offset the entries before it give (the sum of
    /// their lengths, CiA 301 7.4.7 mapping order), with its own size; an
    /// attached variable (ObdVarEntry, check.rs step 5) counts like a RAM
    /// variable.
    // req: M-2.12.1-STATIC-FIELDS
    #[test]
    fn fields_of_variables_of_several_sizes_and_attached_variables() {
        let (_g, od, mut srdo) = setup_parts(&MIXED, &MIX_DEVICE);
        let bad = Err(CopKernel::SrdoErrorMapp);
        assert_eq!(srdo.mapped_len(&od, 0x1301), Ok(6));
        // The UNSIGNED32 at byte 2 of fields of exactly 6 bytes.
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &MIX_N[..6], &MIX_I[..6]),
            Ok(())
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &MIX_N[..5], &MIX_I[..5]),
            bad,
            "fields too short for the UNSIGNED32"
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &MIX_N[2..], &MIX_I[2..]),
            bad,
            "fields that start at the UNSIGNED32"
        );
        // Attached variables (none yet): the fields must be what is
        // attached.
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1302, &ATT_N, &ATT_I),
            bad,
            "nothing attached"
        );
        assert!(E6710_1.attach(&ATT_N) && E6710_2.attach(&ATT_I));
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1302, &ATT_N, &ATT_I),
            Ok(())
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1302, &ATT_I, &ATT_N),
            bad,
            "normal and inverted swapped"
        );
    }

    // With granularity 16 (SRDO_MAX_MAPPENTRIES 8): SRDO 1 maps eight
    // UNSIGNED16 entries of 0x6720, the most a mapping can have (four
    // pairs, 8 bytes a field).
    #[cfg(feature = "srdo-granularity-16")]
    static FULL_N: [AtomicU8; 8] = decl::zeroed();
    #[cfg(feature = "srdo-granularity-16")]
    static FULL_I: [AtomicU8; 8] = decl::zeroed();
    #[cfg(feature = "srdo-granularity-16")]
    static S6720: [ObdSubEntry; 9] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[8]),
        u16_var(1, &FULL_N, 0),
        u16_var(2, &FULL_N, 2),
        u16_var(3, &FULL_N, 4),
        u16_var(4, &FULL_N, 6),
        u16_var(5, &FULL_I, 0),
        u16_var(6, &FULL_I, 2),
        u16_var(7, &FULL_I, 4),
        u16_var(8, &FULL_I, 6),
    ];
    #[cfg(feature = "srdo-granularity-16")]
    static FULL_DEVICE: [ObdEntry; 1] = [ObdEntry::new(0x6720, &S6720, None)];
    #[cfg(feature = "srdo-granularity-16")]
    crate::obd_create_srdo_commu!(mod fc1, 0x1301, 0, 25, 20, 0x101, 0x102);
    #[cfg(feature = "srdo-granularity-16")]
    crate::obd_create_srdo_mapp!(
        mod fm1,
        0x1381,
        [
            0x6720_0110,
            0x6720_0510,
            0x6720_0210,
            0x6720_0610,
            0x6720_0310,
            0x6720_0710,
            0x6720_0410,
            0x6720_0810
        ]
    );
    #[cfg(feature = "srdo-granularity-16")]
    crate::obd_create_srdo_cfg_valid!(mod f_cfg_valid);
    #[cfg(feature = "srdo-granularity-16")]
    crate::obd_create_srdo_crc!(mod f_crcs, [0]);
    #[cfg(feature = "srdo-granularity-16")]
    static FULL: [ObdEntry; 4] = crate::srdo_obd_entries![fc1, fm1, f_cfg_valid, f_crcs];

    /// A mapping with SRDO_MAX_MAPPENTRIES entries (manual 2.4: 128 /
    /// granularity) is a mapping like any other: the fields are checked
    /// entry by entry, up to the last one.
    // req: M-2.12.1-STATIC-FIELDS
    #[cfg(feature = "srdo-granularity-16")]
    #[test]
    fn fields_of_a_mapping_with_the_most_entries() {
        assert_eq!(crate::config::SRDO_MAX_MAPPENTRIES, 8);
        let (_g, od, mut srdo) = setup_parts(&FULL, &FULL_DEVICE);
        assert_eq!(srdo.mapped_len(&od, 0x1301), Ok(8));
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &FULL_N, &FULL_I),
            Ok(())
        );
        assert_eq!(
            srdo.static_define_var_fields(&od, 0x1301, &FULL_N, &FULL_N),
            Err(CopKernel::SrdoErrorMapp),
            "the inverted entries are not in the normal field"
        );
    }

    // req: M-2.12.1-STATIC-FIELDS
    #[test]
    fn active_srdo_without_fields_fails_the_check() {
        let (_g, od, mut srdo) = setup();
        set(&od, 0x1302, 1, 1);
        seal(&od, &srdo);
        assert_eq!(
            srdo.check_config_with(&od, 8),
            Err((CopKernel::SrdoErrorMapp, 0x1302))
        );
        srdo.static_define_var_fields(&od, 0x1302, &NORMAL[0..2], &NORMAL[2..4])
            .unwrap_err();
        // 0x1382 maps 0x6200 sub 1..4: normal sub 1 and 3, inverted 2 and 4,
        // which are not contiguous fields.
        assert!(srdo.check_config_with(&od, 8).is_err());
    }
}

/// 64 receive SRDOs: dispatch, overrun and timer steps keep the action
/// queue small (it holds 16 actions) and nothing is lost.
#[cfg(not(srdo_static_mapping))]
mod sixty_four {
    use super::*;
    use crate::od::ObdSubEntry;
    use crate::srdo::objects::{
        COMMU_SUBS, CommuDefaults, CommuVars, MAPP_SUBS, MappDefaults, MappVars, commu_subs,
        crc_subs, mapp_subs,
    };

    const N: usize = 64;
    const PH: ObdSubEntry = ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[0]);
    const PE: ObdEntry = ObdEntry::new(0, &[], None);

    static CV: [CommuVars; N] = [const { CommuVars::new() }; N];
    static MV: [MappVars; N] = [const { MappVars::new() }; N];
    static MD: MappDefaults = MappDefaults::new(&[0x6201_0110, 0x6301_0110]);
    static CD: [CommuDefaults; N] = commu_defaults();
    static CS: [[ObdSubEntry; COMMU_SUBS]; N] = commu_tables();
    static MS: [[ObdSubEntry; MAPP_SUBS]; N] = mapp_tables();
    static CRC_COUNT: [u8; 1] = [N as u8];
    static CRC_VARS: [AtomicU8; 2 * N] = decl::zeroed();
    static CRC_DEF: [u8; 2 * N] = [0; 2 * N];
    static CRC_SUBS: [ObdSubEntry; N + 1] = crc_subs::<{ N + 1 }>(&CRC_COUNT, &CRC_VARS, &CRC_DEF);
    crate::obd_create_srdo_cfg_valid!(mod valid64);
    static GENERIC64: [ObdEntry; 2 * N + 2] = generic();

    /// SRDO n (1..=64) receives on the predefined COB-IDs of node n.
    const fn commu_defaults() -> [CommuDefaults; N] {
        let mut a = [const { CommuDefaults::new(0, 0, 0, 0, 0) }; N];
        let mut i = 0;
        while i < N {
            let ids = match wire::SrdoCobIds::predefined(i as u8 + 1) {
                Some(ids) => ids,
                None => panic!("node out of range"),
            };
            a[i] = CommuDefaults::new(2, 25, 20, ids.normal() as u32, ids.inverted() as u32);
            i += 1;
        }
        a
    }

    const fn commu_tables() -> [[ObdSubEntry; COMMU_SUBS]; N] {
        let mut a = [const { [PH; COMMU_SUBS] }; N];
        let mut i = 0;
        while i < N {
            a[i] = commu_subs(&CV[i], &CD[i]);
            i += 1;
        }
        a
    }

    const fn mapp_tables() -> [[ObdSubEntry; MAPP_SUBS]; N] {
        let mut a = [const { [PH; MAPP_SUBS] }; N];
        let mut i = 0;
        while i < N {
            a[i] = mapp_subs(&MV[i], &MD);
            i += 1;
        }
        a
    }

    const fn generic() -> [ObdEntry; 2 * N + 2] {
        let mut a = [PE; 2 * N + 2];
        let mut i = 0;
        while i < N {
            a[i] = ObdEntry::new(0x1301 + i as u16, &CS[i], None);
            a[N + i] = ObdEntry::new(0x1381 + i as u16, &MS[i], None);
            i += 1;
        }
        a[2 * N] = crate::srdo_obd_entry!(valid64);
        a[2 * N + 1] = ObdEntry::new(CRC_INDEX, &CRC_SUBS, None);
        a
    }

    // req: M-1.5-SIXTYFOUR
    #[test]
    fn sixty_four_receive_srdos() {
        let (_g, od, mut srdo) = setup_with(&GENERIC64);
        assert_eq!(srdo.count(), 64);
        seal(&od, &srdo);
        assert_eq!(srdo.check_config(&od), Ok(()));
        srdo.on_state(&od, NmtState::Operational, 70, Ticks(0));
        assert!(srdo.is_running());

        // Constant-time dispatch: the last SRDO's pair (node 64: 0x17F/0x180).
        let mut q = ActionQueue::new();
        srdo.on_frame(NmtState::Operational, &rx(0x17F, &[7, 0], 5), &mut q);
        srdo.on_frame(NmtState::Operational, &rx(0x180, &[0xF8, 0xFF], 6), &mut q);
        assert_eq!(
            run(&mut srdo, &mut q, manual_app)[0],
            Event::SrdoEvent(0x1340)
        );
        assert_eq!(get(&od, 0x6201, 1), 7);

        // Overrun: one SRDO per step, at most two actions each.
        assert_eq!(overruns(&mut srdo), (0x1301..=0x1340).collect::<Vec<u16>>());

        // Every SCT expires in the same cycle (SRDO 64 was re-armed at 5).
        srdo.begin_cycle();
        let mut timeouts = Vec::new();
        let mut steps = 0;
        loop {
            let done = srdo.poll(NmtState::Operational, Ticks(251), &mut q);
            assert!(q.len() <= 5, "one step queues at most five actions");
            steps += 1;
            timeouts.extend(run(&mut srdo, &mut q, manual_app).into_iter().filter_map(
                |e| match e {
                    Event::SrdoError(idx, CopKernel::SrdoSctTimeout) => Some(idx),
                    _ => None,
                },
            ));
            if done {
                break;
            }
        }
        assert_eq!(timeouts, (0x1301..=0x133F).collect::<Vec<u16>>());
        assert!(steps >= 63);
    }
}

/// SAFETY_BEHAVIOUR.md section 6: an id 0x001 with DLC 0 while 0x1300 == 1
/// calls `AppGfcEvent`, anything else is ignored and counted; in STOPPED
/// (CiA 301 7.3.2.2: only NMT and error control) and before
/// `CcmConnectToNet` not even a valid GFC is reported. The stack drops such
/// frames before the module (tests/srdo_nmt_gfc.rs); the module keeps the
/// rule on its own.
// req: M-1.3-GFC, SB-5-FOREIGN
#[test]
fn gfc_is_reported_only_pre_operational_and_operational() {
    let (_g, od, mut srdo) = setup();
    set(&od, GFC_PARAM_INDEX, 0, 1);
    srdo.init(&od).unwrap();
    let gfc = crate::config::SRDO_USE_GFC;
    let cases: [(NmtState, &[u8], bool); 5] = [
        (NmtState::Stopped, &[], false),
        (NmtState::Initialisation, &[], false),
        (NmtState::PreOperational, &[], true),
        (NmtState::Operational, &[], true),
        (NmtState::Operational, &[0], false),
    ];
    for (state, data, reported) in cases {
        let mut q = ActionQueue::new();
        let taken = srdo.on_frame(state, &rx(0x001, data, 0), &mut q);
        assert_eq!(
            taken, gfc,
            "{state:?}: a GFC frame exactly when GFC is built in"
        );
        let ev = run(&mut srdo, &mut q, |_, _| None);
        let expected = if gfc && reported {
            vec![Event::Gfc]
        } else {
            vec![]
        };
        assert_eq!(ev, expected, "{state:?}, DLC {}", data.len());
    }
    // Other identifiers (NMT, SYNC, a TPDO, a heartbeat; no SRDO runs) are
    // neither an SRDO nor a GFC: offered on, not counted (section 5:
    // identifiers of no active SRDO are ignored).
    for id in [0x000, 0x080, 0x181, 0x701] {
        let mut q = ActionQueue::new();
        let taken = srdo.on_frame(NmtState::Operational, &rx(id, &[], 0), &mut q);
        assert!(!taken, "{id:#x} is not the module's");
        assert!(run(&mut srdo, &mut q, |_, _| None).is_empty(), "{id:#x}");
    }
    assert_eq!(srdo.gfc_ignored(), if gfc { 3 } else { 0 });
}

/// The SRDO write hook (manual 2.8.2: the SRDO objects are written only
/// outside OPERATIONAL) decides only for the SRDO objects it found: a write
/// to another object passes it in every state, while the same write to an
/// SRDO object is refused in OPERATIONAL.
#[test]
fn write_hook_decides_only_for_srdo_objects() {
    let (_g, od, srdo) = setup();
    let stage = |index: u16, sub: u8, value: &[u8]| {
        let obj = od.find(index, sub).unwrap();
        let staged = od.stage(&obj, crate::od::ByteOrder::Wire, value).unwrap();
        (obj, staged)
    };
    let (other, v) = stage(0x6201, 1, &[1, 0]);
    for state in [
        NmtState::PreOperational,
        NmtState::Operational,
        NmtState::Stopped,
    ] {
        assert_eq!(
            srdo.check_write(&od, &other, &v, state),
            Ok(()),
            "{state:?}"
        );
    }
    let (sct, v) = stage(0x1301, 2, &[30, 0]);
    assert_eq!(
        srdo.check_write(&od, &sct, &v, NmtState::PreOperational),
        Ok(())
    );
    assert_eq!(
        srdo.check_write(&od, &sct, &v, NmtState::Operational)
            .map_err(|e| e.kernel),
        Err(CopKernel::SrdoNmtError)
    );
}

/// The subindex tables of the `OBD_CREATE_SRDO_*` equivalents: the macros'
/// parameters as manual 2.10.1 describes them, the objects as
/// SAFETY_BEHAVIOUR.md section 1 and the table of src/srdo/objects.rs lay
/// them out (sub 4 and, with static mapping, the mapping constant). The
/// dictionaries build these tables at compile time; here they are built at
/// run time from the same functions, and the default builders (const
/// functions the statics run at compile time) also run at run time, with
/// inputs the compiler cannot know, giving the same defaults.
// req: M-2.10.1-MACROS
#[test]
fn srdo_object_tables_as_the_macros_declare_them() {
    use super::objects::*;
    use crate::config::SRDO_USE_STATIC_MAPPING;
    use core::hint::black_box;
    use std::sync::OnceLock;
    // Statics, as the dictionaries declare them (no leaked heap, which Miri
    // would report).
    static VARS: CommuVars = CommuVars::new();
    static COMMU_DEFAULTS: CommuDefaults = CommuDefaults::new(1, 30, 15, 0x101, 0x102);
    static MVARS: MappVars = MappVars::new();
    static MAPP_DEFAULTS: MappDefaults = MappDefaults::new(&[0x6200_0108, 0x6300_0108]);
    static BYTE: [AtomicU8; 1] = decl::zeroed::<1>();
    static CRC_VARS: [AtomicU8; 6] = decl::zeroed::<6>();
    static CRC_DEFAULTS: [u8; 6] = crc_defaults::<6>(&[0x1234, 0xABCD, 0]);
    static COMMU_RUN: OnceLock<CommuDefaults> = OnceLock::new();
    static MAPP_RUN: OnceLock<MappDefaults> = OnceLock::new();
    static EMPTY_RUN: OnceLock<MappDefaults> = OnceLock::new();
    type Row = (u8, DataType, Access, Option<Vec<u8>>);
    let rows = |subs: &[ObdSubEntry]| -> Vec<Row> {
        subs.iter()
            .map(|s| {
                let default = s.default_value().map(<[u8]>::to_vec);
                (s.sub(), s.data_type().unwrap(), s.access(), default)
            })
            .collect()
    };
    let (u8_, u16_, u32_) = (DataType::UInt8, DataType::UInt16, DataType::UInt32);
    let ne16 = |v: u16| Some(v.to_ne_bytes().to_vec());
    let ne32 = |v: u32| Some(v.to_ne_bytes().to_vec());
    // OBD_CREATE_SRDO_COMMU(ind, num, dir 1, sct 30, srvt 15, 0x101, 0x102).
    let vars = &VARS;
    let commu = commu_subs(vars, &COMMU_DEFAULTS);
    assert_eq!(
        rows(&commu),
        [
            (0, u8_, Access::CR, Some(vec![6])),
            (1, u8_, Access::SRW, Some(vec![1])),
            (2, u16_, Access::SRW, ne16(30)),
            (3, u8_, Access::SRW, Some(vec![15])),
            (4, u8_, Access::CR, Some(vec![254])),
            (5, u32_, Access::SRW, ne32(0x101)),
            (6, u32_, Access::SRW, ne32(0x102)),
        ]
    );
    let run = COMMU_RUN.get_or_init(|| {
        CommuDefaults::new(black_box(1), black_box(30), black_box(15), 0x101, 0x102)
    });
    assert_eq!(
        rows(&commu_subs(vars, run)),
        rows(&commu),
        "built at run time"
    );
    let var_of = |s: &ObdSubEntry| s.ram_var(0).map(<[AtomicU8]>::as_ptr);
    assert_eq!(var_of(&commu[1]), Some(vars.direction.as_ptr()));
    assert_eq!(var_of(&commu[2]), Some(vars.sct.as_ptr()));
    assert_eq!(var_of(&commu[3]), Some(vars.srvt.as_ptr()));
    assert_eq!(var_of(&commu[4]), None, "a constant");
    assert_eq!(var_of(&commu[5]), Some(vars.cob1.as_ptr()));
    assert_eq!(var_of(&commu[6]), Some(vars.cob2.as_ptr()));
    // OBD_BEGIN_SRDO_MAPP(ind, num, cnt 2) with two entries; the subindices
    // up to SRDO_MAX_MAPPENTRIES exist with 0.
    let mvars = &MVARS;
    let mapp = mapp_subs(mvars, &MAPP_DEFAULTS);
    let access = if SRDO_USE_STATIC_MAPPING {
        Access::CR
    } else {
        Access::SRW
    };
    let mut expected = vec![
        (0, u8_, access, Some(vec![2])),
        (1, u32_, access, ne32(0x6200_0108)),
        (2, u32_, access, ne32(0x6300_0108)),
    ];
    expected.extend(
        (3..=crate::config::SRDO_MAX_MAPPENTRIES as u8).map(|sub| (sub, u32_, access, ne32(0))),
    );
    assert_eq!(rows(&mapp), expected);
    let run = MAPP_RUN.get_or_init(|| MappDefaults::new(black_box(&[0x6200_0108, 0x6300_0108])));
    assert_eq!(rows(&mapp_subs(mvars, run)), expected, "built at run time");
    // No entry: the count 0, every entry 0.
    let empty = EMPTY_RUN.get_or_init(|| MappDefaults::new(black_box(&[])));
    let mut expected = vec![(0, u8_, access, Some(vec![0]))];
    expected.extend(
        (1..=crate::config::SRDO_MAX_MAPPENTRIES as u8).map(|sub| (sub, u32_, access, ne32(0))),
    );
    assert_eq!(rows(&mapp_subs(mvars, empty)), expected);
    let mapped_var = (!SRDO_USE_STATIC_MAPPING).then(|| mvars.entries[4..].as_ptr());
    assert_eq!(var_of(&mapp[2]), mapped_var);
    // OBD_CREATE_SRDO_GFC_PARAM(), OBD_CREATE_SRDO_CFG_VALID(): U8 rw 0.
    let byte = &BYTE;
    for subs in [gfc_param_subs(byte), cfg_valid_subs(byte)] {
        assert_eq!(rows(&subs), [(0, u8_, Access::RW, Some(vec![0]))]);
        assert_eq!(var_of(&subs[0]), Some(byte.as_ptr()));
    }
    // OBD_BEGIN_SRDO_CRC(cnt 3): sub 0 the count, one U16 rw per SRDO.
    let crc_vars = &CRC_VARS;
    let crc = crc_subs::<4>(&[3], crc_vars, &CRC_DEFAULTS);
    assert_eq!(
        rows(&crc),
        [
            (0, u8_, Access::CR, Some(vec![3])),
            (1, u16_, Access::RW, ne16(0x1234)),
            (2, u16_, Access::RW, ne16(0xABCD)),
            (3, u16_, Access::RW, ne16(0)),
        ]
    );
    assert_eq!(var_of(&crc[3]), Some(crc_vars[4..].as_ptr()));
    assert_eq!(
        crc_defaults::<4>(&[0x1234, 0x5678]),
        [0x1234u16.to_ne_bytes(), 0x5678u16.to_ne_bytes()].concat()[..]
    );
}

/// The defaults of the CRC object have exactly two bytes per listed CRC:
/// another length is refused (at compile time in the declaration macro)
/// instead of cutting CRCs off or adding zeros.
// req: M-2.10.1-MACROS
#[test]
#[should_panic(expected = "two bytes per CRC entry")]
fn crc_defaults_of_another_length_are_refused() {
    let _ = crate::srdo::objects::crc_defaults::<2>(&[0x1234, 0x5678]);
}

#[test]
fn default_is_a_module_without_srdos() {
    let d = Srdo::default();
    assert_eq!(d.count(), 0);
    assert_eq!(d.commu_indices().count(), 0);
    assert!(!d.is_running());
    assert_eq!(d.gfc_ignored(), 0);
}
