//! The driver and clock contract.
//!
//! Every protocol module reaches the CAN controller and the time only through
//! these traits. On a target the ffi layer implements them with the SYS TEC
//! driver (`CdrvWriteMsg`, `CdrvReadMsg`, ...) and `TgtGetTickCount`; tests
//! and examples use the simulated bus of `crate::sim` (host builds, feature `std`).
//! With the feature `embedded-can`, `embedded` makes any `embedded-can`
//! driver a [`CanPort`] and a plain tick function a [`Clock`].

use crate::error::CopResult;

#[cfg(feature = "embedded-can")]
pub mod embedded;

/// Stack ticks per millisecond: the SYS TEC tick is 100 µs.
pub const TICKS_PER_MS: u32 = 10;

/// A value of the 100 µs tick counter (`tTime`, 32 bits). It wraps after
/// about 4.97 days; all arithmetic on it is modular.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Ticks(pub u32);

impl Ticks {
    /// Ticks elapsed from `earlier` to `self`, correct across a wrap as long
    /// as the true distance is below 2^32 ticks.
    #[inline]
    pub const fn since(self, earlier: Ticks) -> u32 {
        self.0.wrapping_sub(earlier.0)
    }

    /// This instant plus `ticks`, wrapping.
    #[inline]
    pub const fn plus(self, ticks: u32) -> Ticks {
        Ticks(self.0.wrapping_add(ticks))
    }

    /// This instant plus `ms` milliseconds, wrapping.
    #[inline]
    pub const fn plus_ms(self, ms: u32) -> Ticks {
        self.plus(ms_to_ticks(ms))
    }

    /// True when `self` is strictly later than `deadline`. Valid while the
    /// two are less than 2^31 ticks (about 2.5 days) apart, which every
    /// CANopen timer (at most 65 535 ms) respects.
    #[inline]
    pub const fn is_after(self, deadline: Ticks) -> bool {
        (self.0.wrapping_sub(deadline.0) as i32) > 0
    }

    /// True when `self` is `deadline` or later (a timer planned for
    /// `deadline` is due); the same range as [`Ticks::is_after`].
    #[inline]
    pub const fn reached(self, deadline: Ticks) -> bool {
        (self.0.wrapping_sub(deadline.0) as i32) >= 0
    }
}

/// Converts milliseconds to ticks (saturating; CANopen times are ≤ 65 535 ms).
#[inline]
pub const fn ms_to_ticks(ms: u32) -> u32 {
    ms.saturating_mul(TICKS_PER_MS)
}

/// An 11-bit or 29-bit CAN identifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CanId(u32);

impl CanId {
    /// Flag bit marking an extended (29-bit) identifier inside [`CanId::raw`].
    pub const EXTENDED: u32 = 0x2000_0000;

    /// An 11-bit identifier; `None` above 0x7FF.
    pub const fn std(id: u16) -> Option<CanId> {
        if id <= 0x7FF {
            Some(CanId(id as u32))
        } else {
            None
        }
    }

    /// An 11-bit identifier known to be valid at compile time (masked).
    pub const fn std_masked(id: u16) -> CanId {
        CanId((id & 0x7FF) as u32)
    }

    /// A 29-bit identifier; `None` above 0x1FFF_FFFF.
    pub const fn ext(id: u32) -> Option<CanId> {
        if id <= 0x1FFF_FFFF {
            Some(CanId(id | Self::EXTENDED))
        } else {
            None
        }
    }

    /// The identifier without the extended flag.
    pub const fn id(self) -> u32 {
        self.0 & 0x1FFF_FFFF
    }

    /// True for 29-bit identifiers.
    pub const fn is_extended(self) -> bool {
        self.0 & Self::EXTENDED != 0
    }

    /// Identifier with the extended flag in bit 29 (CiA 301 COB-ID layout).
    pub const fn raw(self) -> u32 {
        self.0
    }

    /// Builds a CanId from a CiA 301 COB-ID value (bit 29 = 29-bit frame).
    pub const fn from_cob_id(cob: u32) -> CanId {
        if cob & Self::EXTENDED != 0 {
            CanId((cob & 0x1FFF_FFFF) | Self::EXTENDED)
        } else {
            CanId(cob & 0x7FF)
        }
    }
}

/// One CAN data or remote frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CanFrame {
    /// Identifier.
    pub id: CanId,
    /// Remote transmission request.
    pub rtr: bool,
    /// Data length code, 0..=8.
    pub len: u8,
    /// Payload; bytes at `len..` are zero.
    pub data: [u8; 8],
}

impl CanFrame {
    /// A data frame; `data` longer than 8 bytes is cut at 8.
    pub fn new(id: CanId, data: &[u8]) -> CanFrame {
        let mut buf = [0u8; 8];
        let n = data.len().min(8);
        for (b, d) in buf.iter_mut().zip(data) {
            *b = *d;
        }
        CanFrame {
            id,
            rtr: false,
            len: n as u8,
            data: buf,
        }
    }

    /// A remote frame asking for `len` bytes.
    pub fn remote(id: CanId, len: u8) -> CanFrame {
        CanFrame {
            id,
            rtr: true,
            len: len.min(8),
            data: [0; 8],
        }
    }

    /// The payload (`len` bytes).
    pub fn payload(&self) -> &[u8] {
        let n = usize::from(self.len.min(8));
        self.data.get(..n).unwrap_or(&self.data)
    }
}

/// A received frame with its receive time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RxFrame {
    /// The frame.
    pub frame: CanFrame,
    /// When it was received: the driver's timestamp where it has one
    /// (`CDRV_TIMESTAMP`), otherwise the tick count when the stack took it.
    pub time: Ticks,
}

/// Transmit buffer selection. SRDO, GFC and NMT frames use the high
/// priority buffer (`kMtbHighPrio`), everything else the low one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Priority {
    /// High priority buffer.
    High,
    /// Normal buffer.
    Low,
}

/// The error flags of [`CanPort::status`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PortStatus {
    /// At least one received frame was lost since the last call that can
    /// have been an SRDO or GFC frame (a buffer those identifiers use, or a
    /// loss the driver cannot place).
    pub rx_overrun: bool,
    /// Received frames were lost since the last call, all of them from a
    /// buffer that holds no SRDO or GFC identifier (the driver's low
    /// buffer while SRDO and GFC are received in the high one): a CAN
    /// overrun of the communication, not of the safety function.
    pub rx_overrun_other: bool,
    /// The controller is bus-off.
    pub bus_off: bool,
}

/// The CAN controller as the stack sees it.
pub trait CanPort {
    /// Queues a frame for transmission. `Err` carries the driver's code
    /// (for example `kCopCdrvTxBuffHighOverrun` when the buffer is full).
    fn send(&mut self, frame: &CanFrame, prio: Priority) -> CopResult;

    /// Takes the oldest received frame, if any.
    fn receive(&mut self) -> Option<RxFrame>;

    /// Reports (and clears) a receive overrun: at least one received frame
    /// was lost because the driver's buffer was full.
    fn take_rx_overrun(&mut self) -> bool {
        false
    }

    /// The controller's error flags, read once per cycle: the receive
    /// overrun of [`CanPort::take_rx_overrun`] (cleared) and whether the
    /// controller is bus-off (left as it is; the stack reacts when it is
    /// raised, 0x1029). The default reports no bus-off.
    fn status(&mut self) -> PortStatus {
        PortStatus {
            rx_overrun: self.take_rx_overrun(),
            ..PortStatus::default()
        }
    }

    /// Asks the driver to receive `id` (acceptance filter). Drivers without
    /// filters accept everything and ignore this.
    fn subscribe(&mut self, id: CanId, prio: Priority) -> CopResult {
        let _ = (id, prio);
        Ok(())
    }

    /// Withdraws a [`CanPort::subscribe`].
    fn unsubscribe(&mut self, id: CanId) -> CopResult {
        let _ = id;
        Ok(())
    }
}

/// The tick source (`TgtGetTickCount`).
pub trait Clock {
    /// The current tick count.
    fn now(&self) -> Ticks;
}

/// A port that records every frame sent and receives nothing (unit
/// tests of the services).
#[cfg(test)]
#[derive(Default)]
pub(crate) struct Recorder(pub(crate) Vec<CanFrame>);

#[cfg(test)]
impl CanPort for Recorder {
    fn send(&mut self, frame: &CanFrame, _: Priority) -> CopResult {
        self.0.push(*frame);
        Ok(())
    }
    fn receive(&mut self) -> Option<RxFrame> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_arithmetic_wraps() {
        let before = Ticks(u32::MAX - 5);
        let after = before.plus(10);
        assert_eq!(after, Ticks(4));
        assert_eq!(after.since(before), 10);
        assert!(after.is_after(before));
        assert!(!before.is_after(after));
        assert!(!after.is_after(after));
        assert_eq!(Ticks(0).plus_ms(25), Ticks(250));
    }

    #[test]
    fn can_id_ranges() {
        assert_eq!(CanId::std(0x7FF).map(CanId::id), Some(0x7FF));
        assert_eq!(CanId::std(0x800), None);
        let e = CanId::ext(0x1234_5678 & 0x1FFF_FFFF).unwrap_or(CanId::std_masked(0));
        assert!(e.is_extended());
        assert_eq!(CanId::from_cob_id(0x8000_0181).id(), 0x181);
    }

    #[test]
    fn frame_payload() {
        let f = CanFrame::new(CanId::std_masked(0x602), &[0x40, 0, 0x60, 1]);
        assert_eq!(f.len, 4);
        assert_eq!(f.payload(), &[0x40, 0, 0x60, 1]);
    }
}
