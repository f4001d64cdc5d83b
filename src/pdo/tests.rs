//! Unit tests of the PDO rules and the payload conversion, on a small
//! dictionary declared here. Byte layouts follow CiA 301 §7.2.2 (mapping,
//! LSB first) and §7.5.2.35–38 (parameter objects).

use core::sync::atomic::AtomicU8;

use super::decl::{CommuDefaults, CommuVars, commu_subs};
use super::mapping::{Rules, check_entry, check_mapping, check_write, refuse};
use super::*;
use crate::od::{Access, DataType, NoHooks, ObdEntry, ObdSubEntry, decl as od_decl};

crate::pdo_commu!(static S1400, V1400 = 0x8000_0200, 255, 0, 0);
crate::pdo_mapp!(static S1600, V1600 = [0x2000_0108, 0x2000_0210]);
static V1800: CommuVars = CommuVars::new();
// The predefined connection set base: the node-ID is added.
static D1800: CommuDefaults = CommuDefaults::new(0x180, 255, 0, 0);
static S1800: [ObdSubEntry; 5] = commu_subs(&V1800, &D1800);
crate::pdo_mapp!(static S1A00, V1A00 = [0x2000_0108, 0x2000_0210, 0x2000_0320]);

static U8V: [AtomicU8; 1] = od_decl::zeroed();
static U16V: [AtomicU8; 2] = od_decl::zeroed();
static U32V: [AtomicU8; 4] = od_decl::zeroed();
static B1: [AtomicU8; 1] = od_decl::zeroed();
static PLAIN: [AtomicU8; 1] = od_decl::zeroed();
static RO: [AtomicU8; 1] = od_decl::zeroed();
static RANGED: [AtomicU8; 2] = od_decl::zeroed();
static RANGED_LIMITS: [u8; 6] = od_decl::limits(
    0i16.to_ne_bytes(),
    (-100i16).to_ne_bytes(),
    100i16.to_ne_bytes(),
);
static B2: [AtomicU8; 1] = od_decl::zeroed();
static TEXT: [AtomicU8; 5] = od_decl::zeroed();
static S2000: [ObdSubEntry; 10] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[9]),
    ObdSubEntry::ram(1, DataType::UInt8, Access::PRW, &U8V, None),
    ObdSubEntry::ram(2, DataType::UInt16, Access::PRW, &U16V, None),
    ObdSubEntry::ram(3, DataType::UInt32, Access::PRW, &U32V, None),
    ObdSubEntry::ram(4, DataType::Bool, Access::PRW, &B1, None),
    ObdSubEntry::ram(5, DataType::UInt8, Access::RW, &PLAIN, None),
    ObdSubEntry::ram(6, DataType::UInt8, Access::PR, &RO, None),
    ObdSubEntry::ram_range(7, DataType::Int16, Access::PRW, &RANGED, &RANGED_LIMITS),
    ObdSubEntry::ram(8, DataType::Bool, Access::PRW, &B2, None),
    ObdSubEntry::ram_string(9, Access::PRW, &TEXT, c""),
];

crate::od_ram!(static S1005, SYNC_COB: u32 = 0x80 => UInt32, SRW);
crate::od_ram!(static S1007, SYNC_WINDOW: u32 = 0 => UInt32, SRW);

static GENERIC: [ObdEntry; 6] = [
    ObdEntry::new(0x1005, &S1005, None),
    ObdEntry::new(0x1007, &S1007, None),
    ObdEntry::new(0x1400, &S1400, None),
    ObdEntry::new(0x1600, &S1600, None),
    ObdEntry::new(0x1800, &S1800, None),
    ObdEntry::new(0x1A00, &S1A00, None),
];
static MANUFACTURER: [ObdEntry; 1] = [ObdEntry::new(0x2000, &S2000, None)];

static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// The dictionary with its defaults restored (tests share its statics and
/// hold the lock).
fn fresh() -> (std::sync::MutexGuard<'static, ()>, ObjectDictionary) {
    let g = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let od = ObjectDictionary::new(&GENERIC, &MANUFACTURER, &[]).unwrap();
    od.restore_defaults(0x1000, 0xFFFF);
    (g, od)
}

/// [`fresh`] with TPDO 1 valid at 0x181.
fn tpdo_1_valid() -> (std::sync::MutexGuard<'static, ()>, ObjectDictionary) {
    let (g, od) = fresh();
    od.poke_uint(0x1800, 1, 0x181).unwrap();
    (g, od)
}

const BITS: Rules = Rules {
    bit_mapping: true,
    dummy: true,
};
const BYTES: Rules = Rules {
    bit_mapping: false,
    dummy: true,
};

#[test]
fn entries_must_name_mappable_objects_of_the_right_length() {
    let (_g, od) = fresh();
    let tx = Direction::Tx;
    let rx = Direction::Rx;
    assert_eq!(check_entry(&od, tx, 0x2000_0108, BYTES), Ok(8));
    assert_eq!(check_entry(&od, tx, 0x2000_0320, BYTES), Ok(32));
    // CiA 301 §7.5.2.36 abort codes: object / subindex missing.
    assert_eq!(
        check_entry(&od, tx, 0x2100_0108, BYTES),
        Err(refuse::NO_OBJECT)
    );
    assert_eq!(refuse::NO_OBJECT.abort, 0x0602_0000);
    assert_eq!(
        check_entry(&od, tx, 0x2000_1508, BYTES),
        Err(refuse::NO_SUBINDEX)
    );
    assert_eq!(refuse::NO_SUBINDEX.abort, 0x0609_0011);
    // Not kObdAccPdo: 0x06040041.
    assert_eq!(
        check_entry(&od, tx, 0x2000_0508, BYTES),
        Err(refuse::NOT_MAPPABLE)
    );
    assert_eq!(refuse::NOT_MAPPABLE.abort, 0x0604_0041);
    // Read-only: fine for a TPDO, not for an RPDO.
    assert_eq!(check_entry(&od, tx, 0x2000_0608, BYTES), Ok(8));
    assert_eq!(
        check_entry(&od, rx, 0x2000_0608, BYTES),
        Err(refuse::NOT_MAPPABLE)
    );
    // Length must be the type's.
    assert_eq!(
        check_entry(&od, tx, 0x2000_0210, BYTES),
        Ok(16),
        "UNSIGNED16 with 16 bits"
    );
    assert_eq!(
        check_entry(&od, tx, 0x2000_0208, BYTES),
        Err(refuse::NOT_MAPPABLE)
    );
    assert_eq!(
        check_entry(&od, tx, 0x2000_020C, BYTES),
        Err(refuse::GRANULARITY)
    );
    assert_eq!(
        check_entry(&od, tx, 0x2000_020C, BITS),
        Err(refuse::NOT_MAPPABLE)
    );
    assert_eq!(
        check_entry(&od, tx, 0x2000_0148, BYTES),
        Err(refuse::LENGTH),
        "72 bits"
    );
    // Strings are not mappable here.
    assert_eq!(
        check_entry(&od, tx, 0x2000_0928, BYTES),
        Err(refuse::NOT_MAPPABLE)
    );
    assert_eq!(check_entry(&od, tx, 0, BYTES), Err(refuse::NOT_MAPPABLE));
}

#[test]
fn boolean_bit_mapping_depends_on_the_switch() {
    let (_g, od) = fresh();
    // seed 003 ch. 4: PDO_USE_BIT_MAPPING allows BOOLEANs as single bits.
    assert_eq!(check_entry(&od, Direction::Tx, 0x2000_0401, BITS), Ok(1));
    assert_eq!(
        check_entry(&od, Direction::Tx, 0x2000_0401, BYTES),
        Err(refuse::GRANULARITY)
    );
    assert_eq!(
        refuse::GRANULARITY.kernel,
        CopKernel::PdoGranularityMismatch
    );
    // A BOOLEAN as a whole byte is always accepted.
    assert_eq!(check_entry(&od, Direction::Rx, 0x2000_0408, BYTES), Ok(8));
}

#[test]
fn dummy_entries_only_in_rpdos() {
    let (_g, od) = fresh();
    // CiA 301 §7.5.2.36: 0x00050008 maps an UNSIGNED8 place holder.
    assert_eq!(check_entry(&od, Direction::Rx, 0x0005_0008, BYTES), Ok(8));
    assert_eq!(check_entry(&od, Direction::Rx, 0x0007_0020, BYTES), Ok(32));
    assert_eq!(check_entry(&od, Direction::Rx, 0x0001_0001, BITS), Ok(1));
    assert_eq!(
        check_entry(&od, Direction::Tx, 0x0005_0008, BYTES),
        Err(refuse::NOT_MAPPABLE)
    );
    let no_dummy = Rules {
        bit_mapping: false,
        dummy: false,
    };
    assert_eq!(
        check_entry(&od, Direction::Rx, 0x0005_0008, no_dummy),
        Err(refuse::NOT_MAPPABLE)
    );
    assert_eq!(
        check_entry(&od, Direction::Rx, 0x0005_0010, BYTES),
        Err(refuse::NOT_MAPPABLE),
        "length of an UNSIGNED8 place holder"
    );
}

#[test]
fn a_mapping_carries_at_most_64_bits() {
    let (_g, od) = fresh();
    let tx = Direction::Tx;
    assert_eq!(
        check_mapping(&od, tx, &[0x2000_0320, 0x2000_0320], BYTES),
        Ok(64)
    );
    let e = check_mapping(&od, tx, &[0x2000_0320, 0x2000_0320, 0x2000_0108], BYTES);
    assert_eq!(e, Err(refuse::LENGTH));
    assert_eq!(refuse::LENGTH.abort, 0x0604_0042);
    let many = [0x2000_0108u32; PDO_MAX_MAPPENTRIES + 1];
    assert_eq!(check_mapping(&od, tx, &many, BITS), Err(refuse::LENGTH));
}

fn write(od: &ObjectDictionary, index: u16, sub: u8, v: u64) -> Result<(), OdError> {
    let obj = od.find(index, sub)?;
    let wire = obj.data_type().wire_size().unwrap_or(4);
    let bytes = v.to_le_bytes();
    let staged = od.stage(&obj, ByteOrder::Wire, &bytes[..wire])?;
    check_write(od, &obj, &staged, BITS)?;
    od.write(index, sub, ByteOrder::Wire, &bytes[..wire], &mut NoHooks)
}

#[test]
fn cia301_mapping_procedure() {
    let (_g, od) = tpdo_1_valid();
    // Step 1 missing: the PDO is valid, the mapping stays as it is.
    assert_eq!(write(&od, 0x1A00, 0, 0), Err(refuse::STATE));
    assert_eq!(refuse::STATE.abort, 0x0800_0022);
    assert_eq!(od.read_uint(0x1A00, 0), Ok(3));
    // Step 1: destroy the PDO.
    write(&od, 0x1800, 1, 0x8000_0181).unwrap();
    // Step 3 before step 2: sub 0 is not 0.
    assert_eq!(write(&od, 0x1A00, 1, 0x2000_0210), Err(refuse::STATE));
    // Step 2, then step 3 with one bad and one good entry.
    write(&od, 0x1A00, 0, 0).unwrap();
    assert_eq!(
        write(&od, 0x1A00, 1, 0x2000_0508),
        Err(refuse::NOT_MAPPABLE)
    );
    assert_eq!(od.read_uint(0x1A00, 1), Ok(0x2000_0108), "unchanged");
    write(&od, 0x1A00, 1, 0x2000_0320).unwrap();
    write(&od, 0x1A00, 2, 0x2000_0320).unwrap();
    write(&od, 0x1A00, 3, 0x2000_0108).unwrap();
    // Step 4: three entries would be 72 bits.
    assert_eq!(write(&od, 0x1A00, 0, 3), Err(refuse::LENGTH));
    // One entry more than the PDO has (9 at granularity 8).
    let too_many = PDO_MAX_MAPPENTRIES as u64 + 1;
    assert_eq!(write(&od, 0x1A00, 0, too_many), Err(refuse::LENGTH));
    assert_eq!(od.read_uint(0x1A00, 0), Ok(0));
    write(&od, 0x1A00, 0, 2).unwrap();
    // Step 5: create the PDO again.
    write(&od, 0x1800, 1, 0x181).unwrap();
    assert_eq!(od.read_uint(0x1800, 1), Ok(0x181));
}

#[test]
fn communication_parameter_rules() {
    let (_g, od) = tpdo_1_valid();
    // CiA 301 §7.5.2.37: bits 0-29 do not change while valid; bit 30
    // (remote requests) may.
    assert_eq!(write(&od, 0x1800, 1, 0x182), Err(refuse::INVALID));
    assert_eq!(refuse::INVALID.abort, 0x0609_0030);
    assert_eq!(write(&od, 0x1800, 1, 0x4000_0182), Err(refuse::INVALID));
    write(&od, 0x1800, 1, 0x4000_0181).unwrap();
    write(&od, 0x1800, 1, 0x181).unwrap();
    // Inhibit time only while invalid.
    assert_eq!(write(&od, 0x1800, 3, 10), Err(refuse::INVALID));
    // Transmission types 241..=251 are reserved.
    assert_eq!(write(&od, 0x1800, 2, 241), Err(refuse::INVALID));
    write(&od, 0x1800, 2, 252).unwrap();
    write(&od, 0x1800, 5, 100).unwrap();
    // Invalid: the identifier and the inhibit time may change.
    write(&od, 0x1800, 1, 0x8000_0181).unwrap();
    write(&od, 0x1800, 3, 10).unwrap();
    // Restricted identifiers (CiA 301 §7.3.5) cannot be made valid.
    for bad in [0x701u64, 0x601, 0x000, 0x7FF, 0x800] {
        assert_eq!(write(&od, 0x1800, 1, bad), Err(refuse::INVALID), "{bad:#x}");
    }
    // 29-bit identifiers need a CAN 2.0B driver.
    let ext = write(&od, 0x1800, 1, 0x2000_0181);
    assert_eq!(ext.is_ok(), crate::config::CDRV_CAN20B);
    // RPDOs: 252/253 are reserved.
    assert_eq!(write(&od, 0x1400, 2, 252), Err(refuse::INVALID));
    write(&od, 0x1400, 2, 0).unwrap();
    write(&od, 0x1400, 2, 254).unwrap();
}

#[test]
fn a_pdo_cannot_become_valid_with_a_bad_default_mapping() {
    let (_g, od) = fresh();
    od.poke_uint(0x1600, 1, 0x2000_0508).unwrap(); // not mappable
    assert_eq!(write(&od, 0x1400, 1, 0x201), Err(refuse::NOT_MAPPABLE));
    od.poke_uint(0x1600, 1, 0x2000_0108).unwrap();
    write(&od, 0x1400, 1, 0x201).unwrap();
}

#[test]
fn sync_cob_id_rules() {
    let (_g, od) = fresh();
    // CiA 301 §7.5.2.5: bit 30 = "generate SYNC" (this node produces);
    // restricted identifiers are refused with 0x06090030, also with bit 30.
    assert_eq!(write(&od, 0x1005, 0, 0x701), Err(refuse::INVALID));
    assert_eq!(write(&od, 0x1005, 0, 0x4000_0701), Err(refuse::INVALID));
    assert_eq!(od.read_uint(0x1005, 0), Ok(0x80));
    write(&od, 0x1005, 0, 0x4000_0080).unwrap();
    write(&od, 0x1005, 0, 0x80).unwrap();
    // Bit 31 is "do not care".
    write(&od, 0x1005, 0, 0x8000_0081).unwrap();
    write(&od, 0x1005, 0, 0x81).unwrap();
    write(&od, 0x1007, 0, 5000).unwrap();
}

fn channel<W: Watching>(od: &ObjectDictionary, dir: Direction, entries: &[u32]) -> Channel<W> {
    let mut ch = Channel::new();
    ch.cfg.present = true;
    ch.cfg.cob = Some(CanId::std_masked(0x181));
    ch.cfg.count = entries.len();
    for (d, s) in ch.cfg.entries.iter_mut().zip(entries) {
        *d = *s;
    }
    ch.cfg.total_bits = check_mapping(od, dir, entries, BITS).unwrap();
    ch.cfg.mapping_ok = true;
    ch
}

#[test]
fn tpdo_payload_is_packed_lsb_first() {
    let (_g, od) = fresh();
    od.poke_uint(0x2000, 1, 0xAB).unwrap();
    od.poke_uint(0x2000, 2, 0x1234).unwrap();
    od.poke_uint(0x2000, 3, 0xDEAD_BEEF).unwrap();
    let ch = channel(&od, Direction::Tx, &[0x2000_0108, 0x2000_0210, 0x2000_0320]);
    let p = sample(&od, &ch).unwrap();
    // CiA 301 §7.2.2: objects in mapping order, each little-endian.
    assert_eq!(p.bytes(), &[0xAB, 0x34, 0x12, 0xEF, 0xBE, 0xAD, 0xDE]);

    // Bits: BOOLEAN 1, BOOLEAN 0, then the UNSIGNED8 from bit 2.
    od.poke_uint(0x2000, 4, 1).unwrap();
    od.poke_uint(0x2000, 8, 0).unwrap();
    let ch = channel(&od, Direction::Tx, &[0x2000_0401, 0x2000_0801, 0x2000_0108]);
    let p = sample(&od, &ch).unwrap();
    assert_eq!(p.bytes(), &[0b1010_1101, 0b10]);
}

#[test]
fn rpdo_payload_reaches_all_variables_or_none() {
    let (_g, od) = fresh();
    let ch = channel(
        &od,
        Direction::Rx,
        &[0x2000_0108, 0x0005_0008, 0x2000_0210, 0x2000_0710],
    );
    let good = Payload {
        data: [0x11, 0xFF, 0x22, 0x33, 0x9C, 0xFF, 0, 0], // -100
        len: 6,
    };
    apply(&od, &ch, &good).unwrap();
    assert_eq!(od.read_uint(0x2000, 1), Ok(0x11));
    assert_eq!(od.read_uint(0x2000, 2), Ok(0x3322));
    assert_eq!(od.read_uint(0x2000, 7), Ok(0xFF9C));
    // 0x2000 sub 7 allows -100..=100: 101 makes the whole PDO be dropped.
    let bad = Payload {
        data: [0x55, 0, 0x66, 0x77, 101, 0, 0, 0],
        len: 6,
    };
    assert_eq!(apply(&od, &ch, &bad), Err(CopKernel::PdoErrorPdoDecode));
    assert_eq!(od.read_uint(0x2000, 1), Ok(0x11), "first object untouched");
    assert_eq!(od.read_uint(0x2000, 2), Ok(0x3322));
    // A BOOLEAN byte must be 0 or 1.
    let ch = channel(&od, Direction::Rx, &[0x2000_0108, 0x2000_0408]);
    let bad = Payload {
        data: [0x42, 2, 0, 0, 0, 0, 0, 0],
        len: 2,
    };
    assert!(apply(&od, &ch, &bad).is_err());
    assert_eq!(od.read_uint(0x2000, 1), Ok(0x11));
}

#[test]
fn rpdo_bits_unpack() {
    let (_g, od) = fresh();
    let ch = channel(&od, Direction::Rx, &[0x2000_0401, 0x0001_0001, 0x2000_0801]);
    let p = Payload {
        data: [0b101, 0, 0, 0, 0, 0, 0, 0],
        len: 1,
    };
    apply(&od, &ch, &p).unwrap();
    assert_eq!(od.read_uint(0x2000, 4), Ok(1));
    assert_eq!(od.read_uint(0x2000, 8), Ok(1));
}

#[test]
fn predefined_connection_set_gets_the_node_id() {
    let (_g, od) = fresh();
    predefined_node_id(&od, Direction::Tx, 0, 5);
    assert_eq!(od.read_uint(0x1800, 1), Ok(0x185));
    // Only once: 0x185 is no longer the default.
    predefined_node_id(&od, Direction::Tx, 0, 5);
    assert_eq!(od.read_uint(0x1800, 1), Ok(0x185));
    // Flags stay: the invalid RPDO 1 default 0x80000200.
    predefined_node_id(&od, Direction::Rx, 0, 5);
    assert_eq!(od.read_uint(0x1400, 1), Ok(0x8000_0205));
    od.poke_uint(0x1400, 1, 0x8000_0207).unwrap();
    predefined_node_id(&od, Direction::Rx, 0, 5);
    assert_eq!(
        od.read_uint(0x1400, 1),
        Ok(0x8000_0207),
        "written value kept"
    );
}

#[test]
fn pdo_index_decoding() {
    let p = PdoIndex::of(0x1A05).unwrap();
    assert_eq!((p.dir, p.role, p.number), (Direction::Tx, Role::Mapp, 5));
    assert_eq!((p.commu(), p.mapp()), (0x1805, 0x1A05));
    let p = PdoIndex::of(0x15FF).unwrap();
    assert_eq!(
        (p.dir, p.role, p.number),
        (Direction::Rx, Role::Commu, 0x1FF)
    );
    assert_eq!(PdoIndex::of(0x1C00), None);
    assert!(handles(0x1005) && handles(0x1007) && handles(0x1BFF));
    assert!(!handles(0x1008) && !handles(0x13FF) && !handles(0x1C00));
    if PDO_GRANULARITY == 8 || !PDO_USE_BIT_MAPPING {
        assert_eq!(PDO_MAX_MAPPENTRIES, 8, "granularity 8 (SYSTEC_API.md §9b)");
    } else {
        assert_eq!(PDO_MAX_MAPPENTRIES, 64, "bit mapping, granularity 64");
    }
}

use crate::port::Recorder;

/// One processing cycle of the module alone; `true` when its work was done.
fn cycle(pdo: &mut Pdo, od: &ObjectDictionary, port: &mut Recorder, now: Ticks) -> bool {
    let mut q = ActionQueue::new();
    let mut emcy = EmcyProducer::new();
    pdo.begin_cycle();
    pdo.poll(od, NmtState::Operational, port, now, &mut q, &mut emcy)
}

#[test]
fn idle_cycles_skip_the_pdos_until_something_changes() {
    let (_g, od) = fresh();
    let mut port = Recorder::default();
    let mut pdo = Pdo::new();
    pdo.reconfigure(&od, 5, &mut port);
    pdo.on_state(NmtState::Operational, Ticks(0));
    // TPDO 0x185, event-driven without event timer: nothing is armed after
    // the first pass, so the next cycles have nothing to do.
    assert!(cycle(&mut pdo, &od, &mut port, Ticks(1)));
    assert!(pdo.quiet);
    assert!(cycle(&mut pdo, &od, &mut port, Ticks(2)));
    assert!(port.0.is_empty());
    // An application event wakes the module: the TPDO goes out in the
    // next cycle, and afterwards the module is quiet again.
    pdo.signal(0x1800).unwrap();
    assert!(!pdo.quiet);
    assert!(cycle(&mut pdo, &od, &mut port, Ticks(3)));
    assert_eq!(port.0.len(), 1);
    assert_eq!(port.0[0].id, CanId::std_masked(0x185));
    assert!(pdo.quiet);
    // An event timer keeps it awake: written over the dictionary hook.
    write(&od, 0x1800, 5, 10).unwrap();
    let obj = od.find(0x1800, 5).unwrap();
    pdo.after_store(&od, &obj, Ticks(3));
    assert!(cycle(&mut pdo, &od, &mut port, Ticks(4)));
    assert!(!pdo.quiet);
    // 10 ms = 100 ticks later the timer sends the TPDO again.
    assert!(cycle(&mut pdo, &od, &mut port, Ticks(104)));
    assert_eq!(port.0.len(), 2);
    // Leaving OPERATIONAL and coming back wakes it as well.
    pdo.on_state(NmtState::PreOperational, Ticks(105));
    assert!(!pdo.quiet);
}
