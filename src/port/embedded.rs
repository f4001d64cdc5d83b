//! Any [`embedded_can`] 0.4 driver as a [`CanPort`] (feature
//! `embedded-can`), and a [`Clock`] from a plain tick function.
//!
//! * [`NbPort`] wraps an [`embedded_can::nb::Can`]: the stack's `send`
//!   is `transmit`, its `receive` polls `receive`. A frame the controller
//!   pushed out of its mailbox for a higher-priority one (`transmit`
//!   returning `Ok(Some(frame))`) is kept and sent again first.
//! * [`BlockingPort`] wraps an [`embedded_can::blocking::Can`]: the stack's
//!   `send` is the blocking `transmit`. A blocking `receive` cannot be
//!   polled, so the application receives (from its receive task or
//!   interrupt, [`BlockingPort::driver_mut`]) and hands each frame over
//!   with [`BlockingPort::deliver`] into a queue of `N` frames.
//!
//! Errors become the stack's codes (`tCopKernel`): a full transmit mailbox
//! (`WouldBlock`, or [`ErrorKind::Overrun`] on transmit) is
//! `kCopCdrvTxBuffHighOverrun` / `kCopCdrvTxBuffLowOverrun` by the
//! frame's priority, as with the SYS TEC driver; a bus error on transmit
//! (bit, stuff, CRC, form, acknowledge) is `kCopCdrvBusy`; any other
//! driver error `kCopCdrvHostOsError`; a frame the driver's type cannot
//! hold `kCopCdrvInvalidParam`. On receive, [`ErrorKind::Overrun`] (and a
//! full [`BlockingPort`] queue) is the receive overrun the stack reads with
//! [`CanPort::status`]; other receive errors are counted
//! ([`NbPort::rx_errors`]) and the frame is not there.

use embedded_can::{ErrorKind, ExtendedId, Frame, Id, StandardId};

use crate::error::{CopKernel, CopResult};
use crate::port::{CanFrame, CanId, CanPort, Clock, Priority, RxFrame, Ticks};

/// The identifier of the stack for an [`embedded_can::Id`].
pub fn id_from_embedded(id: Id) -> CanId {
    match id {
        Id::Standard(s) => CanId::std_masked(s.as_raw()),
        // as_raw() of an ExtendedId is at most 0x1FFF_FFFF
        Id::Extended(e) => CanId::from_cob_id(e.as_raw() | CanId::EXTENDED),
    }
}

/// The [`embedded_can::Id`] of an identifier of the stack.
pub fn id_to_embedded(id: CanId) -> Option<Id> {
    if id.is_extended() {
        ExtendedId::new(id.id()).map(Id::Extended)
    } else {
        u16::try_from(id.id())
            .ok()
            .and_then(StandardId::new)
            .map(Id::Standard)
    }
}

/// The stack's frame for a driver's frame; `None` for a data length
/// beyond 8 (CAN FD).
pub fn frame_from_embedded<F: Frame>(f: &F) -> Option<CanFrame> {
    let id = id_from_embedded(f.id());
    let dlc = u8::try_from(f.dlc()).ok().filter(|d| *d <= 8)?;
    if f.is_remote_frame() {
        Some(CanFrame::remote(id, dlc))
    } else {
        let data = f.data();
        if data.len() > 8 {
            return None;
        }
        Some(CanFrame::new(id, data))
    }
}

/// The driver's frame for a frame of the stack; `None` when the driver's
/// type cannot hold it.
pub fn frame_to_embedded<F: Frame>(f: &CanFrame) -> Option<F> {
    let id = id_to_embedded(f.id)?;
    if f.rtr {
        F::new_remote(id, usize::from(f.len))
    } else {
        F::new(id, f.payload())
    }
}

/// The stack's code for a transmit error of the driver.
pub fn tx_error(kind: ErrorKind, prio: Priority) -> CopKernel {
    match kind {
        ErrorKind::Overrun => full(prio),
        ErrorKind::Bit
        | ErrorKind::Stuff
        | ErrorKind::Crc
        | ErrorKind::Form
        | ErrorKind::Acknowledge => CopKernel::CdrvBusy,
        _ => CopKernel::CdrvHostOsError,
    }
}

/// A full transmit buffer of the priority.
fn full(prio: Priority) -> CopKernel {
    match prio {
        Priority::High => CopKernel::CdrvTxBuffHighOverrun,
        Priority::Low => CopKernel::CdrvTxBuffLowOverrun,
    }
}

/// A classic CAN frame implementing [`embedded_can::Frame`] for code
/// without a HAL of its own: host programs, tests and examples that put
/// [`NbPort`] or [`BlockingPort`] over a simulated or scripted driver.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlainFrame {
    id: Id,
    remote: bool,
    dlc: usize,
    data: [u8; 8],
}

impl Frame for PlainFrame {
    fn new(id: impl Into<Id>, data: &[u8]) -> Option<Self> {
        let mut d = [0; 8];
        d.get_mut(..data.len())?.copy_from_slice(data);
        Some(PlainFrame {
            id: id.into(),
            remote: false,
            dlc: data.len(),
            data: d,
        })
    }
    fn new_remote(id: impl Into<Id>, dlc: usize) -> Option<Self> {
        (dlc <= 8).then(|| PlainFrame {
            id: id.into(),
            remote: true,
            dlc,
            data: [0; 8],
        })
    }
    fn is_extended(&self) -> bool {
        matches!(self.id, Id::Extended(_))
    }
    fn is_remote_frame(&self) -> bool {
        self.remote
    }
    fn id(&self) -> Id {
        self.id
    }
    fn dlc(&self) -> usize {
        self.dlc
    }
    fn data(&self) -> &[u8] {
        if self.remote {
            &[]
        } else {
            self.data.get(..self.dlc).unwrap_or(&[])
        }
    }
}

/// A [`Clock`] from a plain function returning a free-running counter:
/// 100 µs ticks ([`TickFn::ticks`]) or milliseconds ([`TickFn::millis`]).
/// The counter may wrap at 2^32; the stack's tick arithmetic is modular.
#[derive(Clone, Copy, Debug)]
pub struct TickFn<T> {
    read: T,
    per_tick: u32,
}

impl<T: Fn() -> u32> TickFn<T> {
    /// A clock whose function counts the stack's 100 µs ticks.
    pub const fn ticks(read: T) -> TickFn<T> {
        TickFn { read, per_tick: 1 }
    }

    /// A clock whose function counts milliseconds (the ticks are ten
    /// times the value, wrapping).
    pub const fn millis(read: T) -> TickFn<T> {
        TickFn {
            read,
            per_tick: crate::port::TICKS_PER_MS,
        }
    }
}

impl<T: Fn() -> u32> Clock for TickFn<T> {
    fn now(&self) -> Ticks {
        Ticks((self.read)().wrapping_mul(self.per_tick))
    }
}

/// An [`embedded_can::nb::Can`] driver with a [`Clock`] for the receive
/// times: a [`CanPort`].
#[derive(Debug)]
pub struct NbPort<C: embedded_can::nb::Can, K> {
    can: C,
    clock: K,
    displaced: Option<(C::Frame, Priority)>,
    rx_overrun: bool,
    rx_errors: u32,
}

impl<C: embedded_can::nb::Can, K: Clock> NbPort<C, K> {
    /// Wraps a driver; `clock` stamps the received frames.
    pub fn new(can: C, clock: K) -> Self {
        NbPort {
            can,
            clock,
            displaced: None,
            rx_overrun: false,
            rx_errors: 0,
        }
    }

    /// The driver.
    pub fn driver_mut(&mut self) -> &mut C {
        &mut self.can
    }

    /// The driver, given back.
    pub fn into_inner(self) -> C {
        self.can
    }

    /// Receive errors other than an overrun since the port was made.
    pub fn rx_errors(&self) -> u32 {
        self.rx_errors
    }

    /// A frame of the driver's type, or the code of a frame it cannot hold.
    fn convert(frame: &CanFrame) -> CopResult<C::Frame> {
        frame_to_embedded(frame).ok_or(CopKernel::CdrvInvalidParam)
    }

    /// Sends a displaced frame again; `Err` when the mailbox is still full.
    fn resend_displaced(&mut self) -> CopResult {
        let Some((frame, prio)) = self.displaced.take() else {
            return Ok(());
        };
        match self.can.transmit(&frame) {
            Ok(again) => {
                self.displaced = again.map(|f| (f, prio));
                Ok(())
            }
            Err(nb::Error::WouldBlock) => {
                self.displaced = Some((frame, prio));
                Err(full(prio))
            }
            Err(nb::Error::Other(e)) => Err(tx_error(embedded_can::Error::kind(&e), prio)),
        }
    }
}

impl<C: embedded_can::nb::Can, K: Clock> CanPort for NbPort<C, K> {
    fn send(&mut self, frame: &CanFrame, prio: Priority) -> CopResult {
        // A frame pushed out earlier goes first (the order of the bus).
        self.resend_displaced()?;
        let f = Self::convert(frame)?;
        match self.can.transmit(&f) {
            Ok(None) => Ok(()),
            Ok(Some(pushed_out)) => {
                self.displaced = Some((pushed_out, prio));
                Ok(())
            }
            Err(nb::Error::WouldBlock) => Err(full(prio)),
            Err(nb::Error::Other(e)) => Err(tx_error(embedded_can::Error::kind(&e), prio)),
        }
    }

    fn receive(&mut self) -> Option<RxFrame> {
        // a displaced frame is retried once per receive poll (each cycle)
        let _ = self.resend_displaced();
        loop {
            match self.can.receive() {
                Ok(f) => {
                    if let Some(frame) = frame_from_embedded(&f) {
                        return Some(RxFrame {
                            frame,
                            time: self.clock.now(),
                        });
                    }
                    // a CAN FD frame: not for this stack
                }
                Err(nb::Error::WouldBlock) => return None,
                Err(nb::Error::Other(e)) => {
                    if embedded_can::Error::kind(&e) == ErrorKind::Overrun {
                        self.rx_overrun = true;
                    } else {
                        self.rx_errors = self.rx_errors.wrapping_add(1);
                    }
                    return None;
                }
            }
        }
    }

    fn take_rx_overrun(&mut self) -> bool {
        core::mem::take(&mut self.rx_overrun)
    }
}

/// An [`embedded_can::blocking::Can`] driver as a [`CanPort`]: blocking
/// transmit, received frames handed over by the application
/// ([`BlockingPort::deliver`]) into a queue of `N` frames.
#[derive(Debug)]
pub struct BlockingPort<C, K, const N: usize> {
    can: C,
    clock: K,
    queue: [Option<RxFrame>; N],
    head: usize,
    len: usize,
    rx_overrun: bool,
}

impl<C: embedded_can::blocking::Can, K: Clock, const N: usize> BlockingPort<C, K, N> {
    /// Wraps a driver; `clock` stamps the frames handed over.
    pub fn new(can: C, clock: K) -> Self {
        BlockingPort {
            can,
            clock,
            queue: [None; N],
            head: 0,
            len: 0,
            rx_overrun: false,
        }
    }

    /// The driver (its `receive` is the application's to call).
    pub fn driver_mut(&mut self) -> &mut C {
        &mut self.can
    }

    /// Hands a received frame to the stack, stamped with the clock. A full
    /// queue loses the frame and reports a receive overrun; a frame the
    /// stack cannot hold (CAN FD) is ignored. `true` when queued.
    pub fn deliver(&mut self, f: &C::Frame) -> bool {
        let Some(frame) = frame_from_embedded(f) else {
            return false;
        };
        if self.len >= N {
            self.rx_overrun = true;
            return false;
        }
        let at = (self.head + self.len) % N;
        match self.queue.get_mut(at) {
            Some(slot) => {
                *slot = Some(RxFrame {
                    frame,
                    time: self.clock.now(),
                });
                self.len += 1;
                true
            }
            None => false,
        }
    }

    /// Receives one frame with the driver's blocking `receive` and hands it
    /// over ([`BlockingPort::deliver`]). A driver's overrun raises the
    /// receive overrun (`Ok(false)`); other driver errors are
    /// `kCopCdrvHostOsError`.
    pub fn receive_blocking(&mut self) -> CopResult<bool> {
        match self.can.receive() {
            Ok(f) => Ok(self.deliver(&f)),
            Err(e) if embedded_can::Error::kind(&e) == ErrorKind::Overrun => {
                self.rx_overrun = true;
                Ok(false)
            }
            Err(_) => Err(CopKernel::CdrvHostOsError),
        }
    }
}

impl<C: embedded_can::blocking::Can, K: Clock, const N: usize> CanPort for BlockingPort<C, K, N> {
    fn send(&mut self, frame: &CanFrame, prio: Priority) -> CopResult {
        let f: C::Frame = frame_to_embedded(frame).ok_or(CopKernel::CdrvInvalidParam)?;
        self.can
            .transmit(&f)
            .map_err(|e| tx_error(embedded_can::Error::kind(&e), prio))
    }

    fn receive(&mut self) -> Option<RxFrame> {
        if self.len == 0 || N == 0 {
            return None;
        }
        let taken = self.queue.get_mut(self.head).and_then(Option::take);
        self.head = (self.head + 1) % N;
        self.len -= 1;
        taken
    }

    fn take_rx_overrun(&mut self) -> bool {
        core::mem::take(&mut self.rx_overrun)
    }
}

#[cfg(test)]
mod tests;
