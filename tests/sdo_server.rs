//! Whole-stack tests of the SDO server: a Rust dictionary, the stack
//! (`cop::ccm::Stack`) and the simulated bus. A client is played by
//! injecting request frames on 0x600 + node-ID and reading what the node
//! sends. Byte vectors cite seed 004 ("SDO – Zugriffe ohne Ballast") or the
//! CiA 301 section they follow.

use core::sync::atomic::AtomicU8;

use cop::ccm::Stack;
use cop::config::{SDOS_BUFFER_SIZE, SDOS_DEFAULT_TIMEOUT};
use cop::error::{CopKernel, SdoAbort};
use cop::event::NmtState;
use cop::od::table::ObdCbParam;
use cop::od::{
    Access, ByteOrder, DataType, ObdEntry, ObdSubEntry, ObdVarEntry, ObjectDictionary, decl, event,
};
use cop::port::{CanFrame, CanId};
use cop::sim::{SimBus, SimPort};
use cop::wire::sdo::{ClientFrame, Multiplexer, SegmentData, ServerFrame};

const NODE: u8 = 2;
/// Capacity of the VISIBLE_STRING 0x2000: more than the transfer buffer.
const STR_CAP: usize = SDOS_BUFFER_SIZE + 44;
/// Length of the DOMAIN 0x2001 (at least 200 bytes with the default buffer).
const DOMAIN_LEN: usize = if SDOS_BUFFER_SIZE < 240 {
    SDOS_BUFFER_SIZE
} else {
    240
};
/// Length of the long string transfers.
const LONG: usize = if SDOS_BUFFER_SIZE < 250 {
    SDOS_BUFFER_SIZE
} else {
    250
};

const fn array_of(access: Access) -> Access {
    Access(access.0 | Access::ARRAY)
}

/// Application callback of 0x2006: each subindex refuses in its own way,
/// as an application would for a value it cannot take at the moment.
///
/// # Safety
/// Called by the dictionary with a valid parameter block.
unsafe extern "C" fn refusing_callback(param: *mut ObdCbParam) -> u32 {
    // SAFETY: the dictionary passes a parameter block valid for the call.
    let p = unsafe { &mut *param };
    let refuse = CopKernel::ObdAccessViolation.code();
    let code = match (p.m_ObdEvent, p.m_bSubIndex) {
        (event::PRE_WRITE, 1) => SdoAbort::DeviceState.code(),
        // Refusal without an abort code: the dictionary's default applies.
        (event::PRE_WRITE, 2) => return refuse,
        (event::PRE_WRITE, 3) => SdoAbort::UnsupportedAccess.code(),
        (event::PRE_WRITE, 4) => SdoAbort::ValueRange.code(),
        (event::PRE_WRITE, 5) => SdoAbort::General.code(),
        (event::PRE_WRITE, 6) => SdoAbort::NotMappable.code(),
        (event::PRE_READ, 7) => SdoAbort::DeviceState.code(),
        _ => return 0,
    };
    p.m_dwAbortCode = code;
    refuse
}

/// The test dictionary. Each expansion has its own variables, so tests
/// running in parallel never share state.
///
/// | index | content |
/// |---|---|
/// | 0x1000 | U32 const 0x00000191 |
/// | 0x1017 | U16 rw producer heartbeat, default 0 |
/// | 0x1018 | identity record, subs 1..4 U32 const |
/// | 0x2000 | VISIBLE_STRING rw, capacity STR_CAP, default "CANopen" |
/// | 0x2001 | DOMAIN rw, application variable of DOMAIN_LEN bytes |
/// | 0x2002 | U16 rw, range 10..=1000, default 100 |
/// | 0x2003 | U32 read-only 0xCAFEBABE |
/// | 0x2004 | U32 write-only |
/// | 0x2005 | every basic type, subs 1..10 (U8 U16 U32 U64 I8 I16 I32 I64 REAL32 REAL64) |
/// | 0x2006 | subs 1..7 U8 rw with a refusing application callback |
/// | 0x6000 | digital inputs, array of 8 U8, read-only, 0x6000.1 = 0x01 |
/// | 0x6200 | digital outputs, sub 1 U8 rw |
/// | 0x6401 | analogue inputs, array of 2 I16, read-only, 0x6401.1 = 0x1234 |
macro_rules! test_od {
    () => {{
        cop::od_rom!(static S1000: u32 = 0x0000_0191 => UInt32, R);
        cop::od_ram!(static S1017, HB: u16 = 0 => UInt16, SRW);
        static ID_COUNT: [u8; 1] = [4];
        static VENDOR: [u8; 4] = 0x0000_0147u32.to_ne_bytes();
        static PRODUCT: [u8; 4] = 0x0000_1234u32.to_ne_bytes();
        static REVISION: [u8; 4] = 0x0001_0002u32.to_ne_bytes();
        static SERIAL: [u8; 4] = 0x0000_0815u32.to_ne_bytes();
        static S1018: [ObdSubEntry; 5] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &ID_COUNT),
            ObdSubEntry::rom(1, DataType::UInt32, Access::R, &VENDOR),
            ObdSubEntry::rom(2, DataType::UInt32, Access::R, &PRODUCT),
            ObdSubEntry::rom(3, DataType::UInt32, Access::R, &REVISION),
            ObdSubEntry::rom(4, DataType::UInt32, Access::R, &SERIAL),
        ];
        static TEXT: [AtomicU8; STR_CAP + 1] = decl::zeroed();
        static S2000: [ObdSubEntry; 1] =
            [ObdSubEntry::ram_string(0, Access::RW, &TEXT, c"CANopen")];
        static DOMAIN: [AtomicU8; DOMAIN_LEN] = decl::zeroed();
        static DOMAIN_VAR: ObdVarEntry = ObdVarEntry::new();
        static S2001: [ObdSubEntry; 1] = [ObdSubEntry::var(
            0,
            DataType::Domain,
            Access::RW,
            &DOMAIN_VAR,
            DOMAIN_LEN as u32,
            None,
        )];
        cop::od_ram!(static S2002, RANGED: u16 = 100 => UInt16, RW, range(10, 1000));
        static RO: [AtomicU8; 4] = decl::init(0xCAFE_BABEu32.to_ne_bytes());
        static S2003: [ObdSubEntry; 1] =
            [ObdSubEntry::ram(0, DataType::UInt32, Access::R, &RO, None)];
        static WO: [AtomicU8; 4] = decl::zeroed();
        static S2004: [ObdSubEntry; 1] =
            [ObdSubEntry::ram(0, DataType::UInt32, Access::W, &WO, None)];
        static TYPES_COUNT: [u8; 1] = [10];
        static T_U8: [AtomicU8; 1] = decl::zeroed();
        static T_U16: [AtomicU8; 2] = decl::zeroed();
        static T_U32: [AtomicU8; 4] = decl::zeroed();
        static T_U64: [AtomicU8; 8] = decl::zeroed();
        static T_I8: [AtomicU8; 1] = decl::zeroed();
        static T_I16: [AtomicU8; 2] = decl::zeroed();
        static T_I32: [AtomicU8; 4] = decl::zeroed();
        static T_I64: [AtomicU8; 8] = decl::zeroed();
        static T_R32: [AtomicU8; 4] = decl::zeroed();
        static T_R64: [AtomicU8; 8] = decl::zeroed();
        static S2005: [ObdSubEntry; 11] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &TYPES_COUNT),
            ObdSubEntry::ram(1, DataType::UInt8, Access::RW, &T_U8, None),
            ObdSubEntry::ram(2, DataType::UInt16, Access::RW, &T_U16, None),
            ObdSubEntry::ram(3, DataType::UInt32, Access::RW, &T_U32, None),
            ObdSubEntry::ram(4, DataType::UInt64, Access::RW, &T_U64, None),
            ObdSubEntry::ram(5, DataType::Int8, Access::RW, &T_I8, None),
            ObdSubEntry::ram(6, DataType::Int16, Access::RW, &T_I16, None),
            ObdSubEntry::ram(7, DataType::Int32, Access::RW, &T_I32, None),
            ObdSubEntry::ram(8, DataType::Int64, Access::RW, &T_I64, None),
            ObdSubEntry::ram(9, DataType::Real32, Access::RW, &T_R32, None),
            ObdSubEntry::ram(10, DataType::Real64, Access::RW, &T_R64, None),
        ];
        static CB_COUNT: [u8; 1] = [7];
        static CB_VARS: [[AtomicU8; 1]; 7] = [const { decl::zeroed() }; 7];
        static S2006: [ObdSubEntry; 8] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &CB_COUNT),
            ObdSubEntry::ram(1, DataType::UInt8, Access::RW, &CB_VARS[0], None),
            ObdSubEntry::ram(2, DataType::UInt8, Access::RW, &CB_VARS[1], None),
            ObdSubEntry::ram(3, DataType::UInt8, Access::RW, &CB_VARS[2], None),
            ObdSubEntry::ram(4, DataType::UInt8, Access::RW, &CB_VARS[3], None),
            ObdSubEntry::ram(5, DataType::UInt8, Access::RW, &CB_VARS[4], None),
            ObdSubEntry::ram(6, DataType::UInt8, Access::RW, &CB_VARS[5], None),
            ObdSubEntry::ram(7, DataType::UInt8, Access::RW, &CB_VARS[6], None),
        ];
        static DI_COUNT: [u8; 1] = [8];
        static DI: [AtomicU8; 8] = decl::init([0x01, 0, 0, 0, 0, 0, 0, 0]);
        static S6000: [ObdSubEntry; 2] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &DI_COUNT),
            ObdSubEntry {
                m_dwSize: 1,
                ..ObdSubEntry::ram(1, DataType::UInt8, array_of(Access::PR), &DI, None)
            },
        ];
        static DO_COUNT: [u8; 1] = [1];
        static DO: [AtomicU8; 1] = decl::zeroed();
        static DO_DEF: [u8; 1] = [0];
        static S6200: [ObdSubEntry; 2] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &DO_COUNT),
            ObdSubEntry::ram(1, DataType::UInt8, Access::PRW, &DO, Some(&DO_DEF)),
        ];
        static AI_COUNT: [u8; 1] = [2];
        static AI: [AtomicU8; 4] = {
            let a = 0x1234i16.to_ne_bytes();
            decl::init([a[0], a[1], 0, 0])
        };
        static S6401: [ObdSubEntry; 2] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &AI_COUNT),
            ObdSubEntry {
                m_dwSize: 2,
                ..ObdSubEntry::ram(1, DataType::Int16, array_of(Access::PR), &AI, None)
            },
        ];
        static GENERIC: [ObdEntry; 3] = [
            ObdEntry::new(0x1000, &S1000, None),
            ObdEntry::new(0x1017, &S1017, None),
            ObdEntry::new(0x1018, &S1018, None),
        ];
        static MANUFACTURER: [ObdEntry; 7] = [
            ObdEntry::new(0x2000, &S2000, None),
            ObdEntry::new(0x2001, &S2001, None),
            ObdEntry::new(0x2002, &S2002, None),
            ObdEntry::new(0x2003, &S2003, None),
            ObdEntry::new(0x2004, &S2004, None),
            ObdEntry::new(0x2005, &S2005, None),
            ObdEntry::new(0x2006, &S2006, Some(refusing_callback)),
        ];
        static DEVICE: [ObdEntry; 3] = [
            ObdEntry::new(0x6000, &S6000, None),
            ObdEntry::new(0x6200, &S6200, None),
            ObdEntry::new(0x6401, &S6401, None),
        ];
        assert!(DOMAIN_VAR.attach(&DOMAIN));
        ObjectDictionary::new(&GENERIC, &MANUFACTURER, &DEVICE).unwrap()
    }};
}

/// A node on the simulated bus and the client's view of it.
struct Rig {
    bus: SimBus,
    port: SimPort,
    stack: Stack,
    node: u8,
}

impl Rig {
    /// Creates the stack, connects it (PRE-OPERATIONAL) and clears the trace.
    fn new(od: ObjectDictionary, node: u8) -> Rig {
        let bus = SimBus::new();
        let port = bus.attach(64);
        let stack = Stack::new(od, node).unwrap();
        let mut rig = Rig {
            bus,
            port,
            stack,
            node,
        };
        rig.stack.connect().unwrap();
        rig.cycle();
        assert_eq!(rig.stack.nmt_state(), NmtState::PreOperational);
        rig.bus.clear_trace();
        rig
    }

    fn cycle(&mut self) {
        let now = self.bus.now();
        self.stack.process(&mut self.port, now, |_, _| {});
    }

    /// Puts `frame` on the bus, runs one cycle and returns what the node
    /// sent meanwhile.
    fn exchange(&mut self, frame: CanFrame) -> Vec<CanFrame> {
        let mark = self.bus.sent().len();
        self.bus.inject(frame);
        self.cycle();
        self.sent_since(mark)
    }

    fn sent_since(&self, mark: usize) -> Vec<CanFrame> {
        self.bus.sent()[mark..]
            .iter()
            .filter(|(from, _, _)| *from == self.port.node())
            .map(|(_, _, f)| *f)
            .collect()
    }

    /// One SDO request on `rx`; returns the response bytes, asserting that
    /// exactly one 8-byte frame came back on `tx`.
    fn sdo_on(&mut self, rx: u16, tx: u16, req: [u8; 8]) -> [u8; 8] {
        let sent = self.exchange(CanFrame::new(CanId::std_masked(rx), &req));
        assert_eq!(sent.len(), 1, "one response to {req:02X?}, got {sent:?}");
        assert_eq!(sent[0].id, CanId::std_masked(tx));
        assert_eq!(sent[0].len, 8);
        sent[0].data
    }

    /// One request on the predefined connection set.
    fn sdo(&mut self, req: [u8; 8]) -> [u8; 8] {
        let (rx, tx) = (0x600 + u16::from(self.node), 0x580 + u16::from(self.node));
        self.sdo_on(rx, tx, req)
    }

    /// A request that must get no answer at all.
    fn sdo_silent(&mut self, frame: CanFrame) {
        let sent = self.exchange(frame);
        assert!(sent.is_empty(), "expected silence, got {sent:?}");
    }

    fn nmt(&mut self, cs: u8) {
        self.exchange(CanFrame::new(CanId::std_masked(0), &[cs, self.node]));
    }

    /// NMT command to all nodes (node-ID 0).
    fn nmt_all(&mut self, cs: u8) {
        self.exchange(CanFrame::new(CanId::std_masked(0), &[cs, 0x00]));
    }

    /// Ends a transfer the test started only to look at its first answer
    /// (CiA 301 SDO abort transfer protocol: the client's abort is not answered).
    fn client_abort(&mut self, index: u16, sub: u8) {
        let [lo, hi] = index.to_le_bytes();
        self.sdo_silent(CanFrame::new(
            CanId::std_masked(0x600 + u16::from(self.node)),
            &[0x80, lo, hi, sub, 0x00, 0x00, 0x00, 0x08],
        ));
    }

    /// Reads a value through the stack's API (wire order).
    fn value(&self, index: u16, sub: u8) -> Vec<u8> {
        let mut buf = vec![0u8; STR_CAP + 8];
        let n = self
            .stack
            .read_object(index, sub, ByteOrder::Wire, &mut buf)
            .unwrap();
        buf.truncate(n);
        buf
    }

    fn set(&mut self, index: u16, sub: u8, data: &[u8]) {
        let now = self.bus.now();
        self.stack
            .write_object(index, sub, ByteOrder::Wire, data, now)
            .unwrap();
    }

    /// Segmented download (size stated); returns the last answer.
    fn download(&mut self, index: u16, sub: u8, data: &[u8]) -> [u8; 8] {
        let [lo, hi] = index.to_le_bytes();
        let size = (data.len() as u32).to_le_bytes();
        let r = self.sdo([0x21, lo, hi, sub, size[0], size[1], size[2], size[3]]);
        if r[0] != 0x60 {
            return r;
        }
        assert_eq!(r, [0x60, lo, hi, sub, 0, 0, 0, 0]);
        let mut toggle = false;
        let n = data.chunks(7).count();
        for (i, c) in data.chunks(7).enumerate() {
            let last = i + 1 == n;
            let req = ClientFrame::DownloadSegment {
                toggle,
                data: SegmentData::new(c).unwrap(),
                last,
            }
            .encode();
            let r = self.sdo(req);
            if last {
                return r;
            }
            // CiA 301 SDO download segment protocol: 0x20 / 0x30 echoing the toggle bit.
            assert_eq!(r, [0x20 | (u8::from(toggle) << 4), 0, 0, 0, 0, 0, 0, 0]);
            toggle = !toggle;
        }
        unreachable!("no data")
    }

    /// Upload of any length; returns the data or the abort code.
    fn upload(&mut self, index: u16, sub: u8) -> Result<Vec<u8>, u32> {
        let mux = Multiplexer::new(index, sub);
        let r = self.sdo(ClientFrame::InitiateUpload { mux }.encode());
        match ServerFrame::decode(&r).unwrap() {
            ServerFrame::Abort { mux: m, code } => {
                assert_eq!(m, mux);
                Err(code)
            }
            ServerFrame::InitiateUploadResponse {
                mux: m,
                payload: cop::wire::sdo::Initiate::Expedited { data, sized },
            } => {
                assert_eq!(m, mux);
                assert!(sized, "the server always states the size");
                Ok(data.as_slice().to_vec())
            }
            ServerFrame::InitiateUploadResponse {
                mux: m,
                payload: cop::wire::sdo::Initiate::Segmented { size },
            } => {
                assert_eq!(m, mux);
                let size = size.expect("the server always states the size") as usize;
                let mut out = Vec::new();
                let mut toggle = false;
                loop {
                    let r = self.sdo(ClientFrame::UploadSegment { toggle }.encode());
                    let ServerFrame::UploadSegmentResponse {
                        toggle: t,
                        data,
                        last,
                    } = ServerFrame::decode(&r).unwrap()
                    else {
                        panic!("unexpected {r:02X?}");
                    };
                    assert_eq!(t, toggle);
                    out.extend_from_slice(data.as_slice());
                    if last {
                        break;
                    }
                    toggle = !toggle;
                }
                assert_eq!(out.len(), size);
                Ok(out)
            }
            other => panic!("unexpected {other:?}"),
        }
    }
}

fn abort(index: u16, sub: u8, code: SdoAbort) -> [u8; 8] {
    ServerFrame::Abort {
        mux: Multiplexer::new(index, sub),
        code: code.code(),
    }
    .encode()
}

fn expedited_upload(index: u16, sub: u8) -> [u8; 8] {
    let [lo, hi] = index.to_le_bytes();
    [0x40, lo, hi, sub, 0, 0, 0, 0]
}

#[test]
fn seed_004_examples_byte_for_byte() {
    let mut rig = Rig::new(test_od!(), NODE);
    // Seed 004 "Initialisierung des Netzwerks": 000 01 00 (start all nodes);
    // example 1 expects the module to be OPERATIONAL.
    rig.nmt_all(0x01);
    assert_eq!(rig.stack.nmt_state(), NmtState::Operational);
    rig.bus.clear_trace();
    // Seed 004 "Beispiel 1": 8-bit write of 0xFF to 0x6200.1 of node 2.
    rig.sdo([0x2F, 0x00, 0x62, 0x01, 0xFF, 0x00, 0x00, 0x00]);
    // Seed 004 "Beispiel 2": 8-bit read of 0x6000.1, which holds 0x01.
    rig.sdo([0x40, 0x00, 0x60, 0x01, 0x00, 0x00, 0x00, 0x00]);
    // Seed 004 "Beispiel 3": 16-bit read of 0x6401.1, which holds 0x1234.
    // The seed prints the request's index high byte as 0x40; that is a typo
    // (the text and the response name 0x6401), so the request is 40 01 64 01.
    rig.sdo([0x40, 0x01, 0x64, 0x01, 0x00, 0x00, 0x00, 0x00]);
    assert_eq!(
        rig.bus.trace(),
        vec![
            "  can0  602   [8]  2F 00 62 01 FF 00 00 00",
            "  can0  582   [8]  60 00 62 01 00 00 00 00",
            "  can0  602   [8]  40 00 60 01 00 00 00 00",
            "  can0  582   [8]  4F 00 60 01 01 00 00 00",
            "  can0  602   [8]  40 01 64 01 00 00 00 00",
            "  can0  582   [8]  4B 01 64 01 34 12 00 00",
        ]
    );
    assert_eq!(rig.value(0x6200, 1), vec![0xFF]);
}

#[test]
fn identity_and_device_type() {
    let mut rig = Rig::new(test_od!(), NODE);
    // CiA 301 objects 1000h and 1018h: expedited U32/U8 reads.
    assert_eq!(
        rig.sdo(expedited_upload(0x1000, 0)),
        [0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0x00, 0x00]
    );
    assert_eq!(
        rig.sdo(expedited_upload(0x1018, 0)),
        [0x4F, 0x18, 0x10, 0x00, 0x04, 0x00, 0x00, 0x00]
    );
    assert_eq!(
        rig.sdo(expedited_upload(0x1018, 1)),
        [0x43, 0x18, 0x10, 0x01, 0x47, 0x01, 0x00, 0x00]
    );
    assert_eq!(rig.upload(0x1018, 4), Ok(0x0815u32.to_le_bytes().to_vec()));
}

#[test]
fn long_visible_string_both_directions() {
    let mut rig = Rig::new(test_od!(), NODE);
    // Upload returns the current length: the default "CANopen", 7 bytes.
    // CiA 301 SDO upload initiate protocol: 0x41 with the size.
    assert_eq!(
        rig.sdo(expedited_upload(0x2000, 0)),
        [0x41, 0x00, 0x20, 0x00, 7, 0, 0, 0]
    );
    rig.client_abort(0x2000, 0);
    assert_eq!(rig.upload(0x2000, 0), Ok(b"CANopen".to_vec()));
    // A long text, segmented download then upload.
    let text: Vec<u8> = (0..LONG).map(|i| b' ' + (i % 90) as u8).collect();
    // At least 200 bytes unless the build chose a smaller buffer.
    assert!(text.len() >= 200 || SDOS_BUFFER_SIZE < 250);
    let mark = rig.bus.sent().len();
    // Last segment of LONG bytes: toggle = (segments - 1) odd/even.
    let segments = LONG.div_ceil(7);
    let last = rig.download(0x2000, 0, &text);
    let t = u8::from((segments - 1) % 2 == 1) << 4;
    assert_eq!(last, [0x20 | t, 0, 0, 0, 0, 0, 0, 0]);
    assert_eq!(rig.sent_since(mark).len(), segments + 1);
    assert_eq!(rig.value(0x2000, 0), text);
    // Upload: 0x41 announces exactly LONG bytes.
    assert_eq!(
        rig.sdo(expedited_upload(0x2000, 0)),
        [0x41, 0x00, 0x20, 0x00, LONG as u8, (LONG >> 8) as u8, 0, 0]
    );
    rig.client_abort(0x2000, 0);
    assert_eq!(rig.upload(0x2000, 0), Ok(text.clone()));
    // A shorter string afterwards: the upload shows the new current length.
    assert_eq!(
        rig.download(0x2000, 0, b"short again"),
        [0x30, 0, 0, 0, 0, 0, 0, 0]
    );
    assert_eq!(rig.upload(0x2000, 0), Ok(b"short again".to_vec()));
}

#[test]
fn domain_both_directions() {
    let mut rig = Rig::new(test_od!(), NODE);
    let data: Vec<u8> = (0..DOMAIN_LEN).map(|i| (i * 7 + 3) as u8).collect();
    assert!(data.len() >= 200 || SDOS_BUFFER_SIZE < 240);
    let last = rig.download(0x2001, 0, &data);
    assert_eq!(last[0] & 0xEF, 0x20, "last segment confirmed: {last:02X?}");
    assert_eq!(rig.value(0x2001, 0), data);
    assert_eq!(rig.upload(0x2001, 0), Ok(data));
}

#[test]
fn every_basic_type_round_trips() {
    let mut rig = Rig::new(test_od!(), NODE);
    // (sub, wire value, native value): CiA 301 data type encoding, little-endian.
    let cases: Vec<(u8, Vec<u8>, Vec<u8>)> = vec![
        (1, vec![0xA5], vec![0xA5]),
        (
            2,
            0xBEEFu16.to_le_bytes().to_vec(),
            0xBEEFu16.to_ne_bytes().to_vec(),
        ),
        (
            3,
            0xDEAD_BEEFu32.to_le_bytes().to_vec(),
            0xDEAD_BEEFu32.to_ne_bytes().to_vec(),
        ),
        (
            4,
            0x0123_4567_89AB_CDEFu64.to_le_bytes().to_vec(),
            0x0123_4567_89AB_CDEFu64.to_ne_bytes().to_vec(),
        ),
        (
            5,
            (-5i8).to_le_bytes().to_vec(),
            (-5i8).to_ne_bytes().to_vec(),
        ),
        (
            6,
            (-1234i16).to_le_bytes().to_vec(),
            (-1234i16).to_ne_bytes().to_vec(),
        ),
        (
            7,
            (-123_456_789i32).to_le_bytes().to_vec(),
            (-123_456_789i32).to_ne_bytes().to_vec(),
        ),
        (
            8,
            (-1_234_567_890_123i64).to_le_bytes().to_vec(),
            (-1_234_567_890_123i64).to_ne_bytes().to_vec(),
        ),
        (
            9,
            1.5f32.to_le_bytes().to_vec(),
            1.5f32.to_ne_bytes().to_vec(),
        ),
        (
            10,
            (-2.25f64).to_le_bytes().to_vec(),
            (-2.25f64).to_ne_bytes().to_vec(),
        ),
    ];
    for (sub, wire, native) in cases {
        if wire.len() <= 4 {
            // Expedited with size: 0x23 | (4 - n) << 2.
            let mut req = [
                0x23 | (((4 - wire.len()) as u8) << 2),
                0x05,
                0x20,
                sub,
                0,
                0,
                0,
                0,
            ];
            req[4..4 + wire.len()].copy_from_slice(&wire);
            assert_eq!(rig.sdo(req), [0x60, 0x05, 0x20, sub, 0, 0, 0, 0]);
        } else {
            // 8-byte types do not fit an expedited frame: segmented.
            assert_eq!(
                rig.download(0x2005, sub, &wire),
                [0x30, 0, 0, 0, 0, 0, 0, 0]
            );
        }
        let mut n = [0u8; 8];
        let len = rig
            .stack
            .read_object(0x2005, sub, ByteOrder::Native, &mut n)
            .unwrap();
        assert_eq!(n[..len], native[..], "native value of sub {sub}");
        assert_eq!(rig.upload(0x2005, sub), Ok(wire), "upload of sub {sub}");
    }
}

/// One refused access: the request, the abort it must produce and the
/// object that must keep its value.
struct Refusal {
    what: &'static str,
    req: [u8; 8],
    code: SdoAbort,
    keep: (u16, u8),
}

#[test]
fn refused_requests_give_the_cia301_abort_and_change_nothing() {
    let mut rig = Rig::new(test_od!(), NODE);
    let cases = [
        Refusal {
            what: "index does not exist",
            req: [0x40, 0x00, 0x30, 0x00, 0, 0, 0, 0],
            code: SdoAbort::ObjectNotExist,
            keep: (0x2002, 0),
        },
        Refusal {
            what: "subindex beyond the record",
            req: [0x40, 0x18, 0x10, 0x05, 0, 0, 0, 0],
            code: SdoAbort::SubindexNotExist,
            keep: (0x1018, 4),
        },
        Refusal {
            what: "element beyond the array",
            req: [0x2F, 0x00, 0x60, 0x09, 0x01, 0, 0, 0],
            code: SdoAbort::SubindexNotExist,
            keep: (0x6000, 8),
        },
        Refusal {
            what: "read of a write-only object",
            req: [0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0],
            code: SdoAbort::ReadWriteOnly,
            keep: (0x2003, 0),
        },
        Refusal {
            what: "write of a read-only object",
            req: [0x23, 0x03, 0x20, 0x00, 1, 2, 3, 4],
            code: SdoAbort::WriteReadOnly,
            keep: (0x2003, 0),
        },
        Refusal {
            what: "write of a constant",
            req: [0x23, 0x00, 0x10, 0x00, 1, 2, 3, 4],
            code: SdoAbort::WriteReadOnly,
            keep: (0x1000, 0),
        },
        Refusal {
            what: "write of a read-only input",
            req: [0x2B, 0x01, 0x64, 0x01, 0, 0, 0, 0],
            code: SdoAbort::WriteReadOnly,
            keep: (0x6401, 1),
        },
        Refusal {
            what: "4 bytes to a U16",
            req: [0x23, 0x02, 0x20, 0x00, 0x20, 0x00, 0x00, 0x00],
            code: SdoAbort::LengthTooHigh,
            keep: (0x2002, 0),
        },
        Refusal {
            what: "1 byte to a U32",
            req: [0x2F, 0x05, 0x20, 0x03, 0x20, 0, 0, 0],
            code: SdoAbort::LengthTooLow,
            keep: (0x2005, 3),
        },
        Refusal {
            what: "above the range",
            req: [0x2B, 0x02, 0x20, 0x00, 0xE9, 0x03, 0, 0],
            code: SdoAbort::ValueTooHigh,
            keep: (0x2002, 0),
        },
        Refusal {
            what: "below the range",
            req: [0x2B, 0x02, 0x20, 0x00, 0x09, 0x00, 0, 0],
            code: SdoAbort::ValueTooLow,
            keep: (0x2002, 0),
        },
        Refusal {
            what: "application: wrong device state",
            req: [0x2F, 0x06, 0x20, 0x01, 0x11, 0, 0, 0],
            code: SdoAbort::DeviceState,
            keep: (0x2006, 1),
        },
        Refusal {
            what: "application refuses without a code",
            req: [0x2F, 0x06, 0x20, 0x02, 0x11, 0, 0, 0],
            code: SdoAbort::CannotStore,
            keep: (0x2006, 2),
        },
        Refusal {
            what: "application: unsupported access",
            req: [0x2F, 0x06, 0x20, 0x03, 0x11, 0, 0, 0],
            code: SdoAbort::UnsupportedAccess,
            keep: (0x2006, 3),
        },
        Refusal {
            what: "application: value range",
            req: [0x2F, 0x06, 0x20, 0x04, 0x11, 0, 0, 0],
            code: SdoAbort::ValueRange,
            keep: (0x2006, 4),
        },
        Refusal {
            what: "application: general error",
            req: [0x2F, 0x06, 0x20, 0x05, 0x11, 0, 0, 0],
            code: SdoAbort::General,
            keep: (0x2006, 5),
        },
        Refusal {
            what: "application: object not mappable",
            req: [0x2F, 0x06, 0x20, 0x06, 0x11, 0, 0, 0],
            code: SdoAbort::NotMappable,
            keep: (0x2006, 6),
        },
        Refusal {
            what: "application refuses a read",
            req: [0x40, 0x06, 0x20, 0x07, 0, 0, 0, 0],
            code: SdoAbort::DeviceState,
            keep: (0x2006, 1),
        },
    ];
    for c in &cases {
        let before = rig.value(c.keep.0, c.keep.1);
        let mux = Multiplexer::from_frame(&c.req);
        assert_eq!(
            rig.sdo(c.req),
            abort(mux.index, mux.sub, c.code),
            "{}",
            c.what
        );
        assert_eq!(rig.value(c.keep.0, c.keep.1), before, "{}", c.what);
    }
    // The refusing callback lets other accesses through.
    assert_eq!(
        rig.sdo([0x2F, 0x06, 0x20, 0x07, 0x42, 0, 0, 0]),
        [0x60, 0x06, 0x20, 0x07, 0, 0, 0, 0]
    );
    assert_eq!(rig.upload(0x2006, 1), Ok(vec![0]));
    // Ranged object still accepts its limits.
    assert_eq!(
        rig.sdo([0x2B, 0x02, 0x20, 0x00, 0xE8, 0x03, 0, 0]),
        [0x60, 0x02, 0x20, 0x00, 0, 0, 0, 0]
    );
    assert_eq!(rig.value(0x2002, 0), 1000u16.to_le_bytes().to_vec());
}

#[test]
fn refused_segmented_download_changes_nothing() {
    let mut rig = Rig::new(test_od!(), NODE);
    // The application refuses when the complete value is written, after
    // the last segment (a client may use segmented transfer for one byte):
    // the abort replaces the last confirmation.
    assert_eq!(
        rig.sdo([0x21, 0x06, 0x20, 0x01, 1, 0, 0, 0]),
        [0x60, 0x06, 0x20, 0x01, 0, 0, 0, 0]
    );
    // t = 0, n = 6, c = 1 -> 0x0D (CiA 301 SDO download segment protocol).
    assert_eq!(
        rig.sdo([0x0D, 0x11, 0, 0, 0, 0, 0, 0]),
        abort(0x2006, 1, SdoAbort::DeviceState)
    );
    assert_eq!(rig.value(0x2006, 1), vec![0]);
    // Stated size differs from the data (CiA 301 abort 0x06070010).
    let r = rig.sdo([0x21, 0x00, 0x20, 0x00, 20, 0, 0, 0]);
    assert_eq!(r[0], 0x60);
    assert_eq!(
        rig.sdo([0x00, b'a', b'b', b'c', b'd', b'e', b'f', b'g']),
        [0x20, 0, 0, 0, 0, 0, 0, 0]
    );
    assert_eq!(
        rig.sdo([0x13, b'h', b'i', b'j', b'k', b'l', b'm', 0]),
        abort(0x2000, 0, SdoAbort::LengthMismatch)
    );
    assert_eq!(rig.value(0x2000, 0), b"CANopen".to_vec());
    // More than the transfer buffer, size stated at initiate (0x06070012).
    let size = ((SDOS_BUFFER_SIZE + 1) as u32).to_le_bytes();
    assert_eq!(
        rig.sdo([0x21, 0x00, 0x20, 0x00, size[0], size[1], size[2], size[3]]),
        abort(0x2000, 0, SdoAbort::LengthTooHigh)
    );
    // More than the object holds: the dictionary refuses at initiate.
    let size = ((DOMAIN_LEN + 1) as u32).to_le_bytes();
    assert_eq!(
        rig.sdo([0x21, 0x01, 0x20, 0x00, size[0], size[1], size[2], size[3]]),
        abort(0x2001, 0, SdoAbort::LengthTooHigh)
    );
    // 8 bytes announced for a U32.
    assert_eq!(
        rig.sdo([0x21, 0x05, 0x20, 0x03, 8, 0, 0, 0]),
        abort(0x2005, 3, SdoAbort::LengthTooHigh)
    );
    // 3 bytes announced for a U64.
    assert_eq!(
        rig.sdo([0x21, 0x05, 0x20, 0x04, 3, 0, 0, 0]),
        abort(0x2005, 4, SdoAbort::LengthTooLow)
    );
    assert_eq!(rig.value(0x2000, 0), b"CANopen".to_vec());
    assert_eq!(rig.value(0x2005, 4), vec![0; 8]);
}

#[test]
fn upload_larger_than_the_buffer_is_out_of_memory() {
    let mut rig = Rig::new(test_od!(), NODE);
    let long = vec![b'#'; SDOS_BUFFER_SIZE + 1];
    rig.set(0x2000, 0, &long);
    assert_eq!(
        rig.sdo(expedited_upload(0x2000, 0)),
        abort(0x2000, 0, SdoAbort::OutOfMemory)
    );
    // The server is free again.
    assert_eq!(rig.upload(0x1000, 0), Ok(0x191u32.to_le_bytes().to_vec()));
}

#[test]
fn toggle_error_aborts_and_keeps_the_value() {
    let mut rig = Rig::new(test_od!(), NODE);
    // Download: first segment t = 0, second must be t = 1 (CiA 301 SDO download segment protocol).
    assert_eq!(rig.sdo([0x21, 0x00, 0x20, 0x00, 10, 0, 0, 0])[0], 0x60);
    assert_eq!(
        rig.sdo([0x00, 1, 2, 3, 4, 5, 6, 7]),
        [0x20, 0, 0, 0, 0, 0, 0, 0]
    );
    assert_eq!(
        rig.sdo([0x09, 8, 9, 10, 0, 0, 0, 0]),
        abort(0x2000, 0, SdoAbort::ToggleBit)
    );
    assert_eq!(rig.value(0x2000, 0), b"CANopen".to_vec());
    // Upload: first request with t = 1.
    assert_eq!(rig.sdo(expedited_upload(0x2000, 0))[0], 0x41);
    assert_eq!(
        rig.sdo([0x70, 0, 0, 0, 0, 0, 0, 0]),
        abort(0x2000, 0, SdoAbort::ToggleBit)
    );
}

#[test]
fn unknown_and_unexpected_commands() {
    let mut rig = Rig::new(test_od!(), NODE);
    // Reserved command specifier 7 (0xE0).
    assert_eq!(
        rig.sdo([0xE0, 0x00, 0x10, 0x00, 0, 0, 0, 0]),
        abort(0x1000, 0, SdoAbort::UnknownCommand)
    );
    // Block download initiate (CiA 301 SDO block download protocol, ccs = 6)
    // is served: A4 = scs 5 with CRC support, block size in byte 4. Inside
    // the sub-block only the client's abort (0x80) ends it, unanswered.
    assert_eq!(
        rig.sdo([0xC6, 0x00, 0x20, 0x00, 0x20, 0, 0, 0]),
        [
            0xA4,
            0x00,
            0x20,
            0x00,
            cop::config::SDO_BLOCKSIZE_DOWNLOAD,
            0,
            0,
            0
        ]
    );
    rig.client_abort(0x2000, 0);
    // Segment request with no transfer: multiplexer 0000h/00h.
    assert_eq!(
        rig.sdo([0x60, 0, 0, 0, 0, 0, 0, 0]),
        abort(0, 0, SdoAbort::UnknownCommand)
    );
    // A new initiate while a download runs aborts the download and is
    // not carried out.
    assert_eq!(rig.sdo([0x21, 0x00, 0x20, 0x00, 10, 0, 0, 0])[0], 0x60);
    assert_eq!(
        rig.sdo([0x2F, 0x00, 0x62, 0x01, 0x0F, 0, 0, 0]),
        abort(0x2000, 0, SdoAbort::UnknownCommand)
    );
    assert_eq!(rig.value(0x6200, 1), vec![0]);
    assert_eq!(rig.value(0x2000, 0), b"CANopen".to_vec());
    // Afterwards the server serves again.
    assert_eq!(
        rig.sdo([0x2F, 0x00, 0x62, 0x01, 0x0F, 0, 0, 0]),
        [0x60, 0x00, 0x62, 0x01, 0, 0, 0, 0]
    );
}

#[test]
fn timeout_aborts_a_stalled_transfer() {
    let mut rig = Rig::new(test_od!(), NODE);
    assert_eq!(rig.sdo(expedited_upload(0x2000, 0))[0], 0x41);
    let mark = rig.bus.sent().len();
    rig.bus.advance_ticks(SDOS_DEFAULT_TIMEOUT - 1);
    rig.cycle();
    assert!(rig.sent_since(mark).is_empty());
    rig.bus.advance_ticks(1);
    rig.cycle();
    let sent = rig.sent_since(mark);
    assert_eq!(sent.len(), 1);
    assert_eq!(sent[0].id, CanId::std_masked(0x582));
    // CiA 301 abort 0x05040000 "SDO protocol timed out".
    assert_eq!(sent[0].data, abort(0x2000, 0, SdoAbort::Timeout));
    // Nothing more, and the late segment request finds no transfer.
    rig.bus.advance_ticks(SDOS_DEFAULT_TIMEOUT * 3);
    rig.cycle();
    assert_eq!(rig.sent_since(mark).len(), 1);
    assert_eq!(
        rig.sdo([0x60, 0, 0, 0, 0, 0, 0, 0]),
        abort(0, 0, SdoAbort::UnknownCommand)
    );
}

#[test]
fn frames_with_dlc_other_than_8_are_ignored() {
    let mut rig = Rig::new(test_od!(), NODE);
    let id = CanId::std_masked(0x602);
    // Seed 004 example 2 shortened to the 4 meaningful bytes.
    rig.sdo_silent(CanFrame::new(id, &[0x40, 0x00, 0x60, 0x01]));
    rig.sdo_silent(CanFrame::new(id, &[0x40, 0x00, 0x60, 0x01, 0, 0, 0]));
    rig.sdo_silent(CanFrame::remote(id, 8));
    // A short frame in the middle of a transfer does not disturb it.
    assert_eq!(rig.sdo(expedited_upload(0x2000, 0))[0], 0x41);
    rig.sdo_silent(CanFrame::new(id, &[0x70]));
    assert_eq!(
        rig.sdo([0x60, 0, 0, 0, 0, 0, 0, 0]),
        [0x01, b'C', b'A', b'N', b'o', b'p', b'e', b'n']
    );
}

#[test]
fn silent_in_stopped_working_in_preoperational_and_operational() {
    let mut rig = Rig::new(test_od!(), NODE);
    let read = [0x40, 0x00, 0x60, 0x01, 0, 0, 0, 0];
    // Seed 004 "Hinweis 2": SDO works in PRE-OPERATIONAL ...
    assert_eq!(rig.sdo(read), [0x4F, 0x00, 0x60, 0x01, 0x01, 0, 0, 0]);
    // ... and in OPERATIONAL.
    rig.nmt(0x01);
    assert_eq!(rig.stack.nmt_state(), NmtState::Operational);
    assert_eq!(rig.sdo(read), [0x4F, 0x00, 0x60, 0x01, 0x01, 0, 0, 0]);
    // A transfer running when the node is stopped is dropped silently.
    assert_eq!(rig.sdo(expedited_upload(0x2000, 0))[0], 0x41);
    rig.nmt(0x02);
    assert_eq!(rig.stack.nmt_state(), NmtState::Stopped);
    rig.sdo_silent(CanFrame::new(CanId::std_masked(0x602), &read));
    rig.sdo_silent(CanFrame::new(
        CanId::std_masked(0x602),
        &[0x2F, 0x00, 0x62, 0x01, 0xFF, 0, 0, 0],
    ));
    assert_eq!(rig.value(0x6200, 1), vec![0]);
    // Not even a timeout abort while stopped.
    let mark = rig.bus.sent().len();
    rig.bus.advance_ticks(SDOS_DEFAULT_TIMEOUT * 2);
    rig.cycle();
    assert!(rig.sent_since(mark).is_empty());
    // Back to PRE-OPERATIONAL: served again; the old transfer is gone.
    rig.nmt(0x80);
    assert_eq!(rig.stack.nmt_state(), NmtState::PreOperational);
    assert_eq!(
        rig.sdo([0x60, 0, 0, 0, 0, 0, 0, 0]),
        abort(0, 0, SdoAbort::UnknownCommand)
    );
    assert_eq!(rig.sdo(read), [0x4F, 0x00, 0x60, 0x01, 0x01, 0, 0, 0]);
}

#[test]
fn sdo_writes_reach_the_module_hooks() {
    let mut rig = Rig::new(test_od!(), NODE);
    // 0x1017 = 100 ms through SDO: the heartbeat producer follows (its
    // reconfiguration runs in the stack's write hooks).
    assert_eq!(
        rig.sdo([0x2B, 0x17, 0x10, 0x00, 100, 0, 0, 0]),
        [0x60, 0x17, 0x10, 0x00, 0, 0, 0, 0]
    );
    assert_eq!(rig.stack.heartbeat().period_ms(), 100);
    let mark = rig.bus.sent().len();
    for _ in 0..25 {
        rig.bus.advance_ms(10);
        rig.cycle();
    }
    let hb: Vec<_> = rig
        .sent_since(mark)
        .into_iter()
        .filter(|f| f.id == CanId::std_masked(0x702))
        .collect();
    // CiA 301 heartbeat protocol: 0x700 + node-ID, state 0x7F (pre-operational).
    assert_eq!(hb.len(), 2);
    assert_eq!(hb[0].payload(), &[0x7F]);
}

/// A dictionary with the server parameter 0x1200 (rw here so that tests can
/// change it) and one object to read.
macro_rules! od_with_1200 {
    ($rx:expr, $tx:expr) => {{
        static COUNT: [u8; 1] = [2];
        static RX: [AtomicU8; 4] = decl::zeroed();
        static RX_DEF: [u8; 4] = ($rx as u32).to_ne_bytes();
        static TX: [AtomicU8; 4] = decl::zeroed();
        static TX_DEF: [u8; 4] = ($tx as u32).to_ne_bytes();
        static S1200: [ObdSubEntry; 3] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &COUNT),
            ObdSubEntry::ram(1, DataType::UInt32, Access::RW, &RX, Some(&RX_DEF)),
            ObdSubEntry::ram(2, DataType::UInt32, Access::RW, &TX, Some(&TX_DEF)),
        ];
        cop::od_rom!(static S1000: u32 = 0x0000_0191 => UInt32, R);
        static GENERIC: [ObdEntry; 2] = [
            ObdEntry::new(0x1000, &S1000, None),
            ObdEntry::new(0x1200, &S1200, None),
        ];
        ObjectDictionary::new(&GENERIC, &[], &[]).unwrap()
    }};
}

const READ_1000: [u8; 8] = [0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0];
const DEVICE_TYPE_RESPONSE: [u8; 8] = [0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0, 0];

#[test]
fn base_cob_ids_in_0x1200_mean_plus_node_id() {
    // objdict.h files often declare 0x600 / 0x580; the node-ID is added.
    let mut rig = Rig::new(od_with_1200!(0x600, 0x580), 3);
    assert_eq!(rig.sdo_on(0x603, 0x583, READ_1000), DEVICE_TYPE_RESPONSE);
    rig.sdo_silent(CanFrame::new(CanId::std_masked(0x600), &READ_1000));
}

#[test]
fn explicit_and_changed_cob_ids_from_0x1200() {
    let mut rig = Rig::new(od_with_1200!(0x640, 0x5C0), 3);
    assert_eq!(rig.sdo_on(0x640, 0x5C0, READ_1000), DEVICE_TYPE_RESPONSE);
    rig.sdo_silent(CanFrame::new(CanId::std_masked(0x603), &READ_1000));
    // CiA 301 §7.5.2.33: while the COB-ID is valid its identifier stays;
    // another one is refused (abort 0x06090030) and changes nothing.
    assert_eq!(
        rig.sdo_on(0x640, 0x5C0, [0x23, 0x00, 0x12, 0x02, 0xC1, 0x05, 0, 0]),
        [0x80, 0x00, 0x12, 0x02, 0x30, 0x00, 0x09, 0x06]
    );
    assert_eq!(rig.sdo_on(0x640, 0x5C0, READ_1000), DEVICE_TYPE_RESPONSE);
    // An identifier CiA 301 §7.3.5 reserves for another service (here
    // COB-ID 2 of SRDO 1 of node 1) is refused (abort 0x06090030, value
    // range) and changes nothing.
    assert_eq!(
        rig.sdo_on(0x640, 0x5C0, [0x23, 0x00, 0x12, 0x02, 0x02, 0x01, 0, 0]),
        [0x80, 0x00, 0x12, 0x02, 0x30, 0x00, 0x09, 0x06]
    );
    // Bit 31 of 0x1200.2 through SDO: the confirmation still goes out on
    // the old COB-ID, then the server is silent.
    assert_eq!(
        rig.sdo_on(0x640, 0x5C0, [0x23, 0x00, 0x12, 0x02, 0xC0, 0x05, 0, 0x80]),
        [0x60, 0x00, 0x12, 0x02, 0, 0, 0, 0]
    );
    rig.sdo_silent(CanFrame::new(CanId::std_masked(0x640), &READ_1000));
    // Now the new identifier is taken, and the server answers on it.
    rig.set(0x1200, 2, &0x5C1u32.to_le_bytes());
    assert_eq!(rig.sdo_on(0x640, 0x5C1, READ_1000), DEVICE_TYPE_RESPONSE);
    // Bit 31 (CiA 301 object 1200h: not valid) switches the server off.
    rig.set(0x1200, 1, &0x8000_0640u32.to_le_bytes());
    rig.sdo_silent(CanFrame::new(CanId::std_masked(0x640), &READ_1000));
    // Reset communication restores 0x1200 and with it the server.
    rig.nmt(0x82);
    rig.cycle();
    assert_eq!(rig.sdo_on(0x640, 0x5C0, READ_1000), DEVICE_TYPE_RESPONSE);
}

/// A server parameter object beyond `SDO_MAX_SERVER_IN_OBD` (CiA 301
/// 7.5.2.33 numbers servers from 0x1200): the stack has no channel for it,
/// so a valid COB-ID there would be a server that never answers. Such a
/// write is refused (abort 0x06090030); an invalid value (bit 31) stays
/// data as before.
#[test]
fn a_server_object_without_a_channel_takes_no_valid_cob_id() {
    const BEYOND: u16 = 0x1200 + cop::config::SDO_MAX_SERVER_IN_OBD as u16;
    static COUNT: [u8; 1] = [3];
    static RX: [AtomicU8; 4] = decl::zeroed();
    static TX: [AtomicU8; 4] = decl::zeroed();
    static OFF: [u8; 4] = 0x8000_0000u32.to_ne_bytes();
    static SUBS: [ObdSubEntry; 3] = [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &COUNT),
        ObdSubEntry::ram(1, DataType::UInt32, Access::RW, &RX, Some(&OFF)),
        ObdSubEntry::ram(2, DataType::UInt32, Access::RW, &TX, Some(&OFF)),
    ];
    cop::od_rom!(static S1000: u32 = 0x0000_0191 => UInt32, R);
    static GENERIC: [ObdEntry; 2] = [
        ObdEntry::new(0x1000, &S1000, None),
        ObdEntry::new(BEYOND, &SUBS, None),
    ];
    let mut rig = Rig::new(ObjectDictionary::new(&GENERIC, &[], &[]).unwrap(), 3);
    let [lo, hi] = BEYOND.to_le_bytes();
    for sub in [1, 2] {
        assert_eq!(
            rig.sdo([0x23, lo, hi, sub, 0x41, 0x06, 0, 0]),
            [0x80, lo, hi, sub, 0x30, 0x00, 0x09, 0x06],
            "valid COB-ID in sub {sub}"
        );
        assert_eq!(
            rig.sdo([0x23, lo, hi, sub, 0x41, 0x06, 0, 0x80]),
            [0x60, lo, hi, sub, 0, 0, 0, 0],
            "bit 31 set in sub {sub}"
        );
    }
}
