//! A CAN port that costs next to nothing: a fixed ring of received frames
//! and a record of the last frame sent. The simulated bus of the library
//! (`cop::sim`) shares frames between nodes through `Rc<RefCell<..>>`; its
//! bookkeeping would show up in the instruction counts, this port's does
//! not (a few instructions per frame).

use cop::CopResult;
use cop::port::{CanFrame, CanPort, Priority, RxFrame};

/// Frames the port can hold between two cycles.
const RX_CAPACITY: usize = 4;

/// The benchmark's driver.
pub struct BenchPort {
    rx: [Option<RxFrame>; RX_CAPACITY],
    head: usize,
    len: usize,
    /// Frames handed to `send`.
    pub sent: u32,
    /// The last frame handed to `send`.
    pub last_sent: Option<CanFrame>,
}

impl BenchPort {
    /// An empty port.
    pub fn new() -> BenchPort {
        BenchPort {
            rx: [None; RX_CAPACITY],
            head: 0,
            len: 0,
            sent: 0,
            last_sent: None,
        }
    }

    /// Queues a received frame (outside the measured region).
    pub fn inject(&mut self, f: RxFrame) {
        assert!(self.len < RX_CAPACITY, "bench port: receive ring full");
        self.rx[(self.head + self.len) % RX_CAPACITY] = Some(f);
        self.len += 1;
    }

    /// Frames not yet taken by the stack.
    pub fn pending(&self) -> usize {
        self.len
    }
}

impl CanPort for BenchPort {
    fn send(&mut self, frame: &CanFrame, _prio: Priority) -> CopResult {
        self.sent = self.sent.wrapping_add(1);
        self.last_sent = Some(*frame);
        Ok(())
    }

    fn receive(&mut self) -> Option<RxFrame> {
        if self.len == 0 {
            return None;
        }
        let f = self.rx[self.head].take();
        self.head = (self.head + 1) % RX_CAPACITY;
        self.len -= 1;
        f
    }
}
