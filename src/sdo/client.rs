//! SDO client (CiA 301 SDO protocols, client side): expedited, segmented
//! and block upload and download to remote SDO servers, one transfer per
//! client channel at a time, several channels (servers) in parallel.
//!
//! The caller's buffer is used directly, without a copy: a download reads
//! from it, an upload writes into it and never past its length. A reply
//! that does not fit the request aborts the transfer with the CiA 301 code
//! (wrong toggle 0x05030000, wrong command 0x05040001, wrong object
//! 0x08000000 general error), and every abort received from the server is
//! reported with its code. The transfer state and the abort code are what
//! `CcmSdocGetState` reports; the end of a transfer is also an
//! [`Event::SdocFinished`]. Frames with a data length other than 8 are not
//! SDO frames and are ignored.
//!
//! # Block transfer (`kSdocTypeBlockDown` / `kSdocTypeBlockUp`)
//! * Both directions offer the CRC; it is used when the server offers it
//!   too, and a wrong CRC of an upload aborts with 0x05040004.
//! * Block download: the client announces the size; the server sets the
//!   block size. Segments go out while the driver accepts them; the rest
//!   follows in the next cycle ([`SdoClient::poll`]). A confirmation with
//!   ackseq below the segments sent makes the client send again from
//!   ackseq + 1; one naming more than were sent aborts with 0x05040003, a
//!   block size outside 1..=127 with 0x05040002.
//! * Block upload: the client accepts [`SDO_BLOCKSIZE_UPLOAD`] segments per
//!   sub-block and sends the protocol switch threshold [`BLOCK_UPLOAD_PST`]
//!   (0: no switch invited). A server that answers with the SDO upload
//!   protocol (expedited or segmented) all the same is followed, and the
//!   transfer completes as that protocol: CiA 301 lets the server switch,
//!   and some servers always do. A value longer than the
//!   buffer aborts with 0x05040005 as in a segmented upload; the last
//!   segment is written only when the end frame says how many of its bytes
//!   are data, so no padding lands in the buffer. Sub-block confirmation
//!   and the handling of lost segments follow `super::block`.
//! * The timeout runs from the last frame received, and in a download also
//!   from the last segment of a sub-block sent.

use core::sync::atomic::{AtomicU8, Ordering};

use super::block::{BlockRx, BlockTx, valid_blksize};
use crate::config::SDO_BLOCKSIZE_UPLOAD;
use crate::error::{CopKernel, CopResult, SdoAbort};
use crate::event::{ActionQueue, Event};
use crate::od::ObjectDictionary;
use crate::port::{CanFrame, CanId, CanPort, Priority, Ticks};
use crate::wire::sdo::{
    BlockSegment, ClientFrame, EXPEDITED_MAX, Initiate, Multiplexer, SEGMENT_MAX, SegmentData,
    ServerFrame, SubBlockFrame, block_crc, frame_bytes,
};

/// First client parameter object.
pub const CLIENT_BASE_INDEX: u16 = 0x1280;
/// Capacity: `SDO_MAX_CLIENT_IN_OBD`.
pub const CAPACITY: usize = crate::config::SDO_MAX_CLIENT_IN_OBD;
/// Default transfer timeout in ticks (`SDOC_DEFAULT_TIMEOUT`, 0.5 s).
pub const DEFAULT_TIMEOUT_TICKS: u32 = 5000;
/// Protocol switch threshold the client sends in a block upload: 0, no
/// switch invited. The application asked for block transfer (with its
/// CRC); a server that switches anyway is followed.
pub const BLOCK_UPLOAD_PST: u8 = 0;

c_enum! {
    /// Transfer state (`tSdocState`).
    #[derive(Default)]
    pub enum SdocState: u8, fn from_u8(u8) {
        /// kSdocTransferNotActive.
        #[default]
        NotActive = 0,
        /// kSdocTransferRunning.
        Running = 1,
        /// kSdocTransferTxAborted: this client aborted (timeout, bad reply).
        TxAborted = 2,
        /// kSdocTransferRxAborted: the server aborted.
        RxAborted = 3,
        /// kSdocTransferFinished.
        Finished = 4,
    }
}

/// Protocol and direction of a transfer (`tSdocType`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// kSdocTypeSegDown: download (write to the server); expedited when
    /// ≤ 4 bytes.
    Download,
    /// kSdocTypeSegUp: upload (read from the server).
    Upload,
    /// kSdocTypeBlockDown: block download.
    BlockDownload,
    /// kSdocTypeBlockUp: block upload (the server may switch to the SDO
    /// upload protocol).
    BlockUpload,
}

/// A client channel's parameters (`tSdocParam`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClientParam {
    /// COB-ID client -> server (bit 31 = not valid).
    pub tx_cob: u32,
    /// COB-ID server -> client (bit 31 = not valid).
    pub rx_cob: u32,
    /// Node-ID of the server.
    pub server_node: u8,
    /// Timeout in ticks; 0 = [`DEFAULT_TIMEOUT_TICKS`].
    pub timeout_ticks: u32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    InitiateSent,
    SegmentSent,
    /// Block download: sub-blocks go out and are confirmed.
    BlockDown(BlockTx),
    /// Block download: end frame sent.
    BlockDownEnd,
    /// Block upload: sub-blocks arrive.
    BlockUp(BlockRx),
    /// Block upload: the last sub-block is confirmed, the end frame is next.
    BlockUpEnd(BlockRx),
}

#[derive(Clone, Copy, Debug)]
struct Transfer {
    dir: Direction,
    mux: Multiplexer,
    buf: &'static [AtomicU8],
    /// Download: bytes to send; upload: buffer capacity.
    len: usize,
    offset: usize,
    toggle: bool,
    phase: Phase,
    deadline: Ticks,
    timeout: u32,
    /// Upload: size announced by the server.
    announced: Option<u32>,
    /// Block transfer: both sides support the CRC.
    crc: bool,
    /// Block upload: CRC of the full segments received in order.
    crc_acc: u16,
    /// Block upload: the segment with c = 1, kept until the end frame says
    /// how many of its bytes are data.
    last_segment: [u8; SEGMENT_MAX],
    /// Time of the last frame received.
    last_rx: Ticks,
    /// A request the driver refused (a full transmit buffer), sent again
    /// by [`SdoClient::poll`] before anything else of the transfer.
    held: Option<CanFrame>,
}

#[derive(Clone, Copy, Debug, Default)]
struct Channel {
    defined: bool,
    param: ClientParam,
    transfer: Option<Transfer>,
    state: SdocState,
    abort: u32,
    transferred: u32,
}

/// The SDO client channels.
#[derive(Clone, Debug)]
pub struct SdoClient {
    channels: [Channel; CAPACITY],
}

crate::od::decl::default_is_new!(SdoClient);

fn cob_id(v: u32) -> Option<CanId> {
    if v & 0x8000_0000 != 0 || !super::usable_cob_id(v) {
        None
    } else {
        Some(CanId::from_cob_id(v))
    }
}

impl SdoClient {
    /// No channels defined.
    pub const fn new() -> Self {
        SdoClient {
            channels: [Channel {
                defined: false,
                param: ClientParam {
                    tx_cob: 0x8000_0000,
                    rx_cob: 0x8000_0000,
                    server_node: 0,
                    timeout_ticks: 0,
                },
                transfer: None,
                state: SdocState::NotActive,
                abort: 0,
                transferred: 0,
            }; CAPACITY],
        }
    }

    fn slot(index: u16) -> CopResult<usize> {
        let n = usize::from(index.wrapping_sub(CLIENT_BASE_INDEX));
        if index < CLIENT_BASE_INDEX || n >= CAPACITY {
            return Err(CopKernel::SdocClientNotExist);
        }
        Ok(n)
    }

    fn channel(&self, index: u16) -> CopResult<&Channel> {
        let c = self
            .channels
            .get(Self::slot(index)?)
            .ok_or(CopKernel::SdocClientNotExist)?;
        if c.defined {
            Ok(c)
        } else {
            Err(CopKernel::SdocClientNotExist)
        }
    }

    /// Loads channels from client objects 0x1280.. present in the
    /// dictionary (sub 1 COB-ID client->server, sub 2 server->client, sub 3
    /// server node-ID). Running transfers are dropped.
    pub fn reconfigure(&mut self, od: &ObjectDictionary) {
        for (n, c) in self.channels.iter_mut().enumerate() {
            let index = CLIENT_BASE_INDEX + n as u16;
            c.transfer = None;
            if od.find_entry(index).is_none() {
                continue;
            }
            let rd = |sub| {
                od.read_uint(index, sub)
                    .map(|v| v as u32)
                    .unwrap_or(0x8000_0000)
            };
            c.defined = true;
            c.param.tx_cob = rd(1);
            c.param.rx_cob = rd(2);
            c.param.server_node = od.read_uint(index, 3).map(|v| v as u8).unwrap_or(0);
        }
    }

    /// Defines or updates a channel (`CcmSdocDefineClientTab`). A transfer
    /// running on the channel ends first as [`SdoClient::abort`] ends it,
    /// with 0x08000000 (general error) on the old definition's COB-ID and
    /// `SdocFinished` queued: a master that gives up on a server before the
    /// client's timeout may define the channel again and start anew. An
    /// index outside 0x1280.. + capacity gives kCopSdocClientNotExist;
    /// COB-IDs above 11 bits (without bit 29) or identifiers of another
    /// service ([`super::usable_cob_id`]) kCopSdocInvalidParam, and then
    /// nothing changes, a running transfer included.
    pub fn define(
        &mut self,
        port: &mut impl CanPort,
        index: u16,
        p: ClientParam,
        q: &mut ActionQueue,
    ) -> CopResult {
        for cob in [p.tx_cob, p.rx_cob] {
            if cob & 0x8000_0000 == 0 && cob & 0x2000_0000 == 0 && cob > 0x7FF
                || !super::usable_cob_id(cob)
            {
                return Err(CopKernel::SdocInvalidParam);
            }
        }
        if p.server_node > 127 {
            return Err(CopKernel::SdocInvalidParam);
        }
        let c = self
            .channels
            .get_mut(Self::slot(index)?)
            .ok_or(CopKernel::SdocClientNotExist)?;
        if let Some(t) = c.transfer {
            finish_tx_abort(c, port, index, t.mux, SdoAbort::General.code(), q);
        }
        c.defined = true;
        c.param = p;
        Ok(())
    }

    /// The parameters of a channel.
    pub fn param(&self, index: u16) -> CopResult<ClientParam> {
        Ok(self.channel(index)?.param)
    }

    /// State and abort code of a channel (`CcmSdocGetState`).
    pub fn state(&self, index: u16) -> CopResult<(SdocState, u32)> {
        let c = self.channel(index)?;
        Ok((c.state, c.abort))
    }

    /// Bytes moved by the last transfer (`SdocGetTransmittedBytes`).
    pub fn transferred(&self, index: u16) -> CopResult<u32> {
        Ok(self.channel(index)?.transferred)
    }

    /// Response COB-IDs of channels with a running transfer.
    pub fn rx_ids(&self) -> impl Iterator<Item = CanId> + '_ {
        self.channels
            .iter()
            .filter(|c| c.defined)
            .filter_map(|c| cob_id(c.param.rx_cob))
    }

    /// Starts a transfer (`CcmSdocStartTransfer`). `buf` is read (download,
    /// `len` bytes) or written (upload, at most `len` bytes) until the
    /// transfer ends. Codes: kCopSdocClientNotExist, kCopSdocInvalidParam
    /// (COB-IDs not valid, `len` larger than the buffer, empty download),
    /// kCopSdocBusy (this channel, or another channel to the same server,
    /// is running a transfer: CiA 301 allows one per server), or the
    /// driver's code when the first frame cannot be sent.
    #[allow(clippy::too_many_arguments)]
    pub fn start(
        &mut self,
        port: &mut impl CanPort,
        now: Ticks,
        index: u16,
        dir: Direction,
        mux: Multiplexer,
        buf: &'static [AtomicU8],
        len: usize,
        timeout_ticks: u32,
    ) -> CopResult {
        let slot = Self::slot(index)?;
        let c = *self.channel(index)?;
        let (Some(tx), Some(_)) = (cob_id(c.param.tx_cob), cob_id(c.param.rx_cob)) else {
            return Err(CopKernel::SdocInvalidParam);
        };
        let download = matches!(dir, Direction::Download | Direction::BlockDownload);
        if len > buf.len() || (download && len == 0) {
            return Err(CopKernel::SdocInvalidParam);
        }
        let busy_same_server = self.channels.iter().any(|o| {
            o.transfer.is_some()
                && o.defined
                && (o.param.tx_cob == c.param.tx_cob || o.param.rx_cob == c.param.rx_cob)
        });
        if c.transfer.is_some() || busy_same_server {
            return Err(CopKernel::SdocBusy);
        }
        let timeout = match (timeout_ticks, c.param.timeout_ticks) {
            (0, 0) => DEFAULT_TIMEOUT_TICKS,
            (0, t) => t,
            (t, _) => t,
        };
        let mut t = Transfer {
            dir,
            mux,
            buf,
            len,
            offset: 0,
            toggle: false,
            phase: Phase::InitiateSent,
            deadline: now.plus(timeout),
            timeout,
            announced: None,
            crc: false,
            crc_acc: 0,
            last_segment: [0; SEGMENT_MAX],
            last_rx: now,
            held: None,
        };
        let frame = match dir {
            Direction::Upload => ClientFrame::InitiateUpload { mux },
            Direction::BlockDownload => ClientFrame::BlockDownloadInitiate {
                mux,
                crc: true,
                size: Some(u32::try_from(len).map_err(|_| CopKernel::SdocInvalidParam)?),
            },
            Direction::BlockUpload => ClientFrame::BlockUploadInitiate {
                mux,
                crc: true,
                blksize: SDO_BLOCKSIZE_UPLOAD,
                pst: BLOCK_UPLOAD_PST,
            },
            Direction::Download => {
                let payload = if len <= EXPEDITED_MAX {
                    let mut tmp = [0u8; EXPEDITED_MAX];
                    let chunk = tmp.get_mut(..len).ok_or(CopKernel::SdocInvalidParam)?;
                    load(buf, 0, chunk);
                    Initiate::expedited(chunk).ok_or(CopKernel::SdocInvalidParam)?
                } else {
                    Initiate::Segmented {
                        size: Some(len as u32),
                    }
                };
                ClientFrame::InitiateDownload { mux, payload }
            }
        };
        port.send(&frame.to_can(tx), Priority::Low)?;
        if let Some(ch) = self.channels.get_mut(slot) {
            if dir == Direction::Download && len <= EXPEDITED_MAX {
                t.offset = len;
            }
            ch.transfer = Some(t);
            ch.state = SdocState::Running;
            ch.abort = 0;
            ch.transferred = 0;
        }
        Ok(())
    }

    /// Aborts a running transfer with `code` (`CcmSdocAbort`); the server
    /// is told. kCopSdocClientNotExist; kCopSdocTransferError when no
    /// transfer runs.
    pub fn abort(
        &mut self,
        port: &mut impl CanPort,
        index: u16,
        code: u32,
        q: &mut ActionQueue,
    ) -> CopResult {
        let slot = Self::slot(index)?;
        self.channel(index)?;
        let Some(ch) = self.channels.get_mut(slot) else {
            return Err(CopKernel::SdocClientNotExist);
        };
        let Some(t) = ch.transfer else {
            return Err(CopKernel::SdocTransferError);
        };
        finish_tx_abort(ch, port, index, t.mux, code, q);
        Ok(())
    }

    /// A frame that may be a response for one of the channels. Returns
    /// `true` when a channel took it.
    pub fn on_frame(
        &mut self,
        port: &mut impl CanPort,
        frame: &CanFrame,
        now: Ticks,
        q: &mut ActionQueue,
    ) -> bool {
        for (n, ch) in self.channels.iter_mut().enumerate() {
            if !ch.defined || cob_id(ch.param.rx_cob) != Some(frame.id) {
                continue;
            }
            let index = CLIENT_BASE_INDEX + n as u16;
            let Some(mut t) = ch.transfer else {
                return true; // a late reply to a finished transfer
            };
            let Ok(bytes) = frame_bytes(frame) else {
                return true; // not an SDO frame (CiA 301: always 8 bytes)
            };
            let step = if let Phase::BlockUp(rx) = t.phase {
                // Inside a sub-block every frame is a segment (or an abort).
                match SubBlockFrame::decode(bytes) {
                    SubBlockFrame::Abort { code, .. } => {
                        finish_rx_abort(ch, index, code, q);
                        return true;
                    }
                    SubBlockFrame::Segment(seg) => block_upload_segment(&mut t, rx, &seg),
                }
            } else {
                let reply = match ServerFrame::decode(bytes) {
                    Ok(r) => r,
                    Err(_) => {
                        finish_tx_abort(ch, port, index, t.mux, SdoAbort::UnknownCommand.code(), q);
                        return true;
                    }
                };
                if let ServerFrame::Abort { code, .. } = reply {
                    finish_rx_abort(ch, index, code, q);
                    return true;
                }
                step(&mut t, reply)
            };
            t.deadline = now.plus(t.timeout);
            t.last_rx = now;
            apply(ch, port, index, t, step, now, q);
            return true;
        }
        false
    }

    /// True when [`SdoClient::poll`] would do nothing (no transfer runs).
    #[inline]
    pub fn at_rest(&self) -> bool {
        self.channels.iter().all(|c| c.transfer.is_none())
    }

    /// Timeout supervision: aborts (0x05040000) one timed-out transfer per
    /// call. Returns `true` when nothing timed out.
    pub fn poll(&mut self, port: &mut impl CanPort, now: Ticks, q: &mut ActionQueue) -> bool {
        for (n, ch) in self.channels.iter_mut().enumerate() {
            let index = CLIENT_BASE_INDEX + n as u16;
            if let Some(mut t) = ch.transfer {
                if now.is_after(t.deadline) {
                    finish_tx_abort(ch, port, index, t.mux, SdoAbort::Timeout.code(), q);
                    return false;
                }
                if let Some(f) = t.held {
                    if port.send(&f, Priority::Low).is_err() {
                        continue;
                    }
                    t.held = None;
                    ch.transfer = Some(t);
                }
            }
            send_block_segments(ch, port, now);
            confirm_stalled_sub_block(ch, port, index, now, q);
        }
        true
    }

    /// Drops every transfer without telling the servers (reset, shutdown).
    pub fn cancel_all(&mut self) {
        for c in self.channels.iter_mut() {
            if c.transfer.take().is_some() {
                c.state = SdocState::NotActive;
            }
        }
    }
}

fn finish_tx_abort(
    ch: &mut Channel,
    port: &mut impl CanPort,
    index: u16,
    mux: Multiplexer,
    code: u32,
    q: &mut ActionQueue,
) {
    if let Some(tx) = cob_id(ch.param.tx_cob) {
        // The abort is best effort: the transfer ends here either way.
        let _ = port.send(&ClientFrame::Abort { mux, code }.to_can(tx), Priority::Low);
    }
    end_aborted(ch, index, SdocState::TxAborted, code, q);
}

/// The server aborted the transfer.
fn finish_rx_abort(ch: &mut Channel, index: u16, code: u32, q: &mut ActionQueue) {
    end_aborted(ch, index, SdocState::RxAborted, code, q);
}

/// Ends the transfer in `state` (one of the aborted states) with `code`.
fn end_aborted(ch: &mut Channel, index: u16, state: SdocState, code: u32, q: &mut ActionQueue) {
    ch.transfer = None;
    ch.state = state;
    ch.abort = code;
    q.emit(Event::SdocFinished {
        client: index,
        state: state as u8,
        abort: code,
    });
}

/// Carries out the outcome of a received frame for transfer `t`.
fn apply(
    ch: &mut Channel,
    port: &mut impl CanPort,
    index: u16,
    t: Transfer,
    step: Step,
    now: Ticks,
    q: &mut ActionQueue,
) {
    let Some(tx) = cob_id(ch.param.tx_cob) else {
        return;
    };
    match step {
        Step::Send(f) => {
            let f = f.to_can(tx);
            let mut t = t;
            // A full transmit buffer delays the request to the next cycle;
            // the transfer's timeout still runs.
            if t.held.is_some() || port.send(&f, Priority::Low).is_err() {
                t.held = Some(f);
            }
            ch.transfer = Some(t);
        }
        Step::Wait => {
            ch.transfer = Some(t);
            send_block_segments(ch, port, now);
        }
        Step::Done(last) => {
            if let Some(f) = last {
                // The server has what it needs; its confirmation is best
                // effort (a lost one only makes the server time out).
                let _ = port.send(&f.to_can(tx), Priority::Low);
            }
            ch.transfer = None;
            ch.state = SdocState::Finished;
            ch.transferred = t.offset as u32;
            q.emit(Event::SdocFinished {
                client: index,
                state: SdocState::Finished as u8,
                abort: 0,
            });
        }
        Step::Abort(code) => finish_tx_abort(ch, port, index, t.mux, code, q),
    }
}

/// Hands the segments of a block download's sub-block to the driver until
/// it refuses one; the rest goes from [`SdoClient::poll`].
fn send_block_segments(ch: &mut Channel, port: &mut impl CanPort, now: Ticks) {
    let (Some(mut t), Some(id)) = (ch.transfer, cob_id(ch.param.tx_cob)) else {
        return;
    };
    let Phase::BlockDown(mut btx) = t.phase else {
        return;
    };
    if t.held.is_some() {
        return;
    }
    while let Some(p) = btx.next() {
        let mut tmp = [0u8; SEGMENT_MAX];
        let chunk = tmp
            .get_mut(..p.end.saturating_sub(p.start))
            .unwrap_or(&mut []);
        load(t.buf, p.start, chunk);
        let seg = BlockTx::segment(&p, chunk);
        if port.send(&seg.to_can(id), Priority::Low).is_err() {
            break;
        }
        btx.mark_sent(&p, chunk);
        if btx.next().is_none() {
            // The confirmation is due from here on.
            t.deadline = now.plus(t.timeout);
        }
    }
    t.phase = Phase::BlockDown(btx);
    ch.transfer = Some(t);
}

/// Confirms a block upload's sub-block whose last segment did not come,
/// half a timeout after the last segment (see [`super::block`]).
fn confirm_stalled_sub_block(
    ch: &mut Channel,
    port: &mut impl CanPort,
    index: u16,
    now: Ticks,
    q: &mut ActionQueue,
) {
    let Some(mut t) = ch.transfer else {
        return;
    };
    let Phase::BlockUp(rx) = t.phase else {
        return;
    };
    if !rx.stalled() || now.since(t.last_rx) < t.timeout / 2 {
        return;
    }
    let step = confirm_upload_sub_block(&mut t, rx);
    t.last_rx = now;
    apply(ch, port, index, t, step, now, q);
}

fn load(buf: &[AtomicU8], from: usize, out: &mut [u8]) {
    for (o, b) in out.iter_mut().zip(buf.iter().skip(from)) {
        *o = b.load(Ordering::Relaxed);
    }
}

fn store(buf: &[AtomicU8], at: usize, data: &[u8]) -> bool {
    match buf.get(at..at + data.len()) {
        Some(dst) => {
            for (d, v) in dst.iter().zip(data) {
                d.store(*v, Ordering::Relaxed);
            }
            true
        }
        None => false,
    }
}

enum Step {
    /// Send this frame; the transfer goes on.
    Send(ClientFrame),
    /// Nothing to answer (a block download's segments follow, or more
    /// segments of a sub-block are expected).
    Wait,
    /// The transfer is complete; send the frame, if any, to close it.
    Done(Option<ClientFrame>),
    /// Abort with this code.
    Abort(u32),
}

fn next_download_segment(t: &mut Transfer) -> Step {
    let n = (t.len - t.offset).min(SEGMENT_MAX);
    let mut tmp = [0u8; SEGMENT_MAX];
    let chunk = tmp.get_mut(..n).unwrap_or(&mut []);
    load(t.buf, t.offset, chunk);
    let Some(data) = SegmentData::new(chunk) else {
        return Step::Abort(SdoAbort::General.code());
    };
    t.offset += n;
    t.phase = Phase::SegmentSent;
    Step::Send(ClientFrame::DownloadSegment {
        toggle: t.toggle,
        data,
        last: t.offset >= t.len,
    })
}

fn step(t: &mut Transfer, reply: ServerFrame) -> Step {
    let general = SdoAbort::General.code();
    let command = SdoAbort::UnknownCommand.code();
    match (t.dir, t.phase, reply) {
        (
            Direction::Download,
            Phase::InitiateSent,
            ServerFrame::InitiateDownloadResponse { mux },
        ) => {
            if mux != t.mux {
                return Step::Abort(general);
            }
            if t.offset >= t.len {
                Step::Done(None) // expedited: the data went with the request
            } else {
                next_download_segment(t)
            }
        }
        (
            Direction::Download,
            Phase::SegmentSent,
            ServerFrame::DownloadSegmentResponse { toggle },
        ) => {
            if toggle != t.toggle {
                return Step::Abort(SdoAbort::ToggleBit.code());
            }
            t.toggle = !t.toggle;
            if t.offset >= t.len {
                Step::Done(None)
            } else {
                next_download_segment(t)
            }
        }
        (
            Direction::Upload,
            Phase::InitiateSent,
            ServerFrame::InitiateUploadResponse { mux, payload },
        ) => {
            if mux != t.mux {
                return Step::Abort(general);
            }
            match payload {
                Initiate::Expedited { data, .. } => {
                    let d = data.as_slice();
                    if d.len() > t.len || !store(t.buf, 0, d) {
                        return Step::Abort(SdoAbort::OutOfMemory.code());
                    }
                    t.offset = d.len();
                    Step::Done(None)
                }
                Initiate::Segmented { size } => {
                    if size.is_some_and(|s| s as usize > t.len) {
                        return Step::Abort(SdoAbort::OutOfMemory.code());
                    }
                    t.announced = size;
                    t.phase = Phase::SegmentSent;
                    Step::Send(ClientFrame::UploadSegment { toggle: t.toggle })
                }
            }
        }
        (
            Direction::Upload,
            Phase::SegmentSent,
            ServerFrame::UploadSegmentResponse { toggle, data, last },
        ) => {
            if toggle != t.toggle {
                return Step::Abort(SdoAbort::ToggleBit.code());
            }
            let d = data.as_slice();
            if t.offset + d.len() > t.len || !store(t.buf, t.offset, d) {
                return Step::Abort(SdoAbort::OutOfMemory.code());
            }
            t.offset += d.len();
            t.toggle = !t.toggle;
            if last {
                if t.announced.is_some_and(|s| s as usize != t.offset) {
                    return Step::Abort(SdoAbort::LengthMismatch.code());
                }
                Step::Done(None)
            } else {
                Step::Send(ClientFrame::UploadSegment { toggle: t.toggle })
            }
        }
        (
            Direction::BlockUpload,
            Phase::InitiateSent,
            ServerFrame::InitiateUploadResponse { .. },
        ) => {
            // Protocol switch: the server answers with the SDO upload
            // protocol; the transfer continues as one.
            t.dir = Direction::Upload;
            step(t, reply)
        }
        (dir, phase, reply) => block_step(t, dir, phase, reply).unwrap_or(Step::Abort(command)),
    }
}

/// The block transfer part of [`step`]; `None` for a reply that does not
/// belong to the transfer.
fn block_step(t: &mut Transfer, dir: Direction, phase: Phase, reply: ServerFrame) -> Option<Step> {
    Some(match (dir, phase, reply) {
        // The answer to an initiate request for another object.
        (
            Direction::BlockDownload,
            Phase::InitiateSent,
            ServerFrame::BlockDownloadInitiateResponse { mux, .. },
        )
        | (
            Direction::BlockUpload,
            Phase::InitiateSent,
            ServerFrame::BlockUploadInitiateResponse { mux, .. },
        ) if mux != t.mux => Step::Abort(SdoAbort::General.code()),
        (
            Direction::BlockDownload,
            Phase::InitiateSent,
            ServerFrame::BlockDownloadInitiateResponse { crc, blksize, .. },
        ) => {
            if !valid_blksize(blksize) {
                return Some(Step::Abort(SdoAbort::InvalidBlockSize.code()));
            }
            t.crc = crc;
            t.phase = Phase::BlockDown(BlockTx::new(t.len, blksize));
            Step::Wait
        }
        (
            Direction::BlockDownload,
            Phase::BlockDown(mut btx),
            ServerFrame::BlockDownloadAck { ackseq, blksize },
        ) => match btx.on_ack(ackseq, blksize) {
            Err(code) => Step::Abort(code.code()),
            Ok(false) => {
                t.phase = Phase::BlockDown(btx);
                Step::Wait
            }
            Ok(true) => {
                t.phase = Phase::BlockDownEnd;
                Step::Send(ClientFrame::BlockDownloadEnd {
                    unused: btx.unused(),
                    crc: if t.crc { btx.crc() } else { 0 },
                })
            }
        },
        (Direction::BlockDownload, Phase::BlockDownEnd, ServerFrame::BlockDownloadEndResponse) => {
            t.offset = t.len;
            Step::Done(None)
        }
        (
            Direction::BlockUpload,
            Phase::InitiateSent,
            ServerFrame::BlockUploadInitiateResponse { crc, size, .. },
        ) => {
            if size.is_some_and(|s| s as usize > t.len) {
                return Some(Step::Abort(SdoAbort::OutOfMemory.code()));
            }
            t.announced = size;
            t.crc = crc;
            t.phase = Phase::BlockUp(BlockRx::new(SDO_BLOCKSIZE_UPLOAD));
            Step::Send(ClientFrame::BlockUploadStart)
        }
        (
            Direction::BlockUpload,
            Phase::BlockUpEnd(rx),
            ServerFrame::BlockUploadEnd { unused, crc },
        ) => block_upload_end(t, rx, unused, crc),
        _ => return None,
    })
}

/// A segment of a block upload (`rx` is the sub-block state before it).
fn block_upload_segment(t: &mut Transfer, mut rx: BlockRx, seg: &BlockSegment) -> Step {
    let verdict = match rx.on_segment(seg) {
        Ok(v) => v,
        Err(code) => return Step::Abort(code.code()),
    };
    if let Some(index) = verdict.accept {
        let start = index.saturating_mul(SEGMENT_MAX);
        if index > 0 && start >= t.len {
            return Step::Abort(SdoAbort::OutOfMemory.code());
        }
        if index > 0 && t.announced.is_some_and(|s| start >= s as usize) {
            return Step::Abort(SdoAbort::LengthMismatch.code());
        }
        if seg.last {
            t.last_segment = seg.data;
        } else {
            // Only the last segment may carry padding: this one is data.
            if start.saturating_add(SEGMENT_MAX) > t.len || !store(t.buf, start, &seg.data) {
                return Step::Abort(SdoAbort::OutOfMemory.code());
            }
            t.crc_acc = block_crc(t.crc_acc, &seg.data);
            t.offset = start.saturating_add(SEGMENT_MAX);
        }
    }
    t.phase = Phase::BlockUp(rx);
    if verdict.confirm {
        confirm_upload_sub_block(t, rx)
    } else {
        Step::Wait
    }
}

/// Confirms the running sub-block of a block upload.
fn confirm_upload_sub_block(t: &mut Transfer, mut rx: BlockRx) -> Step {
    let ackseq = rx.confirm(SDO_BLOCKSIZE_UPLOAD);
    t.phase = if rx.complete() {
        Phase::BlockUpEnd(rx)
    } else {
        Phase::BlockUp(rx)
    };
    Step::Send(ClientFrame::BlockUploadAck {
        ackseq,
        blksize: SDO_BLOCKSIZE_UPLOAD,
    })
}

/// The end frame of a block upload: writes the data bytes of the last
/// segment, checks length and CRC.
fn block_upload_end(t: &mut Transfer, rx: BlockRx, unused: u8, crc: u16) -> Step {
    let padded = rx.segments().saturating_mul(SEGMENT_MAX);
    let len = padded.saturating_sub(usize::from(unused));
    let last_start = padded.saturating_sub(SEGMENT_MAX);
    let tail = t
        .last_segment
        .get(..len.saturating_sub(last_start))
        .unwrap_or(&[]);
    if len > t.len || !store(t.buf, last_start, tail) {
        return Step::Abort(SdoAbort::OutOfMemory.code());
    }
    if t.announced.is_some_and(|s| s as usize != len) {
        return Step::Abort(SdoAbort::LengthMismatch.code());
    }
    if t.crc && block_crc(t.crc_acc, tail) != crc {
        return Step::Abort(SdoAbort::CrcError.code());
    }
    t.offset = len;
    Step::Done(Some(ClientFrame::BlockUploadEndResponse))
}
