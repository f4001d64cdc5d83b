//! The stack's API for the smaller CCM services: emergency consumer,
//! pre-defined error field, life guarding slave, SYNC producer, TIME
//! producer and store / restore. Each service's rules are documented in its
//! module ([`crate::emcy`], [`crate::nmt::lifeguard`], [`crate::sync`],
//! [`crate::wire::time`], [`crate::store`]); this file
//! connects them to the dictionary, the NMT state and the other modules.

use super::Stack;
use crate::emcy::EmcyConsumer;
use crate::emcy::producer::{self as emcp, ERROR_FIELD_INDEX, ERROR_REGISTER_INDEX};
use crate::error::{CopKernel, CopResult};
use crate::event::NmtState;
use crate::nmt::error_behaviour;
use crate::nmt::lifeguard::{self as lgs, LifeGuardSlave};
use crate::od::ByteOrder;
use crate::port::{CanId, CanPort, Priority, Ticks};
use crate::store::{self, StoreRestore};
use crate::sync::producer::{self as syncp, SyncProducer};
use crate::wire::emcy::Emergency;
use crate::wire::pdo::{COB_INVALID, COB_NO_RTR};
use crate::wire::time::{self, TimeOfDay};

impl Stack {
    pub(super) fn operating(&self) -> bool {
        self.connected && matches!(self.state, NmtState::PreOperational | NmtState::Operational)
    }

    /// Writes an object through the dictionary's checks and the module
    /// hooks, with the kernel code of a refusal.
    fn write_le(&mut self, index: u16, value: &[u8], now: Ticks) -> CopResult {
        self.write_object(index, 0, ByteOrder::Wire, value, now)
            .map_err(|e| e.kernel)
    }

    /// Module parameters that follow the communication objects (after
    /// reset communication and after a dynamic OD changed the dictionary).
    pub(super) fn reconfigure_services(&mut self, now: Ticks) {
        self.lgs.reconfigure(&self.od);
        self.syncp.reconfigure(&self.od, now);
        self.store.reconfigure(&self.od);
    }

    // ------------------------------------------------------------------
    // Emergency consumer
    // ------------------------------------------------------------------

    /// The emergency consumer.
    pub fn emcc(&self) -> &EmcyConsumer {
        &self.emcc
    }

    /// `CcmInitEmcc` / `CcmInitEmccEx`: received emergencies of the listed
    /// producers become [`crate::event::Event::Emcc`] from now on.
    pub fn init_emcc(&mut self) {
        self.emcc.enable();
    }

    /// `CcmEmccDefineProducerTab` (codes: [`EmcyConsumer::define_producers`]).
    pub fn define_emcc_producers(&mut self, port: &mut impl CanPort, nodes: &[u8]) -> CopResult {
        self.emcc.define_producers(nodes, self.node_id, port)
    }

    /// True when `nodes` lists the emergency producers already defined
    /// (entries 0 skipped).
    pub fn emcc_producers_are(&self, nodes: &[u8]) -> bool {
        self.emcc.same_producers(nodes)
    }

    // ------------------------------------------------------------------
    // Pre-defined error field
    // ------------------------------------------------------------------

    /// `CcmClearPreDefinedErrorField`: empties 0x1003 (sub 0 = 0) and
    /// resets 0x1001. kCopObdIndexNotExist when the dictionary has no
    /// 0x1003 (nothing changes).
    pub fn clear_error_field(&mut self) -> CopResult {
        if self.od.find_entry(ERROR_FIELD_INDEX).is_none() {
            return Err(CopKernel::ObdIndexNotExist);
        }
        emcp::clear_error_field(&self.od);
        Ok(())
    }

    // ------------------------------------------------------------------
    // Life guarding slave
    // ------------------------------------------------------------------

    /// The life guarding slave.
    pub fn lgs(&self) -> &LifeGuardSlave {
        &self.lgs
    }

    /// `CcmInitLgs`.
    pub fn init_lgs(&mut self) {
        self.lgs.init();
    }

    /// `CcmConfigLgs`: guard time (ms) and life time factor, written to
    /// 0x100C / 0x100D where the dictionary has them and kept by the module
    /// otherwise. kCopNmtLifeguardVsHeartbeat when a non-zero life time is
    /// asked for while the producer heartbeat time (0x1017) is not 0
    /// (nothing changes); a refused object write gives its code.
    pub fn config_lgs(&mut self, guard_ms: u16, factor: u8, now: Ticks) -> CopResult {
        if guard_ms > 0 && factor > 0 && self.hb.period_ms() > 0 {
            return Err(CopKernel::NmtLifeguardVsHeartbeat);
        }
        if self.od.find_entry(lgs::GUARD_TIME_INDEX).is_some() {
            self.write_le(lgs::GUARD_TIME_INDEX, &guard_ms.to_le_bytes(), now)?;
        }
        if self.od.find_entry(lgs::LIFE_TIME_FACTOR_INDEX).is_some() {
            self.write_le(lgs::LIFE_TIME_FACTOR_INDEX, &[factor], now)?;
        }
        self.lgs.set_own(guard_ms, factor);
        self.lgs.reconfigure(&self.od);
        Ok(())
    }

    /// `CcmConfigHbp`: writes the producer heartbeat time 0x1017 (ms).
    /// kCopNmtLifeguardVsHeartbeat when a non-zero time is asked for while
    /// life guarding is configured (after `CcmInitLgs`, life time not 0);
    /// otherwise the codes of the object write.
    pub fn config_hbp(&mut self, time_ms: u16, now: Ticks) -> CopResult {
        if time_ms > 0 && self.lgs.is_configured() {
            return Err(CopKernel::NmtLifeguardVsHeartbeat);
        }
        self.write_le(
            crate::heartbeat::PRODUCER_TIME_INDEX,
            &time_ms.to_le_bytes(),
            now,
        )
    }

    /// `CcmConfigEmcp`: the emergency COB-ID (bit 31 set: no producer).
    /// Written to 0x1014 where the dictionary has it, so that the object
    /// shows the COB-ID in use and the producer takes it from there after
    /// every communication reset (the NMT callback configures it at
    /// `kNmtEvResetCommunication`, before the modules read their
    /// objects); kept by the producer otherwise, until the next
    /// communication reset. `kCopInvalidParam` for a COB-ID the producer
    /// cannot use ([`emcp::usable_cob_id`]); the codes of the object write
    /// (a read-only 0x1014: `kCopObdWriteViolation`).
    pub fn config_emcp(&mut self, cob: u32, now: Ticks) -> CopResult {
        if !emcp::usable_cob_id(cob) {
            return Err(CopKernel::InvalidParam);
        }
        if self.od.find_entry(emcp::COB_ID_INDEX).is_some() {
            return self.write_le(emcp::COB_ID_INDEX, &cob.to_le_bytes(), now);
        }
        self.emcy.set_own(&self.od, cob, self.node_id);
        Ok(())
    }

    /// The life guarding event: emergency 0x8130 with the error register's
    /// generic and communication bits ([`Stack::communication_emergency`]),
    /// then the reaction of 0x1029.
    pub(super) fn poll_life_guarding(&mut self, port: &mut impl CanPort, now: Ticks) {
        if !self.connected || !self.lgs.poll(now, self.hb.period_ms() > 0) {
            return;
        }
        self.communication_emergency(port, now, lgs::EMCY_LIFE_GUARD);
        self.communication_error();
    }

    /// The driver lost received frames of identifiers that no SRDO or GFC
    /// uses (`PortStatus::rx_overrun_other`): emergency 0x8110, "CAN
    /// overrun (objects lost)" (CiA 301 table 21), with the error
    /// register's generic and communication bits. No SRDO error: the
    /// safety function lost nothing.
    pub(super) fn can_overrun(&mut self, port: &mut impl CanPort, now: Ticks) {
        self.communication_emergency(port, now, emcp::EMCY_CAN_OVERRUN);
    }

    /// An emergency of a communication error with the error register's
    /// generic and communication bits, recorded in 0x1001 / 0x1003 and sent
    /// (in STOPPED, where EMCY is not sent, only recorded).
    fn communication_emergency(&mut self, port: &mut impl CanPort, now: Ticks, code: u16) {
        let register = self
            .od
            .read_uint(ERROR_REGISTER_INDEX, 0)
            .map_or(0, |v| v as u8);
        let e = Emergency {
            code,
            register: register | lgs::ERROR_REGISTER_BITS,
            manufacturer: [0; 5],
        };
        if self.state == NmtState::Stopped {
            emcp::record(&self.od, &e);
        } else {
            // A full inhibit-time queue or a disabled producer loses the
            // frame; the error is recorded in 0x1001 / 0x1003 either way.
            let _ = self.emcy.send(&self.od, port, now, e);
        }
    }

    /// A communication error of this node (heartbeat producer lost, life
    /// guarding event, bus-off): queues the NMT state change 0x1029 sub 1
    /// asks for ([`crate::nmt::error_behaviour`]), after the events already
    /// queued.
    pub(super) fn communication_error(&mut self) {
        if let Some(target) = error_behaviour::reaction(&self.od).and_then(|r| r.target(self.state))
        {
            self.queue_state(target);
        }
    }

    // ------------------------------------------------------------------
    // SYNC producer
    // ------------------------------------------------------------------

    /// The SYNC producer.
    pub fn syncp(&self) -> &SyncProducer {
        &self.syncp
    }

    /// `CcmConfigSyncProducer`: SYNC COB-ID (bit 30 set: this node
    /// produces) and communication cycle period in µs, written to 0x1006
    /// and 0x1005 where the dictionary has them and kept by the module
    /// otherwise; the COB-ID is also the SYNC consumer's (one object, CiA
    /// 301 7.5.2.5). kCopInvalidParam for an identifier this node cannot
    /// send on (nothing changes); a refused object write gives its code.
    pub fn config_sync_producer(&mut self, cob: u32, cycle_us: u32, now: Ticks) -> CopResult {
        if !syncp::usable_cob_id(cob) {
            return Err(CopKernel::InvalidParam);
        }
        if self.od.find_entry(syncp::CYCLE_PERIOD_INDEX).is_some() {
            self.write_le(syncp::CYCLE_PERIOD_INDEX, &cycle_us.to_le_bytes(), now)?;
        }
        if self.od.find_entry(syncp::COB_ID_SYNC_INDEX).is_some() {
            self.write_le(syncp::COB_ID_SYNC_INDEX, &cob.to_le_bytes(), now)?;
        } else {
            let window = self.pdo.sync_window_us();
            self.pdo
                .set_sync(cob & !(COB_INVALID | COB_NO_RTR), window)?;
        }
        self.syncp.set_own(cob, cycle_us);
        self.syncp.reconfigure(&self.od, now);
        Ok(())
    }

    /// Sends this node's SYNC when due and lets its own PDOs see it.
    pub(super) fn produce_sync(&mut self, port: &mut impl CanPort, now: Ticks) {
        let operating = self.operating();
        if self.syncp.poll(port, operating, now) {
            self.own_sync(now);
        }
    }

    // ------------------------------------------------------------------
    // TIME producer
    // ------------------------------------------------------------------

    /// `CcmTspSend`: sends one TIME frame on `cob` (bit 29: 29-bit
    /// identifier; bits 30 and 31, the producer / consumer flags of 0x1012,
    /// are ignored). kCopNmtStateError unless connected and PRE-OPERATIONAL
    /// or OPERATIONAL (CiA 301 7.3.2.2), kCopInvalidParam for an identifier
    /// this node cannot send on, or the driver's code.
    pub fn send_time_stamp(
        &mut self,
        port: &mut impl CanPort,
        cob: u32,
        t: TimeOfDay,
    ) -> CopResult {
        if !self.operating() {
            return Err(CopKernel::NmtStateError);
        }
        if !syncp::usable_cob_id(cob) {
            return Err(CopKernel::InvalidParam);
        }
        let id = CanId::from_cob_id(cob & !(COB_INVALID | COB_NO_RTR));
        port.send(&time::encode(id, &t), Priority::Low)
    }

    // ------------------------------------------------------------------
    // Store / restore
    // ------------------------------------------------------------------

    /// The store / restore bookkeeping.
    pub fn store(&self) -> &StoreRestore {
        &self.store
    }

    /// Registers the application's non-volatile memory and the
    /// configuration key of its images (`OD_BUILDER_KEY`); `None` leaves
    /// the node without storage. Used from the next `CcmInitStore` on.
    pub fn set_store_driver(&mut self, driver: Option<store::Driver>, key: u32) {
        self.store.set_driver(driver, key);
        self.store.reconfigure(&self.od);
    }

    /// `CcmInitStore` ([`StoreRestore::init`]): without a driver
    /// kCopCcmStoreHwError and nothing else changes; with one the stored
    /// parameters are loaded.
    pub fn init_store(&mut self) -> CopResult {
        let r = self.store.init(&self.od);
        self.store.reconfigure(&self.od);
        r
    }

    /// `CcmStoreCheckArchivState`: kCopObdIllegalPart for a `part` that is
    /// not a combination of `kObdPart*` bits, else
    /// [`StoreRestore::check_archive`].
    pub fn check_archive(&self, part: u32) -> CopResult {
        store::check_part(part)?;
        self.store
            .check_archive(&self.od, u8::try_from(part).unwrap_or(0))
    }

    /// Stores `parts` (`kObdPart*` bits) as "save" on 0x1010 does, for
    /// dictionaries without 0x1010 (same codes: kCopCcmStoreHwError,
    /// kCopCcmStoreUnvalidState while OPERATIONAL).
    pub fn save_parameters(&mut self, parts: u8) -> CopResult {
        self.store
            .save(&self.od, parts, self.state)
            .map_err(|e| e.kernel)
    }

    /// `CcmStoreRestoreDefault`: erases the stored parameters (with a
    /// driver); every part is restored to its defaults at the next reset,
    /// as with "load" on 0x1011 sub 1.
    pub fn restore_default(&mut self) -> CopResult {
        self.store.restore_default()
    }
}
