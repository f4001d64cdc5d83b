//! One capture per fault class of the campaign ([`super::faults`]), for
//! tools that look at the bus from outside (the Wireshark dissector
//! `tools/wireshark/cop_srdo.lua`).
//!
//! Each capture is a short, fixed scenario on a [`SimBus`] with the
//! campaign's devices ([`super::srdo_net`]): the producer's pairs (SRDO 1,
//! COB-IDs 0x101/0x102, DLC 4, SCT 50 ms, SRVT 20 ms) every 20 ms (the
//! second pair on both limits: its inverted frame exactly SRVT after the
//! normal one, the next pair exactly SCT later), the
//! pair number [`FAULT_PAIR`] with the fault of the class, then
//! [`PAIRS_AFTER`] pairs of recovery. The producer's frames are taken off
//! the bus by a filter and put back at the planned instants, changed as
//! the class asks; the consumer receives them and its error reports are
//! kept with the capture (so a reader can compare what a node saw with
//! what the tool shows).
//!
//! What an observer of the bus must report, frame by frame, follows from
//! the plan alone ([`FaultCapture::expected`]): the rules of a CiA 304
//! consumer applied to the frames as they were on the wire (SAFETY_BEHAVIOUR
//! §5: order normal then inverted, equal and configured DLC, bitwise
//! complement, SRVT between the frames, SCT between valid pairs).
//!
//! Three classes of the campaign leave nothing wrong on the wire: the
//! tick-counter wrap (the capture clock runs on), the driver overrun (the
//! frames are all on the bus, the consumer's queue loses them) and the
//! configuration CRC (no SRDO frame is faulty, the consumer refuses to
//! start). The first two have captures whose expectation is "nothing";
//! the third has none ([`WIRE_CLASSES`]).

use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

use super::faults::Class;
use super::srdo_net::{
    COB_INVERTED, COB_NORMAL, Device, Role, SCT_MS, SRDO, SRVT_MS, answer_as_manual,
};
use super::{Delivery, SimBus};
use crate::ccm::NmtCommand;
use crate::error::CopKernel;
use crate::event::Event;
use crate::port::{CanFrame, CanId, Ticks};

/// The classes with a capture: every class of the campaign but the
/// configuration CRC.
pub const WIRE_CLASSES: [Class; 12] = [
    Class::BitFlipNormal,
    Class::BitFlipInverted,
    Class::LossNormal,
    Class::LossInverted,
    Class::Reordering,
    Class::Repetition,
    Class::WrongDlc,
    Class::LateInverted,
    Class::ProducerSilence,
    Class::Masquerade,
    Class::TickWrap,
    Class::Overrun,
];

/// Fault-free pairs before the faulty one (numbered from 1).
pub const FAULT_PAIR: u32 = 4;
/// Fault-free pairs after it.
pub const PAIRS_AFTER: u32 = 3;
/// Distance of two pairs, in ticks (20 ms: one lost pair still keeps the
/// next one within SCT).
const PERIOD: u32 = 200;
/// Distance of the inverted frame from the normal one, in ticks.
const GAP: u32 = 20;
/// Frames of unrelated traffic in the overrun capture (more than the
/// consumer's queue holds).
const BURST: u32 = 20;
/// The consumer's receive queue.
const RX_CAPACITY: usize = 16;

/// What an observer must report on one frame: the expert field of the
/// dissector (`cop_srdo.order`, `.dlc`, `.data`, `.srvt`, `.sct`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Expected {
    /// Frame number in the capture, from 1.
    pub frame: u32,
    /// The expert field.
    pub expert: &'static str,
}

/// A capture written by [`write()`](fn@write).
#[derive(Clone, Debug)]
pub struct FaultCapture {
    /// The class.
    pub class: Class,
    /// Frames in the capture.
    pub frames: u32,
    /// The reports an observer of the bus must make, in frame order.
    pub expected: Vec<Expected>,
    /// Frames that belong to a valid pair.
    pub valid_pair_frames: Vec<u32>,
    /// What the consumer reported: (frame number after which it was
    /// reported, `AppSrdoError` code).
    pub consumer_errors: Vec<(u32, CopKernel)>,
}

/// A short file name of the class (`bit_flip_normal`, ...).
pub const fn file_stem(class: Class) -> &'static str {
    match class {
        Class::BitFlipNormal => "bit_flip_normal",
        Class::BitFlipInverted => "bit_flip_inverted",
        Class::LossNormal => "loss_normal",
        Class::LossInverted => "loss_inverted",
        Class::Reordering => "reordering",
        Class::Repetition => "repetition",
        Class::WrongDlc => "wrong_dlc",
        Class::LateInverted => "late_inverted",
        Class::ProducerSilence => "producer_silence",
        Class::Masquerade => "masquerade",
        Class::ConfigCrc => "config_crc",
        Class::TickWrap => "tick_wrap",
        Class::Overrun => "overrun",
    }
}

/// The consumer's SRDO configuration as a DCF (CiA 306), the objects the
/// dissector reads: 0x1301 (direction 2, SCT, SRVT, COB-IDs) and 0x1381
/// (the mapping, four UNSIGNED16 entries: DLC 4).
pub fn consumer_dcf() -> String {
    let mut s = String::from(
        "[DeviceComissioning]\nNodeID=2\n\n[1301]\nParameterName=SRDO 1 communication\nObjectType=0x9\nSubNumber=7\n",
    );
    let subs: [(u8, &str, u32); 6] = [
        (1, "0x0005", 2),
        (2, "0x0006", u32::from(SCT_MS)),
        (3, "0x0005", u32::from(SRVT_MS)),
        (4, "0x0005", 254),
        (5, "0x0007", u32::from(COB_NORMAL)),
        (6, "0x0007", u32::from(COB_INVERTED)),
    ];
    for (sub, ty, v) in subs {
        s += &format!("\n[1301sub{sub}]\nDataType={ty}\nAccessType=rw\nParameterValue={v:#X}\n");
    }
    s += "\n[1381]\nParameterName=SRDO 1 mapping\nObjectType=0x9\nSubNumber=5\n";
    s += "\n[1381sub0]\nDataType=0x0005\nAccessType=rw\nParameterValue=4\n";
    let entries = [0x6200_0110u32, 0x6300_0110, 0x6201_0110, 0x6301_0110];
    for (i, e) in entries.iter().enumerate() {
        s += &format!(
            "\n[1381sub{}]\nDataType=0x0007\nAccessType=rw\nParameterValue={e:#010X}\n",
            i + 1
        );
    }
    s
}

/// One frame to put on the bus.
#[derive(Clone, Copy, Debug)]
struct Planned {
    at: u32,
    frame: CanFrame,
    /// The frame and its copy (a CAN retransmission).
    twice: bool,
}

struct Run {
    bus: SimBus,
    producer: Device,
    rogue: Device,
    consumer: Device,
    stash: Rc<RefCell<Vec<CanFrame>>>,
    on_wire: Rc<RefCell<u32>>,
    consumer_errors: Vec<(u32, CopKernel)>,
}

impl Run {
    fn new(epoch: Ticks) -> Result<Run, String> {
        let bus = SimBus::new();
        bus.set_time(epoch);
        let setup = |e: String| format!("set-up: {e}");
        let mut producer =
            Device::new(&bus, Role::Producer, 0).map_err(|e| setup(format!("{e:?}")))?;
        let mut consumer =
            Device::new(&bus, Role::Consumer, RX_CAPACITY).map_err(|e| setup(format!("{e:?}")))?;
        let mut rogue = Device::new(&bus, Role::Rogue, 0).map_err(|e| setup(format!("{e:?}")))?;
        for d in [&mut producer, &mut consumer, &mut rogue] {
            d.seal().map_err(|e| setup(format!("seal: {e:?}")))?;
        }
        let stash = Rc::new(RefCell::new(Vec::new()));
        let on_wire = Rc::new(RefCell::new(0u32));
        let (st, count) = (Rc::clone(&stash), Rc::clone(&on_wire));
        let (p, r) = (producer.port.node(), rogue.port.node());
        bus.set_filter(Some(Box::new(move |from, f: &mut CanFrame| {
            if from == p || from == r {
                st.borrow_mut().push(*f);
                return Delivery::Drop;
            }
            *count.borrow_mut() += 1;
            Delivery::Deliver
        })));
        for d in [&mut producer, &mut consumer, &mut rogue] {
            d.command(NmtCommand::StartRemoteNode)
                .map_err(|e| setup(format!("start: {e:?}")))?;
        }
        // past the first-send delays (0.5 ms per node-ID)
        bus.advance_ms(5);
        consumer.process(|_, _| {});
        Ok(Run {
            bus,
            producer,
            rogue,
            consumer,
            stash,
            on_wire,
            consumer_errors: Vec::new(),
        })
    }

    /// The pair the producer (or the rogue) sends for `normal`.
    fn pair(&mut self, rogue: bool, normal: &[u8]) -> Result<(CanFrame, CanFrame), String> {
        let dev = if rogue {
            &mut self.rogue
        } else {
            &mut self.producer
        };
        dev.set_data(normal);
        dev.send(|_, _| {}).map_err(|e| format!("send: {e:?}"))?;
        let mut st = self.stash.borrow_mut();
        let frames: Vec<CanFrame> = st.drain(..).collect();
        match frames.as_slice() {
            [a, b] => Ok((*a, *b)),
            other => Err(format!("{} frames from one send", other.len())),
        }
    }

    /// Puts the planned frames on the bus in time order, the consumer
    /// processing after the last frame of each instant.
    fn play(&mut self, start: Ticks, mut plan: Vec<Planned>) {
        plan.sort_by_key(|p| p.at);
        let instants: Vec<u32> = plan.iter().map(|p| p.at).collect();
        for (i, p) in plan.into_iter().enumerate() {
            let at = start.plus(p.at);
            let now = self.bus.now();
            self.bus.advance_ticks(at.since(now));
            let copies = if p.twice { 2 } else { 1 };
            for _ in 0..copies {
                self.bus.inject(p.frame);
            }
            if instants.get(i + 1) == Some(&p.at) {
                continue;
            }
            let frame_no = *self.on_wire.borrow();
            let errors = &mut self.consumer_errors;
            self.consumer.process(|stack, e| {
                if let Event::SrdoError(idx, code) = e {
                    if idx == SRDO {
                        errors.push((frame_no, code));
                    }
                }
                let _ = answer_as_manual(stack, &e);
            });
        }
    }
}

fn flip(mut f: CanFrame, byte: usize, bit: u8) -> CanFrame {
    if let Some(b) = f.data.get_mut(byte) {
        *b ^= 1 << bit;
    }
    f
}

fn with_len(mut f: CanFrame, len: u8) -> CanFrame {
    f.len = len;
    for (i, b) in f.data.iter_mut().enumerate() {
        if i >= usize::from(len) {
            *b = 0;
        }
    }
    f
}

/// Writes the capture of `class` to `pcap` and returns what it holds and
/// what an observer must report.
pub fn write(class: Class, pcap: &Path) -> Result<FaultCapture, String> {
    // For the tick-counter wrap, the fault pair's two frames lie on both
    // sides of the wrap of the 32-bit counter (the set-up takes 5 ms).
    let epoch = if class == Class::TickWrap {
        // pairs 1 and 3.. are PERIOD apart, pair 2 SCT from pair 3
        let fault_at = (FAULT_PAIR - 2) * PERIOD + u32::from(SCT_MS) * 10;
        Ticks(0u32.wrapping_sub(50 + fault_at + GAP / 2))
    } else {
        Ticks(0)
    };
    let mut run = Run::new(epoch)?;
    run.bus
        .capture(Some(pcap), None)
        .map_err(|e| format!("capture: {e}"))?;
    let start = run.bus.now();

    let mut plan: Vec<Planned> = Vec::new();
    let mut expected: Vec<Expected> = Vec::new();
    let mut valid: Vec<u32> = Vec::new();
    // Frame numbers follow from the plan: every planned frame is one
    // frame of the capture (two when repeated), in time order.
    let mut t = 0u32;
    let mut frame_no = 0u32;
    let put =
        |plan: &mut Vec<Planned>, frame_no: &mut u32, at: u32, frame: CanFrame, twice: bool| {
            plan.push(Planned { at, frame, twice });
            *frame_no += if twice { 2 } else { 1 };
            *frame_no
        };
    let expect = |expected: &mut Vec<Expected>, frame: u32, expert: &'static str| {
        expected.push(Expected { frame, expert });
    };

    let total = FAULT_PAIR + PAIRS_AFTER;
    for n in 1..=total {
        let value = n as u8;
        let data = [value, 0x10 ^ value, 0x5A, 0xC0 | value];
        let (f1, f2) = run.pair(false, &data)?;
        if n != FAULT_PAIR {
            // Pair 2 meets both limits exactly (valid): its inverted frame
            // SRVT after its normal frame, the next pair SCT after it.
            let (gap, period) = if n == 2 {
                (u32::from(SRVT_MS) * 10, u32::from(SCT_MS) * 10)
            } else {
                (GAP, PERIOD)
            };
            let a = put(&mut plan, &mut frame_no, t, f1, false);
            let b = put(&mut plan, &mut frame_no, t + gap, f2, false);
            valid.extend([a, b]);
            t += period;
            continue;
        }
        let mut next = t + PERIOD;
        match class {
            Class::BitFlipNormal | Class::BitFlipInverted => {
                let (g1, g2) = if class == Class::BitFlipNormal {
                    (flip(f1, 1, 3), f2)
                } else {
                    (f1, flip(f2, 2, 6))
                };
                put(&mut plan, &mut frame_no, t, g1, false);
                let b = put(&mut plan, &mut frame_no, t + GAP, g2, false);
                expect(&mut expected, b, "cop_srdo.data");
            }
            Class::LossNormal => {
                let b = put(&mut plan, &mut frame_no, t + GAP, f2, false);
                expect(&mut expected, b, "cop_srdo.order");
            }
            Class::LossInverted => {
                put(&mut plan, &mut frame_no, t, f1, false);
                // reported on the next normal frame
                expect(&mut expected, frame_no + 1, "cop_srdo.order");
            }
            Class::Reordering => {
                let a = put(&mut plan, &mut frame_no, t, f2, false);
                put(&mut plan, &mut frame_no, t + GAP, f1, false);
                expect(&mut expected, a, "cop_srdo.order");
                // the held normal frame never gets its inverted frame
                expect(&mut expected, frame_no + 1, "cop_srdo.order");
            }
            Class::Repetition => {
                let a = put(&mut plan, &mut frame_no, t, f1, true);
                let b = put(&mut plan, &mut frame_no, t + GAP, f2, false);
                expect(&mut expected, a, "cop_srdo.order");
                valid.extend([a, b]);
            }
            Class::WrongDlc => {
                let a = put(&mut plan, &mut frame_no, t, with_len(f1, 3), false);
                let b = put(&mut plan, &mut frame_no, t + GAP, f2, false);
                expect(&mut expected, a, "cop_srdo.dlc");
                expect(&mut expected, b, "cop_srdo.order");
            }
            Class::LateInverted => {
                // SRVT + 1 tick: one tick beyond the limit
                let late = u32::from(SRVT_MS) * 10 + 1;
                put(&mut plan, &mut frame_no, t, f1, false);
                let b = put(&mut plan, &mut frame_no, t + late, f2, false);
                expect(&mut expected, b, "cop_srdo.srvt");
                // the next pair after it, within SCT of the last valid one
                next = t + late + 49;
            }
            Class::ProducerSilence => {
                // the normal frame SCT + 1 tick after the previous one
                let late = t - PERIOD + u32::from(SCT_MS) * 10 + 1;
                let a = put(&mut plan, &mut frame_no, late, f1, false);
                let b = put(&mut plan, &mut frame_no, late + GAP, f2, false);
                expect(&mut expected, a, "cop_srdo.sct");
                valid.extend([a, b]);
                next = late + PERIOD;
            }
            Class::Masquerade => {
                let (r1, r2) = run.pair(true, &[0x11, 0x22])?;
                let a = put(&mut plan, &mut frame_no, t, r1, false);
                let b = put(&mut plan, &mut frame_no, t + GAP, r2, false);
                expect(&mut expected, a, "cop_srdo.dlc");
                expect(&mut expected, b, "cop_srdo.order");
            }
            Class::TickWrap => {
                let a = put(&mut plan, &mut frame_no, t, f1, false);
                let b = put(&mut plan, &mut frame_no, t + GAP, f2, false);
                valid.extend([a, b]);
            }
            Class::Overrun | Class::ConfigCrc => {
                // unrelated traffic (0x181) between the two frames: the
                // consumer's queue overflows, the bus carries everything
                let a = put(&mut plan, &mut frame_no, t, f1, false);
                for i in 0..BURST {
                    let foreign = CanFrame::new(CanId::std_masked(0x181), &[i as u8]);
                    put(&mut plan, &mut frame_no, t + 1, foreign, false);
                }
                let b = put(&mut plan, &mut frame_no, t + GAP, f2, false);
                valid.extend([a, b]);
            }
        }
        t = next;
    }
    if class == Class::ConfigCrc {
        return Err("the configuration CRC class has no faulty frame to capture".into());
    }
    run.play(start, plan);
    run.bus
        .flush_capture()
        .map_err(|e| format!("capture: {e}"))?;
    let on_wire = *run.on_wire.borrow();
    if on_wire != frame_no {
        return Err(format!("{on_wire} frames on the bus, {frame_no} planned"));
    }
    valid.sort_unstable();
    Ok(FaultCapture {
        class,
        frames: frame_no,
        expected,
        valid_pair_frames: valid,
        consumer_errors: run.consumer_errors,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::srdo_net::lock;

    fn capture(class: Class) -> FaultCapture {
        let _g = lock();
        let path = std::env::temp_dir().join(format!(
            "cop_fault_capture_{}_{}.pcap",
            file_stem(class),
            std::process::id()
        ));
        let c = write(class, &path).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        let _ = std::fs::remove_file(&path);
        // 24 bytes file header, 32 bytes per frame (pcap record header and
        // SocketCAN record)
        assert_eq!(bytes.len() as u32, 24 + 32 * c.frames);
        c
    }

    #[test]
    #[cfg_attr(miri, ignore = "writes files; Miri runs isolated from the file system")]
    fn the_consumer_reports_what_the_campaign_expects_of_each_class() {
        use CopKernel::*;
        let codes = |class| -> Vec<CopKernel> {
            capture(class)
                .consumer_errors
                .iter()
                .map(|&(_, k)| k)
                .collect()
        };
        assert_eq!(codes(Class::BitFlipNormal), [SrdoDataError]);
        assert_eq!(codes(Class::BitFlipInverted), [SrdoDataError]);
        assert_eq!(codes(Class::LossNormal), [SrdoNotInOrder]);
        assert_eq!(codes(Class::WrongDlc), [SrdoDlcNotValid, SrdoNotInOrder]);
        assert_eq!(codes(Class::LateInverted), [SrdoSrvtTimeout]);
        assert_eq!(codes(Class::Repetition), [SrdoNotInOrder]);
        assert_eq!(codes(Class::Masquerade), [SrdoDlcNotValid, SrdoNotInOrder]);
        assert_eq!(codes(Class::TickWrap), []);
        assert_eq!(codes(Class::Overrun).first(), Some(&SrdoOverrun));
    }

    #[test]
    #[cfg_attr(miri, ignore = "writes files; Miri runs isolated from the file system")]
    fn frame_numbers_of_the_plan() {
        let c = capture(Class::LossNormal);
        // three pairs, then the lone inverted frame: frame 7
        assert_eq!(
            c.expected,
            [Expected {
                frame: 2 * (FAULT_PAIR - 1) + 1,
                expert: "cop_srdo.order"
            }]
        );
        assert_eq!(c.frames, 2 * (FAULT_PAIR + PAIRS_AFTER) - 1);
    }

    #[test]
    fn dcf_names_the_consumer_parameters() {
        let d = consumer_dcf();
        assert!(d.contains("[1301sub2]\nDataType=0x0006\nAccessType=rw\nParameterValue=0x32\n"));
        assert!(d.contains("[1301sub5]\nDataType=0x0007\nAccessType=rw\nParameterValue=0x101\n"));
        assert!(
            d.contains("[1381sub3]\nDataType=0x0007\nAccessType=rw\nParameterValue=0x62010110\n")
        );
    }
}
