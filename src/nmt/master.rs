//! NMT master (SYS TEC NMTM): module control commands, boot-up detection
//! and node guarding of slaves (life guarding master, CiA 301 7.2.8.3.2.1).

use crate::error::{CopKernel, CopResult};
use crate::event::{ActionQueue, ErrCtrlEvent, Event};
use crate::port::{CanFrame, CanPort, Priority, Ticks, ms_to_ticks};
use crate::wire::nmt::{self, NmtCs};

/// Capacity: `NMTM_MAX_SLAVE_ENTRIES`.
pub const CAPACITY: usize = crate::config::NMTM_MAX_SLAVE_ENTRIES;

#[derive(Clone, Copy, Debug, Default)]
struct Slave {
    node: u8,
    guard_ms: u16,
    life_factor: u8,
    next_guard: Ticks,
    awaiting: bool,
    misses: u8,
    toggle: bool,
    state: Option<u8>,
    no_answer_reported: bool,
    bootup_seen: bool,
    answered: bool,
    updated: bool,
    last_toggle: bool,
}

impl Slave {
    /// A listed slave with a guard time: node guarding runs for it.
    fn guarded(&self) -> bool {
        self.node != 0 && self.guard_ms > 0
    }

    /// No guard request outstanding and none missed (an answer arrived, or
    /// guarding starts anew).
    fn answered_in_time(&mut self) {
        self.awaiting = false;
        self.misses = 0;
        self.no_answer_reported = false;
    }
}

/// What the master knows about a slave (`CcmNmtmGetSlaveInfo`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SlaveInfo {
    /// Last state reported by guarding or boot-up (0 = boot-up / unknown).
    pub state: u8,
    /// Guard time in ms (0 = not guarded).
    pub guard_ms: u16,
    /// Life time factor.
    pub life_factor: u8,
    /// Unanswered guard requests in a row.
    pub misses: u8,
    /// `tNmtmSlaveState` bits (`slave_state` constants).
    pub flags: u8,
}

/// The `tNmtmSlaveState` bits of [`SlaveInfo::flags`] (values of the
/// vendored SYS TEC `nmtm.h`).
pub mod slave_state {
    /// The slave is in the slave table.
    pub const USED: u8 = 0x01;
    /// Its boot-up message was received.
    pub const BOOTUP_RECEIVED: u8 = 0x02;
    /// Life guarding is configured (guard time and life time factor).
    pub const LG_ACTIVE: u8 = 0x04;
    /// A guarding answer was received since guarding was configured.
    pub const LG_RECEIVED: u8 = 0x08;
    /// Node guarding requests are being sent.
    pub const NG_ACTIVE: u8 = 0x10;
    /// A guarding answer arrived since the last read.
    pub const UPDATE: u8 = 0x40;
    /// Toggle bit of the last guarding answer.
    pub const TOGGLE_BIT: u8 = 0x80;
}

/// The NMT master.
#[derive(Clone, Debug)]
pub struct NmtMaster {
    enabled: bool,
    slaves: [Slave; CAPACITY],
}

crate::od::decl::default_is_new!(NmtMaster);

fn valid_node(node: u8) -> CopResult {
    if (1..=127).contains(&node) {
        Ok(())
    } else {
        Err(CopKernel::NmtmInvalidSlaveNodeId)
    }
}

impl NmtMaster {
    /// A disabled master (this node is a slave only).
    pub const fn new() -> Self {
        NmtMaster {
            enabled: false,
            slaves: [Slave {
                node: 0,
                guard_ms: 0,
                life_factor: 0,
                next_guard: Ticks(0),
                awaiting: false,
                misses: 0,
                toggle: false,
                state: None,
                no_answer_reported: false,
                bootup_seen: false,
                answered: false,
                updated: false,
                last_toggle: false,
            }; CAPACITY],
        }
    }

    /// `CcmInitNmtm`: enables the master (boot-up detection, guarding).
    pub fn enable(&mut self) {
        self.enabled = true;
    }

    /// True after [`NmtMaster::enable`].
    pub fn is_enabled(&self) -> bool {
        self.enabled
    }

    /// `CcmDefineSlaveTab`: the slaves the master manages (replaces the
    /// list); node-ID 0 marks an unused entry and is skipped. Codes:
    /// kCopNmtmNoFreeSlaveEntry (more used entries than the capacity),
    /// kCopNmtmInvalidSlaveNodeId, kCopNmtmSlaveNodeExist (duplicate). On
    /// error the previous list is kept.
    pub fn define_slaves(&mut self, nodes: &[u8]) -> CopResult {
        // Node-ID 0 marks an unused entry of the application's table
        // (tables sized for every possible slave, filled as slaves are
        // added): skipped, not refused.
        let used = || nodes.iter().filter(|n| **n != 0);
        if used().count() > CAPACITY {
            return Err(CopKernel::NmtmNoFreeSlaveEntry);
        }
        for (i, n) in used().enumerate() {
            valid_node(*n)?;
            if used().take(i).any(|m| m == n) {
                return Err(CopKernel::NmtmSlaveNodeExist);
            }
        }
        // A node listed before keeps its supervision state (the
        // application's table is read again when it changes).
        let previous = self.slaves;
        self.slaves = Self::new().slaves;
        for (s, n) in self.slaves.iter_mut().zip(used()) {
            match previous.iter().find(|p| p.node == *n) {
                Some(p) => *s = *p,
                None => s.node = *n,
            }
        }
        Ok(())
    }

    /// True when the used entries of `nodes` (node-IDs other than 0), in
    /// their order, are the slaves the master manages.
    pub fn same_slaves(&self, nodes: &[u8]) -> bool {
        let listed = self.slaves.iter().map(|s| s.node).filter(|n| *n != 0);
        listed.eq(nodes.iter().copied().filter(|n| *n != 0))
    }

    fn slave_mut(&mut self, node: u8) -> CopResult<&mut Slave> {
        valid_node(node)?;
        self.slaves
            .iter_mut()
            .find(|s| s.node == node)
            .ok_or(CopKernel::NmtmSlaveEntryNotExist)
    }

    /// `CcmConfigLgm`: guard time (ms) and life time factor of a slave;
    /// time 0 stops guarding it.
    pub fn configure_guarding(
        &mut self,
        node: u8,
        guard_ms: u16,
        life_factor: u8,
        now: Ticks,
    ) -> CopResult {
        let s = self.slave_mut(node)?;
        s.guard_ms = guard_ms;
        s.life_factor = life_factor.max(1);
        s.next_guard = now;
        // The toggle bit is not reset here: the slave resets it only with
        // reset communication (CiA 301 7.2.8.3.2.1), which the master sees
        // as the slave's boot-up message.
        s.answered_in_time();
        s.answered = false;
        s.updated = false;
        Ok(())
    }

    /// What the master knows about a slave; the read clears
    /// [`slave_state::UPDATE`] (`CcmNmtmGetSlaveInfo`).
    pub fn read_slave_info(&mut self, node: u8) -> CopResult<SlaveInfo> {
        let info = self.slave_info(node)?;
        self.slave_mut(node)?.updated = false;
        Ok(info)
    }

    /// What the master knows about a slave.
    pub fn slave_info(&self, node: u8) -> CopResult<SlaveInfo> {
        valid_node(node)?;
        let s = self
            .slaves
            .iter()
            .find(|s| s.node == node)
            .ok_or(CopKernel::NmtmSlaveEntryNotExist)?;
        let guarded = s.guard_ms > 0;
        let bit = |on: bool, b: u8| if on { b } else { 0 };
        let flags = slave_state::USED
            | bit(s.bootup_seen, slave_state::BOOTUP_RECEIVED)
            | bit(guarded && s.life_factor > 0, slave_state::LG_ACTIVE)
            | bit(s.answered, slave_state::LG_RECEIVED)
            | bit(guarded && self.enabled, slave_state::NG_ACTIVE)
            | bit(s.updated, slave_state::UPDATE)
            | bit(s.last_toggle, slave_state::TOGGLE_BIT);
        Ok(SlaveInfo {
            state: s.state.unwrap_or(0),
            guard_ms: s.guard_ms,
            life_factor: s.life_factor,
            misses: s.misses,
            flags,
        })
    }

    /// `CcmSendNmtCommand`: NMT module control to one node or all (0).
    pub fn send_command(port: &mut impl CanPort, node: u8, cs: NmtCs) -> CopResult {
        if node > 127 {
            return Err(CopKernel::NmtmInvalidSlaveNodeId);
        }
        port.send(&nmt::encode_command(cs, node), Priority::High)
    }

    /// `CcmTriggerNodeGuard`: sends one guard request now.
    pub fn trigger_guard(&mut self, port: &mut impl CanPort, node: u8, now: Ticks) -> CopResult {
        let s = self.slave_mut(node)?;
        port.send(
            &CanFrame::remote(nmt::error_control_id(node), 1),
            Priority::Low,
        )?;
        s.awaiting = true;
        s.next_guard = now.plus(ms_to_ticks(u32::from(s.guard_ms)));
        Ok(())
    }

    /// An error control frame (0x701..0x77F, DLC 1) from another node:
    /// a guard answer when one is awaited, otherwise a heartbeat or boot-up.
    /// Returns `true` when it was a guard answer (not a heartbeat).
    pub fn on_error_control(&mut self, frame: &CanFrame, q: &mut ActionQueue) -> bool {
        let Some(ec) = nmt::decode_error_control(frame) else {
            return false;
        };
        if !self.enabled {
            return false;
        }
        let raw = frame.data[0];
        if let Some(s) = self
            .slaves
            .iter_mut()
            .find(|s| s.node == ec.node && s.awaiting)
        {
            s.answered_in_time();
            let toggle = raw & 0x80 != 0;
            s.answered = true;
            s.updated = true;
            s.last_toggle = toggle;
            if toggle != s.toggle {
                q.emit(Event::Nmtm(ec.node, ErrCtrlEvent::LgToggleError));
            }
            s.toggle = !toggle;
            if s.state.is_some_and(|st| st != ec.state) {
                q.emit(Event::Nmtm(ec.node, ErrCtrlEvent::LgNodeStateChanged));
            }
            s.state = Some(ec.state);
            return true;
        }
        if raw == 0 {
            if let Some(s) = self.slaves.iter_mut().find(|s| s.node == ec.node) {
                s.state = Some(0);
                s.toggle = false;
                s.bootup_seen = true;
            }
            q.emit(Event::Nmtm(ec.node, ErrCtrlEvent::BootupReceived));
        }
        false
    }

    /// True when [`NmtMaster::poll`] at `now` would do nothing.
    #[inline]
    pub fn at_rest(&self, now: Ticks) -> bool {
        !self.enabled
            || self
                .slaves
                .iter()
                .filter(|s| s.guarded())
                .all(|s| !now.reached(s.next_guard))
    }

    /// Guarding timers: sends due guard requests and reports a slave that
    /// missed `life factor` answers in a row (once, until it answers).
    /// Returns `true` when nothing was reported.
    pub fn poll(&mut self, port: &mut impl CanPort, now: Ticks, q: &mut ActionQueue) -> bool {
        if !self.enabled {
            return true;
        }
        for s in self.slaves.iter_mut().filter(|s| s.guarded()) {
            if now.reached(s.next_guard) {
                if s.awaiting {
                    s.misses = s.misses.saturating_add(1);
                }
                let frame = CanFrame::remote(nmt::error_control_id(s.node), 1);
                if port.send(&frame, Priority::Low).is_ok() {
                    s.awaiting = true;
                }
                s.next_guard = now.plus(ms_to_ticks(u32::from(s.guard_ms)));
                if s.misses >= s.life_factor && !s.no_answer_reported {
                    s.no_answer_reported = true;
                    q.emit(Event::Nmtm(s.node, ErrCtrlEvent::LgNoAnswer));
                    return false;
                }
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::event::Action;
    use crate::port::CanId;

    use crate::port::Recorder as Sink;

    #[test]
    fn slave_table_checks() {
        let mut m = NmtMaster::new();
        assert_eq!(
            m.define_slaves(&[128]),
            Err(CopKernel::NmtmInvalidSlaveNodeId)
        );
        // 0 = unused entry: skipped (a table of 5 with 2 used fits 4).
        assert!(m.define_slaves(&[0, 5, 0, 6, 0]).is_ok());
        assert_eq!(m.slave_info(5).map(|i| i.flags), Ok(0x01));
        assert_eq!(m.slave_info(0), Err(CopKernel::NmtmInvalidSlaveNodeId));
        assert_eq!(m.define_slaves(&[5, 5]), Err(CopKernel::NmtmSlaveNodeExist));
        assert!(m.define_slaves(&[5, 6]).is_ok());
        assert_eq!(
            m.configure_guarding(7, 100, 3, Ticks(0)),
            Err(CopKernel::NmtmSlaveEntryNotExist)
        );
        assert!(m.configure_guarding(6, 100, 3, Ticks(0)).is_ok());
        assert_eq!(m.slave_info(6).map(|i| i.guard_ms), Ok(100));
    }

    #[test]
    fn a_table_defined_again_keeps_the_state_of_the_nodes_it_still_lists() {
        let mut m = NmtMaster::new();
        m.enable();
        assert!(m.define_slaves(&[0, 0]).is_ok());
        assert!(m.same_slaves(&[0, 0]));
        assert!(!m.same_slaves(&[4, 0]));
        assert!(m.define_slaves(&[4, 0]).is_ok());
        let mut q = ActionQueue::new();
        m.on_error_control(&nmt::encode_bootup(4), &mut q);
        assert!(m.configure_guarding(4, 100, 3, Ticks(0)).is_ok());
        let before = m.slave_info(4);
        assert!(m.same_slaves(&[0, 4]) && !m.same_slaves(&[4, 9]));
        assert!(m.define_slaves(&[4, 9]).is_ok());
        assert_eq!(m.slave_info(4), before);
        assert_eq!(m.slave_info(9).map(|i| i.flags), Ok(0x01));
        assert!(m.define_slaves(&[9]).is_ok());
        assert_eq!(m.slave_info(4), Err(CopKernel::NmtmSlaveEntryNotExist));
    }

    #[test]
    fn slave_state_bits_follow_guarding() {
        // Bit values: vendored SYS TEC nmtm.h (tNmtmSlaveState).
        let mut m = NmtMaster::new();
        m.enable();
        assert!(m.define_slaves(&[4]).is_ok());
        assert_eq!(m.slave_info(4).map(|i| i.flags), Ok(0x01));
        let mut q = ActionQueue::new();
        m.on_error_control(&nmt::encode_bootup(4), &mut q);
        assert_eq!(m.slave_info(4).map(|i| i.flags), Ok(0x03));
        assert!(m.configure_guarding(4, 100, 3, Ticks(0)).is_ok());
        assert_eq!(m.slave_info(4).map(|i| i.flags), Ok(0x17));
        // A guard answer (CiA 301 7.2.8.3.2.1): toggle 1, state 0x7F.
        let mut port = Sink(Vec::new());
        assert!(m.trigger_guard(&mut port, 4, Ticks(0)).is_ok());
        assert_eq!(port.0.len(), 1);
        let answer = CanFrame::new(CanId::std_masked(0x704), &[0xFF]);
        assert!(m.on_error_control(&answer, &mut q));
        let info = m.read_slave_info(4);
        assert_eq!(info.map(|i| (i.flags, i.state)), Ok((0xDF, 0x7F)));
        // The read cleared the update bit.
        assert_eq!(m.slave_info(4).map(|i| i.flags), Ok(0x9F));
    }

    #[test]
    fn bootup_is_reported() {
        let mut m = NmtMaster::new();
        m.enable();
        let mut q = ActionQueue::new();
        let f = nmt::encode_bootup(9);
        assert!(!m.on_error_control(&f, &mut q));
        assert_eq!(
            q.pop(),
            Some(Action::Emit(Event::Nmtm(9, ErrCtrlEvent::BootupReceived)))
        );
        // A heartbeat with a state is not a boot-up.
        let hb = CanFrame::new(CanId::std_masked(0x709), &[0x05]);
        m.on_error_control(&hb, &mut q);
        assert!(q.is_empty());
    }
}
