//! Emergency producer (SYS TEC EMCP, objects 0x1001, 0x1003, 0x1014, 0x1015).
//!
//! The pre-defined error field 0x1003 is emptied by
//! `CcmClearPreDefinedErrorField` or by writing 0 to its subindex 0 (CiA
//! 301 7.5.2.4); both also reset the error register 0x1001. Any other value
//! written to subindex 0 is refused with SDO abort 0x06090030.

use crate::error::{CopKernel, CopResult, OdError};
use crate::od::{Object, ObjectDictionary, Staged};
use crate::port::{CanId, CanPort, Priority, Ticks};
use crate::wire::emcy::{self, Emergency};
use crate::wire::pdo::{COB_INVALID, COB_NO_RTR, check_identifier};

/// Emergency error code "CAN overrun (objects lost)" (CiA 301 table 21).
pub const EMCY_CAN_OVERRUN: u16 = 0x8110;
/// Error register.
pub const ERROR_REGISTER_INDEX: u16 = 0x1001;
/// Pre-defined error field.
pub const ERROR_FIELD_INDEX: u16 = 0x1003;
/// COB-ID EMCY.
pub const COB_ID_INDEX: u16 = 0x1014;
/// Inhibit time EMCY (100 µs units).
pub const INHIBIT_INDEX: u16 = 0x1015;

/// Emergencies waiting for the inhibit time to pass.
const PENDING: usize = 4;

/// True when `cob` is a COB-ID EMCY this node can use (CiA 301
/// §7.5.2.21): bit 31 set (no producer), or bit 30 (reserved) clear and an
/// identifier that CiA 301 §7.3.5 does not reserve, 29-bit only when the
/// driver is configured for CAN 2.0B. The reserved identifiers include
/// 0x101–0x180, so an emergency can never be sent on an SRDO identifier.
pub fn usable_cob_id(cob: u32) -> bool {
    cob & COB_INVALID != 0
        || (cob & COB_NO_RTR == 0 && check_identifier(cob, crate::config::CDRV_CAN20B).is_ok())
}

/// The emergency producer.
#[derive(Clone, Debug, Default)]
pub struct EmcyProducer {
    /// `CcmConfigEmcp` on a dictionary without 0x1014, until the next
    /// communication reset.
    own_cob: Option<u32>,
    cob: Option<CanId>,
    inhibit_ticks: u32,
    last_sent: Option<Ticks>,
    pending: [Option<Emergency>; PENDING],
}

impl EmcyProducer {
    /// A producer without configuration.
    pub const fn new() -> Self {
        EmcyProducer {
            own_cob: None,
            cob: None,
            inhibit_ticks: 0,
            last_sent: None,
            pending: [None; PENDING],
        }
    }

    /// Reads 0x1014 and 0x1015; without 0x1014 the COB-ID is the one
    /// `CcmConfigEmcp` gave ([`EmcyProducer::set_own`]), else the
    /// predefined 0x80 + node-ID. A COB-ID of exactly 0x80 (the predefined
    /// connection set base, as many objdict.h files write it) gets the
    /// node-ID added; bit 31 set, or a COB-ID that is not
    /// [`usable_cob_id`], leaves the node without producer.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, node: u8) {
        let cob = od
            .read_uint(COB_ID_INDEX, 0)
            .map(|v| v as u32)
            .unwrap_or(self.own_cob.unwrap_or(0x80 + u32::from(node)));
        let cob = if cob == 0x80 {
            // The object holds the predefined base: it must show the COB-ID
            // in use (CiA 301), so the node-ID goes into the object too.
            let used = cob + u32::from(node);
            let _ = od.poke_uint(COB_ID_INDEX, 0, u64::from(used));
            used
        } else {
            cob
        };
        self.cob = (cob & COB_INVALID == 0 && usable_cob_id(cob)).then(|| CanId::from_cob_id(cob));
        self.inhibit_ticks = od
            .read_uint(INHIBIT_INDEX, 0)
            .map(|v| v as u32)
            .unwrap_or(0);
    }

    /// The EMCY COB-ID in use.
    pub fn cob_id(&self) -> Option<CanId> {
        self.cob
    }

    /// `CcmConfigEmcp` on a dictionary without 0x1014: keeps the COB-ID
    /// here and takes it over (the caller writes 0x1014 where it exists).
    pub fn set_own(&mut self, od: &ObjectDictionary, cob: u32, node: u8) {
        self.own_cob = Some(cob);
        self.reconfigure(od, node);
    }

    /// Reset communication: forgets the COB-ID kept by
    /// [`EmcyProducer::set_own`] (0x1014 gets its default from the
    /// dictionary).
    pub fn reset_communication(&mut self) {
        self.own_cob = None;
    }

    /// Records the error in 0x1001/0x1003 and sends it, or queues it while
    /// the inhibit time runs. `kCopNoResource` when the queue is full.
    pub fn send(
        &mut self,
        od: &ObjectDictionary,
        port: &mut impl CanPort,
        now: Ticks,
        e: Emergency,
    ) -> CopResult {
        record(od, &e);
        if self.inhibited(now) || self.pending.iter().any(Option::is_some) {
            let slot = self
                .pending
                .iter_mut()
                .find(|p| p.is_none())
                .ok_or(CopKernel::NoResource)?;
            *slot = Some(e);
            return Ok(());
        }
        self.transmit(port, now, &e)
    }

    fn inhibited(&self, now: Ticks) -> bool {
        match self.last_sent {
            Some(t) if self.inhibit_ticks > 0 => now.since(t) < self.inhibit_ticks,
            _ => false,
        }
    }

    fn transmit(&mut self, port: &mut impl CanPort, now: Ticks, e: &Emergency) -> CopResult {
        let Some(id) = self.cob else {
            return Err(CopKernel::CobIllegalCanId);
        };
        port.send(&emcy::encode(id, e), Priority::Low)?;
        self.last_sent = Some(now);
        Ok(())
    }

    /// True when [`EmcyProducer::poll`] at `now` would do nothing.
    #[inline]
    pub fn at_rest(&self, now: Ticks) -> bool {
        self.pending.first().copied().flatten().is_none() || self.inhibited(now)
    }

    /// Sends the oldest queued emergency once the inhibit time has passed.
    pub fn poll(&mut self, port: &mut impl CanPort, now: Ticks) {
        if self.inhibited(now) {
            return;
        }
        if let Some(e) = self.pending.first().copied().flatten() {
            if self.transmit(port, now, &e).is_ok() {
                self.pending.rotate_left(1);
                if let Some(last) = self.pending.last_mut() {
                    *last = None;
                }
            }
        }
    }
}

/// A write of anything but 0 to 0x1003 sub 0 (CiA 301 7.5.2.4).
pub const REFUSE_ERROR_COUNT: OdError = OdError::VALUE_RANGE;

/// Module hook: only 0 may be written to 0x1003 sub 0 (the other
/// subindices follow the dictionary's access rights), and only a
/// [`usable_cob_id`] to 0x1014.
pub fn check_write(obj: &Object, value: &Staged) -> Result<(), OdError> {
    match (obj.index(), obj.sub()) {
        (ERROR_FIELD_INDEX, 0) if value.as_u64() != Some(0) => Err(REFUSE_ERROR_COUNT),
        (COB_ID_INDEX, 0) if !value.as_u64().is_some_and(|v| usable_cob_id(v as u32)) => {
            Err(OdError::VALUE_RANGE)
        }
        _ => Ok(()),
    }
}

/// Empties the pre-defined error field (sub 0 = 0, the entries 0) and
/// resets the error register, where those objects exist.
pub fn clear_error_field(od: &ObjectDictionary) {
    let _ = od.poke_uint(ERROR_REGISTER_INDEX, 0, 0);
    let Some(entry) = od.find_entry(ERROR_FIELD_INDEX) else {
        return;
    };
    for sub in 1..od.sub_count(entry) {
        if let Ok(sub) = u8::try_from(sub) {
            let _ = od.poke_uint(ERROR_FIELD_INDEX, sub, 0);
        }
    }
    let _ = od.poke_uint(ERROR_FIELD_INDEX, 0, 0);
}

/// Updates the error register and pushes the error into the pre-defined
/// error field (newest at subindex 1), where those objects exist, without
/// sending anything (an error that arises while EMCY may not be sent, such
/// as in STOPPED).
pub fn record(od: &ObjectDictionary, e: &Emergency) {
    let _ = od.poke_uint(ERROR_REGISTER_INDEX, 0, u64::from(e.register));
    let Some(entry) = od.find_entry(ERROR_FIELD_INDEX) else {
        return;
    };
    let capacity = od.sub_count(entry).saturating_sub(1);
    if capacity == 0 {
        return;
    }
    let count = od.read_uint(ERROR_FIELD_INDEX, 0).unwrap_or(0) as usize;
    let count = count.min(capacity);
    let mut sub = count.min(capacity - 1);
    while sub >= 1 {
        if let Ok(v) = od.read_uint(ERROR_FIELD_INDEX, sub as u8) {
            let _ = od.poke_uint(ERROR_FIELD_INDEX, (sub + 1) as u8, v);
        }
        sub -= 1;
    }
    let manuf = u64::from(u16::from_le_bytes([e.manufacturer[0], e.manufacturer[1]]));
    let _ = od.poke_uint(ERROR_FIELD_INDEX, 1, u64::from(e.code) | (manuf << 16));
    let _ = od.poke_uint(ERROR_FIELD_INDEX, 0, ((count + 1).min(capacity)) as u64);
}
