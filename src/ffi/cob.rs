//! The COB view (`CcmCobGetParam`, SYS TEC `cob.h` / `ccmmain.h`).
//!
//! The library keeps no COB tables: frames go through the protocol
//! modules. The view it gives an application numbers the PDOs: receive
//! handle `n` (`kCobHdlRxTable | n`) is the RPDO at 0x1400+n, transmit
//! handle `kCobHdlTxTable | n` the TPDO at 0x1800+n. Other communication
//! objects (NMT, SDO, EMCY, heartbeat, SRDO) have no handle.

use super::global;
use super::instance;
use super::ptr::{self, c_try};
#[cfg(multi_instance)]
use super::types::tCopInstanceHdl;
use super::types::{COB_HDL_TX_TABLE, msg_type, tCanId, tCobParam, tCopKernel};
use crate::error::CopKernel;
use crate::pdo::Direction;

/// `CcmCobGetParam`: identifier, type and frame length of the communication
/// object that `pCobParam_p->m_CobHdl` selects (see the module
/// documentation for the handles). Writes `m_CobId`, `m_bCobType`
/// (`kCobTypRecv` / `kCobTypSend`), `m_bSize`, and NULL into
/// `m_fpCallback`, `m_pArg`, `m_pbData`, `m_pbRecvdSize`; `m_CobHdl` is
/// kept. Codes: kCopInvalidParam (NULL), kCopCobIllegalHdl (no PDO there,
/// or the PDO is not valid: nothing is written), kCopIllegalInstance.
///
/// # Safety
/// `pCobParam_p` must be NULL or valid for reading and writing a
/// `tCobParam`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmCobGetParam(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pCobParam_p: *mut tCobParam,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or a valid tCobParam).
    let out = c_try!(unsafe { ptr::out(pCobParam_p) });
    let mut p = out.get();
    let hdl = p.m_CobHdl;
    // kCobTypSend = kMsgTypSend = 0, kCobTypRecv = kMsgTypRecv (cob.h).
    let (dir, n, ty) = if hdl & COB_HDL_TX_TABLE != 0 {
        (Direction::Tx, hdl & !COB_HDL_TX_TABLE, 0)
    } else {
        (Direction::Rx, hdl, msg_type::RECV)
    };
    let r = global::with(|i| {
        i.stack
            .pdo()
            .cob_entry(dir, usize::from(n))
            .ok_or(CopKernel::CobIllegalHdl)
    });
    match r {
        Ok(Ok((id, len))) => {
            // tCanId holds the identifier: 11 bits in a WORD (CAN 2.0A) or
            // 29 bits in a DWORD (CAN 2.0B, the build that allows them).
            p.m_CobId = tCanId::try_from(id.id()).unwrap_or(tCanId::MAX);
            p.m_bCobType = ty;
            p.m_bSize = len;
            p.m_fpCallback = None;
            p.m_pArg = core::ptr::null_mut();
            p.m_pbData = core::ptr::null_mut();
            p.m_pbRecvdSize = core::ptr::null_mut();
            out.set(p);
            0
        }
        Ok(Err(e)) | Err(e) => e.code(),
    }
}
