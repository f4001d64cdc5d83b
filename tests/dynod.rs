//! Whole-stack tests of the dynamic object dictionary (seed manual L-1087d):
//! containers built with `cop::od::dcf::encode`, applied with
//! `DynPool::build` to a stack on the simulated bus, read back through the
//! dictionary and through this library's SDO client and server; PDOs
//! carrying network variables between two nodes; refusals that must leave
//! the dictionary and the PDOs exactly as they were.

mod common;

use core::sync::atomic::{AtomicBool, AtomicU8, Ordering};

use cop::ccm::{NmtCommand, Stack};
use cop::error::CopKernel;
use cop::event::NmtState;
use cop::od::dcf::{EntrySpec, PiParams, encode, encoded_len};
use cop::od::dynamic::DynPool;
use cop::od::table::ObdCbParam;
use cop::od::{Access, ByteOrder, DataType, ObdEntry, ObdSubEntry, ObjectDictionary, decl, event};
use cop::pdo::PDO_MAX_MAPPENTRIES;
use cop::pdo::decl::{CommuDefaults, CommuVars, MappDefaults, MappVars, commu_subs, mapp_subs};
use cop::port::Ticks;
use cop::sdo::client::{Direction, SdocState};
use cop::sim::{SimBus, SimPort};
use cop::wire::sdo::Multiplexer;

/// A node's static dictionary. Each expansion has its own variables and
/// its own pool, so tests never share state.
///
/// | index | content |
/// |---|---|
/// | 0x1000 | U32 const |
/// | 0x1001 | U8 ro error register |
/// | 0x1017 | U16 rw heartbeat, default 0 |
/// | 0x1018 | identity, U32 const |
/// | 0x1400/0x1600 | RPDO 1, invalid, empty mapping |
/// | 0x1800/0x1A00 | TPDO 1, invalid, empty mapping |
/// | 0x2000 | U8 rw mappable |
/// | 0x2010 | U16 rw whose callback refuses writes while `REFUSE` is set |
macro_rules! node {
    ($name:ident) => {
        #[allow(dead_code)]
        mod $name {
            use super::*;

            pub static POOL: DynPool<4096> = DynPool::new();
            pub static REFUSE: AtomicBool = AtomicBool::new(false);

            unsafe extern "C" fn refuse(param: *mut ObdCbParam) -> u32 {
                // SAFETY: the dictionary passes a valid parameter block.
                let p = unsafe { &*param };
                if p.m_ObdEvent == event::PRE_WRITE && REFUSE.load(Ordering::Relaxed) {
                    CopKernel::ObdAccessViolation.code()
                } else {
                    0
                }
            }

            static DEVICE: [u8; 4] = 0x0001_0191u32.to_ne_bytes();
            static S1000: [ObdSubEntry; 1] =
                [ObdSubEntry::rom(0, DataType::UInt32, Access::R, &DEVICE)];
            static ERR: [AtomicU8; 1] = decl::zeroed();
            static S1001: [ObdSubEntry; 1] = [ObdSubEntry::ram(
                0,
                DataType::UInt8,
                Access::R,
                &ERR,
                Some(&[0]),
            )];
            static HB: [AtomicU8; 2] = decl::zeroed();
            static HB_DEF: [u8; 2] = 0u16.to_ne_bytes();
            static S1017: [ObdSubEntry; 1] = [ObdSubEntry::ram(
                0,
                DataType::UInt16,
                Access::SRW,
                &HB,
                Some(&HB_DEF),
            )];
            static VENDOR: [u8; 4] = 0x0000_0123u32.to_ne_bytes();
            static S1018: [ObdSubEntry; 2] = [
                ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
                ObdSubEntry::rom(1, DataType::UInt32, Access::R, &VENDOR),
            ];
            static V1400: CommuVars = CommuVars::new();
            static D1400: CommuDefaults = CommuDefaults::new(0x8000_0200, 255, 0, 0);
            static S1400: [ObdSubEntry; 5] = commu_subs(&V1400, &D1400);
            static V1600: MappVars = MappVars::new();
            static D1600: MappDefaults = MappDefaults::new(&[]);
            static S1600: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1600, &D1600);
            static V1800: CommuVars = CommuVars::new();
            static D1800: CommuDefaults = CommuDefaults::new(0x8000_0180, 255, 0, 0);
            static S1800: [ObdSubEntry; 5] = commu_subs(&V1800, &D1800);
            static V1A00: MappVars = MappVars::new();
            static D1A00: MappDefaults = MappDefaults::new(&[]);
            static S1A00: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1A00, &D1A00);
            static V2000: [AtomicU8; 1] = decl::zeroed();
            static S2000: [ObdSubEntry; 1] = [ObdSubEntry::ram(
                0,
                DataType::UInt8,
                Access::PRW,
                &V2000,
                Some(&[0]),
            )];
            static V2010: [AtomicU8; 2] = decl::zeroed();
            static S2010: [ObdSubEntry; 1] = [ObdSubEntry::ram(
                0,
                DataType::UInt16,
                Access::RW,
                &V2010,
                Some(&[0, 0]),
            )];

            static GENERIC: [ObdEntry; 8] = [
                ObdEntry::new(0x1000, &S1000, None),
                ObdEntry::new(0x1001, &S1001, None),
                ObdEntry::new(0x1017, &S1017, None),
                ObdEntry::new(0x1018, &S1018, None),
                ObdEntry::new(0x1400, &S1400, None),
                ObdEntry::new(0x1600, &S1600, None),
                ObdEntry::new(0x1800, &S1800, None),
                ObdEntry::new(0x1A00, &S1A00, None),
            ];
            static MANUFACTURER: [ObdEntry; 2] = [
                ObdEntry::new(0x2000, &S2000, None),
                ObdEntry::new(0x2010, &S2010, Some(refuse)),
            ];

            pub fn od() -> ObjectDictionary {
                ObjectDictionary::new(&GENERIC, &MANUFACTURER, &[]).unwrap()
            }
        }
    };
}

/// One node on the bus.
struct Node {
    stack: Stack,
    port: SimPort,
}

impl Node {
    fn new(bus: &SimBus, od: ObjectDictionary, id: u8) -> Node {
        let (port, stack) = common::attach(bus, od, id, 64);
        Node { stack, port }
    }

    /// A node with node-ID 1 on a bus of its own.
    fn alone(od: ObjectDictionary) -> Node {
        Node::new(&SimBus::new(), od, 1)
    }

    fn now(&self) -> Ticks {
        self.port.bus().now()
    }

    /// Runs the stack's pending work without taking frames; drops the
    /// events.
    fn drain(&mut self) {
        let now = self.now();
        while self.stack.drain(&mut self.port, now).is_some() {}
    }

    fn build<const N: usize>(
        &mut self,
        pool: &'static DynPool<N>,
        c: &[u8],
        image: Option<&'static [AtomicU8]>,
    ) -> Result<cop::od::dynamic::BuildInfo, CopKernel> {
        let now = self.now();
        let r = pool.build(&mut self.stack, &mut self.port, now, c, image);
        self.drain();
        r
    }

    /// Builds `c`, expecting the refusal `code` that leaves the node as
    /// `before` and `pool` free.
    #[track_caller]
    fn refused<const N: usize>(
        &mut self,
        pool: &'static DynPool<N>,
        c: &[u8],
        image: Option<&'static [AtomicU8]>,
        code: CopKernel,
        before: &Snapshot,
    ) {
        assert_eq!(self.build(pool, c, image), Err(code));
        assert_eq!(&snapshot(&self.stack), before);
        assert!(!pool.is_in_use());
    }

    fn destroy<const N: usize>(&mut self, pool: &'static DynPool<N>) {
        let now = self.now();
        pool.destroy(&mut self.stack, &mut self.port, now).unwrap();
        self.drain();
    }

    fn read(&self, index: u16, sub: u8) -> Vec<u8> {
        let mut b = [0u8; 256];
        let n = self
            .stack
            .read_object(index, sub, ByteOrder::Wire, &mut b)
            .unwrap_or_else(|e| panic!("{index:04X}sub{sub}: {e:?}"));
        b[..n].to_vec()
    }

    fn uint(&self, index: u16, sub: u8) -> u64 {
        self.stack.od().read_uint(index, sub).unwrap()
    }

    /// `CcmWriteObject` of `value` (wire order).
    fn write(&mut self, index: u16, sub: u8, value: &[u8]) {
        let now = self.now();
        self.stack
            .write_object(index, sub, ByteOrder::Wire, value, now)
            .unwrap();
    }

    fn command(&mut self, cmd: NmtCommand) {
        self.stack.exec_command(cmd).unwrap();
        self.drain();
    }

    fn cycle(&mut self) {
        let now = self.now();
        self.stack.process(&mut self.port, now, |_, _| {});
    }

    /// `ms` cycles, 1 ms apart.
    fn run(&mut self, ms: u32) {
        for _ in 0..ms {
            self.cycle();
            self.port.bus().advance_ms(1);
        }
    }
}

/// Everything observable of a node: every value of every subindex (CPU
/// order), the object list with types and access, and the PDO module's
/// view of its PDOs.
#[derive(Debug, PartialEq)]
struct Snapshot {
    values: Vec<(u16, u8, u8, u8, Vec<u8>)>,
    pdos: Vec<(u16, Option<u32>)>,
}

fn snapshot(s: &Stack) -> Snapshot {
    let od = s.od();
    let mut values = Vec::new();
    for e in od.entries() {
        for sub in 0..od.sub_count(e).min(256) {
            let Ok(obj) = od.find(e.index(), sub as u8) else {
                continue;
            };
            let mut b = [0u8; 512];
            let n = od.peek(&obj, ByteOrder::Native, &mut b).unwrap_or(0);
            values.push((
                e.index(),
                sub as u8,
                obj.data_type().code(),
                obj.access().0,
                b[..n].to_vec(),
            ));
        }
    }
    let pdos = (0x1400..0x1410)
        .chain(0x1800..0x1810)
        .map(|i| (i, s.pdo().cob_id(i).map(|c| c.raw())))
        .collect();
    Snapshot { values, pdos }
}

/// `(index, sub, attribute, value)` of one container entry.
type Spec = (u16, u8, u8, &'static [u8]);

/// A container from `(index, sub, attribute, value)`, with an address
/// segment and a parameter segment where given.
fn encoded(
    entries: &[(u16, u8, u8, &[u8])],
    addresses: Option<&[u16]>,
    pi: Option<&PiParams>,
) -> Vec<u8> {
    let specs: Vec<EntrySpec<'_>> = entries
        .iter()
        .map(|(index, sub, attr, data)| EntrySpec {
            index: *index,
            sub: *sub,
            data,
            attr: *attr,
        })
        .collect();
    let n = encoded_len(&specs, addresses, true, pi).unwrap();
    let mut out = vec![0u8; n];
    encode(&specs, addresses, true, pi, &mut out).unwrap();
    out
}

/// A container from `(index, sub, attribute, value)` without address and
/// parameter segment.
fn container(entries: &[(u16, u8, u8, &[u8])]) -> Vec<u8> {
    encoded(entries, None, None)
}

const U32_1A00_1: [u8; 4] = 0xA4C0_0108u32.to_le_bytes();
const U32_1A00_2: [u8; 4] = 0xA580_0310u32.to_le_bytes();
const U32_1601_1: [u8; 4] = 0xA040_0108u32.to_le_bytes();

/// The main sample: existing objects (heartbeat, a read-only identity
/// entry that is ignored, TPDO 1 reconfigured in an order the CiA 301
/// procedure would refuse), a new RPDO 2, network variables of seed Bild 8
/// (0xA4C0 sub 1..3, 0xA580 sub 3) and an input 0xA040 sub 1, and new
/// manufacturer objects of every attribute type.
fn sample_entries() -> Vec<Spec> {
    vec![
        (0x1017, 0, 0x70, &[0xF4, 0x01]),
        (0x1018, 1, 0x30, &[0x99, 0x09, 0, 0]),
        (0x1800, 1, 0x70, &[0x81, 0x01, 0, 0]),
        (0x1800, 2, 0x70, &[0xFE]),
        (0x1A00, 0, 0x70, &[2]),
        (0x1A00, 1, 0x70, &U32_1A00_1),
        (0x1A00, 2, 0x70, &U32_1A00_2),
        (0x1401, 0, 0x30, &[5]),
        (0x1401, 1, 0x70, &[0x01, 0x03, 0, 0]),
        (0x1401, 2, 0x70, &[0xFF]),
        (0x1601, 0, 0x70, &[1]),
        (0x1601, 1, 0x70, &U32_1601_1),
        (0xA040, 0, 0x30, &[1]),
        (0xA040, 1, 0x70, &[0]),
        (0xA4C0, 0, 0x30, &[3]),
        (0xA4C0, 1, 0xF0, &[0x11]),
        (0xA4C0, 2, 0xF0, &[0x22]),
        (0xA4C0, 3, 0xF0, &[0x33]),
        (0xA580, 0, 0x30, &[3]),
        (0xA580, 3, 0xF0, &[0x34, 0x12]),
        (0x2100, 0, 0x28, b"dynamic"),
        (0x2101, 0, 0x60, &[1, 2, 3]),
        (0x2102, 0, 0x70, &[0x78, 0x56, 0x34, 0x12]),
        (0x2103, 0, 0xE1, &[1]),
    ]
}

/// The container of [`sample_entries`].
fn sample() -> Vec<u8> {
    container(&sample_entries())
}

/// The container of [`sample_entries`] with the addresses `addr` of its
/// candidates (in container order: A040.1, A4C0.1..3, A580.3, 2100, 2101,
/// 2102, 2103) and the parameter segment `pi` where given.
fn sample_at(addr: &[u16; 9], pi: Option<&PiParams>) -> Vec<u8> {
    encoded(&sample_entries(), Some(addr), pi)
}

/// A 48-byte image with the inputs at 40..48 and the outputs at 16..40.
const AREAS: PiParams = PiParams {
    total: 48,
    input_offset: 40,
    input_size: 8,
    output_offset: 16,
    output_size: 24,
};

node!(build_sample);
// req: D-2.1.2-INDEX, D-2.1.2-NETVAR, D-2.1.4-ATTRIBUTES
#[test]
fn container_values_are_read_back() {
    let mut n = Node::alone(build_sample::od());
    let c = sample();
    let info = n.build(&build_sample::POOL, &c, None).unwrap();
    assert!(build_sample::POOL.is_in_use());
    // 0x1401, 0x1601, 0xA040, 0xA4C0, 0xA580, 0x2100..0x2103.
    assert_eq!(info.new_indices, 9);
    for (index, sub, _, data) in sample_entries() {
        if (index, sub) == (0x1018, 1) {
            continue;
        }
        assert_eq!(n.read(index, sub), data, "{index:04X}sub{sub}");
    }
    assert_eq!(
        n.uint(0x1018, 1),
        0x123,
        "read-only objects keep the firmware's value"
    );
    // Types and access of new objects (seed 2.1.2, 2.1.4, table 2).
    let od = n.stack.od();
    let t = |i, s| {
        let o = od.find(i, s).unwrap();
        (o.data_type(), o.access().0)
    };
    assert_eq!(t(0xA4C0, 1), (DataType::UInt8, 0x0B));
    assert_eq!(t(0xA580, 3), (DataType::UInt16, 0x0B));
    assert_eq!(t(0xA040, 1), (DataType::UInt8, 0x0B));
    assert_eq!(t(0xA4C0, 0), (DataType::UInt8, 0x01));
    assert_eq!(t(0x2100, 0), (DataType::VString, 0x01));
    assert_eq!(t(0x2101, 0), (DataType::Domain, 0x03));
    assert_eq!(t(0x2102, 0), (DataType::UInt32, 0x03));
    assert_eq!(t(0x2103, 0), (DataType::Bool, 0x0B));
    assert!(
        od.find(0xA580, 1).is_err(),
        "subindices the container leaves out do not exist"
    );
    // The PDO module took over both PDOs.
    assert_eq!(n.stack.pdo().cob_id(0x1800).map(|c| c.raw()), Some(0x181));
    assert_eq!(n.stack.pdo().cob_id(0x1401).map(|c| c.raw()), Some(0x301));
    // Numbers are stored in the CPU's byte order.
    let mut b = [0u8; 4];
    n.stack
        .read_object(0x2102, 0, ByteOrder::Native, &mut b)
        .unwrap();
    assert_eq!(u32::from_ne_bytes(b), 0x1234_5678);
}

node!(image_rule);
static IMAGE_RULE: [AtomicU8; 32] = decl::zeroed();
// req: D-6-OFFSETS
#[test]
fn network_variables_are_placed_by_the_offset_rule() {
    let mut n = Node::alone(image_rule::od());
    let c = sample();
    let info = n.build(&image_rule::POOL, &c, Some(&IMAGE_RULE)).unwrap();
    // Inputs: 0xA040 sub 1 at 0. Outputs from 8 (next multiple of 8):
    // seed Bild 8, three BYTEs at +0..+2, the WORD of sub 3 at +4.
    assert_eq!(
        info.pi,
        PiParams {
            total: 14,
            input_offset: 0,
            input_size: 1,
            output_offset: 8,
            output_size: 6
        }
    );
    let img = decl::get(&IMAGE_RULE);
    assert_eq!(&img[8..11], &[0x11, 0x22, 0x33]);
    assert_eq!(&img[12..14], &0x1234u16.to_ne_bytes());
    // The image is the variable: writing it changes the object.
    IMAGE_RULE[9].store(0x5A, Ordering::Relaxed);
    assert_eq!(n.read(0xA4C0, 2), [0x5A]);
    // New objects outside 0xA000 stay in the pool without address segment.
    assert_eq!(n.read(0x2102, 0), [0x78, 0x56, 0x34, 0x12]);
}

node!(image_address);
static IMAGE_ADDRESS: [AtomicU8; 64] = decl::zeroed();
// req: D-2.1.3-ADDRESS, D-2.1.5-PIPARAM
#[test]
fn address_segment_and_parameter_segment_win() {
    let mut n = Node::alone(image_address::od());
    let addr = [40u16, 20, 21, 22, 24, 0xFFFF, 0xFFFF, 32, 0xFFFF];
    let c = sample_at(&addr, Some(&AREAS));
    let info = n
        .build(&image_address::POOL, &c, Some(&IMAGE_ADDRESS))
        .unwrap();
    assert_eq!(info.pi, AREAS);
    let img = decl::get(&IMAGE_ADDRESS);
    assert_eq!(&img[20..23], &[0x11, 0x22, 0x33]);
    assert_eq!(&img[24..26], &0x1234u16.to_ne_bytes());
    assert_eq!(&img[32..36], &0x1234_5678u32.to_ne_bytes());
    assert_eq!(n.read(0x2100, 0), b"dynamic", "strings stay in the pool");
}

node!(overlap);
static IMAGE_OVERLAP: [AtomicU8; 64] = decl::zeroed();
#[test]
fn variables_sharing_bytes_or_outside_the_image_are_refused() {
    let mut n = Node::alone(overlap::od());
    let before = snapshot(&n.stack);
    let addr = [40u16, 20, 21, 22, 21, 0xFFFF, 0xFFFF, 32, 0xFFFF];
    let c = sample_at(&addr, None);
    let (pool, image) = (&overlap::POOL, Some(&IMAGE_OVERLAP[..]));
    n.refused(pool, &c, image, CopKernel::DynInvalidConfig, &before);
    let addr = [40u16, 20, 21, 22, 63, 0xFFFF, 0xFFFF, 32, 0xFFFF];
    let c = sample_at(&addr, None);
    n.refused(pool, &c, image, CopKernel::DynNoMemory, &before);
    assert!(
        decl::get(&IMAGE_OVERLAP).iter().all(|b| *b == 0),
        "image untouched"
    );
}

/// Containers that the dictionary refuses before the pool is needed, with
/// the codes.
fn dictionary_refusals() -> Vec<(Vec<Spec>, CopKernel)> {
    vec![
        // A subindex an existing object does not have.
        (
            vec![(0x1017, 1, 0x70, &[0, 0])],
            CopKernel::ObdSubindexNotExist,
        ),
        // An index that cannot be created.
        (vec![(0x0005, 0, 0x70, &[0])], CopKernel::ObdIndexNotExist),
        // A value of the wrong length for an existing object.
        (
            vec![(0x1017, 0, 0x70, &[1, 2, 3])],
            CopKernel::ObdValueLengthError,
        ),
        // Network variable of the wrong size for its type (UNSIGNED16).
        (vec![(0xA580, 1, 0x70, &[1])], CopKernel::DynInvalidConfig),
        // A new object without type information and two different sizes.
        (
            vec![(0x2104, 0, 0x70, &[1]), (0x2104, 0, 0x70, &[1, 2])],
            CopKernel::DynInvalidConfig,
        ),
    ]
}

node!(refusals);

/// The SDO server and client parameter objects right after the last
/// channel of this build (CiA 301 7.5.2.33 / 7.5.2.34: 0x1200.. and
/// 0x1280..).
const FIRST_SERVER_BEYOND: u16 = 0x1200 + cop::config::SDO_MAX_SERVER_IN_OBD as u16;
const FIRST_CLIENT_BEYOND: u16 = 0x1280 + cop::config::SDO_MAX_CLIENT_IN_OBD as u16;
// req: D-2.1.2-PDO-PAIR, D-5.1-CODES
#[test]
fn refused_containers_change_nothing() {
    let mut n = Node::alone(refusals::od());
    let before = snapshot(&n.stack);
    let mut cases: Vec<(Vec<Spec>, CopKernel)> = vec![
        // Mapping object 0x1602 missing (seed 2.1.2).
        (
            vec![(0x1402, 1, 0x70, &[0x02, 0x04, 0, 0x80])],
            CopKernel::DynInvalidConfig,
        ),
        // Mapping without communication object.
        (vec![(0x1A05, 0, 0x70, &[0])], CopKernel::DynInvalidConfig),
        // A mapped object that does not exist.
        (
            vec![
                (0x1A00, 1, 0x70, &[0x08, 0x01, 0x00, 0x30]),
                (0x1A00, 0, 0x70, &[1]),
            ],
            CopKernel::PdoErrorMapp,
        ),
        // More than 64 bits.
        (
            vec![
                (0x1A00, 0, 0x70, &[3]),
                (0x1A00, 1, 0x70, &[0x20, 0x00, 0x02, 0x21]),
                (0x1A00, 2, 0x70, &[0x20, 0x00, 0x02, 0x21]),
                (0x1A00, 3, 0x70, &[0x20, 0x00, 0x02, 0x21]),
                (0x2102, 0, 0xF0, &[0; 4]),
            ],
            CopKernel::PdoErrorMapp,
        ),
        // Restricted COB-ID (CiA 301 7.3.5).
        (
            vec![(0x1800, 1, 0x70, &[0x01, 0, 0, 0])],
            CopKernel::CobIllegalCanId,
        ),
        // 11-bit COB-ID above 0x7FF.
        (
            vec![(0x1800, 1, 0x70, &[0x00, 0x08, 0, 0])],
            CopKernel::CobIllegalCanId,
        ),
        // TPDO 9 beyond PDO_MAX_TXPDO_IN_OBD (8).
        (
            vec![
                (0x1808, 1, 0x70, &[0x81, 0x02, 0, 0]),
                (0x1A08, 0, 0x70, &[0]),
            ],
            CopKernel::CobNoFreeEntry,
        ),
        // The first SDO server beyond SDO_MAX_SERVER_IN_OBD (0x1201 by
        // default) with valid COB-IDs: it would answer nowhere.
        (
            vec![
                (FIRST_SERVER_BEYOND, 0, 0x30, &[3]),
                (FIRST_SERVER_BEYOND, 1, 0x70, &[0x41, 0x06, 0, 0]),
                (FIRST_SERVER_BEYOND, 2, 0x70, &[0xC1, 0x05, 0, 0]),
                (FIRST_SERVER_BEYOND, 3, 0x70, &[0x05]),
            ],
            CopKernel::SdosNoFreeEntry,
        ),
        // The same for an SDO client beyond SDO_MAX_CLIENT_IN_OBD (0x1284
        // by default); one valid COB-ID is enough.
        (
            vec![
                (FIRST_CLIENT_BEYOND, 1, 0x70, &[0x05, 0x06, 0, 0x80]),
                (FIRST_CLIENT_BEYOND, 2, 0x70, &[0x85, 0x05, 0, 0]),
                (FIRST_CLIENT_BEYOND, 3, 0x70, &[0x05]),
            ],
            CopKernel::SdocNoFreeEntry,
        ),
        // Two TPDOs, one COB-ID.
        (
            vec![
                (0x1800, 1, 0x70, &[0x81, 0x01, 0, 0]),
                (0x1801, 1, 0x70, &[0x81, 0x01, 0, 0]),
                (0x1A01, 0, 0x70, &[0]),
            ],
            CopKernel::CobAlreadyExist,
        ),
        // An index that cannot be created.
        (vec![(0xFFFF, 0, 0x70, &[0])], CopKernel::ObdIndexNotExist),
        // A BOOLEAN of value 2.
        (vec![(0x2103, 0, 0xE1, &[2])], CopKernel::DynInvalidConfig),
    ];
    cases.extend(dictionary_refusals());
    for (entries, code) in cases {
        let c = container(&entries);
        assert_eq!(
            n.build(&refusals::POOL, &c, None),
            Err(code),
            "{entries:04X?}"
        );
        assert_eq!(snapshot(&n.stack), before, "{entries:04X?}");
        assert!(!refusals::POOL.is_in_use());
    }
}

node!(malformed);
// req: D-2.1-CONTAINER
#[test]
fn malformed_containers_are_refused_without_change() {
    let mut n = Node::alone(malformed::od());
    let before = snapshot(&n.stack);
    let pi = PiParams {
        total: 16,
        input_offset: 0,
        input_size: 8,
        output_offset: 8,
        output_size: 8,
    };
    let addr = [0u16, 8, 9, 10, 12, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF];
    let good = sample_at(&addr, Some(&pi));
    let put = |b: &mut Vec<u8>, at: usize, v: u32| b[at..at + 4].copy_from_slice(&v.to_le_bytes());
    let get = |b: &Vec<u8>, at: usize| u32::from_le_bytes(b[at..at + 4].try_into().unwrap());
    let mut bad: Vec<(String, Vec<u8>)> = Vec::new();
    for len in 0..good.len() {
        let mut b = good[..len].to_vec();
        // Also with the size field matching the truncated length, so that
        // the segment checks (not only the size check) see it.
        bad.push((format!("truncated to {len}"), b.clone()));
        if len >= 4 {
            put(&mut b, 0, len as u32);
            bad.push((format!("truncated to {len}, size field fixed"), b));
        }
    }
    for at in (0..40).step_by(4).filter(|a| *a != 4) {
        for delta in [1i64, -1, 0x100, -0x100] {
            let mut b = good.clone();
            let v = get(&b, at);
            put(&mut b, at, (i64::from(v) + delta) as u32);
            bad.push((format!("header field {at} {delta:+}"), b));
        }
    }
    // Each segment moved onto the next one.
    for (a, b_) in [(8usize, 16usize), (16, 24), (24, 32)] {
        let mut b = good.clone();
        let o = get(&b, b_);
        put(&mut b, a, o);
        bad.push((format!("segment {a} onto {b_}"), b));
    }
    // Every attribute with a reserved bit or two type bits.
    let ext = get(&good, 24) as usize;
    for i in 0..sample_entries().len() {
        for bits in [0x02u8, 0x04, 0x18] {
            let mut b = good.clone();
            b[ext + i] |= bits;
            bad.push((format!("attribute {i} | {bits:#04x}"), b));
        }
    }
    // Every entry's size field one up and one down.
    let mut at = get(&good, 8) as usize + 4;
    for _ in 0..sample_entries().len() {
        let size = get(&good, at + 3);
        for s in [size + 1, size.wrapping_sub(1)] {
            let mut b = good.clone();
            put(&mut b, at + 3, s);
            bad.push((format!("entry size at {at}: {s}"), b));
        }
        at += 7 + size as usize;
    }
    // Under Miri (scripts/miri.sh) every 25th case keeps the run short;
    // the ordinary run takes them all.
    let stride = if cfg!(miri) { 25 } else { 1 };
    for (what, b) in bad.iter().step_by(stride) {
        let r = n.build(&malformed::POOL, b, None);
        assert!(r.is_err(), "{what} accepted");
        assert_eq!(snapshot(&n.stack), before, "{what}");
        assert!(!malformed::POOL.is_in_use(), "{what}");
    }
    assert!(bad.len() > 700, "{} cases", bad.len());
    n.build(&malformed::POOL, &good, None).unwrap();
}

node!(rollback);
#[test]
fn a_refused_write_midway_puts_everything_back() {
    let mut n = Node::alone(rollback::od());
    let before = snapshot(&n.stack);
    rollback::REFUSE.store(true, Ordering::Relaxed);
    // 0x1017 and TPDO 1 are written before 0x2010 refuses.
    let mut entries = sample_entries();
    entries.push((0x2010, 0, 0x70, &[1, 2]));
    let c = container(&entries);
    let code = CopKernel::ObdAccessViolation;
    n.refused(&rollback::POOL, &c, None, code, &before);
    rollback::REFUSE.store(false, Ordering::Relaxed);
    n.build(&rollback::POOL, &c, None).unwrap();
    assert_eq!(n.uint(0x2010, 0), 0x0201);
}

node!(twice);
// req: D-3-REBUILD, D-5.2-DESTROY
#[test]
fn build_twice_destroy_and_rebuild() {
    let mut n = Node::alone(twice::od());
    let before = snapshot(&n.stack);
    let tpdo_cob = n.uint(0x1800, 1);
    let c = sample();
    n.build(&twice::POOL, &c, None).unwrap();
    assert_eq!(
        n.build(&twice::POOL, &c, None),
        Err(CopKernel::NoFreeInstance),
        "a second build needs DynDestroyOd first"
    );
    n.command(NmtCommand::StartRemoteNode);
    n.destroy(&twice::POOL);
    assert!(!twice::POOL.is_in_use());
    // Seed 5.2: PDO defaults back, PDO module PRE-OPERATIONAL, node state
    // unchanged. Other static objects keep the container's values.
    assert_eq!(n.stack.nmt_state(), NmtState::Operational);
    assert_eq!(n.uint(0x1800, 1), tpdo_cob);
    assert_eq!(n.uint(0x1A00, 0), 0);
    assert!(n.stack.od().find_entry(0xA4C0).is_none());
    assert_eq!(n.uint(0x1017, 0), 500);
    n.write(0x1017, 0, &[0, 0]);
    assert_eq!(snapshot(&n.stack), before);
    // Destroy without a build resets the PDO module too and succeeds.
    n.destroy(&twice::POOL);
    n.build(&twice::POOL, &c, None).unwrap();
    assert_eq!(n.read(0xA580, 3), [0x34, 0x12]);
}

node!(small_pool);
static SMALL: DynPool<256> = DynPool::new();
// req: D-5.1-CODES
#[test]
fn a_pool_too_small_is_no_memory() {
    let mut n = Node::alone(small_pool::od());
    let before = snapshot(&n.stack);
    n.refused(&SMALL, &sample(), None, CopKernel::DynNoMemory, &before);
}

node!(resets);
#[test]
fn nmt_resets_keep_the_dynamic_od_in_force() {
    let mut n = Node::alone(resets::od());
    let c = sample();
    n.build(&resets::POOL, &c, None).unwrap();
    n.write(0x1017, 0, &[7, 0]);
    n.write(0x1401, 2, &[1]);
    n.command(NmtCommand::ResetCommunication);
    assert_eq!(n.stack.nmt_state(), NmtState::PreOperational);
    assert_eq!(n.uint(0x1017, 0), 500);
    assert_eq!(n.uint(0x1401, 2), 0xFF);
    assert_eq!(n.uint(0x1800, 1), 0x181);
    assert_eq!(n.stack.pdo().cob_id(0x1800).map(|c| c.raw()), Some(0x181));
    n.command(NmtCommand::ResetNode);
    assert_eq!(n.uint(0x1A00, 1), 0xA4C0_0108);
}

node!(net_a);
node!(net_b);
static IMAGE_A: [AtomicU8; 32] = decl::zeroed();
static IMAGE_B: [AtomicU8; 32] = decl::zeroed();
static SDO_BUF: [AtomicU8; 16] = decl::zeroed();

// req: D-2-ACCESS
#[test]
fn two_nodes_exchange_network_variables_by_pdo() {
    let bus = SimBus::new();
    let mut a = Node::new(&bus, net_a::od(), 1);
    let mut b = Node::new(&bus, net_b::od(), 2);
    // Node 1 sends its outputs 0xA4C0 sub 1 and 0xA580 sub 3 with TPDO 1
    // (0x181, event timer 10 ms); node 2 receives them into its inputs
    // 0xA040 sub 1 and 0xA100 sub 3 with RPDO 1.
    let ca = container(&[
        (0x1800, 1, 0x70, &[0x81, 0x01, 0, 0]),
        (0x1800, 2, 0x70, &[0xFF]),
        (0x1800, 5, 0x70, &[10, 0]),
        (0x1A00, 0, 0x70, &[2]),
        (0x1A00, 1, 0x70, &U32_1A00_1),
        (0x1A00, 2, 0x70, &U32_1A00_2),
        (0xA4C0, 0, 0x30, &[1]),
        (0xA4C0, 1, 0xF0, &[0]),
        (0xA580, 0, 0x30, &[3]),
        (0xA580, 3, 0xF0, &[0, 0]),
    ]);
    let map_b2 = 0xA100_0310u32.to_le_bytes();
    let cb = container(&[
        (0x1400, 1, 0x70, &[0x81, 0x01, 0, 0]),
        (0x1400, 2, 0x70, &[0xFF]),
        (0x1600, 0, 0x70, &[2]),
        (0x1600, 1, 0x70, &U32_1601_1),
        (0x1600, 2, 0x70, &map_b2),
        (0xA040, 0, 0x30, &[1]),
        (0xA040, 1, 0x70, &[0]),
        (0xA100, 0, 0x30, &[3]),
        (0xA100, 3, 0x70, &[0, 0]),
    ]);
    let pa = a.build(&net_a::POOL, &ca, Some(&IMAGE_A)).unwrap().pi;
    let pb = b.build(&net_b::POOL, &cb, Some(&IMAGE_B)).unwrap().pi;
    a.command(NmtCommand::StartRemoteNode);
    b.command(NmtCommand::StartRemoteNode);
    // The application writes its outputs into the process image.
    let out = pa.output_offset as usize;
    IMAGE_A[out].store(0xC3, Ordering::Relaxed);
    decl::set::<2>(
        (&IMAGE_A[out + 4..out + 6]).try_into().unwrap(),
        0xBEEFu16.to_ne_bytes(),
    );
    for _ in 0..30 {
        a.cycle();
        b.cycle();
        bus.advance_ms(1);
    }
    let inp = pb.input_offset as usize;
    assert_eq!(IMAGE_B[inp].load(Ordering::Relaxed), 0xC3);
    let w = [
        IMAGE_B[inp + 4].load(Ordering::Relaxed),
        IMAGE_B[inp + 5].load(Ordering::Relaxed),
    ];
    assert_eq!(u16::from_ne_bytes(w), 0xBEEF);

    // Node 1 reads node 2's dynamic objects with this library's SDO client.
    let p = common::CLIENT_TO_NODE_2;
    a.stack.define_sdo_client(&mut a.port, 0x1280, p).unwrap();
    for (index, sub, want) in [
        (0xA100u16, 3u8, vec![0xEF, 0xBE]),
        (0xA040, 1, vec![0xC3]),
        (0x1600, 2, map_b2.to_vec()),
        (0xA100, 0, vec![3]),
    ] {
        let now = a.now();
        a.stack
            .sdo_client_start(
                &mut a.port,
                now,
                0x1280,
                Direction::Upload,
                Multiplexer::new(index, sub),
                &SDO_BUF,
                SDO_BUF.len(),
                0,
            )
            .unwrap();
        for _ in 0..5 {
            b.cycle();
            a.cycle();
            bus.advance_ms(1);
        }
        let (state, abort) = a.stack.sdoc().state(0x1280).unwrap();
        let len = a.stack.sdoc().transferred(0x1280).unwrap();
        assert_eq!(
            (state, abort),
            (SdocState::Finished, 0),
            "{index:04X}sub{sub}"
        );
        assert_eq!(
            decl::get(&SDO_BUF)[..len as usize],
            want[..],
            "{index:04X}sub{sub}"
        );
    }
}

// ---------------------------------------------------------------------
// The index of the entries lives in the pool: a pool in use, or one with
// room for the tables but not for the index, decides the same.
// ---------------------------------------------------------------------

node!(busy_owner);
node!(busy_other);
node!(busy_free);
#[test]
fn a_pool_in_use_checks_the_container_as_a_free_one() {
    let bus = SimBus::new();
    let mut owner = Node::new(&bus, busy_owner::od(), 1);
    let mut other = Node::new(&bus, busy_other::od(), 2);
    let mut free = Node::new(&bus, busy_free::od(), 3);
    // The owner's dynamic OD takes busy_owner::POOL.
    owner.build(&busy_owner::POOL, &sample(), None).unwrap();
    let owner_before = snapshot(&owner.stack);
    let other_before = snapshot(&other.stack);
    let mut truncated = sample();
    truncated.truncate(60);
    // The container and the dictionary are checked before the pool is
    // needed; the PDOs' final state (like the writes) only after.
    let mut cases: Vec<(Vec<u8>, CopKernel)> = dictionary_refusals()
        .iter()
        .map(|(entries, code)| (container(entries), *code))
        .collect();
    cases.extend([
        (truncated, CopKernel::DynInvalidConfig),
        (
            container(&[(0x1800, 1, 0x70, &[0x01, 0, 0, 0])]),
            CopKernel::NoFreeInstance,
        ),
        (sample(), CopKernel::NoFreeInstance),
    ]);
    for (c, code) in &cases {
        assert_eq!(other.build(&busy_owner::POOL, c, None), Err(*code));
        if *code != CopKernel::NoFreeInstance {
            assert_eq!(free.build(&busy_free::POOL, c, None), Err(*code));
        }
        assert_eq!(snapshot(&other.stack), other_before);
        assert_eq!(snapshot(&owner.stack), owner_before, "the owner's tables");
        assert!(busy_owner::POOL.is_in_use());
        assert!(!busy_free::POOL.is_in_use());
    }
}

node!(tight);
node!(roomy);
/// Sixty new UNSIGNED8 objects 0x2100..0x213B (subindex 0, one byte each).
fn sixty_bytes() -> Vec<u8> {
    const VALUES: [u8; 60] = {
        let mut v = [0u8; 60];
        let mut i = 0;
        while i < 60 {
            v[i] = i as u8;
            i += 1;
        }
        v
    };
    let entries: Vec<(u16, u8, u8, &[u8])> = (0..60u16)
        .map(|i| (0x2100 + i, 0u8, 0x70u8, &VALUES[i as usize..i as usize + 1]))
        .collect();
    container(&entries)
}
/// What `sixty_bytes` takes of the pool: 60 index entries, 60 subindex
/// entries, 60 variables of one byte and the copy of the index segment
/// (4 + 60 × 8 bytes); no snapshot.
const SIXTY_BYTES_POOL: usize = {
    let entries = 60 * core::mem::size_of::<ObdEntry>();
    let align = core::mem::align_of::<ObdSubEntry>();
    let subs_at = entries.div_ceil(align) * align;
    subs_at + 60 * core::mem::size_of::<ObdSubEntry>() + 60 + (4 + 60 * 8)
};
/// Room for the tables and 16 bytes more: not for the index of the
/// entries (8 bytes per entry) and the plan's notes (1 byte per entry)
/// beside them.
static TIGHT: DynPool<{ SIXTY_BYTES_POOL + 16 }> = DynPool::new();
#[test]
fn a_pool_without_room_for_the_index_builds_the_same() {
    // The same node-ID (the PDOs' default COB-IDs), on buses of their own.
    let mut t = Node::alone(tight::od());
    let mut r = Node::alone(roomy::od());
    let c = sixty_bytes();
    let info = t.build(&TIGHT, &c, None).unwrap();
    assert_eq!(info.pool_used, SIXTY_BYTES_POOL);
    assert_eq!(r.build(&roomy::POOL, &c, None), Ok(info));
    assert_eq!(snapshot(&t.stack), snapshot(&r.stack));
    assert_eq!(t.read(0x213B, 0), [59]);
    t.destroy(&TIGHT);
    assert!(!TIGHT.is_in_use());
}

/// A node with the pre-defined error field and the store / restore
/// objects of an ODBuilder-generated dictionary (0x1003 with 4 entries,
/// 0x1010 / 0x1011 with sub 1).
mod structure_node {
    use super::*;

    pub static POOL: DynPool<4096> = DynPool::new();
    static E0: [AtomicU8; 1] = decl::zeroed();
    static E1: [AtomicU8; 4] = decl::zeroed();
    static E2: [AtomicU8; 4] = decl::zeroed();
    static E3: [AtomicU8; 4] = decl::zeroed();
    static E4: [AtomicU8; 4] = decl::zeroed();
    static S1003: [ObdSubEntry; 5] = [
        ObdSubEntry::ram(0, DataType::UInt8, Access::RW, &E0, Some(&[0])),
        ObdSubEntry::ram(1, DataType::UInt32, Access::R, &E1, Some(&[0; 4])),
        ObdSubEntry::ram(2, DataType::UInt32, Access::R, &E2, Some(&[0; 4])),
        ObdSubEntry::ram(3, DataType::UInt32, Access::R, &E3, Some(&[0; 4])),
        ObdSubEntry::ram(4, DataType::UInt32, Access::R, &E4, Some(&[0; 4])),
    ];
    pub static SAVE: [AtomicU8; 4] = decl::zeroed();
    static S1010: [ObdSubEntry; 2] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
        ObdSubEntry::ram(1, DataType::UInt32, Access::RW, &SAVE, Some(&[0; 4])),
    ];
    static LOAD: [AtomicU8; 4] = decl::zeroed();
    static S1011: [ObdSubEntry; 2] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[1]),
        ObdSubEntry::ram(1, DataType::UInt32, Access::RW, &LOAD, Some(&[0; 4])),
    ];
    static GENERIC: [ObdEntry; 3] = [
        ObdEntry::new(0x1003, &S1003, None),
        ObdEntry::new(0x1010, &S1010, None),
        ObdEntry::new(0x1011, &S1011, None),
    ];

    pub fn od() -> ObjectDictionary {
        ObjectDictionary::new(&GENERIC, &[], &[]).unwrap()
    }
}

/// Entries that describe the device are not ordinary writes: 0x1003 sub 0
/// of a DCF is the number of error entries the device holds (an ordinary
/// write accepts only 0, CiA 301 7.5.2.4), 0x1010 / 0x1011 sub 1 are the
/// store / restore capabilities (written, commands needing "save" /
/// "load", CiA 301 7.5.2.13/14).
#[test]
fn structure_entries_are_checked_not_written() {
    let bus = SimBus::new();
    let mut n = Node::new(&bus, structure_node::od(), 3);
    let entries: Vec<Spec> = vec![
        (0x1003, 0, 0x70, &[4]),
        (0x1003, 1, 0x30, &[0, 0, 0, 0]),
        (0x1010, 0, 0x30, &[1]),
        (0x1010, 1, 0x70, &[1, 0, 0, 0]),
        (0x1011, 0, 0x30, &[1]),
        (0x1011, 1, 0x70, &[1, 0, 0, 0]),
        (0x2000, 0, 0x70, &[7]),
    ];
    let c = container(&entries);
    n.build(&structure_node::POOL, &c, None).unwrap();
    assert_eq!(n.uint(0x1003, 0), 0, "no error was added");
    assert_eq!(n.uint(0x1010, 1), 0, "no store command was given");
    assert_eq!(n.uint(0x2000, 0), 7, "the ordinary entry was applied");
    n.destroy(&structure_node::POOL);
    // More entries than the object holds: the object cannot grow.
    let c = container(&[(0x1003, 0, 0x70, &[5])]);
    assert_eq!(
        n.build(&structure_node::POOL, &c, None).unwrap_err(),
        CopKernel::DynInvalidConfig
    );
}

node!(on_change);
static IMAGE_CHANGE: [AtomicU8; 32] = decl::zeroed();

/// `CCM_USE_PDO_CHECK_VAR` (SYS TEC copdef.h default TRUE; pdo.h
/// `PdoProcessCheckVar`: TPDOs of types 0 and 254 are compared and marked
/// for sending when their data changed): an event-driven TPDO without event
/// timer whose mapped bytes the application changes in the process image,
/// calling neither `CcmSignalCheckVar` nor `CcmSendPdo`, is sent in the
/// next cycle, once per change.
#[test]
fn event_driven_tpdo_follows_the_process_image() {
    let bus = SimBus::new();
    let mut n = Node::new(&bus, on_change::od(), 1);
    let c = container(&[
        (0x1800, 1, 0x70, &[0x81, 0x01, 0, 0]),
        (0x1800, 2, 0x70, &[0xFE]),
        (0x1A00, 0, 0x70, &[1]),
        (0x1A00, 1, 0x70, &U32_1A00_1),
        (0xA4C0, 0, 0x30, &[1]),
        (0xA4C0, 1, 0xF0, &[0]),
    ]);
    let pi = n
        .build(&on_change::POOL, &c, Some(&IMAGE_CHANGE))
        .unwrap()
        .pi;
    n.command(NmtCommand::StartRemoteNode);
    let tpdos = |bus: &SimBus| {
        bus.sent()
            .into_iter()
            .filter(|(_, _, f)| f.id.raw() == 0x181)
            .map(|(_, _, f)| f.data[..usize::from(f.len)].to_vec())
            .collect::<Vec<_>>()
    };
    bus.clear_trace();
    n.run(5);
    assert!(tpdos(&bus).is_empty(), "nothing changed, nothing sent");
    let out = pi.output_offset as usize;
    IMAGE_CHANGE[out].store(0x5A, Ordering::Relaxed);
    n.run(5);
    IMAGE_CHANGE[out].store(0x5B, Ordering::Relaxed);
    n.run(5);
    assert_eq!(tpdos(&bus), [vec![0x5A], vec![0x5B]], "one TPDO per change");
}

/// Byte offset of entry `i` of a container: the index segment starts at
/// the offset in header bytes 8..12 (seed chapter 2, Bild 3: header, then
/// offset/length per segment); after its 4-byte count each entry has
/// index (2), subindex (1), length (4) and the value.
fn entry_offset(c: &[u8], i: usize) -> u32 {
    let mut at = u32::from_le_bytes(c[8..12].try_into().unwrap()) as usize + 4;
    for _ in 0..i {
        let len = u32::from_le_bytes(c[at + 3..at + 7].try_into().unwrap()) as usize;
        at += 7 + len;
    }
    at as u32
}

node!(coverage);
static IMAGE_COVERAGE: [AtomicU8; 64] = decl::zeroed();

/// With a parameter segment, every variable of the image lies inside the
/// image size it names and inside its input or output area; the refusal
/// names the entry (`DynPool::last_error`, C `DynGetLastError`).
// req: D-2.1.5-PIPARAM
#[test]
fn variables_outside_the_areas_are_refused_and_named() {
    let mut n = Node::alone(coverage::od());
    let before = snapshot(&n.stack);
    let (pool, image) = (&coverage::POOL, Some(&IMAGE_COVERAGE[..]));
    // A040.1 at 12: in the image (64 bytes), in no area.
    let addr = [12u16, 20, 21, 22, 24, 0xFFFF, 0xFFFF, 32, 0xFFFF];
    let c = sample_at(&addr, Some(&AREAS));
    n.refused(pool, &c, image, CopKernel::DynInvalidConfig, &before);
    let e = coverage::POOL.last_error().unwrap();
    assert_eq!(e.code, CopKernel::DynInvalidConfig.code());
    let b = e.entry.unwrap();
    let pos = sample_entries()
        .iter()
        .position(|s| (s.0, s.1) == (0xA040, 1))
        .unwrap();
    assert_eq!((b.index, b.sub), (0xA040, 1));
    assert_eq!(b.offset, entry_offset(&c, pos));
    // 0x2102 (4 bytes) at 38: starts in the output area, ends past it.
    let addr = [40u16, 20, 21, 22, 24, 0xFFFF, 0xFFFF, 38, 0xFFFF];
    let c = sample_at(&addr, Some(&AREAS));
    n.refused(pool, &c, image, CopKernel::DynInvalidConfig, &before);
    let b = coverage::POOL.last_error().unwrap().entry.unwrap();
    assert_eq!((b.index, b.sub), (0x2102, 0));
    assert!(decl::get(&IMAGE_COVERAGE).iter().all(|b| *b == 0));
    // Inside the areas it builds, and the last error is cleared.
    let addr = [40u16, 20, 21, 22, 24, 0xFFFF, 0xFFFF, 32, 0xFFFF];
    let c = sample_at(&addr, Some(&AREAS));
    n.build(pool, &c, image).unwrap();
    assert_eq!(coverage::POOL.last_error(), None);
    // A second build concerns the container as a whole.
    assert_eq!(n.build(pool, &c, image), Err(CopKernel::NoFreeInstance));
    assert_eq!(coverage::POOL.last_error().unwrap().entry, None);
}

node!(blamed_write);

/// A value the dictionary refuses names its entry: 0x1017 with 3 bytes for
/// an UNSIGNED16 (kCopObdValueLengthError or the like, the dictionary's
/// code), and a PDO refusal names the PDO's first entry.
#[test]
fn refused_values_and_pdos_name_their_entry() {
    let mut n = Node::alone(blamed_write::od());
    let entries: Vec<Spec> = vec![(0x2000, 0, 0x70, &[1]), (0x1017, 0, 0x70, &[1, 2, 3])];
    let c = container(&entries);
    let code = n.build(&blamed_write::POOL, &c, None).unwrap_err();
    let e = blamed_write::POOL.last_error().unwrap();
    assert_eq!(e.code, code.code());
    let b = e.entry.unwrap();
    assert_eq!((b.index, b.sub, b.offset), (0x1017, 0, entry_offset(&c, 1)));
    // Restricted COB-ID 0x001 of TPDO 1 (CiA 301 7.3.5).
    let entries: Vec<Spec> = vec![
        (0x2000, 0, 0x70, &[1]),
        (0x1800, 2, 0x70, &[0xFE]),
        (0x1800, 1, 0x70, &[0x01, 0, 0, 0]),
    ];
    let c = container(&entries);
    assert_eq!(
        n.build(&blamed_write::POOL, &c, None),
        Err(CopKernel::CobIllegalCanId)
    );
    let b = blamed_write::POOL.last_error().unwrap().entry.unwrap();
    assert_eq!(b.index, 0x1800);
    assert_eq!(b.offset, entry_offset(&c, 1));
}
