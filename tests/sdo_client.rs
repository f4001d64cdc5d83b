//! SDO client against this library's SDO server on the simulated bus:
//! expedited and segmented transfers both ways, aborts from the server,
//! timeout, one transfer per server, buffer bounds (CiA 301 SDO protocols).

mod common;

use core::sync::atomic::AtomicU8;
use std::sync::{Mutex, MutexGuard};

use common::SdoNet as Net;
use cop::event::{Event, NmtState};
use cop::od::{Access, DataType, ObdEntry, ObdSubEntry, decl};
use cop::sdo::client::{ClientParam, Direction, SdocState};
use cop::wire::sdo::Multiplexer;

static SERIAL: Mutex<()> = Mutex::new(());
fn serial() -> MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

// Server dictionary (node 2).
static TEXT: [AtomicU8; 41] = decl::zeroed();
cop::od_ram!(static S2000, U32_VAR: u32 => UInt32, RW);
static S2001: [ObdSubEntry; 1] = [ObdSubEntry::ram_string(0, Access::RW, &TEXT, c"")];
static S2002: [ObdSubEntry; 1] = [ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[0x5A])];
static SERVER_MAN: [ObdEntry; 3] = [
    ObdEntry::new(0x2000, &S2000, None),
    ObdEntry::new(0x2001, &S2001, None),
    ObdEntry::new(0x2002, &S2002, None),
];

// Client buffers (node 1).
static TX_BUF: [AtomicU8; 40] = decl::zeroed();
static RX_BUF: [AtomicU8; 40] = decl::zeroed();
static SMALL_BUF: [AtomicU8; 8] = decl::zeroed();

impl Net {
    fn new() -> Net {
        Net::on_bus(&SERVER_MAN, 64)
    }
}

#[test]
fn expedited_download_and_upload() {
    let _g = serial();
    let mut net = Net::new();
    decl::set(array4(&TX_BUF), [0x78, 0x56, 0x34, 0x12]);
    net.start(Direction::Download, 0x2000, &TX_BUF, 4).unwrap();
    net.run(3);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(decl::get(&U32_VAR), 0x1234_5678u32.to_ne_bytes());
    // CiA 301 expedited download with size: 0x23 = ccs 1, n = 0, e, s.
    let t = net.bus.trace();
    assert_eq!(t[0], "  can0  602   [8]  23 00 20 00 78 56 34 12");
    assert_eq!(t[1], "  can0  582   [8]  60 00 20 00 00 00 00 00");
    net.start(Direction::Upload, 0x2002, &RX_BUF, 40).unwrap();
    net.run(3);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(net.master.1.sdoc().transferred(0x1280), Ok(1));
    assert_eq!(decl::get(array4(&RX_BUF))[0], 0x5A);
    assert_eq!(net.finished.len(), 2);
}

fn array4(b: &'static [AtomicU8; 40]) -> &'static [AtomicU8; 4] {
    b[..4].try_into().unwrap()
}

#[test]
fn segmented_string_both_ways() {
    let _g = serial();
    let mut net = Net::new();
    let text = b"safety data object configured over SDO!";
    assert_eq!(text.len(), 39);
    let mut src = [0u8; 40];
    src[..39].copy_from_slice(text);
    decl::set(&TX_BUF, src);
    net.start(Direction::Download, 0x2001, &TX_BUF, 39).unwrap();
    net.run(20);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(&decl::get(&TEXT)[..39], text);
    decl::set(&RX_BUF, [0; 40]);
    net.start(Direction::Upload, 0x2001, &RX_BUF, 40).unwrap();
    net.run(20);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(net.master.1.sdoc().transferred(0x1280), Ok(39));
    assert_eq!(&decl::get(&RX_BUF)[..39], text);
}

/// A transmit buffer full for a moment (the driver refuses a frame) delays
/// a transfer, it does not end it: the server and the client keep the
/// refused frame and send it in their next cycle, once, in order.
#[test]
fn refused_frames_are_sent_in_the_next_cycle() {
    let _g = serial();
    let mut net = Net::new();
    let text = b"held back by a full transmit buffer....";
    let mut src = [0u8; 40];
    src[..39].copy_from_slice(text);
    decl::set(&TX_BUF, src);
    net.start(Direction::Download, 0x2001, &TX_BUF, 39).unwrap();
    // The server's answer to the initiate request (the server is node 0 of
    // the bus), then the client's first segment.
    net.bus.refuse_tx(0, 1);
    net.run(2);
    net.bus.refuse_tx(1, 1);
    net.run(20);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(&decl::get(&TEXT)[..39], text);
    // Initiate and answer, six segments and six answers (CiA 301
    // segmented download of 39 bytes): nothing lost, nothing twice.
    assert_eq!(net.bus.trace().len(), 2 + 2 * 6);
    net.bus.clear_trace();
    decl::set(&RX_BUF, [0; 40]);
    net.start(Direction::Upload, 0x2001, &RX_BUF, 40).unwrap();
    net.bus.refuse_tx(0, 1);
    net.run(4);
    net.bus.refuse_tx(0, 1);
    net.bus.refuse_tx(1, 1);
    net.run(20);
    assert_eq!(net.state(), (SdocState::Finished, 0));
    assert_eq!(&decl::get(&RX_BUF)[..39], text);
    assert_eq!(net.bus.trace().len(), 2 + 2 * 6);
}

#[test]
fn server_abort_is_reported_with_its_code() {
    let _g = serial();
    let mut net = Net::new();
    net.start(Direction::Upload, 0x2FFF, &RX_BUF, 40).unwrap();
    net.run(3);
    // CiA 301: 0x06020000 object does not exist.
    assert_eq!(net.state(), (SdocState::RxAborted, 0x0602_0000));
    assert_eq!(
        net.finished,
        vec![Event::SdocFinished {
            client: 0x1280,
            state: SdocState::RxAborted as u8,
            abort: 0x0602_0000
        }]
    );
    // Writing a read-only object: 0x06010002.
    net.start(Direction::Download, 0x2002, &TX_BUF, 1).unwrap();
    net.run(3);
    assert_eq!(net.state(), (SdocState::RxAborted, 0x0601_0002));
}

#[test]
fn upload_never_writes_past_the_buffer() {
    let _g = serial();
    let mut net = Net::new();
    let mut src = [0u8; 40];
    src[..20].copy_from_slice(b"twenty bytes of text");
    decl::set(&TX_BUF, src);
    net.start(Direction::Download, 0x2001, &TX_BUF, 20).unwrap();
    net.run(10);
    decl::set(&SMALL_BUF, [0xEE; 8]);
    net.start(Direction::Upload, 0x2001, &SMALL_BUF, 4).unwrap();
    net.run(10);
    // The server announces 20 bytes; the client aborts with 0x05040005
    // (out of memory) and leaves the buffer beyond 4 bytes untouched.
    assert_eq!(net.state(), (SdocState::TxAborted, 0x0504_0005));
    assert_eq!(&decl::get(&SMALL_BUF)[4..], &[0xEE; 4]);
    assert!(
        net.bus
            .trace()
            .iter()
            .any(|l| l == "  can0  602   [8]  80 01 20 00 05 00 04 05")
    );
}

#[test]
fn timeout_aborts_and_busy_is_refused() {
    let _g = serial();
    let mut net = Net::new();
    // Stop the server: it stays silent.
    let now = net.bus.now();
    let (sp, ss) = &mut net.server;
    ss.exec_command(cop::ccm::NmtCommand::StopRemoteNode)
        .unwrap();
    while ss.drain(sp, now).is_some() {}
    assert_eq!(ss.nmt_state(), NmtState::Stopped);
    net.start(Direction::Upload, 0x2000, &RX_BUF, 4).unwrap();
    assert_eq!(
        net.start(Direction::Upload, 0x2000, &RX_BUF, 4),
        Err(cop::CopKernel::SdocBusy)
    );
    net.run(499);
    assert_eq!(net.state().0, SdocState::Running);
    net.run(3);
    // SDOC default timeout 5000 ticks = 0.5 s; abort 0x05040000 sent.
    assert_eq!(net.state(), (SdocState::TxAborted, 0x0504_0000));
    assert!(
        net.bus
            .trace()
            .iter()
            .any(|l| l == "  can0  602   [8]  80 00 20 00 00 00 04 05")
    );
}

/// A channel defined again while its transfer runs (a master that gives
/// up on an absent server before the client's timeout): the transfer ends
/// as an abort by the client does (abort frame to the server, CiA 301
/// 7.2.4.3.17, code 0x08000000 "general error"; `SdocFinished` with
/// TxAborted) and the new definition is taken.
#[test]
fn a_busy_channel_defined_again_ends_its_transfer_and_takes_the_new_one() {
    let _g = serial();
    let mut net = Net::new();
    let now = net.bus.now();
    let (sp, ss) = &mut net.server;
    ss.exec_command(cop::ccm::NmtCommand::StopRemoteNode)
        .unwrap();
    while ss.drain(sp, now).is_some() {}
    net.start(Direction::Upload, 0x2000, &RX_BUF, 4).unwrap();
    net.run(100);
    assert_eq!(net.state().0, SdocState::Running);
    net.bus.clear_trace();
    let node_3 = ClientParam {
        tx_cob: 0x603,
        rx_cob: 0x583,
        server_node: 3,
        timeout_ticks: 0,
    };
    let (port, stack) = &mut net.master;
    assert_eq!(stack.define_sdo_client(port, 0x1280, node_3), Ok(()));
    assert_eq!(
        net.bus.trace(),
        ["  can0  602   [8]  80 00 20 00 00 00 00 08"],
        "the abort goes to the server of the old definition"
    );
    assert_eq!(net.state(), (SdocState::TxAborted, 0x0800_0000));
    assert_eq!(net.master.1.sdoc().param(0x1280), Ok(node_3));
    net.run(1);
    assert_eq!(
        net.finished,
        [Event::SdocFinished {
            client: 0x1280,
            state: SdocState::TxAborted as u8,
            abort: 0x0800_0000
        }]
    );
    // The next transfer runs on the new definition.
    net.bus.clear_trace();
    net.start(Direction::Upload, 0x2000, &RX_BUF, 4).unwrap();
    assert_eq!(
        net.bus.trace(),
        ["  can0  603   [8]  40 00 20 00 00 00 00 00"]
    );
}

#[test]
fn bad_arguments_give_codes() {
    let _g = serial();
    let mut net = Net::new();
    let now = net.bus.now();
    let (port, stack) = &mut net.master;
    assert_eq!(
        stack.sdo_client_start(
            port,
            now,
            0x1290,
            Direction::Upload,
            Multiplexer::new(0x2000, 0),
            &RX_BUF,
            4,
            0
        ),
        Err(cop::CopKernel::SdocClientNotExist)
    );
    assert_eq!(
        stack.sdo_client_start(
            port,
            now,
            0x1280,
            Direction::Download,
            Multiplexer::new(0x2000, 0),
            &SMALL_BUF,
            9,
            0
        ),
        Err(cop::CopKernel::SdocInvalidParam)
    );
    let bad = ClientParam {
        tx_cob: 0x900,
        rx_cob: 0x582,
        server_node: 2,
        timeout_ticks: 0,
    };
    assert_eq!(
        stack.define_sdo_client(port, 0x1281, bad),
        Err(cop::CopKernel::SdocInvalidParam)
    );
    // Identifiers CiA 301 §7.3.5 reserves for other services: the SRDO
    // pair of node 1 (0x101 / 0x102), the GFC (0x001), NMT error control
    // of node 2 (0x702), in either direction; the default SDO channels
    // are SDO's own.
    for (tx, rx) in [
        (0x101, 0x582),
        (0x602, 0x102),
        (0x001, 0x582),
        (0x602, 0x702),
    ] {
        let reserved = ClientParam {
            tx_cob: tx,
            rx_cob: rx,
            server_node: 2,
            timeout_ticks: 0,
        };
        assert_eq!(
            stack.define_sdo_client(port, 0x1281, reserved),
            Err(cop::CopKernel::SdocInvalidParam),
            "{tx:#x} / {rx:#x}"
        );
    }
    let default_channel = ClientParam {
        tx_cob: 0x603,
        rx_cob: 0x583,
        server_node: 3,
        timeout_ticks: 0,
    };
    assert_eq!(
        stack.define_sdo_client(port, 0x1281, default_channel),
        Ok(())
    );
}
