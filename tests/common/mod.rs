//! Harness shared by the whole-stack test files: one node (stack, port on
//! the simulated bus, the events it produced) driven cycle by cycle, two
//! such nodes on one bus, and an SDO client with its server. Each file that uses them adds its own
//! methods in an `impl` block of its own.

// Not every file uses every method.
#![allow(dead_code)]

use core::sync::atomic::AtomicU8;
use std::sync::{Mutex, MutexGuard};

use cop::ccm::{NmtCommand, Stack};
use cop::error::OdError;
use cop::event::Event;
use cop::od::{ByteOrder, ObdEntry, ObjectDictionary};
use cop::port::Ticks;
use cop::sdo::client::{ClientParam, Direction, SdocState};
use cop::sim::{SimBus, SimPort};
use cop::wire::sdo::Multiplexer;

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

impl Node {
    /// Takes the events `pick` selects (as it maps them); the others are
    /// dropped with them.
    pub fn take<T>(&mut self, pick: impl FnMut(&Event) -> Option<T>) -> Vec<T> {
        let v = self.events.iter().filter_map(pick).collect();
        self.events.clear();
        v
    }
}

/// Two nodes on one bus. The test files' dictionaries are statics, so a
/// network holds the file's lock (`serial`) while it exists.
pub struct Net {
    pub bus: SimBus,
    pub a: Node,
    pub b: Node,
    /// The file's lock, held as long as the network exists.
    pub _guard: MutexGuard<'static, ()>,
}

impl Net {
    /// Nodes `a` and `b` with their dictionaries (made once the lock is
    /// held: they share the file's statics) and node-IDs, both
    /// PRE-OPERATIONAL with their start-up events and frames kept.
    pub fn pair(
        serial: &'static Mutex<()>,
        a: (fn() -> ObjectDictionary, u8),
        b: (fn() -> ObjectDictionary, u8),
    ) -> Net {
        let guard = serial.lock().unwrap_or_else(|e| e.into_inner());
        let bus = SimBus::new();
        let a = Node::new(&bus, (a.0)(), a.1);
        let b = Node::new(&bus, (b.0)(), b.1);
        Net {
            bus,
            a,
            b,
            _guard: guard,
        }
    }

    /// Advances the bus by `ms` milliseconds, one cycle per node and ms.
    pub fn run(&mut self, ms: u32) {
        for _ in 0..ms {
            self.bus.advance_ms(1);
            self.step();
        }
    }

    /// One cycle per node without advancing the time.
    pub fn step(&mut self) {
        self.a.cycle();
        self.b.cycle();
    }

    /// (time, payload) of every data frame with identifier `id` so far.
    pub fn frames(&self, id: u32) -> Vec<(u32, Vec<u8>)> {
        self.bus
            .sent()
            .into_iter()
            .filter(|(_, _, f)| f.id.id() == id && !f.rtr)
            .map(|(_, t, f)| (t.0, f.payload().to_vec()))
            .collect()
    }
}

/// A stack on its own port of `bus` with a receive queue of `queue`
/// frames, connected (PRE-OPERATIONAL); its start-up events are dropped.
pub fn attach(bus: &SimBus, od: ObjectDictionary, id: u8, queue: usize) -> (SimPort, Stack) {
    let mut port = bus.attach(queue);
    let mut s = Stack::new(od, id).unwrap();
    while s.drain(&mut port, bus.now()).is_some() {}
    s.connect().unwrap();
    while s.drain(&mut port, bus.now()).is_some() {}
    (port, s)
}

/// The parameters of an SDO client of node 2's default server SDO
/// (COB-IDs 0x602 / 0x582), timeout 0 (the client's default).
pub const CLIENT_TO_NODE_2: ClientParam = ClientParam {
    tx_cob: 0x602,
    rx_cob: 0x582,
    server_node: 2,
    timeout_ticks: 0,
};

/// An SDO client and its server on one bus: node 1 (empty dictionary)
/// with client 0x1280 to node 2 (no timeout), node 2 with `server_part`
/// as its manufacturer part; the trace starts empty.
pub struct SdoNet {
    pub bus: SimBus,
    pub master: (SimPort, Stack),
    pub server: (SimPort, Stack),
    /// The client's `SdocFinished` events.
    pub finished: Vec<Event>,
}

impl SdoNet {
    pub fn on_bus(server_part: &'static [ObdEntry], queue: usize) -> SdoNet {
        let bus = SimBus::new();
        let server = attach(
            &bus,
            ObjectDictionary::new(&[], server_part, &[]).unwrap(),
            2,
            queue,
        );
        let mut master = attach(&bus, ObjectDictionary::empty(), 1, queue);
        master
            .1
            .define_sdo_client(&mut master.0, 0x1280, CLIENT_TO_NODE_2)
            .unwrap();
        bus.clear_trace();
        SdoNet {
            bus,
            master,
            server,
            finished: Vec::new(),
        }
    }

    /// `cycles` cycles of both nodes, 1 ms apart.
    pub fn run(&mut self, cycles: usize) {
        for _ in 0..cycles {
            let now = self.bus.now();
            self.server.1.process(&mut self.server.0, now, |_, _| {});
            let fin = &mut self.finished;
            self.master.1.process(&mut self.master.0, now, |_, e| {
                if matches!(e, Event::SdocFinished { .. }) {
                    fin.push(e);
                }
            });
            self.bus.advance_ms(1);
        }
    }

    /// `CcmSdocStartTransfer` on 0x1280 for `index` sub 0.
    pub fn start(
        &mut self,
        dir: Direction,
        index: u16,
        buf: &'static [AtomicU8],
        len: usize,
    ) -> cop::CopResult {
        let now = self.bus.now();
        let (port, stack) = &mut self.master;
        stack.sdo_client_start(
            port,
            now,
            0x1280,
            dir,
            Multiplexer::new(index, 0),
            buf,
            len,
            0,
        )
    }

    /// The client's state and abort code.
    pub fn state(&self) -> (SdocState, u32) {
        self.master.1.sdoc().state(0x1280).unwrap()
    }
}
