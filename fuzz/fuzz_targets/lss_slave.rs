//! LSS slave fuzzing (CiA 305): arbitrary request sequences on 0x7E5
//! against a stack with the LSS slave and the reference dictionary,
//! started with node-ID 0xFF or 5 (bit 0 of the first byte; bit 1: the
//! node connects as soon as it has a node-ID).
//!
//! Records of 9 bytes: a DLC selector (bit 7 set: DLC from bits 0-3, else
//! 8) and the 8 data bytes. Byte 0 of the data is mapped onto the CiA 305
//! request specifiers when bit 7 of the selector is clear, so that most
//! records are requests the slave serves.
//!
//! Checked after every record: no crash; every answer is an 8-byte data
//! frame on 0x7E4 with an answer specifier of CiA 305; configuration
//! services (configure, store, inquire) are answered only in the LSS
//! configuration state; the node-ID is 1..=127 or 0xFF, and
//! `lss_init_state` / `connect` agree with it.
#![no_main]

use cop::ccm::Stack;
use cop::error::CopKernel;
use cop::port::{CanFrame, CanId};
use cop::sim::SimBus;
use libfuzzer_sys::fuzz_target;

/// Request specifiers of CiA 305 the slave serves.
const REQUESTS: [u8; 22] = [
    0x04, 0x11, 0x13, 0x15, 0x17, 0x40, 0x41, 0x42, 0x43, 0x46, 0x47, 0x48, 0x49, 0x4A, 0x4B,
    0x4C, 0x51, 0x5A, 0x5B, 0x5C, 0x5D, 0x5E,
];
/// Answer specifiers of CiA 305.
const ANSWERS: [u8; 10] = [0x11, 0x13, 0x17, 0x44, 0x4F, 0x50, 0x5A, 0x5B, 0x5C, 0x5D];
/// Requests answered only in the configuration state.
const CONFIGURATION_ONLY: [u8; 8] = [0x11, 0x13, 0x17, 0x5A, 0x5B, 0x5C, 0x5D, 0x5E];

fuzz_target!(|data: &[u8]| {
    let Some((&head, records)) = data.split_first() else {
        return;
    };
    let bus = SimBus::new();
    let mut port = bus.attach(64);
    let start = if head & 1 != 0 { 0xFF } else { 5 };
    let Ok(mut stack) = Stack::with_lss(cop::testod::dictionary(), start) else {
        return;
    };
    let connect_when_possible = head & 2 != 0;
    while stack.drain(&mut port, bus.now()).is_some() {}

    for rec in records.chunks(9) {
        let [sel, rest @ ..] = rec else { break };
        let mut payload = [0u8; 8];
        for (to, from) in payload.iter_mut().zip(rest) {
            *to = *from;
        }
        let dlc = if sel & 0x80 != 0 { usize::from(sel & 0x0F).min(8) } else { 8 };
        if sel & 0x80 == 0 {
            payload[0] = REQUESTS[usize::from(payload[0]) % REQUESTS.len()];
        }
        let was_configuration = stack.lss().is_some_and(|l| l.in_configuration());
        bus.clear_trace();
        bus.inject(CanFrame::new(CanId::std_masked(0x7E5), &payload[..dlc]));
        bus.advance_ms(1);
        let now = bus.now();
        stack.process(&mut port, now, |_, _| {});
        while stack.drain(&mut port, bus.now()).is_some() {}

        for (_, _, f) in bus.sent() {
            if f.id != CanId::std_masked(0x7E4) {
                continue;
            }
            assert!(!f.rtr && f.len == 8, "LSS answer not an 8-byte data frame: {f:?}");
            assert!(ANSWERS.contains(&f.data[0]) || f.data[0] == 0x5E, "answer {:#04x}", f.data[0]);
            if CONFIGURATION_ONLY.contains(&payload[0]) && dlc == 8 {
                assert!(was_configuration, "{:#04x} answered in the waiting state", payload[0]);
            }
        }
        let node = stack.node_id();
        assert!((1..=127).contains(&node) || node == 0xFF, "node-ID {node}");
        assert_eq!(stack.lss_init_state().is_ok(), node != 0xFF);
        if node == 0xFF {
            assert_eq!(stack.connect(), Err(CopKernel::LsssInvalidNodeId));
        } else if connect_when_possible && !stack.is_connected() {
            assert_eq!(stack.connect(), Ok(()));
        }
    }
});
