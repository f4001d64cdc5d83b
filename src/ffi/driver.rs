//! The SYS TEC CAN driver and target contract as the stack's port: the
//! application's existing `Cdrv*` functions and `TgtGetTickCount`.

use super::types::{cdrv_status, msg_type, tCanId, tCdrvInitParam, tCdrvMsg, tCopKernel, tTime};
use crate::error::{CopKernel, CopResult};
use crate::port::{CanFrame, CanId, CanPort, Clock, PortStatus, Priority, RxFrame, Ticks};

// The application's driver. In a multi-instance build every function takes
// the driver's instance pointer first (`MCO_DECL_INSTANCE_PTR_`,
// `MCO_DECL_PTR_INSTANCE_PTR_` for CdrvInit / CdrvAddInstance); the calls
// go through `cdrv!`, which passes the port's pointer where there is one.
unsafe extern "C" {
    fn CdrvInit(
        #[cfg(multi_instance)] ppInstance_p: *mut *mut core::ffi::c_void,
        pInitParam_p: *mut tCdrvInitParam,
    ) -> tCopKernel;
    #[cfg(multi_instance)]
    fn CdrvAddInstance(
        ppInstance_p: *mut *mut core::ffi::c_void,
        pInitParam_p: *mut tCdrvInitParam,
    ) -> tCopKernel;
    fn CdrvDeleteInstance(#[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void)
    -> tCopKernel;
    fn CdrvWriteMsg(
        #[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void,
        pCanMsg_p: *mut tCdrvMsg,
    ) -> tCopKernel;
    fn CdrvReadMsg(
        #[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void,
        ppCanMsg_p: *mut *mut tCdrvMsg,
    ) -> tCopKernel;
    fn CdrvReleaseMsg(
        #[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void,
        pCanMsg_p: *mut tCdrvMsg,
    ) -> tCopKernel;
    fn CdrvDefineCanId(
        #[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void,
        pCanMsg_p: *mut tCdrvMsg,
    ) -> tCopKernel;
    fn CdrvUndefineCanId(
        #[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void,
        pCanMsg_p: *mut tCdrvMsg,
    ) -> tCopKernel;
    fn CdrvGetStatus(
        #[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void,
        pStatus_p: *mut u16,
    ) -> tCopKernel;
    fn CdrvResetStatus(
        #[cfg(multi_instance)] pInstance_p: *mut core::ffi::c_void,
        Status_p: u16,
    ) -> tCopKernel;
    fn TgtGetTickCount() -> tTime;
}

/// Calls a driver function with the port's instance pointer first in a
/// multi-instance build: `cdrv!(port, CdrvWriteMsg(&mut m))`.
#[cfg(multi_instance)]
macro_rules! cdrv {
    ($port:expr, $f:ident($($a:expr),*)) => {
        $f($port.instance $(, $a)*)
    };
}
#[cfg(not(multi_instance))]
macro_rules! cdrv {
    ($port:expr, $f:ident($($a:expr),*)) => {{
        let _ = &$port;
        $f($($a),*)
    }};
}

fn result(code: tCopKernel) -> CopResult {
    if code == 0 { Ok(()) } else { Err(kernel(code)) }
}

/// Maps a driver return code to the enum (unknown codes become
/// `kCopCdrvInitError` so that no value is silently taken for success).
pub fn kernel(code: tCopKernel) -> CopKernel {
    use CopKernel::*;
    match code {
        0x10 => CdrvNoMsg,
        0x11 => CdrvMsgHigh,
        0x12 => CdrvMsgLow,
        0x13 => CdrvInitError,
        0x14 => CdrvNoFreeChannel,
        0x15 => CdrvTxBuffHighOverrun,
        0x16 => CdrvTxBuffLowOverrun,
        0x17 => CdrvIllegalBdi,
        0x18 => CdrvBusy,
        0x19 => CdrvInvalidDriverType,
        0x1A => CdrvDriverNotFound,
        0x1B => CdrvInvalidBaseAddress,
        0x1C => CdrvInvalidParam,
        0x1D => CdrvInvalidDevNumber,
        0x1E => CdrvDevAlreadyInUse,
        0x1F => CdrvHostOsError,
        _ => CdrvInitError,
    }
}

/// `CdrvInit` (`first`) or, in a multi-instance build, `CdrvAddInstance`:
/// the port onto the controller the parameters name.
pub fn init(param: &mut tCdrvInitParam, first: bool) -> Result<CdrvPort, CopKernel> {
    #[cfg(multi_instance)]
    {
        let mut instance: *mut core::ffi::c_void = core::ptr::null_mut();
        // SAFETY: calling the application's driver with a valid, initialised
        // parameter block and a place for its instance pointer, both living
        // for the duration of the call.
        let code = unsafe {
            if first {
                CdrvInit(&mut instance, param)
            } else {
                CdrvAddInstance(&mut instance, param)
            }
        };
        result(code).map(|()| CdrvPort { instance })
    }
    #[cfg(not(multi_instance))]
    {
        let _ = first;
        // SAFETY: calling the application's driver with a valid, initialised
        // parameter block that lives for the duration of the call.
        result(unsafe { CdrvInit(param) }).map(|()| CdrvPort::default())
    }
}

/// `CdrvDeleteInstance` of the port's controller.
pub fn delete_instance(port: &CdrvPort) -> CopResult {
    // SAFETY: plain call into the application's driver.
    result(unsafe { cdrv!(port, CdrvDeleteInstance()) })
}

fn to_msg(frame: &CanFrame, kind: u8) -> tCdrvMsg {
    let mut m = tCdrvMsg {
        m_CanId: frame.id.id() as tCanId,
        m_MsgType: kind,
        m_bSize: frame.len,
        m_bData: frame.data,
        ..tCdrvMsg::default()
    };
    if frame.rtr {
        m.m_MsgType |= msg_type::RTR;
    }
    if frame.id.is_extended() {
        m.m_MsgType |= msg_type::EXTEND;
    }
    m
}

/// Which losses the overrun bits of `CdrvGetStatus` report: (a frame that
/// can have been an SRDO or GFC frame, only other frames). SRDO and GFC
/// identifiers are defined with `kCdrvMsgHigh`, so with
/// `CDRV_USE_HIGHBUFF` an overrun of the low buffer loses other frames
/// only; the controller's own overrun (`kCdrvOverrun`) and, without a high
/// buffer, the low buffer's overrun may have lost one of them.
fn split_overrun(lost: u16) -> (bool, bool) {
    let safety_bits = if crate::config::CDRV_USE_HIGHBUFF {
        cdrv_status::OVERRUN | cdrv_status::RX_BUFF_HIGH_OVERRUN
    } else {
        cdrv_status::OVERRUN | cdrv_status::RX_BUFF_HIGH_OVERRUN | cdrv_status::RX_BUFF_LOW_OVERRUN
    };
    let safety = lost & safety_bits != 0;
    (
        safety,
        !safety && lost & cdrv_status::RX_BUFF_LOW_OVERRUN != 0,
    )
}

/// The stack's port onto the application's driver: in a multi-instance
/// build, the instance pointer of its controller.
#[derive(Clone, Copy, Debug)]
pub struct CdrvPort {
    /// What `CdrvInit` / `CdrvAddInstance` returned for the controller.
    #[cfg(multi_instance)]
    instance: *mut core::ffi::c_void,
}

impl Default for CdrvPort {
    /// A port of no controller (single-instance builds: the one driver).
    fn default() -> CdrvPort {
        CdrvPort {
            #[cfg(multi_instance)]
            instance: core::ptr::null_mut(),
        }
    }
}

impl CanPort for CdrvPort {
    fn send(&mut self, frame: &CanFrame, prio: Priority) -> CopResult {
        let mut m = to_msg(
            frame,
            match prio {
                Priority::High => msg_type::HIGH_PRIO,
                Priority::Low => 0,
            },
        );
        // SAFETY: `m` is a valid tCdrvMsg on our stack; the driver copies it.
        result(unsafe { cdrv!(self, CdrvWriteMsg(&mut m)) })
    }

    // Inlined into the stack's one receive loop.
    #[inline(always)]
    fn receive(&mut self) -> Option<RxFrame> {
        let mut p: *mut tCdrvMsg = core::ptr::null_mut();
        // SAFETY: the driver stores a pointer to one of its buffer entries
        // into `p` (or leaves it untouched and returns kCopCdrvNoMsg).
        let code = unsafe { cdrv!(self, CdrvReadMsg(&mut p)) };
        if (code != CopKernel::CdrvMsgHigh.code()
            && code != CopKernel::CdrvMsgLow.code()
            && code != 0)
            || p.is_null()
        {
            return None;
        }
        // SAFETY: on success `p` points to a driver buffer entry that stays
        // valid until CdrvReleaseMsg; we copy it before releasing.
        let m = unsafe { *p };
        // SAFETY: releases the entry obtained above, exactly once.
        unsafe { cdrv!(self, CdrvReleaseMsg(p)) };
        let id = if m.m_MsgType & msg_type::EXTEND != 0 {
            CanId::ext(u32::from(m.m_CanId)).unwrap_or(CanId::std_masked(0x7FF))
        } else {
            CanId::std_masked(m.m_CanId as u16)
        };
        let len = m.m_bSize.min(8);
        // The payload as one 8-byte word with the bytes at `len..` zeroed
        // (what `CanFrame::new` makes of the first `len` bytes), without a
        // copy of variable length.
        let keep = u64::MAX.checked_shr(64 - 8 * u32::from(len)).unwrap_or(0);
        let frame = CanFrame {
            id,
            rtr: m.m_MsgType & msg_type::RTR != 0,
            len,
            data: (u64::from_le_bytes(m.m_bData) & keep).to_le_bytes(),
        };
        #[cfg(cdrv_timestamp)]
        let time = Ticks(m.m_Time);
        #[cfg(not(cdrv_timestamp))]
        let time = TgtClock.now();
        Some(RxFrame { frame, time })
    }

    fn take_rx_overrun(&mut self) -> bool {
        self.status().rx_overrun
    }

    /// One `CdrvGetStatus` per cycle: the overrun bits are cleared with
    /// `CdrvResetStatus` once taken; kCdrvBusOff is only read, so that the
    /// application and the driver see it as before.
    #[inline(always)]
    fn status(&mut self) -> PortStatus {
        let mut status: u16 = 0;
        // SAFETY: `status` is a valid WORD for the driver to fill.
        if unsafe { cdrv!(self, CdrvGetStatus(&mut status)) } != 0 {
            return PortStatus::default();
        }
        let lost = status
            & (cdrv_status::OVERRUN
                | cdrv_status::RX_BUFF_HIGH_OVERRUN
                | cdrv_status::RX_BUFF_LOW_OVERRUN);
        let (safety, other) = if lost == 0 {
            (false, false)
        } else {
            // SAFETY: plain call; clears the bits we consumed.
            unsafe { cdrv!(self, CdrvResetStatus(lost)) };
            split_overrun(lost)
        };
        PortStatus {
            rx_overrun: safety,
            rx_overrun_other: other,
            bus_off: status & cdrv_status::BUS_OFF != 0,
        }
    }

    fn subscribe(&mut self, id: CanId, prio: Priority) -> CopResult {
        let frame = CanFrame::new(id, &[]);
        let mut m = to_msg(
            &frame,
            msg_type::RECV
                | match prio {
                    Priority::High => msg_type::HIGH_PRIO,
                    Priority::Low => 0,
                },
        );
        // SAFETY: valid message descriptor for the duration of the call.
        result(unsafe { cdrv!(self, CdrvDefineCanId(&mut m)) })
    }

    fn unsubscribe(&mut self, id: CanId) -> CopResult {
        let frame = CanFrame::new(id, &[]);
        let mut m = to_msg(&frame, msg_type::RECV);
        // SAFETY: valid message descriptor for the duration of the call.
        result(unsafe { cdrv!(self, CdrvUndefineCanId(&mut m)) })
    }
}

/// The application's tick counter.
#[derive(Clone, Copy, Debug, Default)]
pub struct TgtClock;

impl Clock for TgtClock {
    fn now(&self) -> Ticks {
        // SAFETY: plain call into the application's target code.
        Ticks(unsafe { TgtGetTickCount() })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Only a loss that can have hit an SRDO or GFC frame is one for the
    /// SRDO module (SAFETY_BEHAVIOUR.md section 5); a low-buffer overrun
    /// with a high buffer is a CAN overrun of the other communication.
    #[test]
    fn low_buffer_overrun_is_no_safety_loss_with_a_high_buffer() {
        use cdrv_status::*;
        assert_eq!(split_overrun(0), (false, false));
        assert_eq!(split_overrun(OVERRUN), (true, false));
        assert_eq!(split_overrun(RX_BUFF_HIGH_OVERRUN), (true, false));
        assert_eq!(
            split_overrun(RX_BUFF_LOW_OVERRUN),
            (
                !crate::config::CDRV_USE_HIGHBUFF,
                crate::config::CDRV_USE_HIGHBUFF
            )
        );
        assert_eq!(
            split_overrun(RX_BUFF_LOW_OVERRUN | RX_BUFF_HIGH_OVERRUN),
            (true, false)
        );
        assert_eq!(split_overrun(BUS_OFF), (false, false));
    }
}
