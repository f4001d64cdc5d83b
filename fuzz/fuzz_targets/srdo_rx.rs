//! SRDO reception fuzzing: arbitrary frame sequences, with time passing
//! between them as the input says, into the consumer of
//! `cop::sim::srdo_net` (SRDO 1 receives 0x101/0x102, DLC 4, SCT 50 ms,
//! SRVT 20 ms; SRDO 2 disabled; GFC on) with a valid configuration in
//! OPERATIONAL.
//!
//! Input: 5 header bytes (the 32-bit tick counter at the start, so the
//! fuzzer can put the wrap anywhere; the receive queue length 1..=16; bit 7
//! of byte 4: the application ignores `AppSrdoError`), then records of 11
//! bytes `[op, dlc, d0..d7, dt]`. `op` bits 0-2 choose the frame: frame 1,
//! frame 2, a complete valid pair, a pair with one bit wrong, another
//! identifier (GFC, SRDO 2, border COB-IDs, unrelated, NMT), a remote frame,
//! a burst of unrelated frames (receive overrun), nothing; bit 3 set: no
//! consumer cycle after this record; bits 4-5: `dt` counts ticks × 1, 10,
//! 100 or 5000.
//!
//! Checked on every input:
//! * no crash;
//! * the mapped variables change only when `AppSrdoEvent` is reported, and
//!   then the normal variables hold the data of the last frame 1 and the
//!   inverted variables that of the last frame 2 the consumer took from its
//!   queue (the pair just completed), exact complements of each other;
//! * every `AppSrdoError` code is a reception code (`kCopSrdoNotHandledInApp`
//!   only when the application ignores errors);
//! * the action queue never overflows: every `AppSrdoEvent` and
//!   `AppSrdoError` is followed by its program-monitor event, which a push
//!   refused by the full queue would lose.
#![no_main]

use std::cell::RefCell;
use std::collections::VecDeque;
use std::rc::Rc;

use cop::CopKernel;
use cop::ccm::NmtCommand;
use cop::event::{Event, ProgMonEvent};
use cop::port::{CanFrame, CanId, Ticks};
use cop::sim::srdo_net::{self, DATA_LEN, Device, Role, SRDO};
use cop::sim::{Delivery, SimBus};
use libfuzzer_sys::fuzz_target;

const RECEPTION_CODES: [CopKernel; 6] = [
    CopKernel::SrdoDlcNotValid,
    CopKernel::SrdoNotInOrder,
    CopKernel::SrdoSrvtTimeout,
    CopKernel::SrdoSctTimeout,
    CopKernel::SrdoDataError,
    CopKernel::SrdoOverrun,
];

/// Identifiers of `op` 4: GFC, SRDO 2, the border COB-IDs, unrelated
/// traffic, NMT.
const OTHER_IDS: [u16; 8] = [0x001, 0x103, 0x104, 0x100, 0x17F, 0x180, 0x181, 0x000];

fn frame(id: u16, data: &[u8]) -> CanFrame {
    CanFrame::new(CanId::std_masked(id), data)
}

/// The frames in the consumer's driver queue, as the bus filled it (a full
/// queue loses the newest frame).
struct Mirror {
    queue: VecDeque<CanFrame>,
    capacity: usize,
}

fuzz_target!(|data: &[u8]| {
    let Some((head, records)) = data.split_first_chunk::<5>() else {
        return;
    };
    let _guard = srdo_net::lock();
    let bus = SimBus::new();
    bus.set_time(Ticks(u32::from_le_bytes([
        head[0], head[1], head[2], head[3],
    ])));
    let capacity = usize::from(head[4] & 0x0F) + 1;
    let app_ignores = head[4] & 0x80 != 0;
    let Ok(mut c) = Device::new(&bus, Role::Consumer, capacity) else {
        return;
    };
    c.set_fields(&[0; DATA_LEN], &[0; DATA_LEN]);
    if c.seal().is_err() || c.command(NmtCommand::StartRemoteNode).is_err() {
        return;
    }
    assert!(c.stack.srdo().is_running(), "the configuration is valid");
    // Everything the consumer sends (boot-up, SDO) leaves the picture.
    let me = c.port.node();
    bus.set_filter(Some(Box::new(move |from, _: &mut CanFrame| {
        if from == me {
            Delivery::Drop
        } else {
            Delivery::Deliver
        }
    })));
    let mirror = Rc::new(RefCell::new(Mirror {
        queue: VecDeque::new(),
        capacity,
    }));
    let fields = c.fields();
    let probe = c.port.clone();
    let mut values = (fields.normal(), fields.inverted());
    let mut last_normal: Option<CanFrame> = None;
    let mut last_inverted: Option<CanFrame> = None;

    let deliver = |f: CanFrame| {
        let mut m = mirror.borrow_mut();
        if m.queue.len() < m.capacity {
            m.queue.push_back(f);
        }
        bus.inject(f);
    };

    for rec in records.chunks(11) {
        let [op, dlc, rest @ ..] = rec else { break };
        let payload = rest.get(..8).unwrap_or(rest);
        let n = usize::from(*dlc % 9).min(payload.len());
        let d4: [u8; 4] = core::array::from_fn(|i| payload.get(i).copied().unwrap_or(0));
        let sel = payload.get(7).copied().unwrap_or(0);
        match op & 0x07 {
            0 => deliver(frame(0x101, &payload[..n])),
            1 => deliver(frame(0x102, &payload[..n])),
            2 => {
                deliver(frame(0x101, &d4));
                deliver(frame(0x102, &d4.map(|b| !b)));
            }
            3 => {
                let mut inv = d4.map(|b| !b);
                inv[usize::from(sel / 8 % 4)] ^= 1 << (sel % 8);
                deliver(frame(0x101, &d4));
                deliver(frame(0x102, &inv));
            }
            4 => {
                let id = OTHER_IDS[usize::from(sel % 8)];
                let mut p = payload[..n].to_vec();
                // Resets restore the defaults of the variables and the
                // configuration: outside reception, so not generated.
                if id == 0 && matches!(p.first(), Some(0x81 | 0x82)) {
                    p[0] = 0x01;
                }
                deliver(frame(id, &p));
            }
            5 => deliver(CanFrame::remote(
                CanId::std_masked(0x101 + u16::from(sel & 1)),
                *dlc % 9,
            )),
            6 => {
                for _ in 0..sel % 32 {
                    deliver(frame(0x181, &d4));
                }
            }
            _ => {}
        }
        if let Some(dt) = rest.get(8) {
            let scale = [1u32, 10, 100, 5000][usize::from((op >> 4) & 0x03)];
            bus.advance_ticks(u32::from(*dt) * scale);
        }
        if op & 0x08 != 0 {
            continue;
        }
        // Events that must come next, in this order.
        let mut follow: VecDeque<Event> = VecDeque::new();
        c.process(|stack, e| {
            // The frames the stack has taken from its queue so far.
            {
                let mut m = mirror.borrow_mut();
                while m.queue.len() > probe.pending() {
                    let Some(f) = m.queue.pop_front() else { break };
                    if !f.rtr && f.id == CanId::std_masked(0x101) {
                        last_normal = Some(f);
                    }
                    if !f.rtr && f.id == CanId::std_masked(0x102) {
                        last_inverted = Some(f);
                    }
                }
            }
            if let Some(want) = follow.pop_front() {
                assert_eq!(e, want, "an event after the callback was lost");
                return;
            }
            let now = (fields.normal(), fields.inverted());
            match e {
                Event::SrdoEvent(idx) => {
                    assert_eq!(idx, SRDO);
                    let (n, i) = (
                        last_normal.expect("frame 1"),
                        last_inverted.expect("frame 2"),
                    );
                    assert_eq!((n.len, i.len), (4, 4));
                    assert_eq!(now.0[..], n.data[..4], "normal variables = frame 1");
                    assert_eq!(now.1[..], i.data[..4], "inverted variables = frame 2");
                    assert_eq!(now.1, now.0.map(|b| !b), "exact complements");
                    values = now;
                    srdo_net::answer_as_manual(stack, &e);
                    follow.push_back(Event::ProgMon(ProgMonEvent::SrdoReceived));
                }
                Event::SrdoError(idx, code) => {
                    assert_eq!(idx, SRDO);
                    assert_eq!(now, values, "variables changed on an error");
                    assert!(RECEPTION_CODES.contains(&code), "{code:?}");
                    if app_ignores {
                        follow.push_back(Event::SrdoError(SRDO, CopKernel::SrdoNotHandledInApp));
                    } else {
                        srdo_net::answer_as_manual(stack, &e);
                    }
                    follow.push_back(Event::ProgMon(ProgMonEvent::SrdoError));
                }
                _ => assert_eq!(now, values, "variables changed without AppSrdoEvent"),
            }
        });
        assert!(
            follow.is_empty(),
            "events lost at the end of the cycle: {follow:?}"
        );
        assert_eq!((fields.normal(), fields.inverted()), values);
    }
});
