//! Emergency producer (SYS TEC EMCP, objects 0x1001, 0x1003, 0x1014, 0x1015).
//!
//! The pre-defined error field 0x1003 is emptied by
//! `CcmClearPreDefinedErrorField` or by writing 0 to its subindex 0 (CiA
//! 301 7.5.2.4); both also reset the error register 0x1001. Any other value
//! written to subindex 0 is refused with SDO abort 0x06090030.

use crate::error::{CopKernel, CopResult, OdError, SdoAbort};
use crate::od::{Object, ObjectDictionary, Staged};
use crate::port::{CanId, CanPort, Priority, Ticks};
use crate::wire::emcy::{self, Emergency};

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

/// The emergency producer.
#[derive(Clone, Debug, Default)]
pub struct EmcyProducer {
    cob: Option<CanId>,
    inhibit_ticks: u32,
    last_sent: Option<Ticks>,
    pending: [Option<Emergency>; PENDING],
}

impl EmcyProducer {
    /// A producer without configuration.
    pub const fn new() -> Self {
        EmcyProducer {
            cob: None,
            inhibit_ticks: 0,
            last_sent: None,
            pending: [None; PENDING],
        }
    }

    /// Reads 0x1014 and 0x1015. A COB-ID of exactly 0x80 (the predefined
    /// connection set base, as many objdict.h files write it) gets the
    /// node-ID added; bit 31 set disables the producer.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, node: u8) {
        let cob = od
            .read_uint(COB_ID_INDEX, 0)
            .map(|v| v as u32)
            .unwrap_or(0x80 + u32::from(node));
        let cob = if cob == 0x80 {
            // The object holds the predefined base: it must show the COB-ID
            // in use (CiA 301), so the node-ID goes into the object too.
            let used = cob + u32::from(node);
            let _ = od.poke_uint(COB_ID_INDEX, 0, u64::from(used));
            used
        } else {
            cob
        };
        self.cob = if cob & 0x8000_0000 != 0 {
            None
        } else {
            Some(CanId::from_cob_id(cob))
        };
        self.inhibit_ticks = od
            .read_uint(INHIBIT_INDEX, 0)
            .map(|v| v as u32)
            .unwrap_or(0);
    }

    /// The EMCY COB-ID in use.
    pub fn cob_id(&self) -> Option<CanId> {
        self.cob
    }

    /// Sets the COB-ID directly (`CcmConfigEmcp`).
    pub fn set_cob_id(&mut self, cob: u32) {
        self.cob = if cob & 0x8000_0000 != 0 {
            None
        } else {
            Some(CanId::from_cob_id(cob))
        };
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
pub const REFUSE_ERROR_COUNT: OdError = OdError::new(CopKernel::InvalidParam, SdoAbort::ValueRange);

/// Module hook: only 0 may be written to 0x1003 sub 0 (the other
/// subindices follow the dictionary's access rights).
pub fn check_error_field_write(obj: &Object, value: &Staged) -> Result<(), OdError> {
    if obj.index() == ERROR_FIELD_INDEX && obj.sub() == 0 && value.as_u64() != Some(0) {
        return Err(REFUSE_ERROR_COUNT);
    }
    Ok(())
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
