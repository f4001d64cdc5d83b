//! Life guarding of an NMT slave (CiA 301 7.2.8.3.2.1): the SYS TEC
//! module LGS (`CcmInitLgs`, `CcmConfigLgs`; switch `NMTS_USE_LIFEGUARDING`).
//!
//! The NMT master guards this node with remote frames on 0x700 + node-ID;
//! the answer itself is sent by the stack whether or not this module runs.
//! This module is the other half: this node watches the master. The node
//! life time is guard time (0x100C, ms) × life time factor (0x100D). Once
//! the first guard request has arrived, each request must follow the
//! previous one within the life time; when it does not, the node has lost
//! its master (the life guarding event), which the stack reports with
//! emergency 0x8130 (CiA 301 table 21, "life guard error or heartbeat
//! error").
//!
//! # Behaviour decisions
//! * The module acts after `CcmInitLgs` only (the SYS TEC application calls
//!   it at kNmtEvEnterInitialising); with `NMTS_USE_LIFEGUARDING` FALSE it
//!   never acts.
//! * Where the dictionary has 0x100C / 0x100D they are the configuration
//!   (also when written over SDO); otherwise the values of `CcmConfigLgs`
//!   are kept here and reset with the communication objects.
//! * A life time of 0 (either value 0) switches supervision off.
//! * A request arriving exactly at the end of the life time is in time.
//! * The event is reported once; the next guard request reconnects, and a
//!   later loss is reported again.
//! * While the producer heartbeat time (0x1017) is not 0, heartbeat is the
//!   node's error control protocol (CiA 301 7.2.8.3.2) and life guarding is
//!   suspended; it starts again with the next guard request after 0x1017
//!   returns to 0.
//! * Reset communication ends supervision until the next guard request.

use super::Supervision;
use crate::event::ErrCtrlEvent;
use crate::od::ObjectDictionary;
use crate::port::{Ticks, ms_to_ticks};

/// Guard time (ms).
pub const GUARD_TIME_INDEX: u16 = 0x100C;
/// Life time factor.
pub const LIFE_TIME_FACTOR_INDEX: u16 = 0x100D;
/// Emergency error code of the life guarding event (CiA 301 table 21).
pub const EMCY_LIFE_GUARD: u16 = 0x8130;
/// Error register bits set with the life guarding event (CiA 301
/// 7.5.2.2): generic error and communication error.
pub const ERROR_REGISTER_BITS: u8 = 0x11;

/// The life guarding slave.
#[derive(Clone, Debug, Default)]
pub struct LifeGuardSlave {
    initialised: bool,
    /// Values of `CcmConfigLgs` for a dictionary without 0x100C / 0x100D.
    own_guard_ms: u16,
    own_factor: u8,
    guard_ms: u16,
    factor: u8,
    deadline: Ticks,
    supervision: Supervision,
}

impl LifeGuardSlave {
    /// A module that does nothing until [`LifeGuardSlave::init`].
    pub const fn new() -> Self {
        LifeGuardSlave {
            initialised: false,
            own_guard_ms: 0,
            own_factor: 0,
            guard_ms: 0,
            factor: 0,
            deadline: Ticks(0),
            supervision: Supervision::Waiting,
        }
    }

    /// `CcmInitLgs`: the module acts from now on (unless the build has
    /// `NMTS_USE_LIFEGUARDING` FALSE).
    pub fn init(&mut self) {
        self.initialised = crate::config::NMTS_USE_LIFEGUARDING;
    }

    /// True after [`LifeGuardSlave::init`] in a build with life guarding.
    pub fn is_initialised(&self) -> bool {
        self.initialised
    }

    /// Guard time in ms and life time factor in force.
    pub fn config(&self) -> (u16, u8) {
        (self.guard_ms, self.factor)
    }

    /// The node life time in ticks (0 = no supervision).
    pub fn life_time_ticks(&self) -> u32 {
        ms_to_ticks(u32::from(self.guard_ms)).saturating_mul(u32::from(self.factor))
    }

    /// True when the module is initialised and has a life time, i.e. life
    /// guarding is configured (whether or not a request has come yet).
    pub fn is_configured(&self) -> bool {
        self.initialised && self.life_time_ticks() > 0
    }

    /// Configured, and the life time since the last guard request is over
    /// at `now` (what `poll` reports while supervising, and `at_rest` asks).
    fn life_time_over(&self, now: Ticks) -> bool {
        self.is_configured() && now.is_after(self.deadline)
    }

    /// What the module last observed: `kNmtErrCtrlEvIdle` before the first
    /// guard request, `kNmtErrCtrlEvLgConnected` while requests arrive in
    /// time, `kNmtErrCtrlEvLgLostConnection` after the life guarding event.
    pub fn status(&self) -> ErrCtrlEvent {
        match self.supervision {
            Supervision::Waiting => ErrCtrlEvent::Idle,
            Supervision::Active => ErrCtrlEvent::LgConnected,
            Supervision::Lost => ErrCtrlEvent::LgLostConnection,
        }
    }

    /// `CcmConfigLgs` on a dictionary without the objects: keeps the values
    /// here (the caller writes the objects where they exist).
    pub fn set_own(&mut self, guard_ms: u16, factor: u8) {
        self.own_guard_ms = guard_ms;
        self.own_factor = factor;
    }

    /// Takes the configuration from 0x100C / 0x100D where they exist (the
    /// values kept by [`LifeGuardSlave::set_own`] otherwise). A running
    /// supervision continues; the new life time applies from the next
    /// request. Life time 0 ends it.
    pub fn reconfigure(&mut self, od: &ObjectDictionary) {
        self.guard_ms = od.read_or(GUARD_TIME_INDEX, 0, self.own_guard_ms);
        self.factor = od.read_or(LIFE_TIME_FACTOR_INDEX, 0, self.own_factor);
        if self.life_time_ticks() == 0 {
            self.supervision = Supervision::Waiting;
        }
    }

    /// Reset communication: supervision waits for the next request and the
    /// kept values return to 0 (the objects get their defaults from the
    /// dictionary).
    pub fn reset_communication(&mut self) {
        self.own_guard_ms = 0;
        self.own_factor = 0;
        self.supervision = Supervision::Waiting;
    }

    /// A guard request for this node arrived at `time`.
    pub fn on_guard_request(&mut self, time: Ticks) {
        if !self.is_configured() {
            return;
        }
        self.deadline = time.plus(self.life_time_ticks());
        self.supervision = Supervision::Active;
    }

    /// True when [`LifeGuardSlave::poll`] at `now` (with the same
    /// `heartbeat`) would do nothing.
    #[inline]
    pub fn at_rest(&self, now: Ticks, heartbeat: bool) -> bool {
        self.supervision != Supervision::Active || !(heartbeat || self.life_time_over(now))
    }

    /// Checks the life time. Returns `true` exactly once per loss: the
    /// caller reports the life guarding event. `heartbeat` is true while
    /// the producer heartbeat time is not 0 (life guarding suspended).
    pub fn poll(&mut self, now: Ticks, heartbeat: bool) -> bool {
        if heartbeat && self.supervision == Supervision::Active {
            self.supervision = Supervision::Waiting;
        }
        if self.supervision == Supervision::Active && self.life_time_over(now) {
            self.supervision = Supervision::Lost;
            return true;
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn configured(guard_ms: u16, factor: u8) -> LifeGuardSlave {
        let mut l = LifeGuardSlave::new();
        l.init();
        l.set_own(guard_ms, factor);
        l.reconfigure(&ObjectDictionary::empty());
        l
    }

    #[test]
    fn supervision_starts_with_the_first_request() {
        if !crate::config::NMTS_USE_LIFEGUARDING {
            return;
        }
        let mut l = configured(100, 3);
        assert_eq!(l.life_time_ticks(), 3000);
        assert!(!l.poll(Ticks(1_000_000), false));
        assert_eq!(l.status(), ErrCtrlEvent::Idle);
        l.on_guard_request(Ticks(0));
        assert_eq!(l.status(), ErrCtrlEvent::LgConnected);
        // Exactly at the life time is in time; one tick later is lost, once.
        assert!(!l.poll(Ticks(3000), false));
        assert!(l.poll(Ticks(3001), false));
        assert!(!l.poll(Ticks(9000), false));
        assert_eq!(l.status(), ErrCtrlEvent::LgLostConnection);
        l.on_guard_request(Ticks(9000));
        assert_eq!(l.status(), ErrCtrlEvent::LgConnected);
        assert!(l.poll(Ticks(12_001), false));
    }

    #[test]
    fn zero_life_time_heartbeat_and_no_init_do_not_supervise() {
        let mut l = configured(100, 0);
        l.on_guard_request(Ticks(0));
        assert!(!l.poll(Ticks(100_000), false));
        let mut l = configured(100, 3);
        l.on_guard_request(Ticks(0));
        assert!(!l.poll(Ticks(100_000), true));
        assert_eq!(l.status(), ErrCtrlEvent::Idle);
        let mut l = LifeGuardSlave::new();
        l.set_own(100, 3);
        l.reconfigure(&ObjectDictionary::empty());
        l.on_guard_request(Ticks(0));
        assert!(!l.is_configured());
        assert!(!l.poll(Ticks(100_000), false));
    }

    #[test]
    fn reset_communication_forgets_the_kept_values() {
        let mut l = configured(50, 2);
        assert_eq!(l.config(), (50, 2));
        l.reset_communication();
        l.reconfigure(&ObjectDictionary::empty());
        assert_eq!(l.config(), (0, 0));
    }
}
