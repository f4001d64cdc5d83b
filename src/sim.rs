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

use std::cell::RefCell;
use std::collections::VecDeque;
use std::io;
use std::path::Path;
use std::rc::Rc;

use crate::error::{CopKernel, CopResult};
use crate::port::{CanFrame, CanPort, Clock, PortStatus, Priority, RxFrame, Ticks};

pub mod capture;
pub mod fault_captures;
pub mod faults;
pub mod nvram;
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
}

struct Bus {
    now: Ticks,
    nodes: Vec<Node>,
    trace: Vec<String>,
    echo: bool,
    filter: Option<FaultFilter>,
    sent: Vec<(usize, Ticks, CanFrame)>,
    capture: Option<capture::Capture>,
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
        })))
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
        self.0.borrow_mut().now = t;
    }

    /// Attaches a node with a receive queue of `capacity` frames (a full
    /// queue loses the newest frame and reports an overrun).
    pub fn attach(&self, capacity: usize) -> SimPort {
        let mut b = self.0.borrow_mut();
        b.nodes.push(Node {
            rx: VecDeque::new(),
            capacity,
            overrun: false,
            overrun_other: false,
            tx_refuse: 0,
            bus_off: false,
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
        b.now = b.now.plus(ticks);
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
        self.transmit(usize::MAX, frame);
    }

    fn transmit(&self, from: usize, mut frame: CanFrame) {
        let mut b = self.0.borrow_mut();
        let delivery = match b.filter.as_mut() {
            Some(f) => f(from, &mut frame),
            None => Delivery::Deliver,
        };
        let line = candump(&frame);
        if b.echo {
            println!("{line}");
        }
        b.trace.push(line);
        let now = b.now;
        b.sent.push((from, now, frame));
        let copies = match delivery {
            Delivery::Deliver => 1,
            Delivery::Drop => 0,
            Delivery::Duplicate => 2,
        };
        if let Some(c) = b.capture.as_mut() {
            for _ in 0..copies {
                if let Err(e) = c.record(now, &frame) {
                    eprintln!("sim: capture stopped: {e}");
                    b.capture = None;
                    break;
                }
            }
        }
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
            .map_or(0, |n| n.rx.len())
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
        self.bus.transmit(self.node, *frame);
        Ok(())
    }

    fn receive(&mut self) -> Option<RxFrame> {
        self.bus
            .0
            .borrow_mut()
            .nodes
            .get_mut(self.node)
            .and_then(|n| n.rx.pop_front())
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
