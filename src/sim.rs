//! A simulated CAN bus for tests and examples (host builds, `std` feature).
//!
//! Several nodes share one bus; a frame sent by one node is delivered, in
//! sending order, to every other node's receive queue with the bus time as
//! its receive timestamp. The clock only moves when told to
//! ([`SimBus::advance_ms`]), so every run is reproducible. Each frame is
//! recorded in candump format (`  can0  702   [1]  00`). A fault filter can
//! drop, change or duplicate frames on their way (fault injection).
//!
//! A bus writes a pcap file (SocketCAN, link type 227) and a `candump -l`
//! log of its frames, with the simulated time as timestamps, when asked:
//! [`SimBus::capture`], or the environment variables `COP_SIM_PCAP` and
//! `COP_SIM_CANDUMP` naming the files for every bus the program creates
//! ([`capture`]).
//!
//! That bus is ideal: no bit time, no arbitration, no transmit queue. A bus
//! made with [`SimBus::with_model`] or [`SimBus::with_bit_rate`] is
//! physical ([`physical`]): a frame takes its length in bits (bit stuffing
//! included) at the bus's bit rate, waits in its node's high or low
//! transmit buffer until it wins arbitration (lowest identifier), and
//! arrives at the end of its end of frame field, which is its receive
//! timestamp. A node receives only the identifiers it subscribed (the
//! driver's identifier filter, `CdrvDefineCanId`), those subscribed with
//! [`Priority::High`] in a bounded high buffer, the others in a bounded
//! low buffer. A loss in the high buffer is
//! reported as `PortStatus::rx_overrun`, in the low buffer as
//! `PortStatus::rx_overrun_other`.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::io;
use std::path::Path;
use std::rc::Rc;

use crate::error::{CopKernel, CopResult};
use crate::port::{CanFrame, CanId, CanPort, Clock, PortStatus, Priority, RxFrame, Ticks};

pub use physical::{BusFrame, BusModel, BusStats};
use physical::{NS_PER_TICK, NodeQueues, Pending};

pub mod capture;
pub mod fault_captures;
pub mod faults;
pub mod nvram;
pub mod physical;
pub mod srdo_net;

/// What a fault filter does with a frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Delivery {
    /// Deliver as is (possibly modified in place by the filter).
    Deliver,
    /// Lose the frame.
    Drop,
    /// Deliver it twice.
    Duplicate,
}

/// A fault filter: sees (sender node, frame) and may modify the frame.
pub type FaultFilter = Box<dyn FnMut(usize, &mut CanFrame) -> Delivery>;

struct Node {
    rx: VecDeque<RxFrame>,
    capacity: usize,
    overrun: bool,
    /// Frames lost from a buffer without SRDO or GFC identifiers
    /// ([`SimBus::raise_other_overrun`]).
    overrun_other: bool,
    tx_refuse: usize,
    bus_off: bool,
    /// The buffers on a physical bus (unused on the ideal bus).
    q: NodeQueues,
}

/// The state of a physical bus.
struct Phys {
    model: BusModel,
    /// Bus time in ns since the bus was made.
    now_ns: u64,
    /// The tick count at `origin_ns` ([`SimBus::set_time`]).
    origin_ticks: Ticks,
    origin_ns: u64,
    /// No SOF before this time (end of the last frame plus intermission).
    idle_from_ns: u64,
    in_flight: Option<BusFrame>,
    /// The transmit buffer of frames injected from outside (unbounded).
    outside: NodeQueues,
    stats: BusStats,
    log: Option<Vec<BusFrame>>,
}

impl Phys {
    fn ticks_at(&self, ns: u64) -> Ticks {
        let elapsed = ns.saturating_sub(self.origin_ns) / NS_PER_TICK;
        // Ticks wrap like the target's counter.
        self.origin_ticks.plus(elapsed as u32)
    }
}

struct Bus {
    now: Ticks,
    nodes: Vec<Node>,
    trace: Vec<String>,
    echo: bool,
    filter: Option<FaultFilter>,
    sent: Vec<(usize, Ticks, CanFrame)>,
    capture: Option<capture::Capture>,
    phys: Option<Phys>,
}

impl Bus {
    /// Runs a physical bus for `ns`: frames start, win arbitration and
    /// arrive as the time passes; the tick count follows.
    fn run_for(&mut self, ns: u64) {
        let Some(p) = self.phys.as_mut() else {
            return;
        };
        let until = p.now_ns.saturating_add(ns);
        loop {
            let Some(p) = self.phys.as_mut() else {
                return;
            };
            if let Some(f) = p.in_flight {
                if f.end_ns > until {
                    break;
                }
                p.in_flight = None;
                p.idle_from_ns = f.end_ns + p.model.bits_ns(physical::INTERMISSION_BITS);
                // Counted when it is over, so the load never passes 100 %.
                p.stats.frames += 1;
                p.stats.bits += u64::from(f.bits);
                p.stats.busy_ns += p.model.bits_ns(f.bits);
                self.deliver(f);
                continue;
            }
            if !self.start_next(until) {
                break;
            }
        }
        if let Some(p) = self.phys.as_mut() {
            p.now_ns = until;
            p.stats.elapsed_ns = until;
            self.now = p.ticks_at(until);
        }
    }

    /// Starts the frame that wins arbitration at the next moment the bus
    /// is idle and a frame is waiting, if that is before `until`.
    fn start_next(&mut self, until: u64) -> bool {
        let Some(p) = self.phys.as_mut() else {
            return false;
        };
        let heads = || {
            self.nodes
                .iter()
                .enumerate()
                .filter_map(|(i, n)| n.q.head().map(|h| (i, h)))
                .chain(p.outside.head().map(|h| (usize::MAX, h)))
        };
        let Some(first) = heads().map(|(_, h)| h.queued_ns).min() else {
            return false;
        };
        let start = first.max(p.idle_from_ns);
        if start > until {
            return false;
        }
        let winner = physical::arbitration_winner(
            heads()
                .filter(|(_, h)| h.queued_ns <= start)
                .map(|(i, h)| (i, &h.frame)),
        );
        let taken = match winner {
            Some(usize::MAX) => p.outside.pop_head().map(|h| (usize::MAX, h)),
            Some(i) => self
                .nodes
                .get_mut(i)
                .and_then(|n| n.q.pop_head())
                .map(|h| (i, h)),
            None => None,
        };
        let Some((from, pending)) = taken else {
            return false;
        };
        let bits = physical::frame_bits(&pending.frame);
        let slot = bits + physical::INTERMISSION_BITS;
        p.in_flight = Some(BusFrame {
            from,
            queued_ns: pending.queued_ns,
            start_ns: start,
            end_ns: start + p.model.bits_ns(bits),
            bits: slot,
            frame: pending.frame,
        });
        true
    }

    /// A frame on the bus, either model: the fault filter (which may change
    /// `frame`), the trace, `sent()` and the captures at `time` plus
    /// `sub_us` microseconds. Returns how many copies the receivers get.
    fn on_the_bus(&mut self, from: usize, time: Ticks, sub_us: u64, frame: &mut CanFrame) -> usize {
        let delivery = match self.filter.as_mut() {
            Some(filter) => filter(from, frame),
            None => Delivery::Deliver,
        };
        let line = candump(frame);
        if self.echo {
            println!("{line}");
        }
        self.trace.push(line);
        self.sent.push((from, time, *frame));
        let copies = match delivery {
            Delivery::Deliver => 1,
            Delivery::Drop => 0,
            Delivery::Duplicate => 2,
        };
        if let Some(c) = self.capture.as_mut() {
            for _ in 0..copies {
                if let Err(e) = c.record(time, sub_us, frame) {
                    eprintln!("sim: capture stopped: {e}");
                    self.capture = None;
                    break;
                }
            }
        }
        copies
    }

    /// A frame of a physical bus at its end of frame: the fault filter,
    /// the trace and the captures, then every other node's receive
    /// buffers.
    fn deliver(&mut self, f: BusFrame) {
        let Some(p) = self.phys.as_mut() else {
            return;
        };
        let time = p.ticks_at(f.end_ns);
        let sub_us = f.end_ns.saturating_sub(p.origin_ns) % NS_PER_TICK / 1000;
        let model = p.model;
        let mut frame = f.frame;
        let copies = self.on_the_bus(f.from, time, sub_us, &mut frame);
        if let Some(log) = self.phys.as_mut().and_then(|p| p.log.as_mut()) {
            for _ in 0..copies {
                log.push(BusFrame { frame, ..f });
            }
        }
        let (mut lost_high, mut lost_low) = (0, 0);
        for (i, n) in self.nodes.iter_mut().enumerate() {
            if i == f.from {
                continue;
            }
            let Some(&prio) = n.q.ids.get(&frame.id) else {
                continue;
            };
            for _ in 0..copies {
                let rx = RxFrame { frame, time };
                if prio == Priority::High {
                    if n.q.rx_high.len() >= model.rx_high {
                        n.overrun = true;
                        lost_high += 1;
                    } else {
                        n.q.rx_high.push_back(rx);
                    }
                } else if n.q.rx_low.len() >= model.rx_low {
                    n.overrun_other = true;
                    lost_low += 1;
                } else {
                    n.q.rx_low.push_back(rx);
                }
            }
        }
        if let Some(p) = self.phys.as_mut() {
            p.stats.rx_lost_high += lost_high;
            p.stats.rx_lost_low += lost_low;
        }
    }
}

impl Drop for Bus {
    fn drop(&mut self) {
        if let Some(c) = self.capture.as_mut() {
            if let Err(e) = c.flush() {
                eprintln!("sim: capture not written completely: {e}");
            }
        }
    }
}

/// The shared bus.
#[derive(Clone)]
pub struct SimBus(Rc<RefCell<Bus>>);

/// One node's connection to the bus: a [`CanPort`] and a [`Clock`].
#[derive(Clone)]
pub struct SimPort {
    bus: SimBus,
    node: usize,
}

/// Formats a frame like candump: `  can0  702   [1]  00`.
pub fn candump(f: &CanFrame) -> String {
    let id = if f.id.is_extended() {
        format!("{:08X}", f.id.id())
    } else {
        format!("{:03X}", f.id.id())
    };
    let data = if f.rtr {
        "remote request".to_string()
    } else {
        f.payload()
            .iter()
            .map(|b| format!("{b:02X}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    format!("  can0  {id}   [{}]  {data}", f.len)
}

impl Default for SimBus {
    fn default() -> Self {
        Self::new()
    }
}

impl SimBus {
    /// An empty bus at time 0. When the environment names capture files
    /// (`COP_SIM_PCAP`, `COP_SIM_CANDUMP`), the bus writes them from its
    /// first frame on; a file that cannot be created is reported on
    /// stderr and left out. Every new bus truncates them, so in a program
    /// with several buses they hold the traffic of the last one.
    pub fn new() -> SimBus {
        let capture = match capture::Capture::from_env() {
            Some(Ok(c)) => Some(c),
            Some(Err(e)) => {
                eprintln!("sim: capture files of the environment not created: {e}");
                None
            }
            None => None,
        };
        SimBus(Rc::new(RefCell::new(Bus {
            now: Ticks(0),
            nodes: Vec::new(),
            trace: Vec::new(),
            echo: false,
            filter: None,
            sent: Vec::new(),
            capture,
            phys: None,
        })))
    }

    /// A physical bus ([`physical`]) with the bit rate and buffer sizes of
    /// `model`; `kCopInvalidParam` when the model is out of range
    /// ([`BusModel::check`]). Time 0, no node yet.
    pub fn with_model(model: BusModel) -> Result<SimBus, CopKernel> {
        model.check()?;
        let bus = SimBus::new();
        bus.0.borrow_mut().phys = Some(Phys {
            model,
            now_ns: 0,
            origin_ticks: Ticks(0),
            origin_ns: 0,
            idle_from_ns: 0,
            in_flight: None,
            outside: NodeQueues::default(),
            stats: BusStats::default(),
            log: None,
        });
        Ok(bus)
    }

    /// A physical bus of `bit_rate` bit/s with the buffer sizes of
    /// [`BusModel::new`]; `kCopInvalidParam` outside 10 kbit/s .. 1 Mbit/s.
    pub fn with_bit_rate(bit_rate: u32) -> Result<SimBus, CopKernel> {
        SimBus::with_model(BusModel::new(bit_rate).ok_or(CopKernel::InvalidParam)?)
    }

    /// The model of a physical bus, `None` for the ideal bus.
    pub fn model(&self) -> Option<BusModel> {
        self.0.borrow().phys.as_ref().map(|p| p.model)
    }

    /// The counters of a physical bus (`None` for the ideal bus).
    pub fn stats(&self) -> Option<BusStats> {
        self.0.borrow().phys.as_ref().map(|p| p.stats)
    }

    /// The bus time in ns (physical bus; the ideal bus counts in ticks).
    pub fn now_ns(&self) -> u64 {
        let b = self.0.borrow();
        match b.phys.as_ref() {
            Some(p) => p.now_ns,
            None => u64::from(b.now.0) * NS_PER_TICK,
        }
    }

    /// Starts (or stops) keeping every frame of a physical bus with its
    /// start and end in ns, for [`SimBus::take_bus_log`].
    pub fn keep_bus_log(&self, on: bool) {
        if let Some(p) = self.0.borrow_mut().phys.as_mut() {
            p.log = on.then(Vec::new);
        }
    }

    /// The frames that went over a physical bus since the last call (with
    /// [`SimBus::keep_bus_log`] on), as the receivers got them: after the
    /// fault filter (a dropped frame is missing, a duplicated one twice).
    pub fn take_bus_log(&self) -> Vec<BusFrame> {
        self.0
            .borrow_mut()
            .phys
            .as_mut()
            .and_then(|p| p.log.as_mut().map(std::mem::take))
            .unwrap_or_default()
    }

    /// Writes every frame that reaches the bus from now on into a pcap
    /// file (SocketCAN, link type 227) and/or a `candump -l` log; `None`
    /// leaves that format out, both `None` stops capturing. The files are
    /// created (truncated); what is buffered is written by
    /// [`SimBus::flush_capture`] and when the bus is dropped.
    pub fn capture(&self, pcap: Option<&Path>, candump: Option<&Path>) -> io::Result<()> {
        let mut b = self.0.borrow_mut();
        if let Some(old) = b.capture.as_mut() {
            old.flush()?;
        }
        b.capture = if pcap.is_none() && candump.is_none() {
            None
        } else {
            Some(capture::Capture::create(pcap, candump)?)
        };
        Ok(())
    }

    /// Writes out what the capture files have buffered.
    pub fn flush_capture(&self) -> io::Result<()> {
        match self.0.borrow_mut().capture.as_mut() {
            Some(c) => c.flush(),
            None => Ok(()),
        }
    }

    /// Starts the clock at `t` (wrap tests).
    pub fn set_time(&self, t: Ticks) {
        let mut b = self.0.borrow_mut();
        b.now = t;
        if let Some(p) = b.phys.as_mut() {
            p.origin_ticks = t;
            p.origin_ns = p.now_ns;
        }
    }

    /// Attaches a node with a receive queue of `capacity` frames (a full
    /// queue loses the newest frame and reports an overrun). On a physical
    /// bus the node has the model's buffers instead and `capacity` is not
    /// used.
    pub fn attach(&self, capacity: usize) -> SimPort {
        let mut b = self.0.borrow_mut();
        b.nodes.push(Node {
            rx: VecDeque::new(),
            capacity,
            overrun: false,
            overrun_other: false,
            tx_refuse: 0,
            bus_off: false,
            q: NodeQueues::default(),
        });
        SimPort {
            bus: self.clone(),
            node: b.nodes.len() - 1,
        }
    }

    /// The current bus time.
    pub fn now(&self) -> Ticks {
        self.0.borrow().now
    }

    /// Advances the clock by `ms` milliseconds.
    pub fn advance_ms(&self, ms: u32) {
        self.advance_ticks(crate::port::ms_to_ticks(ms));
    }

    /// Advances the clock by `ticks` (100 µs each).
    pub fn advance_ticks(&self, ticks: u32) {
        let mut b = self.0.borrow_mut();
        if b.phys.is_some() {
            b.run_for(u64::from(ticks) * NS_PER_TICK);
        } else {
            b.now = b.now.plus(ticks);
        }
    }

    /// Prints each frame to stdout as it is sent.
    pub fn set_echo(&self, on: bool) {
        self.0.borrow_mut().echo = on;
    }

    /// Installs (or removes) a fault filter.
    pub fn set_filter(&self, f: Option<FaultFilter>) {
        self.0.borrow_mut().filter = f;
    }

    /// Makes node `node` refuse its next `n` transmissions (driver buffer
    /// full, `kCopCdrvTxBuffHighOverrun`).
    pub fn refuse_tx(&self, node: usize, n: usize) {
        if let Some(x) = self.0.borrow_mut().nodes.get_mut(node) {
            x.tx_refuse = n;
        }
    }

    /// Reports at `node`'s next status read a loss of frames that no SRDO
    /// or GFC uses (a driver's low-buffer overrun while those identifiers
    /// are received in the high buffer).
    pub fn raise_other_overrun(&self, node: usize) {
        if let Some(x) = self.0.borrow_mut().nodes.get_mut(node) {
            x.overrun_other = true;
        }
    }

    /// Sets or clears the bus-off flag node `node`'s driver reports
    /// ([`CanPort::status`]); only the flag, its frames still go out.
    pub fn set_bus_off(&self, node: usize, on: bool) {
        if let Some(x) = self.0.borrow_mut().nodes.get_mut(node) {
            x.bus_off = on;
        }
    }

    /// The candump trace so far.
    pub fn trace(&self) -> Vec<String> {
        self.0.borrow().trace.clone()
    }

    /// Every frame sent so far: (sender, time, frame).
    pub fn sent(&self) -> Vec<(usize, Ticks, CanFrame)> {
        self.0.borrow().sent.clone()
    }

    /// Forgets the trace and the sent list.
    pub fn clear_trace(&self) {
        let mut b = self.0.borrow_mut();
        b.trace.clear();
        b.sent.clear();
    }

    /// Puts a frame on the bus as if sent by an outside node (`usize::MAX`):
    /// every attached node receives it.
    pub fn inject(&self, frame: CanFrame) {
        let mut b = self.0.borrow_mut();
        if let Some(p) = b.phys.as_mut() {
            let queued_ns = p.now_ns;
            p.outside.tx_low.push_back(Pending { frame, queued_ns });
            return;
        }
        drop(b);
        self.transmit(usize::MAX, frame);
    }

    fn transmit(&self, from: usize, mut frame: CanFrame) {
        let mut b = self.0.borrow_mut();
        let now = b.now;
        let copies = b.on_the_bus(from, now, 0, &mut frame);
        for (i, n) in b.nodes.iter_mut().enumerate() {
            if i == from {
                continue;
            }
            for _ in 0..copies {
                if n.rx.len() >= n.capacity {
                    n.overrun = true;
                } else {
                    n.rx.push_back(RxFrame { frame, time: now });
                }
            }
        }
    }
}

impl SimPort {
    /// The bus this port is attached to.
    pub fn bus(&self) -> &SimBus {
        &self.bus
    }

    /// This node's number on the bus.
    pub fn node(&self) -> usize {
        self.node
    }

    /// Frames waiting in this node's receive queue.
    pub fn pending(&self) -> usize {
        self.bus
            .0
            .borrow()
            .nodes
            .get(self.node)
            .map_or(0, |n| n.rx.len() + n.q.rx_len())
    }

    /// Frames waiting in this node's transmit buffers (physical bus).
    pub fn tx_pending(&self) -> usize {
        self.bus
            .0
            .borrow()
            .nodes
            .get(self.node)
            .map_or(0, |n| n.q.tx_high.len() + n.q.tx_low.len())
    }
}

impl CanPort for SimPort {
    fn send(&mut self, frame: &CanFrame, prio: Priority) -> CopResult {
        {
            let mut b = self.bus.0.borrow_mut();
            if let Some(n) = b.nodes.get_mut(self.node) {
                if n.tx_refuse > 0 {
                    n.tx_refuse -= 1;
                    return Err(match prio {
                        Priority::High => CopKernel::CdrvTxBuffHighOverrun,
                        Priority::Low => CopKernel::CdrvTxBuffLowOverrun,
                    });
                }
            }
        }
        {
            let mut b = self.bus.0.borrow_mut();
            let Bus { phys, nodes, .. } = &mut *b;
            if let (Some(p), Some(n)) = (phys.as_mut(), nodes.get_mut(self.node)) {
                let (queue, size, full) = match prio {
                    Priority::High => (
                        &mut n.q.tx_high,
                        p.model.tx_high,
                        CopKernel::CdrvTxBuffHighOverrun,
                    ),
                    Priority::Low => (
                        &mut n.q.tx_low,
                        p.model.tx_low,
                        CopKernel::CdrvTxBuffLowOverrun,
                    ),
                };
                if queue.len() >= size {
                    p.stats.tx_refused += 1;
                    return Err(full);
                }
                queue.push_back(Pending {
                    frame: *frame,
                    queued_ns: p.now_ns,
                });
                return Ok(());
            }
        }
        self.bus.transmit(self.node, *frame);
        Ok(())
    }

    fn receive(&mut self) -> Option<RxFrame> {
        self.bus
            .0
            .borrow_mut()
            .nodes
            .get_mut(self.node)
            .and_then(|n| n.rx.pop_front().or_else(|| n.q.receive()))
    }

    fn subscribe(&mut self, id: CanId, prio: Priority) -> CopResult {
        // The ideal bus delivers everything to one queue; a physical bus
        // receives only subscribed identifiers, each in the buffer of its
        // priority.
        if let Some(n) = self.bus.0.borrow_mut().nodes.get_mut(self.node) {
            n.q.ids.insert(id, prio);
        }
        Ok(())
    }

    fn unsubscribe(&mut self, id: CanId) -> CopResult {
        if let Some(n) = self.bus.0.borrow_mut().nodes.get_mut(self.node) {
            n.q.ids.remove(&id);
        }
        Ok(())
    }

    fn take_rx_overrun(&mut self) -> bool {
        self.status().rx_overrun
    }

    fn status(&mut self) -> PortStatus {
        let mut b = self.bus.0.borrow_mut();
        b.nodes
            .get_mut(self.node)
            .map_or(PortStatus::default(), |n| PortStatus {
                rx_overrun: std::mem::take(&mut n.overrun),
                rx_overrun_other: std::mem::take(&mut n.overrun_other),
                bus_off: n.bus_off,
            })
    }
}

impl Clock for SimPort {
    fn now(&self) -> Ticks {
        self.bus.now()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::port::CanId;

    #[test]
    fn frames_reach_other_nodes_in_order_with_timestamps() {
        let bus = SimBus::new();
        let mut a = bus.attach(8);
        let mut b = bus.attach(8);
        bus.advance_ms(3);
        a.send(
            &CanFrame::new(CanId::std_masked(0x101), &[1]),
            Priority::High,
        )
        .unwrap();
        bus.advance_ms(1);
        a.send(
            &CanFrame::new(CanId::std_masked(0x102), &[0xFE]),
            Priority::High,
        )
        .unwrap();
        assert_eq!(a.receive(), None, "a sender does not hear itself");
        let f1 = b.receive().unwrap();
        let f2 = b.receive().unwrap();
        assert_eq!((f1.frame.id.id(), f1.time), (0x101, Ticks(30)));
        assert_eq!((f2.frame.id.id(), f2.time), (0x102, Ticks(40)));
        assert_eq!(
            bus.trace(),
            vec!["  can0  101   [1]  01", "  can0  102   [1]  FE"]
        );
    }

    #[test]
    fn full_queue_reports_overrun() {
        let bus = SimBus::new();
        let mut a = bus.attach(1);
        let mut b = bus.attach(1);
        a.send(&CanFrame::new(CanId::std_masked(1), &[]), Priority::Low)
            .unwrap();
        a.send(&CanFrame::new(CanId::std_masked(2), &[]), Priority::Low)
            .unwrap();
        assert!(b.take_rx_overrun());
        assert!(!b.take_rx_overrun());
        assert_eq!(b.receive().unwrap().frame.id.id(), 1);
        assert_eq!(b.receive(), None);
    }

    #[test]
    #[cfg_attr(miri, ignore = "writes files; Miri runs isolated from the file system")]
    fn capture_holds_what_reached_the_bus_with_bus_time() {
        let dir = std::env::temp_dir();
        let pcap = dir.join(format!("cop_sim_capture_{}.pcap", std::process::id()));
        let log = dir.join(format!("cop_sim_capture_{}.log", std::process::id()));
        let bus = SimBus::new();
        bus.capture(Some(&pcap), Some(&log)).unwrap();
        let mut a = bus.attach(8);
        let _b = bus.attach(8);
        bus.set_filter(Some(Box::new(|_, f: &mut CanFrame| match f.id.id() {
            0x102 => Delivery::Drop,
            0x103 => Delivery::Duplicate,
            _ => Delivery::Deliver,
        })));
        for (ms, id) in [(0, 0x101), (2, 0x102), (3, 0x103)] {
            bus.advance_ms(ms);
            a.send(
                &CanFrame::new(CanId::std_masked(id), &[0xA5]),
                Priority::High,
            )
            .unwrap();
        }
        bus.flush_capture().unwrap();
        let text = std::fs::read_to_string(&log).unwrap();
        assert_eq!(
            text,
            "(1700000000.000000) can0 101#A5\n\
             (1700000000.005000) can0 103#A5\n\
             (1700000000.005000) can0 103#A5\n"
        );
        let bytes = std::fs::read(&pcap).unwrap();
        // 24-byte file header, then per frame 16 bytes record header and
        // 16 bytes SocketCAN record.
        assert_eq!(bytes.len(), 24 + 3 * 32);
        assert_eq!(&bytes[24 + 32 + 4..24 + 32 + 8], &5000u32.to_le_bytes());
        assert_eq!(&bytes[24 + 32 + 16..24 + 32 + 20], &[0, 0, 1, 3]);
        let _ = std::fs::remove_file(pcap);
        let _ = std::fs::remove_file(log);
    }

    fn frame(id: u16, data: &[u8]) -> CanFrame {
        CanFrame::new(CanId::std_masked(id), data)
    }

    #[test]
    fn physical_frame_arrives_at_its_end_of_frame() {
        // Heartbeat 0x705 [05]: 56 bits (physical.rs, ISO 11898-1 10.4.2),
        // at 125 kbit/s 8 µs each: 448 µs, so in tick 4 (100 µs ticks).
        let bus = SimBus::with_bit_rate(125_000).unwrap();
        let mut a = bus.attach(8);
        let mut b = bus.attach(8);
        for p in [&mut a, &mut b] {
            p.subscribe(CanId::std_masked(0x705), Priority::Low)
                .unwrap();
        }
        a.send(&frame(0x705, &[0x05]), Priority::Low).unwrap();
        assert_eq!(a.tx_pending(), 1);
        bus.advance_ticks(4);
        assert_eq!(b.receive(), None, "still on the bus at 400 µs");
        bus.advance_ticks(1);
        let rx = b.receive().unwrap();
        assert_eq!((rx.frame.id.id(), rx.time), (0x705, Ticks(4)));
        assert_eq!(a.receive(), None, "a sender does not hear itself");
        assert_eq!(bus.sent(), vec![(0, Ticks(4), frame(0x705, &[0x05]))]);
        let st = bus.stats().unwrap();
        assert_eq!((st.frames, st.bits), (1, 56 + 3));
        assert_eq!(st.busy_ns, 59 * 8_000);
        assert_eq!(st.elapsed_ns, 500_000);
    }

    /// Four nodes; the first three queue a PDO (0x181, 8 bytes), a
    /// heartbeat (0x705 [05]) and an NMT command (0x000 [01 00], high)
    /// at the same moment, the fourth receives all three.
    fn three_senders_and_a_receiver(bus: &SimBus) -> Vec<SimPort> {
        let mut n: Vec<SimPort> = (0..4).map(|_| bus.attach(8)).collect();
        for id in [0x000, 0x181, 0x705] {
            n[3].subscribe(CanId::std_masked(id), Priority::Low)
                .unwrap();
        }
        let data = [0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88];
        n[0].send(&frame(0x181, &data), Priority::Low).unwrap();
        n[1].send(&frame(0x705, &[0x05]), Priority::Low).unwrap();
        n[2].send(&frame(0x000, &[0x01, 0x00]), Priority::High)
            .unwrap();
        n
    }

    #[test]
    fn physical_bus_sends_the_lowest_identifier_first() {
        let bus = SimBus::with_bit_rate(1_000_000).unwrap();
        bus.keep_bus_log(true);
        let mut n = three_senders_and_a_receiver(&bus);
        bus.advance_ms(1);
        let log = bus.take_bus_log();
        let order: Vec<u32> = log.iter().map(|f| f.frame.id.id()).collect();
        assert_eq!(order, vec![0x000, 0x181, 0x705]);
        // 65, 112 and 56 bits (physical.rs), each followed by 3 bits of
        // intermission before the next SOF; 1 µs per bit.
        let times: Vec<(u64, u64)> = log.iter().map(|f| (f.start_ns, f.end_ns)).collect();
        assert_eq!(
            times,
            vec![(0, 65_000), (68_000, 180_000), (183_000, 239_000)]
        );
        let got: Vec<(u32, Ticks)> = std::iter::from_fn(|| n[3].receive())
            .map(|r| (r.frame.id.id(), r.time))
            .collect();
        assert_eq!(
            got,
            vec![(0x000, Ticks(0)), (0x181, Ticks(1)), (0x705, Ticks(2))]
        );
    }

    #[test]
    #[cfg_attr(miri, ignore = "writes files; Miri runs isolated from the file system")]
    fn physical_capture_has_the_end_of_frame_times() {
        // The frames of physical_bus_sends_the_lowest_identifier_first:
        // ends at 65, 180 and 239 µs. examples_c/sim (c_tests/test_sim.c,
        // PhysicalBus) writes the same lines for the same frames.
        let dir = std::env::temp_dir();
        let log = dir.join(format!("cop_sim_phys_{}.log", std::process::id()));
        let bus = SimBus::with_bit_rate(1_000_000).unwrap();
        bus.capture(None, Some(&log)).unwrap();
        let _n = three_senders_and_a_receiver(&bus);
        bus.advance_ms(1);
        bus.flush_capture().unwrap();
        let text = std::fs::read_to_string(&log).unwrap();
        assert_eq!(
            text,
            "(1700000000.000065) can0 000#0100\n\
             (1700000000.000180) can0 181#1122334455667788\n\
             (1700000000.000239) can0 705#05\n"
        );
        let _ = std::fs::remove_file(log);
    }

    #[test]
    fn physical_node_empties_its_high_buffer_first() {
        // With CDRV_USE_HIGHBUFF the driver offers its high buffer before
        // the low one, whatever the identifiers.
        let bus = SimBus::with_bit_rate(500_000).unwrap();
        let mut a = bus.attach(8);
        let mut b = bus.attach(8);
        for id in [0x080, 0x102] {
            b.subscribe(CanId::std_masked(id), Priority::Low).unwrap();
        }
        a.send(&frame(0x080, &[1]), Priority::Low).unwrap();
        a.send(&frame(0x102, &[2]), Priority::High).unwrap();
        bus.advance_ms(1);
        assert_eq!(b.receive().unwrap().frame.id.id(), 0x102);
        assert_eq!(b.receive().unwrap().frame.id.id(), 0x080);
    }

    #[test]
    fn physical_frame_queued_later_waits_for_the_bus() {
        // A frame queued while another is on the bus starts after that
        // frame and the intermission, whatever its identifier.
        let bus = SimBus::with_bit_rate(10_000).unwrap();
        bus.keep_bus_log(true);
        let mut a = bus.attach(8);
        let mut b = bus.attach(8);
        a.send(&frame(0x705, &[0x05]), Priority::Low).unwrap();
        bus.advance_ticks(1);
        b.send(&frame(0x000, &[0x01, 0x00]), Priority::High)
            .unwrap();
        bus.advance_ms(20);
        let log = bus.take_bus_log();
        assert_eq!(log.len(), 2);
        assert_eq!(log[0].frame.id.id(), 0x705);
        // 56 bits at 100 µs, then 3 bits of intermission.
        assert_eq!(log[1].start_ns, 59 * 100_000);
        assert_eq!(log[1].end_ns, (59 + 65) * 100_000);
    }

    #[test]
    fn physical_low_buffer_overrun_is_not_a_safety_overrun() {
        let model = BusModel {
            tx_low: 32,
            tx_high: 32,
            ..BusModel::new(1_000_000).unwrap()
        };
        let bus = SimBus::with_model(model).unwrap();
        let mut a = bus.attach(8);
        let mut b = bus.attach(8);
        b.subscribe(CanId::std_masked(0x101), Priority::High)
            .unwrap();
        b.subscribe(CanId::std_masked(0x581), Priority::Low)
            .unwrap();
        // One frame more than the low buffer's 10.
        for i in 0..11u8 {
            a.send(&frame(0x581, &[i]), Priority::Low).unwrap();
        }
        bus.advance_ms(5);
        let st = b.status();
        assert!(st.rx_overrun_other, "low buffer lost a frame");
        assert!(!st.rx_overrun, "nothing an SRDO uses was lost");
        assert_eq!(b.pending(), 10);
        assert_eq!(bus.stats().unwrap().rx_lost_low, 1);
        // One frame more than the high buffer's 16: rx_overrun.
        for i in 0..17u8 {
            a.send(&frame(0x101, &[i]), Priority::High).unwrap();
        }
        bus.advance_ms(5);
        let st = b.status();
        assert!(st.rx_overrun && !st.rx_overrun_other);
        assert_eq!(b.pending(), 26);
        // The high buffer is read first.
        assert_eq!(b.receive().unwrap().frame.id.id(), 0x101);
        assert_eq!(b.status(), PortStatus::default());
    }

    #[test]
    #[cfg_attr(miri, ignore = "bus model only, no unsafe code; long under Miri")]
    fn physical_node_receives_only_its_identifiers() {
        // The driver's identifier filter (CdrvDefineCanId): other nodes'
        // SRDOs never fill a node's buffers, an unsubscribed identifier
        // stops arriving, a new subscription moves an identifier between
        // the buffers.
        let bus = SimBus::with_bit_rate(1_000_000).unwrap();
        let mut a = bus.attach(8);
        let mut b = bus.attach(8);
        b.subscribe(CanId::std_masked(0x101), Priority::Low)
            .unwrap();
        // 16 fit the transmit buffer.
        for _ in 0..20 {
            let _ = a.send(&frame(0x103, &[0; 8]), Priority::High);
        }
        a.send(&frame(0x101, &[1]), Priority::Low).unwrap();
        bus.advance_ms(5);
        assert_eq!(b.pending(), 1);
        assert_eq!(b.status(), PortStatus::default(), "nothing lost");
        b.subscribe(CanId::std_masked(0x101), Priority::High)
            .unwrap();
        for _ in 0..11 {
            a.send(&frame(0x101, &[2]), Priority::High).unwrap();
        }
        bus.advance_ms(5);
        assert_eq!(b.pending(), 12, "11 more in the high buffer of 16");
        b.unsubscribe(CanId::std_masked(0x101)).unwrap();
        a.send(&frame(0x101, &[3]), Priority::Low).unwrap();
        bus.advance_ms(1);
        assert_eq!(b.pending(), 12);
        assert_eq!(bus.stats().unwrap().frames, 16 + 1 + 11 + 1);
    }

    #[test]
    fn physical_full_transmit_buffer_refuses() {
        let bus = SimBus::with_bit_rate(250_000).unwrap();
        let mut a = bus.attach(8);
        let _b = bus.attach(8);
        for _ in 0..10 {
            a.send(&frame(0x281, &[0; 8]), Priority::Low).unwrap();
        }
        assert_eq!(
            a.send(&frame(0x281, &[0; 8]), Priority::Low),
            Err(CopKernel::CdrvTxBuffLowOverrun)
        );
        assert!(a.send(&frame(0x101, &[0; 8]), Priority::High).is_ok());
        assert_eq!(bus.stats().unwrap().tx_refused, 1);
        assert!(SimBus::with_bit_rate(2_000_000).is_err());
    }

    #[test]
    #[cfg_attr(miri, ignore = "bus model only, no unsafe code; long under Miri")]
    fn physical_bus_load_of_back_to_back_frames() {
        // Frames queued faster than the bus carries them keep it busy:
        // the busy time equals the elapsed time while frames wait.
        let bus = SimBus::with_bit_rate(1_000_000).unwrap();
        let mut a = bus.attach(8);
        let _b = bus.attach(64);
        let ms = 100;
        for _ in 0..ms {
            for _ in 0..9 {
                let _ = a.send(&frame(0x181, &[0x55; 8]), Priority::Low);
            }
            bus.advance_ms(1);
        }
        let st = bus.stats().unwrap();
        let load = st.load_percent();
        assert!(load > 99.0 && load <= 100.0, "{load}");
    }

    #[test]
    fn candump_format() {
        let f = CanFrame::new(
            CanId::std_masked(0x602),
            &[0x2F, 0x00, 0x62, 0x01, 0xFF, 0, 0, 0],
        );
        assert_eq!(candump(&f), "  can0  602   [8]  2F 00 62 01 FF 00 00 00");
        assert_eq!(
            candump(&CanFrame::remote(CanId::std_masked(0x702), 1)),
            "  can0  702   [1]  remote request"
        );
    }
}
