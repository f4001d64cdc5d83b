//! Heartbeat consumer (SYS TEC HBC, object 0x1016, CiA 301 7.2.8.3.2.2).
//!
//! Each entry of 0x1016 holds `node-ID << 16 | heartbeat time (ms)`; an
//! entry with node-ID 0 or time 0 is unused. Supervision of a node starts
//! with its first heartbeat (CiA 301); when the time passes without a new
//! one the node is reported lost once, and connected again with its next
//! heartbeat. From the loss until that heartbeat (or boot-up) the node's
//! state reads [`NODE_STATE_DISCONNECTED`], not the last state it reported.

use crate::event::{ActionQueue, ErrCtrlEvent, Event};
use crate::nmt::Supervision;
use crate::od::ObjectDictionary;
use crate::port::{Ticks, ms_to_ticks};
use crate::wire::nmt::ErrorControl;

/// Consumer heartbeat time object.
pub const CONSUMER_TIME_INDEX: u16 = 0x1016;

/// The node state of a producer whose heartbeat was lost: 0x01,
/// "disconnected" among the node states of DS 301 v3 node guarding, which
/// no heartbeat carries (CiA 301 7.2.8.3.2 knows 0x00, 0x04, 0x05, 0x7F),
/// so a master that only polls the state tells a lost node from a working
/// one.
pub const NODE_STATE_DISCONNECTED: u8 = 0x01;

/// Capacity: `HBC_MAX_CONSUMER_IN_OBD`.
pub const CAPACITY: usize = crate::config::HBC_MAX_CONSUMER_IN_OBD;

#[derive(Clone, Copy, Debug, Default)]
struct Entry {
    node: u8,
    time_ms: u16,
    deadline: Ticks,
    state: Option<u8>,
    supervision: Supervision,
}

impl Entry {
    /// A supervised producer whose heartbeat is overdue at `now` (what
    /// [`HeartbeatConsumer::poll`] reports and `at_rest` asks).
    fn expired(&self, now: Ticks) -> bool {
        self.time_ms > 0 && self.supervision == Supervision::Active && now.is_after(self.deadline)
    }
}

/// The heartbeat consumer.
#[derive(Clone, Debug)]
pub struct HeartbeatConsumer {
    entries: [Entry; CAPACITY],
}

crate::od::decl::default_is_new!(HeartbeatConsumer);

impl HeartbeatConsumer {
    /// A consumer without entries.
    pub const fn new() -> Self {
        HeartbeatConsumer {
            entries: [Entry {
                node: 0,
                time_ms: 0,
                deadline: Ticks(0),
                state: None,
                supervision: Supervision::Waiting,
            }; CAPACITY],
        }
    }

    /// Reads 0x1016 (absent: no supervision). Entries beyond the capacity
    /// are ignored; supervision restarts for every node.
    pub fn reconfigure(&mut self, od: &ObjectDictionary) {
        for (i, e) in self.entries.iter_mut().enumerate() {
            let v = u8::try_from(i + 1)
                .ok()
                .and_then(|sub| od.read_uint(CONSUMER_TIME_INDEX, sub).ok())
                .unwrap_or(0) as u32;
            *e = Entry {
                node: ((v >> 16) & 0x7F) as u8,
                time_ms: (v & 0xFFFF) as u16,
                ..Entry::default()
            };
        }
    }

    /// Sets one entry directly (`CcmHbcDefineProducerTab`).
    /// `false` when `slot` is outside the capacity.
    pub fn define(&mut self, slot: usize, node: u8, time_ms: u16) -> bool {
        match self.entries.get_mut(slot) {
            Some(e) => {
                *e = Entry {
                    node,
                    time_ms,
                    ..Entry::default()
                };
                true
            }
            None => false,
        }
    }

    /// The last state a node reported, if it is supervised and was heard;
    /// [`NODE_STATE_DISCONNECTED`] from the loss of its heartbeat on.
    pub fn node_state(&self, node: u8) -> Option<u8> {
        self.entries
            .iter()
            .find(|e| e.node == node && e.time_ms > 0)
            .and_then(|e| e.state)
    }

    /// True when `node` is supervised.
    pub fn supervises(&self, node: u8) -> bool {
        self.entries.iter().any(|e| e.node == node && e.time_ms > 0)
    }

    /// A heartbeat or boot-up message arrived.
    pub fn on_heartbeat(&mut self, hb: ErrorControl, time: Ticks, q: &mut ActionQueue) {
        for e in self
            .entries
            .iter_mut()
            .filter(|e| e.node == hb.node && e.time_ms > 0)
        {
            e.deadline = time.plus(ms_to_ticks(u32::from(e.time_ms)));
            match e.supervision {
                Supervision::Waiting | Supervision::Lost => {
                    e.supervision = Supervision::Active;
                    q.emit(Event::Hbc(hb.node, ErrCtrlEvent::HbcConnected));
                }
                Supervision::Active => {
                    if e.state.is_some_and(|s| s != hb.state) {
                        q.emit(Event::Hbc(hb.node, ErrCtrlEvent::HbcNodeStateChanged));
                    }
                }
            }
            e.state = Some(hb.state);
        }
    }

    /// True when [`HeartbeatConsumer::poll`] at `now` would do nothing.
    #[inline]
    pub fn at_rest(&self, now: Ticks) -> bool {
        !self.entries.iter().any(|e| e.expired(now))
    }

    /// Checks the deadlines; reports at most one lost node per call (the
    /// stack calls again while events are pending). Returns `true` when no
    /// node was reported.
    pub fn poll(&mut self, now: Ticks, q: &mut ActionQueue) -> bool {
        for e in self.entries.iter_mut() {
            if e.expired(now) {
                e.supervision = Supervision::Lost;
                e.state = Some(NODE_STATE_DISCONNECTED);
                q.emit(Event::Hbc(e.node, ErrCtrlEvent::HbcConnectionLost));
                return false;
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hb(node: u8, state: u8) -> ErrorControl {
        ErrorControl { node, state }
    }

    /// The action the consumer queues for `event` of `node`.
    fn hbc(node: u8, event: ErrCtrlEvent) -> Option<crate::event::Action> {
        Some(crate::event::Action::Emit(Event::Hbc(node, event)))
    }

    #[test]
    fn supervision_starts_with_first_heartbeat() {
        let mut c = HeartbeatConsumer::new();
        assert!(c.define(0, 5, 100));
        let mut q = ActionQueue::new();
        // Nothing is reported before the first heartbeat, however long.
        assert!(c.poll(Ticks(1_000_000), &mut q));
        c.on_heartbeat(hb(5, 0x7F), Ticks(0), &mut q);
        assert_eq!(q.pop(), hbc(5, ErrCtrlEvent::HbcConnected));
        // Exactly at the limit is still in time; later is lost, once.
        assert!(c.poll(Ticks(1000), &mut q));
        assert!(!c.poll(Ticks(1001), &mut q));
        assert_eq!(q.pop(), hbc(5, ErrCtrlEvent::HbcConnectionLost));
        assert!(c.poll(Ticks(5000), &mut q));
        c.on_heartbeat(hb(5, 0x05), Ticks(5000), &mut q);
        assert_eq!(q.pop(), hbc(5, ErrCtrlEvent::HbcConnected));
        c.on_heartbeat(hb(5, 0x7F), Ticks(5500), &mut q);
        assert_eq!(q.pop(), hbc(5, ErrCtrlEvent::HbcNodeStateChanged));
        assert_eq!(c.node_state(5), Some(0x7F));
    }

    #[test]
    fn a_lost_node_reads_disconnected_until_it_is_heard_again() {
        let mut c = HeartbeatConsumer::new();
        assert!(c.define(0, 7, 50));
        let mut q = ActionQueue::new();
        c.on_heartbeat(hb(7, 0x05), Ticks(0), &mut q);
        assert_eq!(q.pop(), hbc(7, ErrCtrlEvent::HbcConnected));
        assert_eq!(c.node_state(7), Some(0x05));
        assert!(!c.poll(Ticks(501), &mut q));
        assert_eq!(q.pop(), hbc(7, ErrCtrlEvent::HbcConnectionLost));
        assert_eq!(c.node_state(7), Some(NODE_STATE_DISCONNECTED));
        assert!(c.poll(Ticks(9000), &mut q));
        assert_eq!(c.node_state(7), Some(NODE_STATE_DISCONNECTED));
        // A boot-up (state 0x00, CiA 301 7.2.8.3.3) ends it as a heartbeat
        // does, with a connection event and no state change event.
        c.on_heartbeat(hb(7, 0x00), Ticks(9000), &mut q);
        assert_eq!(q.pop(), hbc(7, ErrCtrlEvent::HbcConnected));
        assert!(q.is_empty());
        assert_eq!(c.node_state(7), Some(0x00));
    }

    #[test]
    fn unsupervised_nodes_are_ignored() {
        let mut c = HeartbeatConsumer::new();
        let mut q = ActionQueue::new();
        c.on_heartbeat(hb(9, 0x05), Ticks(0), &mut q);
        assert!(q.is_empty());
        assert_eq!(c.node_state(9), None);
        assert!(!c.define(CAPACITY, 1, 1));
    }
}
