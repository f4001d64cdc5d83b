//! Master-side C API: NMT master (`CcmInitNmtm`, `CcmSendNmtCommand`,
//! node guarding), heartbeat consumer (`CcmInitHbc`, ...) and emergency
//! consumer (`CcmInitEmcc`, `CcmInitEmccEx`, `CcmEmccDefineProducerTab`).
//!
//! Conventions as in [`super::ccm`]: `tCopKernel` results, pointers checked
//! first, kCopIllegalInstance before `CcmInitCANopen`.

use super::driver::TgtClock;
use super::global::{self, Instance, code};
use super::instance;
use super::ptr::{self, c_try};
use super::types::*;
use crate::error::CopKernel;
use crate::port::Clock;
use crate::wire::nmt::NmtCs;

pub use super::tables::AppTables;

/// [`global::with`] after the application's tables were read again.
fn with_tables<R>(f: impl FnOnce(&mut Instance) -> R) -> Result<R, CopKernel> {
    global::with(|i| {
        i.tables.sync(&mut i.stack, &mut i.port);
        f(i)
    })
}

/// `CcmInitEmcc`: enables the emergency consumer without an application
/// callback (any registered by `CcmInitEmccEx` is dropped): emergencies of
/// the listed producers are received and not reported. Returns
/// kCopSuccessful (kCopIllegalInstance before `CcmInitCANopen`).
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitEmcc(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run(|i| {
        i.stack.init_emcc();
        i.callbacks.emcc = None;
    })
}

/// `CcmInitEmccEx`: enables the emergency consumer; every valid emergency
/// (DLC 8) of a producer listed with `CcmEmccDefineProducerTab` is reported
/// from inside `CcmProcess` as `pfnCallback_p(node-ID, tEmcParam*)`, in the
/// order received, in PRE-OPERATIONAL and OPERATIONAL. Returns
/// kCopSuccessful (kCopIllegalInstance before `CcmInitCANopen`).
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitEmccEx(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pfnCallback_p: tAppEmccEventCallback,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run(|i| {
        i.stack.init_emcc();
        i.callbacks.emcc = pfnCallback_p;
    })
}

/// `CcmEmccDefineProducerTab`: the producers (node-IDs) whose emergencies
/// are received on COB-ID 0x80 + node-ID; replaces the previous table (a
/// refused table keeps it). Entries 0 are unused and skipped. kCopInvalidParam (NULL with a count),
/// kCopEmccNoFreeProducerEntry (more than `EMCC_MAX_CONSUMER`),
/// kCopEmccNodeIdInvalid (not 1..127, or this node), kCopEmccNodeIdExist
/// (a node twice), or the driver's code from `CdrvDefineCanId`.
///
/// # Safety
/// `pbProducerTab_p` must be valid for `bNumOfProducer_p` bytes and stay
/// valid until the next call or `CcmShutDownCANopen`: the table is read
/// again when the application changes it (README "Tables with free
/// slots").
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmEmccDefineProducerTab(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pbProducerTab_p: *const BYTE,
    bNumOfProducer_p: BYTE,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (bNumOfProducer_p entries).
    let nodes =
        c_try!(unsafe { ptr::slice_or_empty(pbProducerTab_p, usize::from(bNumOfProducer_p)) });
    code(global::with(|i| {
        let Instance {
            stack,
            port,
            tables,
            ..
        } = i;
        stack.define_emcc_producers(port, nodes)?;
        tables.producers = pbProducerTab_p;
        tables.producer_count = bNumOfProducer_p;
        Ok(())
    }))
}

/// `CcmInitNmtm`: enables the NMT master (boot-up detection, guarding).
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitNmtm(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run(|i| {
        i.stack.nmtm_mut().enable();
    })
}

/// `CcmInitNmtmEx`: as `CcmInitNmtm`, with a callback for boot-up and
/// guarding events (`kNmtErrCtrlEvBootupReceived`, `kNmtErrCtrlEvLg*`).
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitNmtmEx(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pfnCallback_p: tAppNmtmEventCallback,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run(|i| {
        i.stack.nmtm_mut().enable();
        i.callbacks.nmtm = pfnCallback_p;
    })
}

/// `CcmDefineSlaveTab`: the slaves the master manages; entries 0 are
/// unused and skipped. kCopInvalidParam (NULL with n > 0), kCopNmtmNoFreeSlaveEntry,
/// kCopNmtmInvalidSlaveNodeId, kCopNmtmSlaveNodeExist.
///
/// # Safety
/// `pbSlaveTab_p` must be valid for `bNumOfSlaves_p` bytes and stay valid
/// until the next call or `CcmShutDownCANopen`: the table is read again
/// when the application changes it (README "Tables with free slots").
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmDefineSlaveTab(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pbSlaveTab_p: *const BYTE,
    bNumOfSlaves_p: BYTE,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (bNumOfSlaves_p entries).
    let nodes = c_try!(unsafe { ptr::slice_or_empty(pbSlaveTab_p, usize::from(bNumOfSlaves_p)) });
    code(global::with(|i| {
        i.stack.nmtm_mut().define_slaves(nodes)?;
        i.tables.slaves = pbSlaveTab_p;
        i.tables.slave_count = bNumOfSlaves_p;
        Ok(())
    }))
}

/// `CcmSendNmtCommand`: NMT module control to a node (0 = all nodes; the
/// command applies to this node too when it is addressed).
/// kCopNmtUnknownCommand, kCopNmtmInvalidSlaveNodeId, kCopNmtStateError
/// before `CcmConnectToNet`, or the driver's code.
#[unsafe(no_mangle)]
pub extern "C" fn CcmSendNmtCommand(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    bNodeId_p: BYTE,
    NmtCommand_p: tNmtCommand,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let cs = match NmtCommand_p {
        0x0001 => NmtCs::Start,
        0x0002 => NmtCs::Stop,
        0x0080 | 0x0180 => NmtCs::EnterPreOperational,
        0x0081 => NmtCs::ResetNode,
        0x0082 => NmtCs::ResetCommunication,
        _ => return CopKernel::NmtUnknownCommand.code(),
    };
    let r = global::with(|i| i.stack.send_nmt_command(&mut i.port, bNodeId_p, cs));
    global::pump(|i, now| i.stack.drain(&mut i.port, now));
    code(r)
}

/// `CcmBootNetwork`: "start remote node" to all nodes.
#[unsafe(no_mangle)]
pub extern "C" fn CcmBootNetwork(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    instance::here!(CcmSendNmtCommand, 0, 0x0001)
}

/// `CcmTriggerNodeGuard`: sends one guard request to a slave now.
#[unsafe(no_mangle)]
pub extern "C" fn CcmTriggerNodeGuard(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    bNodeId_p: BYTE,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let now = TgtClock.now();
    code(with_tables(|i| {
        let Instance { stack, port, .. } = i;
        stack.nmtm_mut().trigger_guard(port, bNodeId_p, now)
    }))
}

/// `CcmConfigLgm`: guard time and life time factor of a slave (time 0
/// stops guarding). kCopInvalidParam for NULL, kCopNmtmSlaveEntryNotExist.
///
/// # Safety
/// `pSlaveParam_p` must be NULL or point to a valid `tNmtmSlaveParam`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmConfigLgm(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    bNodeId_p: BYTE,
    pSlaveParam_p: *const tNmtmSlaveParam,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or a valid tNmtmSlaveParam).
    let p = c_try!(unsafe { ptr::read(pSlaveParam_p) });
    let now = TgtClock.now();
    code(with_tables(|i| {
        i.stack.nmtm_mut().configure_guarding(
            bNodeId_p,
            p.m_wLifeguardTime,
            p.m_bLifeguardFactor,
            now,
        )
    }))
}

/// `CcmNmtmGetSlaveInfo`: what the master knows about a slave: the
/// `kNmtm*` state bits, the guarding answers missed in a row and the NMT
/// state the slave last reported. Reading clears `kNmtmUpdate`. Codes:
/// kCopInvalidParam (NULL), kCopNmtmInvalidSlaveNodeId,
/// kCopNmtmSlaveEntryNotExist (not in the slave table).
///
/// # Safety
/// `pSlaveInfo_p` must be NULL or valid for writing a `tNmtmSlaveInfo`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmNmtmGetSlaveInfo(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    bNodeId_p: BYTE,
    pSlaveInfo_p: *mut tNmtmSlaveInfo,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or a writable tNmtmSlaveInfo).
    let out = c_try!(unsafe { ptr::out(pSlaveInfo_p) });
    out.give(with_tables(|i| {
        let info = i.stack.nmtm_mut().read_slave_info(bNodeId_p)?;
        Ok(tNmtmSlaveInfo {
            m_bSlaveState: info.flags,
            m_bLostMsgCount: info.misses,
            m_bSlaveNodeState: info.state,
        })
    }))
}

/// `CcmInitHbc`: the heartbeat consumer runs from object 0x1016 (always
/// active in this library); kept for source compatibility.
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitHbc(#[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    code(global::with(|_| Ok(())))
}

/// `CcmInitHbcEx`: registers the heartbeat consumer callback
/// (`kNmtErrCtrlEvHbcConnected`, `...ConnectionLost`, `...NodeStateChanged`).
#[unsafe(no_mangle)]
pub extern "C" fn CcmInitHbcEx(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    fpHbcEventCallback_p: tAppHbcEventCallback,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    global::run(|i| {
        i.callbacks.hbc = fpHbcEventCallback_p;
    })
}

/// `CcmHbcDefineProducerTab`: supervises producers by writing their entries
/// into 0x1016 (`bSubindex_p`, 1-based) — through the dictionary, so the
/// object and the consumer agree. kCopInvalidParam (NULL), kCopHbcNoFreeEntry
/// (subindex 0 or beyond 0x1016), kCopHbcEntryAlreadyExist (a node twice).
///
/// # Safety
/// `pbProducerTab_p` must be valid for `bNumOfProducer_p` entries.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmHbcDefineProducerTab(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pbProducerTab_p: *const tHbcProdParam,
    bNumOfProducer_p: BYTE,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (bNumOfProducer_p entries).
    let tab =
        c_try!(unsafe { ptr::slice_or_empty(pbProducerTab_p, usize::from(bNumOfProducer_p)) });
    for (k, p) in tab.iter().enumerate() {
        if tab
            .iter()
            .take(k)
            .any(|q| q.bProducerNodeId_p == p.bProducerNodeId_p)
        {
            return CopKernel::HbcEntryAlreadyExist.code();
        }
    }
    let now = TgtClock.now();
    code(global::with(|i| {
        for p in tab {
            if p.bSubindex_p == 0 {
                return Err(CopKernel::HbcNoFreeEntry);
            }
            let v = (u32::from(p.bProducerNodeId_p) << 16) | u32::from(p.wHeartbeatTime_p);
            i.stack
                .write_object(
                    crate::heartbeat::CONSUMER_TIME_INDEX,
                    p.bSubindex_p,
                    crate::od::ByteOrder::Wire,
                    &v.to_le_bytes(),
                    now,
                )
                .map_err(|e| match e.kernel {
                    CopKernel::ObdIndexNotExist | CopKernel::ObdSubindexNotExist => {
                        CopKernel::HbcNoFreeEntry
                    }
                    k => k,
                })?;
        }
        Ok(())
    }))
}

/// `CcmHbcGetNodeState`: the last NMT state a supervised node reported.
/// kCopInvalidParam (NULL), kCopHbcEntryNotExist (node not supervised or
/// not heard yet).
///
/// # Safety
/// `pNodeState_p` must be NULL or valid for writing one byte.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmHbcGetNodeState(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    bNodeId_p: BYTE,
    pNodeState_p: *mut BYTE,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or one writable byte).
    let out = c_try!(unsafe { ptr::out(pNodeState_p) });
    out.give(global::with(|i| {
        i.stack
            .hbc()
            .node_state(bNodeId_p)
            .ok_or(CopKernel::HbcEntryNotExist)
    }))
}

/// `CcmSdocDefineClientTab`: defines SDO client channels. Per entry the
/// valid flags select the fields taken (kSdocValidFlagRxCanId 0x01,
/// TxCanId 0x02, ServerNodeId 0x04, TimeOut 0x08); a node-ID without
/// COB-IDs gives the predefined connection set (0x600 / 0x580 + node-ID).
/// kCopInvalidParam (NULL), kCopSdocClientNotExist (index outside
/// 0x1280.. + `SDO_MAX_CLIENT_IN_OBD`), kCopSdocInvalidParam, kCopSdocBusy.
///
/// # Safety
/// `pClientTab_p` must be valid for `bNumOfClients_p` entries.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmSdocDefineClientTab(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pClientTab_p: *const tSdocParam,
    bNumOfClients_p: BYTE,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (bNumOfClients_p entries).
    let tab = c_try!(unsafe { ptr::slice_or_empty(pClientTab_p, usize::from(bNumOfClients_p)) });
    code(global::with(|i| {
        for p in tab {
            let mut cp = i.stack.sdoc().param(p.m_wClientIndex).unwrap_or_default();
            if cp == crate::sdo::client::ClientParam::default() {
                cp.tx_cob = 0x8000_0000;
                cp.rx_cob = 0x8000_0000;
            }
            if p.m_bValidFlags & 0x04 != 0 {
                cp.server_node = p.m_bServerNodeId;
                if p.m_bValidFlags & 0x03 == 0 && (1..=127).contains(&p.m_bServerNodeId) {
                    cp.tx_cob = 0x600 + u32::from(p.m_bServerNodeId);
                    cp.rx_cob = 0x580 + u32::from(p.m_bServerNodeId);
                }
            }
            if p.m_bValidFlags & 0x01 != 0 {
                cp.rx_cob = p.m_dwRxCanId;
            }
            if p.m_bValidFlags & 0x02 != 0 {
                cp.tx_cob = p.m_dwTxCanId;
            }
            if p.m_bValidFlags & 0x08 != 0 {
                cp.timeout_ticks = p.m_TimeOut;
            }
            let Instance { stack, port, .. } = i;
            stack.define_sdo_client(port, p.m_wClientIndex, cp)?;
            // Where the dictionary has the client object, it shows the
            // channel as defined (CiA 301: 0x1280+n holds the parameters in
            // use).
            let od = stack.od();
            if od.find_entry(p.m_wClientIndex).is_some() {
                let _ = od.poke_uint(p.m_wClientIndex, 1, u64::from(cp.tx_cob));
                let _ = od.poke_uint(p.m_wClientIndex, 2, u64::from(cp.rx_cob));
                let _ = od.poke_uint(p.m_wClientIndex, 3, u64::from(cp.server_node));
            }
        }
        Ok(())
    }))
}

/// `CcmSdocStartTransfer`: starts an upload (kSdocTypeSegUp), a download
/// (kSdocTypeSegDown; expedited when ≤ 4 bytes), a block download
/// (kSdocTypeBlockDown) or a block upload (kSdocTypeBlockUp; a server that
/// answers with the SDO upload protocol instead is followed) on a client
/// channel; block transfers use the CRC when the server supports it.
/// The buffer `m_pData` is used directly until the transfer ends and an
/// upload never writes more than `m_DataLen` bytes. kCopInvalidParam (NULL),
/// kCopSdocInvalidParam (unknown type, bad sizes),
/// kCopSdocClientNotExist, kCopSdocBusy, kCopNmtStateError (not connected
/// or STOPPED), or the driver's code.
///
/// # Safety
/// `pSdoTransParam_p` must be NULL or valid; `m_pData` must stay valid for
/// `m_DataLen` bytes until the transfer has ended.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmSdocStartTransfer(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    pSdoTransParam_p: *const tSdocTransferParam,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or a valid tSdocTransferParam).
    let p = c_try!(unsafe { ptr::read(pSdoTransParam_p) });
    let dir = match p.m_SdocType {
        0 => crate::sdo::client::Direction::Download,
        1 => crate::sdo::client::Direction::Upload,
        2 => crate::sdo::client::Direction::BlockDownload,
        3 => crate::sdo::client::Direction::BlockUpload,
        _ => return CopKernel::SdocInvalidParam.code(),
    };
    let len = obd_size_len(p.m_DataLen);
    // SAFETY: the caller keeps the buffer valid until the transfer ends;
    // the stack drops this view when it does (finish, abort, reset).
    let buf = c_try!(unsafe { ptr::lent_bytes(p.m_pData, len) });
    let now = TgtClock.now();
    let mux = crate::wire::sdo::Multiplexer::new(p.m_wObjIndex, p.m_bObjSubIndex);
    code(global::with(|i| {
        let Instance {
            stack,
            port,
            callbacks,
            ..
        } = i;
        stack.sdo_client_start(port, now, p.m_wClientIndex, dir, mux, buf, len, p.m_TimeOut)?;
        let slot = usize::from(
            p.m_wClientIndex
                .wrapping_sub(crate::sdo::client::CLIENT_BASE_INDEX),
        );
        if let Some(c) = callbacks.sdoc.get_mut(slot) {
            *c = p.m_pfnCbFinished;
        }
        Ok(())
    }))
}

/// `CcmSdocAbort`: aborts a running transfer and tells the server.
/// kCopSdocClientNotExist, kCopSdocTransferError (no transfer running).
#[unsafe(no_mangle)]
pub extern "C" fn CcmSdocAbort(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wClientIndex_p: WORD,
    dwAbortCode_p: DWORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    let r = global::with(|i| {
        let Instance { stack, port, .. } = i;
        stack.sdo_client_abort(port, wClientIndex_p, dwAbortCode_p)
    });
    global::pump(|i, now| i.stack.drain(&mut i.port, now));
    code(r)
}

/// `CcmSdocGetState`: state of a client channel and the abort code of its
/// last transfer (0 unless aborted). kCopInvalidParam (NULL),
/// kCopSdocClientNotExist.
///
/// # Safety
/// The pointers must be NULL or valid for writing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn CcmSdocGetState(
    #[cfg(multi_instance)] InstanceHandle: tCopInstanceHdl,
    wClientIndex_p: WORD,
    pSdocState_p: *mut tSdocState,
    pdwAbortCode_p: *mut DWORD,
) -> tCopKernel {
    instance::ccm_enter!(InstanceHandle);
    // SAFETY: the caller's contract (NULL or writable).
    let state = c_try!(unsafe { ptr::out(pSdocState_p) });
    // SAFETY: as above.
    let abort_code = c_try!(unsafe { ptr::out(pdwAbortCode_p) });
    match global::with(|i| i.stack.sdoc().state(wClientIndex_p)) {
        Ok(Ok((st, abort))) => {
            state.set(st as u32);
            abort_code.set(abort);
            0
        }
        Ok(Err(e)) | Err(e) => e.code(),
    }
}

/// `SdocGetTransmittedBytes`: bytes moved by the channel's last finished
/// transfer (the length of an upload). kCopInvalidParam (NULL),
/// kCopSdocClientNotExist.
///
/// # Safety
/// `pdwBytes_p` must be NULL or valid for writing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn SdocGetTransmittedBytes(
    #[cfg(multi_instance)] pInstance: tCopPtrInstance,
    wClientIndex_p: WORD,
    pdwBytes_p: *mut DWORD,
) -> tCopKernel {
    instance::mco_enter!(pInstance);
    // SAFETY: the caller's contract (NULL or writable).
    let out = c_try!(unsafe { ptr::out(pdwBytes_p) });
    out.give(global::with(|i| i.stack.sdoc().transferred(wClientIndex_p)))
}
