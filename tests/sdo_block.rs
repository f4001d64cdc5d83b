//! SDO block transfer, client and server of this library on the simulated
//! bus (CiA 301 SDO block download and block upload protocols): long
//! objects both ways with CRC, lost and corrupted frames injected by the
//! bus's fault filter, the protocol switch, buffer bounds and the codes of
//! refused transfers. The C view (`CcmSdocStartTransfer` with
//! kSdocTypeBlockDown / kSdocTypeBlockUp) is c_tests/test_master_api.c.

mod common;

use core::sync::atomic::AtomicU8;
use std::cell::Cell;
use std::rc::Rc;
use std::sync::{Mutex, MutexGuard};

use common::SdoNet as Net;
use cop::config::{SDO_BLOCKSIZE_DOWNLOAD, SDO_BLOCKSIZE_UPLOAD, SDOS_BUFFER_SIZE};
use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, decl};
use cop::port::CanFrame;
use cop::sdo::client::{Direction, SdocState};
use cop::sim::{Delivery, SimBus};
use cop::wire::sdo::block_crc;

static SERIAL: Mutex<()> = Mutex::new(());
fn serial() -> MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

/// Length of the long object: at least 200 bytes with the default buffer.
const LONG: usize = if SDOS_BUFFER_SIZE < 240 {
    SDOS_BUFFER_SIZE
} else {
    240
};

// Server dictionary (node 2): 0x2000 a VISIBLE_STRING of LONG bytes
// capacity, 0x2001 U8 const 0x5A, 0x2002 U32 read-only.
static TEXT: [AtomicU8; LONG + 1] = decl::zeroed();
static S2000: [ObdSubEntry; 1] = [ObdSubEntry::ram_string(0, Access::RW, &TEXT, c"")];
static S2001: [ObdSubEntry; 1] = [ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[0x5A])];
cop::od_ram!(static S2002, RO: u32 => UInt32, R);
static SERVER_MAN: [ObdEntry; 3] = [
    ObdEntry::new(0x2000, &S2000, None),
    ObdEntry::new(0x2001, &S2001, None),
    ObdEntry::new(0x2002, &S2002, None),
];

// Client buffers (node 1).
static TX_BUF: [AtomicU8; 256] = decl::zeroed();
static RX_BUF: [AtomicU8; 256] = decl::zeroed();

/// Printable bytes without NUL (the object is a string).
fn pattern(len: usize, seed: u8) -> Vec<u8> {
    (0..len)
        .map(|i| b' ' + ((i as u8).wrapping_mul(7).wrapping_add(seed) % 95))
        .collect()
}

impl Net {
    fn new() -> Net {
        Net::on_bus(&SERVER_MAN, 256)
    }

    /// Runs until the transfer ends (at most `limit` cycles).
    fn run_until_done(&mut self, limit: usize) {
        for _ in 0..limit {
            if self.state().0 != SdocState::Running {
                return;
            }
            self.run(1);
        }
    }

    /// Block download of `data` (from `TX_BUF`) into 0x2000, run until it
    /// ends (at most `limit` cycles).
    fn download(&mut self, data: &[u8], limit: usize) {
        load_tx(data);
        self.start(Direction::BlockDownload, 0x2000, &TX_BUF, data.len())
            .unwrap();
        self.run_until_done(limit);
    }

    /// Block upload of 0x2000 into the 256 bytes of `RX_BUF`, run until it
    /// ends (at most `limit` cycles).
    fn upload(&mut self, limit: usize) {
        self.start(Direction::BlockUpload, 0x2000, &RX_BUF, 256)
            .unwrap();
        self.run_until_done(limit);
    }

    fn transferred(&self) -> u32 {
        self.master.1.sdoc().transferred(0x1280).unwrap()
    }

    fn has(&self, line: &str) -> bool {
        self.bus.trace().iter().any(|l| l == line)
    }
}

fn load_tx(data: &[u8]) {
    let mut b = [0u8; 256];
    b[..data.len()].copy_from_slice(data);
    decl::set(&TX_BUF, b);
}

fn rx(len: usize) -> Vec<u8> {
    decl::get(&RX_BUF)[..len].to_vec()
}

/// Drops (or changes) the `nth` frame from `node` whose byte 0 is `b0`,
/// once; the counter tells whether it happened.
fn fault_once(
    bus: &SimBus,
    node: usize,
    id: u32,
    b0: u8,
    action: fn(&mut CanFrame) -> Delivery,
) -> Rc<Cell<u32>> {
    let hits = Rc::new(Cell::new(0u32));
    let h = hits.clone();
    bus.set_filter(Some(Box::new(move |from, f| {
        if from == node && f.id.id() == id && f.data[0] == b0 && h.get() == 0 {
            h.set(1);
            return action(f);
        }
        Delivery::Deliver
    })));
    hits
}

const SERVER: usize = 0;
const MASTER: usize = 1;

#[test]
fn long_object_both_ways_with_crc() {
    let _g = serial();
    let mut net = Net::new();
    let data = pattern(LONG, 3);
    net.download(&data, 200);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(&decl::get(&TEXT)[..LONG], &data[..]);
    assert_eq!(net.transferred(), LONG as u32);
    let t = net.bus.trace();
    // CiA 301 initiate SDO block download: C6 = ccs 6, cc, s; size LONG.
    assert_eq!(
        t[0],
        format!("  can0  602   [8]  C6 00 20 00 {:02X} 00 00 00", LONG)
    );
    // Response A4 = scs 5, sc; blksize SDO_BLOCKSIZE_DOWNLOAD.
    assert_eq!(
        t[1],
        format!("  can0  582   [8]  A4 00 20 00 {SDO_BLOCKSIZE_DOWNLOAD:02X} 00 00 00")
    );
    // First segment: seqno 1, the first seven bytes.
    assert!(t[2].starts_with("  can0  602   [8]  01 "));
    // End: C1 | n << 2 with the CRC of the data; response A1.
    let n = (LONG.div_ceil(7) * 7 - LONG) as u8;
    let [lo, hi] = block_crc(0, &data).to_le_bytes();
    let end = format!(
        "  can0  602   [8]  {:02X} {lo:02X} {hi:02X} 00 00 00 00 00",
        0xC1 | (n << 2)
    );
    assert_eq!(t[t.len() - 2], end);
    assert_eq!(t[t.len() - 1], "  can0  582   [8]  A1 00 00 00 00 00 00 00");
    // Segments: ceil(LONG / 7); frames: 2 + segments + one confirmation per
    // sub-block + 2.
    let segments = LONG.div_ceil(7);
    let blocks = segments.div_ceil(usize::from(SDO_BLOCKSIZE_DOWNLOAD));
    assert_eq!(t.len(), 4 + segments + blocks);

    net.bus.clear_trace();
    decl::set(&RX_BUF, [0xEE; 256]);
    net.upload(200);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(net.transferred(), LONG as u32);
    assert_eq!(rx(LONG), data);
    // Nothing past the value (the last segment's padding is not written).
    assert!(decl::get(&RX_BUF)[LONG..].iter().all(|b| *b == 0xEE));
    let t = net.bus.trace();
    // CiA 301 initiate SDO block upload: A4 = ccs 5, cc; blksize, pst 0.
    assert_eq!(
        t[0],
        format!("  can0  602   [8]  A4 00 20 00 {SDO_BLOCKSIZE_UPLOAD:02X} 00 00 00")
    );
    // C6 = scs 6, sc, s; size. Then start A3.
    assert_eq!(
        t[1],
        format!("  can0  582   [8]  C6 00 20 00 {:02X} 00 00 00", LONG)
    );
    assert_eq!(t[2], "  can0  602   [8]  A3 00 00 00 00 00 00 00");
    // End request from the server: C1 | n << 2 (scs 6, ss 1), CRC.
    assert_eq!(t[t.len() - 2], end.replace("602", "582"));
    assert_eq!(t[t.len() - 1], "  can0  602   [8]  A1 00 00 00 00 00 00 00");
    assert_eq!(net.finished.len(), 2);
}

#[test]
fn lost_download_segment_is_sent_again() {
    let _g = serial();
    let mut net = Net::new();
    let data = pattern(LONG, 11);
    // Segment 3 of the first sub-block never reaches the server.
    let hits = fault_once(&net.bus, MASTER, 0x602, 0x03, |_| Delivery::Drop);
    net.download(&data, 300);
    assert_eq!(hits.get(), 1);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(&decl::get(&TEXT)[..LONG], &data[..]);
    // The server confirmed segments 1 and 2 only.
    assert!(net.has(&format!(
        "  can0  582   [8]  A2 02 {SDO_BLOCKSIZE_DOWNLOAD:02X} 00 00 00 00 00"
    )));
}

#[test]
fn lost_upload_segment_is_sent_again() {
    let _g = serial();
    let mut net = Net::new();
    let data = pattern(LONG, 17);
    net.download(&data, 200);
    assert_eq!(net.state().0, SdocState::Finished);
    net.bus.clear_trace();
    let hits = fault_once(&net.bus, SERVER, 0x582, 0x04, |_| Delivery::Drop);
    net.upload(300);
    assert_eq!(hits.get(), 1);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(rx(LONG), data);
    assert!(net.has(&format!(
        "  can0  602   [8]  A2 03 {SDO_BLOCKSIZE_UPLOAD:02X} 00 00 00 00 00"
    )));
}

#[test]
fn lost_last_segment_of_a_sub_block_is_recovered_after_half_the_timeout() {
    let _g = serial();
    let mut net = Net::new();
    let data = pattern(LONG, 23);
    // The segment that ends the first sub-block is lost: the server
    // confirms what it has once no segment came for half its timeout
    // (SDOS_DEFAULT_TIMEOUT 0.5 s).
    let last = SDO_BLOCKSIZE_DOWNLOAD;
    let hits = fault_once(&net.bus, MASTER, 0x602, last, |_| Delivery::Drop);
    net.download(&data, 1000);
    assert_eq!(hits.get(), 1);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(&decl::get(&TEXT)[..LONG], &data[..]);
    assert!(net.has(&format!(
        "  can0  582   [8]  A2 {:02X} {SDO_BLOCKSIZE_DOWNLOAD:02X} 00 00 00 00 00",
        last - 1
    )));
    // The same for an upload: the client confirms after half its timeout.
    net.bus.clear_trace();
    let last = SDO_BLOCKSIZE_UPLOAD;
    let hits = fault_once(&net.bus, SERVER, 0x582, last, |_| Delivery::Drop);
    net.upload(1000);
    assert_eq!(hits.get(), 1);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(rx(LONG), data);
}

#[test]
fn corrupted_data_is_a_crc_error() {
    let _g = serial();
    let mut net = Net::new();
    let old = pattern(LONG, 41);
    net.download(&old, 200);
    assert_eq!(net.state().0, SdocState::Finished);
    let data = pattern(LONG, 29);
    // One data byte of download segment 2 changes on the way (a fault the
    // CAN CRC would normally catch): the server's CRC check does.
    let hits = fault_once(&net.bus, MASTER, 0x602, 0x02, |f| {
        f.data[3] ^= 0x01;
        Delivery::Deliver
    });
    net.download(&data, 200);
    assert_eq!(hits.get(), 1);
    // CiA 301: 0x05040004 CRC error; the object keeps its value.
    assert_eq!(net.state(), (SdocState::RxAborted, 0x0504_0004));
    assert_eq!(&decl::get(&TEXT)[..LONG], &old[..]);
    // Upload: the client checks.
    net.bus.set_filter(None);
    net.download(&data, 200);
    assert_eq!(net.state().0, SdocState::Finished);
    let hits = fault_once(&net.bus, SERVER, 0x582, 0x05, |f| {
        f.data[7] ^= 0x80;
        Delivery::Deliver
    });
    net.upload(200);
    assert_eq!(hits.get(), 1);
    assert_eq!(net.state(), (SdocState::TxAborted, 0x0504_0004));
    assert!(net.has("  can0  602   [8]  80 00 20 00 04 00 04 05"));
}

#[test]
fn short_value_goes_block_and_a_switching_server_is_followed() {
    let _g = serial();
    let mut net = Net::new();
    decl::set(&RX_BUF, [0; 256]);
    net.start(Direction::BlockUpload, 0x2001, &RX_BUF, 256)
        .unwrap();
    net.run_until_done(10);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(net.transferred(), 1);
    assert_eq!(rx(1), [0x5A]);
    // pst 0 in the request: the server stays with block upload (C6, size
    // 1), one segment 81, end C1 | 6 << 2 = D9 with CRC(5A).
    let t = net.bus.trace();
    assert_eq!(
        t[0],
        format!("  can0  602   [8]  A4 01 20 00 {SDO_BLOCKSIZE_UPLOAD:02X} 00 00 00")
    );
    assert_eq!(t[1], "  can0  582   [8]  C6 01 20 00 01 00 00 00");
    assert_eq!(t[3], "  can0  582   [8]  81 5A 00 00 00 00 00 00");
    let [lo, hi] = block_crc(0, &[0x5A]).to_le_bytes();
    assert_eq!(
        t[5],
        format!("  can0  582   [8]  D9 {lo:02X} {hi:02X} 00 00 00 00 00")
    );
    assert_eq!(t.len(), 7);

    // A server that switches to the SDO upload protocol anyway (CiA 301
    // allows it): played by hand with the real server stopped.
    let now = net.bus.now();
    let (sp, ss) = &mut net.server;
    ss.exec_command(cop::ccm::NmtCommand::StopRemoteNode)
        .unwrap();
    while ss.drain(sp, now).is_some() {}
    let resp = |b: [u8; 8]| CanFrame::new(cop::port::CanId::std_masked(0x582), &b);
    // Expedited: 4F = 1 byte.
    net.start(Direction::BlockUpload, 0x2001, &RX_BUF, 256)
        .unwrap();
    net.run(1);
    net.bus
        .inject(resp([0x4F, 0x01, 0x20, 0x00, 0xA5, 0, 0, 0]));
    net.run(2);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!((net.transferred(), rx(1)), (1, vec![0xA5]));
    // Segmented: 41 + size 9, then the client asks for segments (60, 70).
    net.bus.clear_trace();
    net.start(Direction::BlockUpload, 0x2000, &RX_BUF, 256)
        .unwrap();
    net.run(1);
    net.bus.inject(resp([0x41, 0x00, 0x20, 0x00, 9, 0, 0, 0]));
    net.run(1);
    net.bus
        .inject(resp([0x00, b'b', b'l', b'o', b'c', b'k', b' ', b's']));
    net.run(1);
    net.bus.inject(resp([0x1B, b'w', b'!', 0, 0, 0, 0, 0]));
    net.run(2);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!((net.transferred(), rx(9)), (9, b"block sw!".to_vec()));
    assert!(net.has("  can0  602   [8]  60 00 00 00 00 00 00 00"));
    assert!(net.has("  can0  602   [8]  70 00 00 00 00 00 00 00"));
}

#[test]
fn upload_never_writes_past_the_buffer() {
    let _g = serial();
    let mut net = Net::new();
    let data = pattern(LONG, 31);
    net.download(&data, 200);
    decl::set(&RX_BUF, [0xEE; 256]);
    net.start(Direction::BlockUpload, 0x2000, &RX_BUF, 100)
        .unwrap();
    net.run_until_done(20);
    // The server announces LONG bytes: 0x05040005 out of memory.
    assert_eq!(net.state(), (SdocState::TxAborted, 0x0504_0005));
    assert!(decl::get(&RX_BUF).iter().all(|b| *b == 0xEE));
    assert!(net.has("  can0  602   [8]  80 00 20 00 05 00 04 05"));
}

#[test]
fn refused_block_transfers_report_the_servers_code() {
    let _g = serial();
    let mut net = Net::new();
    load_tx(&[1, 2, 3, 4, 5, 6, 7, 8]);
    // Read-only object: 0x06010002 at initiate.
    net.start(Direction::BlockDownload, 0x2002, &TX_BUF, 8)
        .unwrap();
    net.run_until_done(10);
    assert_eq!(net.state(), (SdocState::RxAborted, 0x0601_0002));
    // Missing object: 0x06020000.
    net.start(Direction::BlockUpload, 0x2FFF, &RX_BUF, 256)
        .unwrap();
    net.run_until_done(10);
    assert_eq!(net.state(), (SdocState::RxAborted, 0x0602_0000));
    // Longer than the server's buffer: 0x06070012 at initiate.
    let mut big = [0u8; 256];
    big.fill(b'x');
    decl::set(&TX_BUF, big);
    if SDOS_BUFFER_SIZE < 256 {
        net.start(Direction::BlockDownload, 0x2000, &TX_BUF, 256)
            .unwrap();
        net.run_until_done(10);
        assert_eq!(net.state(), (SdocState::RxAborted, 0x0607_0012));
    }
    // Empty download: refused before anything is sent.
    assert_eq!(
        net.start(Direction::BlockDownload, 0x2000, &TX_BUF, 0),
        Err(cop::CopKernel::SdocInvalidParam)
    );
}

#[test]
fn lost_confirmation_ends_in_a_timeout() {
    let _g = serial();
    let mut net = Net::new();
    let data = pattern(40, 5);
    // The server's first confirmation is lost.
    let hits = fault_once(&net.bus, SERVER, 0x582, 0xA2, |_| Delivery::Drop);
    net.download(&data, 1000);
    assert_eq!(hits.get(), 1);
    // Both wait 0.5 s (SDOS / SDOC default timeout) from the last segment;
    // the server's supervision fires first and its abort 0x05040000 ends
    // the client's transfer too.
    assert_eq!(net.state(), (SdocState::RxAborted, 0x0504_0000));
    assert!(net.has("  can0  582   [8]  80 00 20 00 00 00 04 05"));
    // Both sides are idle again: the next transfer goes through.
    net.bus.set_filter(None);
    net.download(&data, 100);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(&decl::get(&TEXT)[..40], &data[..]);
}

#[test]
fn short_frames_inside_a_sub_block_are_ignored() {
    let _g = serial();
    let mut net = Net::new();
    let data = pattern(LONG, 37);
    net.download(&data, 200);
    // A 7-byte frame on the response COB-ID in the middle of the upload's
    // sub-block: not an SDO frame (CiA 301: always 8 bytes).
    net.start(Direction::BlockUpload, 0x2000, &RX_BUF, 256)
        .unwrap();
    net.run(3);
    assert_eq!(net.state().0, SdocState::Running);
    net.bus.inject(CanFrame::new(
        cop::port::CanId::std_masked(0x582),
        &[0x02, 1, 2, 3, 4, 5, 6],
    ));
    net.bus.inject(CanFrame::new(
        cop::port::CanId::std_masked(0x602),
        &[0x02, 1, 2, 3, 4, 5, 6],
    ));
    net.run_until_done(200);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(rx(LONG), data);
}
