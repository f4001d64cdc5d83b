//! The fault-injection campaign of `cop::sim::faults` with a fixed seed
//! (100 % detection, no false alarm), and the CANopen timing limits of SRDO
//! reception tick by tick: frame 2 exactly SRVT after frame 1 and frame 1
//! exactly SCT after the previous valid pair are valid, one tick (100 µs)
//! later is an error, also where the 32-bit tick counter wraps at the limit.

use std::cell::RefCell;
use std::rc::Rc;

use cop::CopKernel;
use cop::ccm::NmtCommand;
use cop::event::Event;
use cop::port::{CanFrame, Ticks};
use cop::sim::faults::{Class, Config, run};
use cop::sim::srdo_net::{self, Device, Role, SCT_MS, SRDO, SRVT_MS};
use cop::sim::{Delivery, SimBus};

/// The seed of the test command's campaign (any seed must pass).
const SEED: u64 = 0x5EED_0304;

// req: M-1.1-FAULTS
#[test]
fn campaign_detects_every_fault_without_false_alarms() {
    // Miri checks the simulator for undefined behaviour only; the
    // big-endian run is emulated (qemu, some 20 times slower), and byte
    // order matters only for the variable fields, which every cycle uses.
    let cycles = if cfg!(miri) {
        25
    } else if cfg!(target_endian = "big") {
        10_000
    } else {
        100_000
    };
    let started = std::time::Instant::now();
    let report = run(&Config::new(cycles, SEED)).unwrap();
    println!("{}", report.table());
    println!("wall time {:?}", started.elapsed());
    assert!(report.passed(), "{}", report.table());
    assert!(report.cycles >= cycles);
    if cfg!(miri) {
        return;
    }
    for c in Class::ALL {
        let s = report.class(c);
        assert!(
            s.injected >= cycles / 200,
            "{c:?} injected only {} times",
            s.injected
        );
        assert_eq!(s.detected, s.injected, "{c:?}");
        assert_eq!(s.false_alarms, 0, "{c:?}");
    }
    assert!(report.fault_free > cycles / 2);
    assert_eq!(report.false_alarms, 0);
    // The legal jitter reached both limits exactly, the faults went one
    // tick beyond them, and the tick counter wrapped during the run.
    assert!(report.at_srvt > cycles / 100 && report.at_sct > cycles / 100);
    assert!(report.srvt_plus_one > cycles / 2000 && report.sct_plus_one > cycles / 2000);
    assert!(report.counter_wraps > cycles / 200);
}

#[test]
#[cfg_attr(miri, ignore = "covered by the campaign test")]
fn campaign_is_reproducible_from_its_seed() {
    let a = run(&Config::new(3_000, 42)).unwrap();
    let b = run(&Config::new(3_000, 42)).unwrap();
    assert_eq!(a.table(), b.table());
    let c = run(&Config::new(3_000, 43)).unwrap();
    assert_ne!(a.table(), c.table());
}

const SCT: u32 = SCT_MS as u32 * 10;
const SRVT: u32 = SRVT_MS as u32 * 10;

/// Producer and consumer of `srdo_net`; the producer's frames are held
/// back by the bus filter and delivered by the test, and the consumer runs
/// `CcmProcess` in every tick.
struct Bench {
    _guard: std::sync::MutexGuard<'static, ()>,
    bus: SimBus,
    p: Device,
    c: Device,
    held: Rc<RefCell<Vec<CanFrame>>>,
    /// SRDO events of the consumer with the bus tick they came in.
    events: Vec<(u32, Event)>,
    data: u8,
}

impl Bench {
    /// Both devices configured and OPERATIONAL from bus tick `start`.
    fn new(start: u32) -> Bench {
        let guard = srdo_net::lock();
        let bus = SimBus::new();
        bus.set_time(Ticks(start));
        let mut p = Device::new(&bus, Role::Producer, 0).unwrap();
        let mut c = Device::new(&bus, Role::Consumer, 16).unwrap();
        p.seal().unwrap();
        c.seal().unwrap();
        c.set_fields(&[0; 4], &[0; 4]);
        let held = Rc::new(RefCell::new(Vec::new()));
        let h = Rc::clone(&held);
        let from = p.port.node();
        bus.set_filter(Some(Box::new(move |sender, f: &mut CanFrame| {
            if sender == from {
                h.borrow_mut().push(*f);
                Delivery::Drop
            } else {
                Delivery::Deliver
            }
        })));
        p.command(NmtCommand::StartRemoteNode).unwrap();
        c.command(NmtCommand::StartRemoteNode).unwrap();
        assert!(c.stack.srdo().is_running());
        Bench {
            _guard: guard,
            bus,
            p,
            c,
            held,
            events: Vec::new(),
            data: 0,
        }
    }

    /// [`Bench::new`] ten ticks before `t`, run tick by tick up to `t`.
    fn at(t: u32) -> Bench {
        let mut b = Bench::new(t.wrapping_sub(10));
        b.ticks(10);
        b
    }

    fn now(&self) -> u32 {
        self.bus.now().0
    }

    /// `CcmSendSrdo` at the producer; returns (frame 1, frame 2).
    fn send(&mut self) -> (CanFrame, CanFrame) {
        self.data = self.data.wrapping_add(1);
        self.p.set_data(&[self.data, 2, 3, 4]);
        self.p.send(|_, _| {}).unwrap();
        let mut h = self.held.borrow_mut();
        assert_eq!(h.len(), 2);
        let (n, i) = (h[0], h[1]);
        h.clear();
        (n, i)
    }

    /// Runs the consumer once at the current tick.
    fn cycle(&mut self) {
        let t = self.now();
        let mut ev = Vec::new();
        self.c.process(|stack, e| {
            if matches!(e, Event::SrdoEvent(_) | Event::SrdoError(..)) {
                srdo_net::answer_as_manual(stack, &e);
                ev.push((t, e));
            }
        });
        self.events.extend(ev);
    }

    /// `n` ticks, a consumer cycle in each.
    fn ticks(&mut self, n: u32) {
        for _ in 0..n {
            self.bus.advance_ticks(1);
            self.cycle();
        }
    }

    /// Delivers a frame now and runs the consumer.
    fn deliver(&mut self, f: CanFrame) {
        self.bus.inject(f);
        self.cycle();
    }

    /// A valid pair now (both frames in this tick).
    fn pair_now(&mut self) {
        let (n, i) = self.send();
        self.bus.inject(n);
        self.deliver(i);
    }

    fn take(&mut self) -> Vec<(u32, Event)> {
        std::mem::take(&mut self.events)
    }
}

fn ok_at(t: u32) -> (u32, Event) {
    (t, Event::SrdoEvent(SRDO))
}

fn err_at(t: u32, code: CopKernel) -> (u32, Event) {
    (t, Event::SrdoError(SRDO, code))
}

/// The limit instants the timing tests put the boundary on: an ordinary
/// value, the last tick before the counter wraps, and tick 0 after it.
const LIMITS: [u32; 3] = [0x0012_3456, u32::MAX, 0];

#[test]
#[cfg_attr(miri, ignore = "tick-by-tick runs are too slow under Miri")]
fn frame_2_exactly_at_srvt_is_valid_one_tick_later_is_a_timeout() {
    for limit in LIMITS {
        for gap in [SRVT - 1, SRVT, SRVT + 1] {
            // Frame 1 at limit - SRVT, so that frame 1 + SRVT = limit.
            let t1 = limit.wrapping_sub(SRVT);
            let mut b = Bench::at(t1);
            let (n, i) = b.send();
            b.deliver(n);
            // A consumer cycle in every tick; frame 2 comes in its tick
            // before that tick's cycle.
            b.ticks(gap - 1);
            b.bus.advance_ticks(1);
            assert_eq!(b.now(), t1.wrapping_add(gap));
            b.deliver(i);
            let t2 = t1.wrapping_add(gap);
            let want = if gap <= SRVT {
                vec![ok_at(t2)]
            } else {
                vec![err_at(t2, CopKernel::SrdoSrvtTimeout)]
            };
            assert_eq!(b.take(), want, "limit {limit:#x}, gap {gap}");
        }
    }
}

#[test]
#[cfg_attr(miri, ignore = "tick-by-tick runs are too slow under Miri")]
fn srvt_expiry_without_frame_2_follows_the_switch() {
    for limit in LIMITS {
        let t1 = limit.wrapping_sub(SRVT);
        let mut b = Bench::at(t1);
        let (n, _) = b.send();
        b.deliver(n);
        b.ticks(SRVT);
        assert_eq!(b.take(), vec![], "nothing at exactly SRVT ({limit:#x})");
        b.ticks(1);
        let want = if cop::config::SRDO_CHECK_SRVT_BEFORE_1STRX {
            vec![err_at(limit.wrapping_add(1), CopKernel::SrdoSrvtTimeout)]
        } else {
            vec![]
        };
        assert_eq!(b.take(), want, "one tick after SRVT ({limit:#x})");
    }
}

#[test]
#[cfg_attr(miri, ignore = "tick-by-tick runs are too slow under Miri")]
fn frame_1_exactly_at_sct_is_in_time_one_tick_later_is_a_timeout() {
    for limit in LIMITS {
        for interval in [SCT - 1, SCT, SCT + 1] {
            // The previous valid pair at limit - SCT.
            let t0 = limit.wrapping_sub(SCT);
            let mut b = Bench::at(t0);
            b.pair_now();
            assert_eq!(b.take(), vec![ok_at(t0)]);
            // The consumer runs in every tick, so an expiry is found in the
            // first tick after the limit.
            b.ticks(interval);
            let t1 = t0.wrapping_add(interval);
            b.pair_now();
            let want = if interval <= SCT {
                vec![ok_at(t1)]
            } else {
                vec![
                    err_at(limit.wrapping_add(1), CopKernel::SrdoSctTimeout),
                    ok_at(t1),
                ]
            };
            assert_eq!(b.take(), want, "limit {limit:#x}, interval {interval}");
        }
    }
}

#[test]
#[cfg_attr(miri, ignore = "tick-by-tick runs are too slow under Miri")]
fn late_frame_1_reports_the_sct_itself_when_no_cycle_came_between() {
    for limit in LIMITS {
        let t0 = limit.wrapping_sub(SCT);
        let mut b = Bench::at(t0);
        b.pair_now();
        b.take();
        // No consumer cycle between the limit and the late pair.
        b.ticks(SCT - 1);
        b.bus.advance_ticks(2);
        b.pair_now();
        let t1 = limit.wrapping_add(1);
        assert_eq!(
            b.take(),
            vec![err_at(t1, CopKernel::SrdoSctTimeout), ok_at(t1)],
            "limit {limit:#x}"
        );
    }
}

#[test]
#[cfg_attr(miri, ignore = "tick-by-tick runs are too slow under Miri")]
fn sct_from_entering_operational_has_the_same_limit() {
    for limit in LIMITS {
        for first in [SCT, SCT + 1] {
            let start = limit.wrapping_sub(SCT);
            let mut b = Bench::new(start);
            b.ticks(first);
            b.pair_now();
            let t = start.wrapping_add(first);
            let want = if first <= SCT {
                vec![ok_at(t)]
            } else {
                vec![err_at(t, CopKernel::SrdoSctTimeout), ok_at(t)]
            };
            assert_eq!(b.take(), want, "limit {limit:#x}, first pair after {first}");
        }
    }
}
