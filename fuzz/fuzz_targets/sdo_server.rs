//! SDO server fuzzing: arbitrary frame sequences (requests on the server's
//! COB-ID and unrelated frames, with time passing between them) against a
//! device with the reference dictionary. Checked on every input: no crash,
//! every answer is a well-formed SDO frame (DLC 8), and constant objects
//! never change. (Block upload segments may carry any byte 0, so the
//! command specifier is no longer checked.)
#![no_main]

use cop::ccm::Stack;
use cop::od::ByteOrder;
use cop::port::{CanFrame, CanId};
use cop::sim::SimBus;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bus = SimBus::new();
    let mut port = bus.attach(256);
    let Ok(mut stack) = Stack::new(cop::testod::dictionary(), 2) else {
        return;
    };
    while stack.drain(&mut port, bus.now()).is_some() {}
    let _ = stack.connect();
    while stack.drain(&mut port, bus.now()).is_some() {}
    bus.clear_trace();

    // Each record: [selector, dlc, 8 data bytes, ms to advance].
    for rec in data.chunks(11) {
        let [sel, dlc, rest @ ..] = rec else { break };
        let id = match sel % 8 {
            0 => 0x000,
            1 => 0x582,
            _ => 0x602,
        };
        let payload = rest.get(..8).unwrap_or(rest);
        let n = usize::from(*dlc % 9).min(payload.len());
        bus.inject(CanFrame::new(CanId::std_masked(id), &payload[..n]));
        if let Some(ms) = rest.get(8) {
            bus.advance_ms(u32::from(*ms) * 4);
        }
        let now = bus.now();
        stack.process(&mut port, now, |_, _| {});
    }
    for (from, _, f) in bus.sent() {
        if from == usize::MAX || f.id.id() != 0x582 {
            continue;
        }
        assert_eq!(f.len, 8, "SDO responses always carry 8 bytes");
    }
    let mut b = [0u8; 4];
    assert_eq!(stack.read_object(0x1000, 0, ByteOrder::Wire, &mut b), Ok(4));
    assert_eq!(b, 0x0001_0191u32.to_le_bytes(), "a constant object changed");
});
