//! Unit tests of the SDO server against a small dictionary, without the
//! stack. Byte vectors cite seed 004 or the CiA 301 section they follow.

use core::sync::atomic::AtomicU8;

use super::*;
use crate::error::CopKernel;
use crate::od::{
    Access, DataType, NoHooks, ObdEntry, ObdSubEntry, Object, ObjectDictionary, Staged, decl,
};

const NODE: u8 = 2;
const REQ: u16 = 0x602;
const RESP: u16 = 0x582;
/// Capacity of the long string: more than the transfer buffer.
const STR_CAP: usize = SDOS_BUFFER_SIZE + 44;

/// A fresh dictionary per test (the variables are statics of each
/// expansion, so tests running in parallel do not share them):
/// 0x1000 U32 const, 0x2000 U8 rw, 0x2001 U16 rw range 10..=1000,
/// 0x2002 U32 read-only, 0x2003 U32 write-only, 0x2004 VISIBLE_STRING of
/// capacity STR_CAP, 0x2005 U64 rw, 0x6200.1 U8 rw.
macro_rules! test_od {
    () => {{
        static DEVICE_TYPE: [u8; 4] = 0x0000_0191u32.to_ne_bytes();
        static U16_VAR: [AtomicU8; 2] = decl::init(100u16.to_ne_bytes());
        static U16_LIMITS: [u8; 6] = decl::limits(100u16.to_ne_bytes(), 10u16.to_ne_bytes(), 1000u16.to_ne_bytes());
        static RO_VAR: [AtomicU8; 4] = decl::init(0x1234_5678u32.to_ne_bytes());
        static STR_VAR: [AtomicU8; STR_CAP + 1] = decl::zeroed();
        static OUT_COUNT: [u8; 1] = [1];
        static OUT_VAR: [AtomicU8; 1] = decl::zeroed();
        static S1000: [ObdSubEntry; 1] = [ObdSubEntry::rom(
            0,
            DataType::UInt32,
            Access::R,
            &DEVICE_TYPE,
        )];
        crate::od_ram!(static S2000, U8_VAR: u8 => UInt8, RW);
        static S2001: [ObdSubEntry; 1] = [ObdSubEntry::ram_range(
            0,
            DataType::UInt16,
            Access::RW,
            &U16_VAR,
            &U16_LIMITS,
        )];
        static S2002: [ObdSubEntry; 1] = decl::ram_object(DataType::UInt32, Access::R, &RO_VAR);
        crate::od_ram!(static S2003, WO_VAR: u32 => UInt32, W);
        static S2004: [ObdSubEntry; 1] = [ObdSubEntry::ram_string(0, Access::RW, &STR_VAR, c"")];
        crate::od_ram!(static S2005, U64_VAR: u64 => UInt64, RW);
        static S6200: [ObdSubEntry; 2] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &OUT_COUNT),
            ObdSubEntry::ram(1, DataType::UInt8, Access::RW, &OUT_VAR, None),
        ];
        static GENERIC: [ObdEntry; 1] = [ObdEntry::new(0x1000, &S1000, None)];
        static MANUFACTURER: [ObdEntry; 6] = [
            ObdEntry::new(0x2000, &S2000, None),
            ObdEntry::new(0x2001, &S2001, None),
            ObdEntry::new(0x2002, &S2002, None),
            ObdEntry::new(0x2003, &S2003, None),
            ObdEntry::new(0x2004, &S2004, None),
            ObdEntry::new(0x2005, &S2005, None),
        ];
        static DEVICE: [ObdEntry; 1] = [ObdEntry::new(0x6200, &S6200, None)];
        ObjectDictionary::new(&GENERIC, &MANUFACTURER, &DEVICE).unwrap()
    }};
}

/// Records the hook calls and refuses writes to one index.
struct Recorder {
    veto: Option<(u16, SdoAbort)>,
    checks: usize,
    stores: usize,
}

impl Recorder {
    fn new() -> Self {
        Recorder {
            veto: None,
            checks: 0,
            stores: 0,
        }
    }
}

impl WriteHooks for Recorder {
    fn check(&mut self, _: &ObjectDictionary, obj: &Object, _: &Staged) -> Result<(), OdError> {
        self.checks += 1;
        match self.veto {
            Some((index, abort)) if index == obj.index() => {
                Err(OdError::new(CopKernel::ObdAccessViolation, abort))
            }
            _ => Ok(()),
        }
    }
    fn before_store(&mut self, _: &ObjectDictionary, _: &Object, _: &Staged) {}
    fn after_store(&mut self, _: &ObjectDictionary, _: &Object) {
        self.stores += 1;
    }
}

struct Rig {
    od: ObjectDictionary,
    server: SdoServer,
    hooks: Recorder,
    now: Ticks,
}

impl Rig {
    fn new(od: ObjectDictionary) -> Rig {
        let mut server = SdoServer::new();
        server.reconfigure(&od, NODE);
        Rig {
            od,
            server,
            hooks: Recorder::new(),
            now: Ticks(1000),
        }
    }

    /// Sends one request on 0x602; returns the 8 response bytes (asserting
    /// that the response goes out on 0x582 with DLC 8).
    fn req(&mut self, bytes: [u8; 8]) -> Option<[u8; 8]> {
        let f = CanFrame::new(CanId::std_masked(REQ), &bytes);
        let r = self
            .server
            .on_frame(&self.od, &mut self.hooks, &f, self.now)?;
        assert_eq!(r.id, CanId::std_masked(RESP));
        assert_eq!(r.len, 8);
        Some(r.data)
    }

    fn read(&self, index: u16, sub: u8) -> Vec<u8> {
        let mut buf = vec![0u8; STR_CAP + 8];
        let n = self.od.read(index, sub, ByteOrder::Wire, &mut buf).unwrap();
        buf.truncate(n);
        buf
    }

    fn set(&self, index: u16, sub: u8, data: &[u8]) {
        self.od
            .write(index, sub, ByteOrder::Wire, data, &mut NoHooks)
            .unwrap();
    }

    /// Segmented download of `data` to `mux`, size stated or not; returns
    /// the answer to the last frame sent.
    fn download(&mut self, index: u16, sub: u8, data: &[u8], sized: bool) -> [u8; 8] {
        let mut init = [0x20, index as u8, (index >> 8) as u8, sub, 0, 0, 0, 0];
        if sized {
            init[0] = 0x21;
            init[4..].copy_from_slice(&(data.len() as u32).to_le_bytes());
        }
        let r = self.req(init).unwrap();
        if r[0] != 0x60 {
            return r;
        }
        let mut toggle = false;
        let chunks: Vec<&[u8]> = data.chunks(7).collect();
        for (i, c) in chunks.iter().enumerate() {
            let last = i + 1 == chunks.len();
            let f = ClientFrame::DownloadSegment {
                toggle,
                data: SegmentData::new(c).unwrap(),
                last,
            };
            let r = self.req(f.encode()).unwrap();
            if last || r[0] & 0xE0 != 0x20 {
                return r;
            }
            assert_eq!(r[0], 0x20 | if toggle { 0x10 } else { 0 });
            toggle = !toggle;
        }
        unreachable!("empty data")
    }

    /// Segmented upload after a 0x41 initiate response; returns the data.
    fn upload_segments(&mut self, size: usize) -> Vec<u8> {
        let mut out = Vec::new();
        let mut toggle = false;
        loop {
            let r = self
                .req(ClientFrame::UploadSegment { toggle }.encode())
                .unwrap();
            match ServerFrame::decode(&r).unwrap() {
                ServerFrame::UploadSegmentResponse {
                    toggle: t,
                    data,
                    last,
                } => {
                    assert_eq!(t, toggle);
                    out.extend_from_slice(data.as_slice());
                    if last {
                        break;
                    }
                    assert_eq!(data.len(), 7, "only the last segment may be short");
                }
                other => panic!("unexpected {other:?}"),
            }
            toggle = !toggle;
        }
        assert_eq!(out.len(), size);
        out
    }
}

fn abort_bytes(index: u16, sub: u8, code: SdoAbort) -> [u8; 8] {
    ServerFrame::Abort {
        mux: Multiplexer::new(index, sub),
        code: code.code(),
    }
    .encode()
}

#[test]
fn predefined_connection_set_without_0x1200() {
    let rig = Rig::new(test_od!());
    assert_eq!(rig.server.rx_id(), CanId::std(0x602));
    assert_eq!(rig.server.tx_id(), CanId::std(0x582));
}

#[test]
fn unconfigured_server_and_foreign_ids_are_silent() {
    let od = test_od!();
    let mut s = SdoServer::new();
    let f = CanFrame::new(CanId::std_masked(REQ), &[0x40, 0, 0x10, 0, 0, 0, 0, 0]);
    assert_eq!(s.on_frame(&od, &mut NoHooks, &f, Ticks(0)), None);
    s.reconfigure(&od, NODE);
    let other = CanFrame::new(CanId::std_masked(0x603), &f.data);
    assert_eq!(s.on_frame(&od, &mut NoHooks, &other, Ticks(0)), None);
    assert!(s.on_frame(&od, &mut NoHooks, &f, Ticks(0)).is_some());
}

#[test]
fn seed_004_example_1_write_reaches_the_variable() {
    // Seed 004 "Beispiel 1": 602 2F 00 62 01 FF 00 00 00 -> 582 60 00 62 01 00 00 00 00.
    let mut rig = Rig::new(test_od!());
    let r = rig.req([0x2F, 0x00, 0x62, 0x01, 0xFF, 0x00, 0x00, 0x00]);
    assert_eq!(r, Some([0x60, 0x00, 0x62, 0x01, 0x00, 0x00, 0x00, 0x00]));
    assert_eq!(rig.read(0x6200, 1), vec![0xFF]);
    assert_eq!(rig.hooks.checks, 1, "the write went through the hooks");
    assert_eq!(rig.hooks.stores, 1);
}

#[test]
fn expedited_upload_of_each_width() {
    // CiA 301 SDO upload initiate protocol: n = 4 - size; 0x43 for 4 bytes.
    let mut rig = Rig::new(test_od!());
    assert_eq!(
        rig.req([0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0]),
        Some([0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0x00, 0x00])
    );
    assert_eq!(
        rig.req([0x40, 0x01, 0x20, 0x00, 0, 0, 0, 0]),
        Some([0x4B, 0x01, 0x20, 0x00, 100, 0, 0, 0])
    );
    rig.set(0x2004, 0, b"abc");
    assert_eq!(
        rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]),
        Some([0x47, 0x04, 0x20, 0x00, b'a', b'b', b'c', 0])
    );
}

#[test]
fn expedited_download_without_size_uses_the_type_width() {
    // CiA 301 SDO download initiate protocol: 0x22 = expedited, size not indicated.
    let mut rig = Rig::new(test_od!());
    let r = rig.req([0x22, 0x01, 0x20, 0x00, 0xF4, 0x01, 0xEE, 0xEE]);
    assert_eq!(r, Some([0x60, 0x01, 0x20, 0x00, 0, 0, 0, 0]));
    assert_eq!(rig.read(0x2001, 0), 500u16.to_le_bytes().to_vec());
}

#[test]
fn expedited_download_with_wrong_size_keeps_the_value() {
    let mut rig = Rig::new(test_od!());
    // 0x23: four bytes to a U16 -> too long.
    let r = rig.req([0x23, 0x01, 0x20, 0x00, 1, 2, 3, 4]);
    assert_eq!(r, Some(abort_bytes(0x2001, 0, SdoAbort::LengthTooHigh)));
    // 0x2F: one byte to a U16 -> too short.
    let r = rig.req([0x2F, 0x01, 0x20, 0x00, 50, 0, 0, 0]);
    assert_eq!(r, Some(abort_bytes(0x2001, 0, SdoAbort::LengthTooLow)));
    assert_eq!(rig.read(0x2001, 0), 100u16.to_le_bytes().to_vec());
}

#[test]
fn dictionary_refusals_pass_through_unchanged() {
    let mut rig = Rig::new(test_od!());
    let cases: [([u8; 8], [u8; 8]); 6] = [
        (
            [0x40, 0x00, 0x30, 0x00, 0, 0, 0, 0],
            abort_bytes(0x3000, 0, SdoAbort::ObjectNotExist),
        ),
        (
            [0x40, 0x00, 0x62, 0x02, 0, 0, 0, 0],
            abort_bytes(0x6200, 2, SdoAbort::SubindexNotExist),
        ),
        (
            [0x40, 0x03, 0x20, 0x00, 0, 0, 0, 0],
            abort_bytes(0x2003, 0, SdoAbort::ReadWriteOnly),
        ),
        (
            [0x23, 0x02, 0x20, 0x00, 1, 2, 3, 4],
            abort_bytes(0x2002, 0, SdoAbort::WriteReadOnly),
        ),
        (
            [0x2B, 0x01, 0x20, 0x00, 0xE9, 0x03, 0, 0],
            abort_bytes(0x2001, 0, SdoAbort::ValueTooHigh),
        ),
        (
            [0x2B, 0x01, 0x20, 0x00, 9, 0, 0, 0],
            abort_bytes(0x2001, 0, SdoAbort::ValueTooLow),
        ),
    ];
    for (req, want) in cases {
        assert_eq!(rig.req(req), Some(want), "request {req:02X?}");
        assert!(!rig.server.is_busy());
    }
    assert_eq!(rig.read(0x2001, 0), 100u16.to_le_bytes().to_vec());
    assert_eq!(rig.read(0x2002, 0), 0x1234_5678u32.to_le_bytes().to_vec());
}

#[test]
fn module_hook_veto_is_the_abort_code_and_nothing_is_stored() {
    let mut rig = Rig::new(test_od!());
    rig.hooks.veto = Some((0x2000, SdoAbort::DeviceState));
    let r = rig.req([0x2F, 0x00, 0x20, 0x00, 0x55, 0, 0, 0]);
    assert_eq!(r, Some(abort_bytes(0x2000, 0, SdoAbort::DeviceState)));
    assert_eq!(rig.read(0x2000, 0), vec![0]);
    assert_eq!(rig.hooks.stores, 0);
    // The same veto at the end of a segmented download.
    rig.hooks.veto = Some((0x2004, SdoAbort::CannotStore));
    let r = rig.download(0x2004, 0, b"refused text", true);
    assert_eq!(r, abort_bytes(0x2004, 0, SdoAbort::CannotStore));
    assert_eq!(rig.read(0x2004, 0), Vec::<u8>::new());
}

#[test]
fn segmented_upload_frames_follow_cia301() {
    // CiA 301 SDO upload initiate / upload segment protocols: 0x41 + size, then 0x00/0x10 segments,
    // the last with c = 1 and n = unused bytes.
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, b"ABCDEFGHIJ");
    assert_eq!(
        rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]),
        Some([0x41, 0x04, 0x20, 0x00, 10, 0, 0, 0])
    );
    assert!(rig.server.is_busy());
    assert_eq!(
        rig.req([0x60, 0, 0, 0, 0, 0, 0, 0]),
        Some([0x00, b'A', b'B', b'C', b'D', b'E', b'F', b'G'])
    );
    // Second segment: toggle 1, 3 bytes, n = 4, c = 1 -> 0x10 | 0x08 | 0x01.
    assert_eq!(
        rig.req([0x70, 0, 0, 0, 0, 0, 0, 0]),
        Some([0x19, b'H', b'I', b'J', 0, 0, 0, 0])
    );
    assert!(!rig.server.is_busy());
}

#[test]
fn upload_is_a_snapshot_taken_at_initiate() {
    let mut rig = Rig::new(test_od!());
    let first = [b'x'; 40];
    rig.set(0x2004, 0, &first);
    assert_eq!(
        rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]).unwrap()[0],
        0x41
    );
    // The application changes the string while the transfer runs.
    rig.set(0x2004, 0, b"changed");
    assert_eq!(rig.upload_segments(40), first.to_vec());
}

#[test]
fn empty_string_uploads_as_zero_length_segmented_transfer() {
    // Expedited transfer cannot state 0 bytes: 0x41 with size 0, then one
    // segment with n = 7, c = 1 (CiA 301 SDO upload segment protocol).
    let mut rig = Rig::new(test_od!());
    assert_eq!(
        rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]),
        Some([0x41, 0x04, 0x20, 0x00, 0, 0, 0, 0])
    );
    assert_eq!(
        rig.req([0x60, 0, 0, 0, 0, 0, 0, 0]),
        Some([0x0F, 0, 0, 0, 0, 0, 0, 0])
    );
}

#[test]
fn download_is_written_once_after_the_last_segment() {
    let mut rig = Rig::new(test_od!());
    let text: Vec<u8> = (0..100u8).map(|i| b'a' + i % 26).collect();
    let init = [0x21, 0x04, 0x20, 0x00, 100, 0, 0, 0];
    assert_eq!(rig.req(init), Some([0x60, 0x04, 0x20, 0x00, 0, 0, 0, 0]));
    let mut toggle = false;
    for (i, c) in text.chunks(7).enumerate() {
        let last = (i + 1) * 7 >= text.len();
        if !last {
            let f = ClientFrame::DownloadSegment {
                toggle,
                data: SegmentData::new(c).unwrap(),
                last,
            };
            rig.req(f.encode()).unwrap();
            // Nothing reaches the variable before the end.
            assert_eq!(rig.read(0x2004, 0), Vec::<u8>::new());
            assert_eq!(rig.hooks.checks, 0);
            toggle = !toggle;
        } else {
            let f = ClientFrame::DownloadSegment {
                toggle,
                data: SegmentData::new(c).unwrap(),
                last,
            };
            // 100 = 14 * 7 + 2: last segment t = 0, n = 5, c = 1 -> 0x0B.
            assert_eq!(f.encode()[0], 0x0B);
            assert_eq!(rig.req(f.encode()), Some([0x20, 0, 0, 0, 0, 0, 0, 0]));
        }
    }
    assert_eq!(rig.read(0x2004, 0), text);
    assert_eq!((rig.hooks.checks, rig.hooks.stores), (1, 1));
}

#[test]
fn segmented_download_without_size_and_to_a_number() {
    let mut rig = Rig::new(test_od!());
    assert_eq!(
        rig.download(0x2004, 0, b"no size given", false),
        // 13 bytes = 2 segments: the second (last) one has t = 1.
        [0x30, 0, 0, 0, 0, 0, 0, 0]
    );
    assert_eq!(rig.read(0x2004, 0), b"no size given".to_vec());
    // A U64 fits no expedited frame: segmented, 8 bytes.
    let v = 0x0102_0304_0506_0708u64.to_le_bytes();
    assert_eq!(rig.download(0x2005, 0, &v, true)[0], 0x30);
    assert_eq!(rig.read(0x2005, 0), v.to_vec());
}

#[test]
fn stated_size_must_match_the_data() {
    let mut rig = Rig::new(test_od!());
    // Announce 10 bytes, send 14 (CiA 301 abort 0x06070010).
    let r = rig.req([0x21, 0x04, 0x20, 0x00, 10, 0, 0, 0]);
    assert_eq!(r.unwrap()[0], 0x60);
    assert_eq!(rig.req([0x00, 1, 2, 3, 4, 5, 6, 7]).unwrap()[0], 0x20);
    let r = rig.req([0x11, 1, 2, 3, 4, 5, 6, 7]);
    assert_eq!(r, Some(abort_bytes(0x2004, 0, SdoAbort::LengthMismatch)));
    // Announce 10, send 7.
    rig.req([0x21, 0x04, 0x20, 0x00, 10, 0, 0, 0]).unwrap();
    let r = rig.req([0x01, 1, 2, 3, 4, 5, 6, 7]);
    assert_eq!(r, Some(abort_bytes(0x2004, 0, SdoAbort::LengthMismatch)));
    assert_eq!(rig.read(0x2004, 0), Vec::<u8>::new());
    // A U64 announced with 5 bytes is refused at initiate by the dictionary.
    let r = rig.req([0x21, 0x05, 0x20, 0x00, 5, 0, 0, 0]);
    assert_eq!(r, Some(abort_bytes(0x2005, 0, SdoAbort::LengthTooLow)));
}

#[test]
fn download_longer_than_the_buffer_is_refused() {
    let mut rig = Rig::new(test_od!());
    // Size stated at initiate: the object could take it, the buffer not.
    let size = (SDOS_BUFFER_SIZE + 1) as u32;
    let mut init = [0x21, 0x04, 0x20, 0x00, 0, 0, 0, 0];
    init[4..].copy_from_slice(&size.to_le_bytes());
    assert_eq!(
        rig.req(init),
        Some(abort_bytes(0x2004, 0, SdoAbort::LengthTooHigh))
    );
    assert!(!rig.server.is_busy());
    // Size not stated: refused at the segment that overflows.
    let data = vec![b'z'; SDOS_BUFFER_SIZE + 10];
    assert_eq!(
        rig.download(0x2004, 0, &data, false),
        abort_bytes(0x2004, 0, SdoAbort::LengthTooHigh)
    );
    assert!(!rig.server.is_busy());
    assert_eq!(rig.read(0x2004, 0), Vec::<u8>::new());
    // More than the object holds is the dictionary's refusal.
    let mut init = [0x21, 0x04, 0x20, 0x00, 0, 0, 0, 0];
    init[4..].copy_from_slice(&((STR_CAP + 1) as u32).to_le_bytes());
    assert_eq!(
        rig.req(init),
        Some(abort_bytes(0x2004, 0, SdoAbort::LengthTooHigh))
    );
}

#[test]
fn upload_longer_than_the_buffer_is_out_of_memory() {
    let mut rig = Rig::new(test_od!());
    let long = vec![b'q'; SDOS_BUFFER_SIZE + 1];
    rig.set(0x2004, 0, &long);
    assert_eq!(
        rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]),
        Some(abort_bytes(0x2004, 0, SdoAbort::OutOfMemory))
    );
    assert!(!rig.server.is_busy());
    // Exactly the buffer size still works.
    rig.set(0x2004, 0, &long[..SDOS_BUFFER_SIZE]);
    let r = rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]).unwrap();
    assert_eq!(r[0], 0x41);
    assert_eq!(
        rig.upload_segments(SDOS_BUFFER_SIZE),
        long[..SDOS_BUFFER_SIZE]
    );
}

#[test]
fn toggle_errors_abort() {
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, b"0123456789ABCDEF");
    rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]).unwrap();
    // First upload request must have t = 0 (CiA 301 SDO upload segment protocol).
    assert_eq!(
        rig.req([0x70, 0, 0, 0, 0, 0, 0, 0]),
        Some(abort_bytes(0x2004, 0, SdoAbort::ToggleBit))
    );
    assert!(!rig.server.is_busy());
    // Download: the second segment repeats t = 0.
    rig.req([0x21, 0x04, 0x20, 0x00, 14, 0, 0, 0]).unwrap();
    assert_eq!(rig.req([0x00, 1, 2, 3, 4, 5, 6, 7]).unwrap()[0], 0x20);
    assert_eq!(
        rig.req([0x01, 1, 2, 3, 4, 5, 6, 7]),
        Some(abort_bytes(0x2004, 0, SdoAbort::ToggleBit))
    );
    assert!(!rig.server.is_busy());
    assert_eq!(rig.read(0x2004, 0), b"0123456789ABCDEF".to_vec());
}

#[test]
fn unexpected_requests_abort_the_running_transfer() {
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, b"0123456789");
    for intruder in [
        [0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0], // initiate upload
        [0x2F, 0x00, 0x20, 0x00, 1, 0, 0, 0], // initiate download
        [0x00, 1, 2, 3, 4, 5, 6, 7],          // download segment during upload
    ] {
        rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]).unwrap();
        assert_eq!(
            rig.req(intruder),
            Some(abort_bytes(0x2004, 0, SdoAbort::UnknownCommand))
        );
        assert!(!rig.server.is_busy());
    }
    // Upload segment request during a download.
    rig.req([0x21, 0x04, 0x20, 0x00, 3, 0, 0, 0]).unwrap();
    assert_eq!(
        rig.req([0x60, 0, 0, 0, 0, 0, 0, 0]),
        Some(abort_bytes(0x2004, 0, SdoAbort::UnknownCommand))
    );
    // Nothing was written by the intruding initiate download.
    assert_eq!(rig.read(0x2000, 0), vec![0]);
    assert_eq!(rig.read(0x2004, 0), b"0123456789".to_vec());
}

#[test]
fn segment_without_transfer_and_block_initiate_while_busy_are_unknown_commands() {
    let mut rig = Rig::new(test_od!());
    // No transfer: the multiplexer is 0000h/00h (segments carry none).
    assert_eq!(
        rig.req([0x60, 0, 0, 0, 0, 0, 0, 0]),
        Some(abort_bytes(0, 0, SdoAbort::UnknownCommand))
    );
    assert_eq!(
        rig.req([0x00, 1, 2, 3, 4, 5, 6, 7]),
        Some(abort_bytes(0, 0, SdoAbort::UnknownCommand))
    );
    // Block upload initiate (CiA 301 SDO block upload protocol, ccs = 5)
    // of an object this dictionary lacks: the object's abort.
    assert_eq!(
        rig.req([0xA4, 0x18, 0x10, 0x01, 0x7F, 0, 0, 0]),
        Some(abort_bytes(0x1018, 1, SdoAbort::ObjectNotExist))
    );
    // Block download initiate during an upload aborts the upload.
    rig.set(0x2004, 0, b"0123456789");
    rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]).unwrap();
    assert_eq!(
        rig.req([0xC2, 0x00, 0x62, 0x01, 0, 0, 0, 0]),
        Some(abort_bytes(0x2004, 0, SdoAbort::UnknownCommand))
    );
    assert!(!rig.server.is_busy());
}

#[test]
fn client_abort_ends_the_transfer_silently() {
    let mut rig = Rig::new(test_od!());
    rig.req([0x21, 0x04, 0x20, 0x00, 14, 0, 0, 0]).unwrap();
    rig.req([0x00, 1, 2, 3, 4, 5, 6, 7]).unwrap();
    // CiA 301 SDO abort transfer protocol: 0x80, multiplexer, abort code.
    assert_eq!(rig.req([0x80, 0x04, 0x20, 0x00, 0, 0, 0, 0x08]), None);
    assert!(!rig.server.is_busy());
    assert_eq!(rig.read(0x2004, 0), Vec::<u8>::new());
    // An abort with no transfer running is not answered either.
    assert_eq!(rig.req([0x80, 0x04, 0x20, 0x00, 0, 0, 0, 0x08]), None);
}

#[test]
fn frames_with_other_lengths_are_ignored() {
    let mut rig = Rig::new(test_od!());
    let short = CanFrame::new(CanId::std_masked(REQ), &[0x40, 0x00, 0x10, 0x00]);
    assert_eq!(
        rig.server
            .on_frame(&rig.od, &mut rig.hooks, &short, rig.now),
        None
    );
    // ... even in the middle of a transfer, which goes on undisturbed.
    rig.set(0x2004, 0, b"0123456789");
    rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]).unwrap();
    let seven = CanFrame::new(CanId::std_masked(REQ), &[0x70, 0, 0, 0, 0, 0, 0]);
    assert_eq!(
        rig.server
            .on_frame(&rig.od, &mut rig.hooks, &seven, rig.now),
        None
    );
    let remote = CanFrame::remote(CanId::std_masked(REQ), 8);
    assert_eq!(
        rig.server
            .on_frame(&rig.od, &mut rig.hooks, &remote, rig.now),
        None
    );
    assert!(rig.server.is_busy());
    assert_eq!(rig.upload_segments(10), b"0123456789".to_vec());
}

#[test]
fn timeout_aborts_after_the_configured_ticks() {
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, b"0123456789");
    rig.req([0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0]).unwrap();
    let start = rig.now;
    assert_eq!(
        rig.server
            .poll(&rig.od, start.plus(SDOS_DEFAULT_TIMEOUT - 1)),
        None
    );
    // A valid segment restarts the supervision.
    rig.now = start.plus(SDOS_DEFAULT_TIMEOUT - 1);
    rig.req([0x60, 0, 0, 0, 0, 0, 0, 0]).unwrap();
    assert_eq!(
        rig.server.poll(&rig.od, start.plus(SDOS_DEFAULT_TIMEOUT)),
        None
    );
    let f = rig
        .server
        .poll(&rig.od, rig.now.plus(SDOS_DEFAULT_TIMEOUT))
        .unwrap();
    assert_eq!(f.id, CanId::std_masked(RESP));
    assert_eq!(f.data, abort_bytes(0x2004, 0, SdoAbort::Timeout));
    assert!(!rig.server.is_busy());
    assert_eq!(
        rig.server
            .poll(&rig.od, rig.now.plus(2 * SDOS_DEFAULT_TIMEOUT)),
        None
    );
}

#[test]
fn late_request_sees_the_timeout_without_poll() {
    let mut rig = Rig::new(test_od!());
    rig.req([0x21, 0x04, 0x20, 0x00, 14, 0, 0, 0]).unwrap();
    rig.now = rig.now.plus(SDOS_DEFAULT_TIMEOUT);
    // A segment of the expired transfer: answered with the timeout abort.
    assert_eq!(
        rig.req([0x00, 1, 2, 3, 4, 5, 6, 7]),
        Some(abort_bytes(0x2004, 0, SdoAbort::Timeout))
    );
    // A new request after an expired transfer is served.
    rig.req([0x21, 0x04, 0x20, 0x00, 14, 0, 0, 0]).unwrap();
    rig.now = rig.now.plus(SDOS_DEFAULT_TIMEOUT);
    assert_eq!(
        rig.req([0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0]).unwrap()[0],
        0x43
    );
}

#[test]
fn timeout_zero_disables_supervision_and_ticks_wrap() {
    let mut rig = Rig::new(test_od!());
    rig.server.set_timeout_ticks(0);
    rig.req([0x21, 0x04, 0x20, 0x00, 14, 0, 0, 0]).unwrap();
    assert_eq!(rig.server.poll(&rig.od, rig.now.plus(u32::MAX / 2)), None);
    assert!(rig.server.is_busy());
    // Supervision across the 32-bit tick wrap.
    rig.server.set_timeout_ticks(50);
    rig.server.cancel();
    rig.now = Ticks(u32::MAX - 10);
    rig.req([0x21, 0x04, 0x20, 0x00, 14, 0, 0, 0]).unwrap();
    assert_eq!(rig.server.poll(&rig.od, Ticks(38)), None);
    assert!(rig.server.poll(&rig.od, Ticks(39)).is_some());
}

#[test]
fn cancel_drops_the_transfer_without_answer() {
    let mut rig = Rig::new(test_od!());
    rig.req([0x21, 0x04, 0x20, 0x00, 14, 0, 0, 0]).unwrap();
    rig.server.cancel();
    assert!(!rig.server.is_busy());
    assert_eq!(
        rig.server
            .poll(&rig.od, rig.now.plus(10 * SDOS_DEFAULT_TIMEOUT)),
        None
    );
}

/// A server parameter object `index` with one COB-ID pair (0x1200 variants
/// through `od_1200!`): one dictionary per pair.
macro_rules! od_server {
    ($index:expr, $rx:expr, $tx:expr) => {{
        static COUNT: [u8; 1] = [2];
        static RX: [AtomicU8; 4] = decl::init(($rx as u32).to_ne_bytes());
        static TX: [AtomicU8; 4] = decl::init(($tx as u32).to_ne_bytes());
        static S1200: [ObdSubEntry; 3] = [
            ObdSubEntry::rom(0, DataType::UInt8, Access::R, &COUNT),
            ObdSubEntry::ram(1, DataType::UInt32, Access::RW, &RX, None),
            ObdSubEntry::ram(2, DataType::UInt32, Access::RW, &TX, None),
        ];
        static GENERIC: [ObdEntry; 1] = [ObdEntry::new($index, &S1200, None)];
        ObjectDictionary::new(&GENERIC, &[], &[]).unwrap()
    }};
}

macro_rules! od_1200 {
    ($rx:expr, $tx:expr) => {
        od_server!(0x1200, $rx, $tx)
    };
}

#[test]
fn cob_ids_from_0x1200() {
    let ids = |od: ObjectDictionary, node: u8| {
        let mut s = SdoServer::new();
        s.reconfigure(&od, node);
        (s.rx_id(), s.tx_id())
    };
    // The base value means base + node-ID.
    assert_eq!(
        ids(od_1200!(0x600, 0x580), 5),
        (CanId::std(0x605), CanId::std(0x585))
    );
    // Any other value is taken as it is.
    assert_eq!(
        ids(od_1200!(0x640, 0x5C0), 5),
        (CanId::std(0x640), CanId::std(0x5C0))
    );
    // 29-bit identifiers where the driver has them (CDRV_CAN_SPEC CAN20B);
    // otherwise the server is off.
    let ext = if crate::config::CDRV_CAN20B {
        (CanId::ext(0x1234), CanId::ext(0x1235))
    } else {
        (None, None)
    };
    assert_eq!(ids(od_1200!(0x2000_1234, 0x2000_1235), 5), ext);
    // Bit 31 in either direction disables the server.
    assert_eq!(ids(od_1200!(0x8000_0605u32, 0x585), 5), (None, None));
    assert_eq!(ids(od_1200!(0x605, 0x8000_0585u32), 5), (None, None));
    // An 11-bit COB-ID with bits above 10 set is not valid.
    assert_eq!(ids(od_1200!(0x1605, 0x585), 5), (None, None));
    // Identifiers CiA 301 §7.3.5 reserves for other services (here the
    // SRDO 1 pair of node 1 and the GFC) disable the server in either
    // direction.
    assert_eq!(ids(od_1200!(0x101, 0x585), 5), (None, None));
    assert_eq!(ids(od_1200!(0x605, 0x102), 5), (None, None));
    assert_eq!(ids(od_1200!(0x001, 0x585), 5), (None, None));
}

#[test]
fn additional_server_has_no_predefined_connection() {
    // CiA 301 7.5.2.33: the predefined connection set belongs to 0x1200
    // alone; 0x1201.. answer only on the COB-IDs of their objects.
    let ids = |od: ObjectDictionary, node: u8| {
        let mut s = SdoServer::with_index(0x1201);
        s.reconfigure(&od, node);
        (s.rx_id(), s.tx_id())
    };
    assert_eq!(ids(test_od!(), 5), (None, None));
    assert_eq!(
        ids(od_server!(0x1201, 0x641, 0x5C1), 5),
        (CanId::std(0x641), CanId::std(0x5C1))
    );
    // 0x600 / 0x580 are identifiers here, not bases for the node-ID.
    assert_eq!(
        ids(od_server!(0x1201, 0x600, 0x580), 5),
        (CanId::std(0x600), CanId::std(0x580))
    );
    assert_eq!(
        ids(od_server!(0x1201, 0x8000_0641u32, 0x5C1), 5),
        (None, None)
    );
    assert_eq!(ids(od_server!(0x1201, 0x101, 0x5C1), 5), (None, None));
    // Another server's object configures neither channel but its own.
    let od = od_server!(0x1201, 0x641, 0x5C1);
    let mut default = SdoServer::new();
    default.reconfigure(&od, 5);
    assert_eq!(
        (default.rx_id(), default.tx_id()),
        (CanId::std(0x605), CanId::std(0x585))
    );
    assert_eq!(ids(od_server!(0x1202, 0x641, 0x5C1), 5), (None, None));
}

#[test]
fn one_channel_per_server_object_from_0x1200() {
    let mut servers = SdoServers::new();
    assert_eq!(servers.channels().len(), SDO_MAX_SERVER_IN_OBD);
    for (n, s) in servers.channels().iter().enumerate() {
        assert_eq!(s.index(), SERVER_PARAMETER_INDEX + n as u16);
    }
    let od = test_od!();
    assert!(servers.receiving(CanId::std_masked(REQ)).is_none());
    servers.reconfigure(&od, NODE);
    let s = servers.receiving(CanId::std_masked(REQ)).unwrap();
    assert_eq!(s.index(), SERVER_PARAMETER_INDEX);
    assert!(servers.receiving(CanId::std_masked(0x603)).is_none());
    assert!(servers.at_rest());
}

#[test]
fn changed_cob_ids_drop_the_transfer() {
    let od = od_1200!(0x600, 0x580);
    let mut s = SdoServer::new();
    s.reconfigure(&od, 2);
    let init = CanFrame::new(
        CanId::std_masked(0x602),
        &[0x40, 0x00, 0x12, 0x01, 0, 0, 0, 0],
    );
    // 0x1200.1 itself is 4 bytes: expedited. It shows the COB-ID in use
    // (CiA 301), i.e. the base 0x600 plus node-ID 2.
    let r = s.on_frame(&od, &mut NoHooks, &init, Ticks(0)).unwrap();
    assert_eq!(r.data, [0x43, 0x00, 0x12, 0x01, 0x02, 0x06, 0x00, 0x00]);
    // Write 0x1200.1 = 0x8000_0602 through SDO: the server goes quiet.
    let w = CanFrame::new(
        CanId::std_masked(0x602),
        &[0x23, 0x00, 0x12, 0x01, 0x02, 0x06, 0x00, 0x80],
    );
    assert_eq!(
        s.on_frame(&od, &mut NoHooks, &w, Ticks(0)).unwrap().data[0],
        0x60
    );
    s.reconfigure(&od, 2);
    assert_eq!(s.rx_id(), None);
    assert_eq!(s.on_frame(&od, &mut NoHooks, &init, Ticks(0)), None);
    assert_eq!(s.poll(&od, Ticks(u32::MAX / 4)), None);
}

mod block;
