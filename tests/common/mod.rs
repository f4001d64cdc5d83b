//! Harness shared by the whole-stack test files: one node (stack, port on
//! the simulated bus, the events it produced) driven cycle by cycle.
//! Each file that uses it adds its own methods in an `impl Node` block.

// Not every file uses every method.
#![allow(dead_code)]

use cop::ccm::{NmtCommand, Stack};
use cop::error::OdError;
use cop::event::Event;
use cop::od::{ByteOrder, ObjectDictionary};
use cop::port::Ticks;
use cop::sim::{SimBus, SimPort};

/// One node on the simulated bus.
pub struct Node {
    pub stack: Stack,
    pub port: SimPort,
    /// Every event of the node since the test last cleared them.
    pub events: Vec<Event>,
}

impl Node {
    /// A node with the dictionary `od` and node-ID `id`, connected (boot-up
    /// sent, PRE-OPERATIONAL).
    pub fn new(bus: &SimBus, od: ObjectDictionary, id: u8) -> Node {
        let mut n = Node {
            stack: Stack::new(od, id).unwrap(),
            port: bus.attach(64),
            events: Vec::new(),
        };
        n.drain();
        n.stack.connect().unwrap();
        n.drain();
        n
    }

    /// The bus clock.
    pub fn now(&self) -> Ticks {
        self.port.bus().now()
    }

    /// Runs the stack's pending work without taking frames, keeping the
    /// events.
    pub fn drain(&mut self) {
        let now = self.now();
        while let Some(e) = self.stack.drain(&mut self.port, now) {
            self.events.push(e);
        }
    }

    /// One `CcmProcess` cycle, keeping the events.
    pub fn cycle(&mut self) {
        let now = self.now();
        let mut ev = Vec::new();
        self.stack.process(&mut self.port, now, |_, e| ev.push(e));
        self.events.extend(ev);
    }

    /// A local NMT command.
    pub fn command(&mut self, cmd: NmtCommand) {
        self.stack.exec_command(cmd).unwrap();
        self.drain();
    }

    /// `CcmWriteObject` of the `len` low bytes of `v` (wire order).
    pub fn write(&mut self, index: u16, sub: u8, v: u64, len: usize) -> Result<(), OdError> {
        let now = self.now();
        let bytes = v.to_le_bytes();
        let r = self
            .stack
            .write_object(index, sub, ByteOrder::Wire, &bytes[..len], now);
        self.drain();
        r
    }

    /// A numeric object's value.
    pub fn read(&self, index: u16, sub: u8) -> u64 {
        self.stack.od().read_uint(index, sub).unwrap()
    }
}
