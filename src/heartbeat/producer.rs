//! Heartbeat producer (SYS TEC HBP, object 0x1017) and the node guarding answer of an
//! NMT slave (CiA 301 7.2.8.3.2).

use crate::od::ObjectDictionary;
use crate::port::{CanPort, Priority, Ticks};
use crate::wire::nmt;

/// Producer heartbeat time object.
pub const PRODUCER_TIME_INDEX: u16 = 0x1017;

/// The heartbeat producer.
#[derive(Clone, Debug, Default)]
pub struct HeartbeatProducer {
    period_ms: u16,
    next: Option<Ticks>,
    running: bool,
}

impl HeartbeatProducer {
    /// A producer that sends nothing until configured and started.
    pub const fn new() -> Self {
        HeartbeatProducer {
            period_ms: 0,
            next: None,
            running: false,
        }
    }

    /// Reads 0x1017 (absent = no heartbeat).
    pub fn reconfigure(&mut self, od: &ObjectDictionary, now: Ticks) {
        self.period_ms = od
            .read_uint(PRODUCER_TIME_INDEX, 0)
            .map(|v| v as u16)
            .unwrap_or(0);
        self.rearm(now);
    }

    /// The configured period in ms (0 = off).
    pub fn period_ms(&self) -> u16 {
        self.period_ms
    }

    /// Starts producing (after the boot-up message): the first heartbeat
    /// follows one period later.
    pub fn start(&mut self, now: Ticks) {
        self.running = true;
        self.rearm(now);
    }

    /// Stops producing (reset, shutdown).
    pub fn stop(&mut self) {
        self.running = false;
        self.next = None;
    }

    fn rearm(&mut self, now: Ticks) {
        self.next = if self.running && self.period_ms > 0 {
            Some(now.plus_ms(u32::from(self.period_ms)))
        } else {
            None
        };
    }

    /// True when [`HeartbeatProducer::poll`] at `now` would do nothing.
    #[inline]
    pub fn at_rest(&self, now: Ticks) -> bool {
        !self.next.is_some_and(|due| now.reached(due))
    }

    /// Sends a heartbeat when one is due.
    pub fn poll(&mut self, port: &mut impl CanPort, node: u8, state: u8, now: Ticks) {
        let Some(due) = self.next else { return };
        if now.reached(due) {
            // A send refused by a full driver buffer is retried next period;
            // heartbeat consumers tolerate one missing message by design.
            let _ = port.send(&nmt::encode_heartbeat(node, state), Priority::Low);
            let period = crate::port::ms_to_ticks(u32::from(self.period_ms));
            // Keep the phase unless the stack was late by more than a period.
            let next = due.plus(period);
            self.next = Some(if now.is_after(next) {
                now.plus(period)
            } else {
                next
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::port::Recorder as Sink;

    #[test]
    fn sends_every_period_after_start() {
        let mut hb = HeartbeatProducer::new();
        hb.period_ms = 100;
        hb.start(Ticks(0));
        let mut bus = Sink::default();
        hb.poll(&mut bus, 5, 0x7F, Ticks(999));
        assert!(bus.0.is_empty());
        hb.poll(&mut bus, 5, 0x7F, Ticks(1000));
        assert_eq!(bus.0.len(), 1);
        assert_eq!(bus.0[0].id.id(), 0x705);
        assert_eq!(bus.0[0].payload(), &[0x7F]);
        hb.poll(&mut bus, 5, 0x05, Ticks(1500));
        assert_eq!(bus.0.len(), 1);
        hb.poll(&mut bus, 5, 0x05, Ticks(2000));
        assert_eq!(bus.0.len(), 2);
        assert_eq!(bus.0[1].payload(), &[0x05]);
    }

    #[test]
    fn period_zero_sends_nothing() {
        let mut hb = HeartbeatProducer::new();
        hb.start(Ticks(0));
        let mut bus = Sink::default();
        hb.poll(&mut bus, 5, 0x7F, Ticks(100_000));
        assert!(bus.0.is_empty());
    }
}
