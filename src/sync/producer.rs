//! SYNC producer (CiA 301 7.2.5; objects 0x1005 and 0x1006): the producer
//! half of the SYS TEC module SYNC (`CcmConfigSyncProducer`). The consumer
//! half lives in [`crate::pdo`].
//!
//! This node produces SYNC when bit 30 of the SYNC COB-ID
//! (`CANID_SYNC_PRODUCER`) is set and the communication cycle period is not
//! 0: a frame of DLC 0 on the COB-ID every period, in PRE-OPERATIONAL and
//! OPERATIONAL only (CiA 301 7.3.2.2). The stack hands each SYNC it sends
//! to its own PDO module as well, because a controller does not receive its
//! own frames: synchronous TPDOs of this node go out in the same cycle and
//! synchronous RPDO data take effect, as on every other node.
//!
//! # Behaviour decisions
//! * The period is counted in stack ticks of 100 µs: the cycle period in µs
//!   is divided by 100 and rounded down (1 050 µs → 10 ticks = 1 ms); a
//!   period between 1 and 199 µs becomes 1 tick. At most one SYNC is sent
//!   per processing cycle, so the real period is also bounded below by how
//!   often `CcmProcess` runs.
//! * The first SYNC follows one period after production starts or the
//!   COB-ID / period change; after that the phase is kept. A stack that
//!   falls behind by more than a period sends one SYNC and continues one
//!   period later (no burst).
//! * A SYNC the driver refuses is not repeated (the next one keeps the
//!   phase).
//! * Bit 31 of the COB-ID is "do not care" (CiA 301 7.5.2.5).
//!
//! # Synchronous counter (0x1019)
//! Where the dictionary has the synchronous counter overflow value 0x1019
//! (UNSIGNED8, CiA 301 7.5.2.22), it shapes the frame: 0 gives SYNC without
//! data, 2..=240 a SYNC of DLC 1 whose byte counts 1, 2, ... up to the value
//! and starts at 1 again. 1 and 241..=255 are reserved.
//! * A write of a reserved value is refused with abort 0x06090030
//!   (`kCopInvalidParam`); a write while the communication cycle period in
//!   force is not 0 with abort 0x08000022 (`kCopInvalidParam`): the counter
//!   changes only while no SYNC is produced. A DCF therefore sets 0x1019
//!   before it gives 0x1006 a period. A dictionary default of a reserved
//!   value acts as 0 (no counter).
//! * The counter starts again at 1 whenever production starts or the
//!   COB-ID, the period or 0x1019 change, and at reset communication; a
//!   change of the NMT state alone keeps it (the node produces only in
//!   PRE-OPERATIONAL and OPERATIONAL, and continues where it was).
//! * It counts every SYNC period: a SYNC the driver refuses takes its
//!   number with it, so the consumers see the gap.
//! * Where the dictionary has 0x1005 / 0x1006 they are the configuration
//!   (also when written over SDO); otherwise the values of
//!   `CcmConfigSyncProducer` are kept here and reset with the communication
//!   objects.

use crate::error::{CopKernel, OdError, SdoAbort};
use crate::od::{Object, ObjectDictionary, Staged};
use crate::port::{CanId, CanPort, Priority, Ticks};
use crate::wire::pdo::{
    COB_INVALID, COB_NO_RTR, SYNC_DEFAULT_COB_ID, check_identifier, encode_sync,
};

/// COB-ID SYNC.
pub const COB_ID_SYNC_INDEX: u16 = 0x1005;
/// Communication cycle period (µs).
pub const CYCLE_PERIOD_INDEX: u16 = 0x1006;
/// Synchronous counter overflow value.
pub const COUNTER_OVERFLOW_INDEX: u16 = 0x1019;
/// Largest counter overflow value (CiA 301 7.5.2.22).
pub const COUNTER_OVERFLOW_MAX: u8 = 240;
/// COB-ID bit 30: this node produces SYNC (`CANID_SYNC_PRODUCER`).
pub const SYNC_PRODUCER: u32 = COB_NO_RTR;
/// Microseconds per stack tick.
pub const US_PER_TICK: u32 = 100;

/// A cycle period in µs as stack ticks (see the module's rounding rule).
pub const fn cycle_ticks(cycle_us: u32) -> u32 {
    if cycle_us == 0 {
        0
    } else if cycle_us < US_PER_TICK {
        1
    } else {
        cycle_us / US_PER_TICK
    }
}

/// The counter overflow value `value` of 0x1019 stands for: `Some(0)` for
/// SYNC without counter, `Some(n)` for a counter 1..=n, `None` for the
/// reserved values 1 and 241..=255 (and anything wider than a byte).
pub const fn counter_overflow(value: u64) -> Option<u8> {
    match value {
        0 => Some(0),
        v if v >= 2 && v <= COUNTER_OVERFLOW_MAX as u64 => Some(v as u8),
        _ => None,
    }
}

/// True when `cob` names an identifier this node can send on (bits 30 and
/// 31 aside): an 11-bit identifier that CiA 301 does not reserve, or a
/// 29-bit one when the driver is configured for CAN 2.0B.
pub fn usable_cob_id(cob: u32) -> bool {
    check_identifier(
        cob & !(COB_INVALID | COB_NO_RTR),
        crate::config::CDRV_CAN20B,
    )
    .is_ok()
}

/// The SYNC producer.
#[derive(Clone, Debug)]
pub struct SyncProducer {
    /// Values of `CcmConfigSyncProducer` for a dictionary without the
    /// objects.
    own_cob: u32,
    own_cycle_us: u32,
    cob: u32,
    cycle_us: u32,
    /// The identifier while this node produces.
    id: Option<CanId>,
    period: u32,
    next: Ticks,
    /// 0x1019 in force: 0 without counter, else the counter's last value.
    overflow: u8,
    /// The counter of the last SYNC sent, 0 before the first one.
    counter: u8,
}

crate::od::decl::default_is_new!(SyncProducer);

impl SyncProducer {
    /// A producer that sends nothing.
    pub const fn new() -> Self {
        SyncProducer {
            own_cob: SYNC_DEFAULT_COB_ID,
            own_cycle_us: 0,
            cob: SYNC_DEFAULT_COB_ID,
            cycle_us: 0,
            id: None,
            period: 0,
            next: Ticks(0),
            overflow: 0,
            counter: 0,
        }
    }

    /// The identifier SYNC is sent on, while this node produces.
    pub fn cob_id(&self) -> Option<CanId> {
        self.id
    }

    /// The COB-ID value and the cycle period (µs) in force.
    pub fn config(&self) -> (u32, u32) {
        (self.cob, self.cycle_us)
    }

    /// The period in ticks (0 while not producing).
    pub fn period_ticks(&self) -> u32 {
        self.period
    }

    /// `CcmConfigSyncProducer` on a dictionary without the objects: keeps
    /// the values here (the caller writes the objects where they exist).
    pub fn set_own(&mut self, cob: u32, cycle_us: u32) {
        self.own_cob = cob;
        self.own_cycle_us = cycle_us;
    }

    /// The counter overflow value in force (0x1019; 0: no counter).
    pub fn counter_overflow(&self) -> u8 {
        self.overflow
    }

    /// Takes the configuration from 0x1005 / 0x1006 / 0x1019 where they
    /// exist (the kept values otherwise). A changed identifier or period
    /// restarts the schedule: the next SYNC follows one period after `now`;
    /// the counter starts again with it and with a changed 0x1019.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, now: Ticks) {
        self.cob = od.read_or(COB_ID_SYNC_INDEX, 0, self.own_cob);
        self.cycle_us = od.read_or(CYCLE_PERIOD_INDEX, 0, self.own_cycle_us);
        let overflow = od
            .read_uint(COUNTER_OVERFLOW_INDEX, 0)
            .ok()
            .and_then(counter_overflow)
            .unwrap_or(0);
        if overflow != self.overflow {
            self.overflow = overflow;
            self.counter = 0;
        }
        let produce = self.cob & SYNC_PRODUCER != 0 && usable_cob_id(self.cob);
        let id = produce.then(|| CanId::from_cob_id(self.cob & !(COB_INVALID | COB_NO_RTR)));
        let period = if id.is_some() {
            cycle_ticks(self.cycle_us)
        } else {
            0
        };
        let (id, period) = if period == 0 { (None, 0) } else { (id, period) };
        if id != self.id || period != self.period {
            self.id = id;
            self.period = period;
            self.next = now.plus(period);
            self.counter = 0;
        }
    }

    /// Refuses a write of 0x1019 with a reserved value (0x06090030) or
    /// while the communication cycle period in force is not 0
    /// (0x08000022); other objects pass.
    pub fn check_write(&self, obj: &Object, value: &Staged) -> Result<(), OdError> {
        if obj.index() != COUNTER_OVERFLOW_INDEX || obj.sub() != 0 {
            return Ok(());
        }
        if value.as_u64().and_then(counter_overflow).is_none() {
            return Err(OdError::VALUE_RANGE);
        }
        if self.cycle_us != 0 {
            return Err(OdError::new(CopKernel::InvalidParam, SdoAbort::DeviceState));
        }
        Ok(())
    }

    /// Reset communication: stops producing and forgets the kept values
    /// (the objects get their defaults from the dictionary).
    pub fn reset_communication(&mut self) {
        *self = Self::new();
    }

    /// True when [`SyncProducer::poll`] at `now` would do nothing.
    #[inline]
    pub fn at_rest(&self, operating: bool, now: Ticks) -> bool {
        self.id.is_none() || !operating || self.next.is_after(now)
    }

    /// Sends a SYNC when one is due and `operating` (PRE-OPERATIONAL or
    /// OPERATIONAL). Returns `true` when a SYNC went out.
    pub fn poll(&mut self, port: &mut impl CanPort, operating: bool, now: Ticks) -> bool {
        let Some(id) = self.id else {
            return false;
        };
        if !operating || self.next.is_after(now) {
            return false;
        }
        let counter = (self.overflow != 0).then(|| {
            self.counter = if self.counter >= self.overflow {
                1
            } else {
                self.counter + 1
            };
            self.counter
        });
        let sent = port.send(&encode_sync(id, counter), Priority::High).is_ok();
        let next = self.next.plus(self.period);
        self.next = if now.reached(next) {
            now.plus(self.period)
        } else {
            next
        };
        sent
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::port::Recorder as Sink;

    fn producer(cob: u32, cycle_us: u32) -> SyncProducer {
        let mut p = SyncProducer::new();
        p.set_own(cob, cycle_us);
        p.reconfigure(&ObjectDictionary::empty(), Ticks(0));
        p
    }

    #[test]
    fn counter_overflow_values_of_cia_301() {
        // CiA 301 7.5.2.22: 0 no counter, 2..=240 the counter's last value,
        // 1 and 241..=255 reserved.
        assert_eq!(counter_overflow(0), Some(0));
        assert_eq!(counter_overflow(2), Some(2));
        assert_eq!(counter_overflow(240), Some(240));
        for v in [1, 241, 255, 256, u64::MAX] {
            assert_eq!(counter_overflow(v), None, "{v}");
        }
    }

    #[test]
    fn rounding_to_ticks() {
        assert_eq!(cycle_ticks(0), 0);
        assert_eq!(cycle_ticks(1), 1);
        assert_eq!(cycle_ticks(150), 1);
        assert_eq!(cycle_ticks(199), 1);
        assert_eq!(cycle_ticks(200), 2);
        assert_eq!(cycle_ticks(1_050), 10);
        assert_eq!(cycle_ticks(1_000_000), 10_000);
    }

    #[test]
    fn produces_every_period_with_dlc_0_while_operating() {
        let mut p = producer(0x4000_0080, 10_000);
        assert_eq!(p.cob_id(), Some(CanId::std_masked(0x80)));
        let mut bus = Sink::default();
        assert!(!p.poll(&mut bus, true, Ticks(99)));
        assert!(p.poll(&mut bus, true, Ticks(100)));
        // CiA 301 7.2.5: SYNC without counter has no data.
        assert_eq!(bus.0[0].payload(), &[] as &[u8]);
        assert_eq!(bus.0[0].id, CanId::std_masked(0x80));
        assert!(!p.poll(&mut bus, true, Ticks(150)));
        // Not in STOPPED; once allowed again the overdue SYNC goes at once
        // and the schedule continues from there.
        assert!(!p.poll(&mut bus, false, Ticks(200)));
        assert!(p.poll(&mut bus, true, Ticks(450)));
        assert!(!p.poll(&mut bus, true, Ticks(549)));
        assert!(p.poll(&mut bus, true, Ticks(550)));
        assert_eq!(bus.0.len(), 3);
    }

    #[test]
    fn no_production_without_bit_30_period_or_usable_id() {
        let mut bus = Sink::default();
        for (cob, cycle) in [(0x80, 1000), (0x4000_0080, 0), (0x4000_0701, 1000)] {
            let mut p = producer(cob, cycle);
            assert_eq!(p.cob_id(), None);
            assert!(!p.poll(&mut bus, true, Ticks(1_000_000)));
        }
        // Bit 31 does not matter.
        assert!(producer(0xC000_0081, 1000).cob_id().is_some());
        assert!(bus.0.is_empty());
    }
}
