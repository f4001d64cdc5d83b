//! The default SDO server (CiA 301 SDO protocols, object 0x1200): expedited and
//! segmented upload and download. Block transfer is not implemented and is
//! refused with abort 0x05040001.
//!
//! # Data consistency
//! The server owns one transfer buffer of [`SDOS_BUFFER_SIZE`] bytes.
//! * An upload reads the whole value into the buffer at the initiate
//!   request (one [`ObjectDictionary::read`]), so the segments that follow
//!   all come from the same snapshot even if the application changes the
//!   variable meanwhile. A value longer than the buffer is refused at the
//!   initiate request with abort 0x05040005 (out of memory): streaming it
//!   from the variable would give up the snapshot.
//! * A download collects every segment in the buffer and writes the value
//!   with a single [`ObjectDictionary::write`] after the last segment, so a
//!   partial value never reaches the variable and every check of the
//!   dictionary (access, length, range, module hooks, application callback)
//!   applies to the complete value. A value longer than the buffer is
//!   refused with abort 0x06070012: at the initiate request when the client
//!   states the size, otherwise at the segment that would overflow.
//!
//! # Abort codes
//! Everything about the object (existence, access, length, range, refusals
//! by a module or the application) is the dictionary's [`OdError::abort`],
//! passed through unchanged. The server itself decides only the protocol
//! codes: toggle bit (0x05030000), timeout (0x05040000), unknown or
//! unexpected command (0x05040001), upload too large for the buffer
//! (0x05040005), download longer than the buffer (0x06070012) and a
//! segmented download whose data length differs from the size stated at
//! initiate (0x06070010).
//!
//! # Protocol decisions
//! * Frames with a data length other than 8, and remote frames, are not SDO
//!   frames (CiA 301 defines every SDO frame with 8 data bytes): they are
//!   ignored without answer and without touching a running transfer.
//! * While a transfer runs, any request other than its next step (the
//!   segment with the expected command, or an abort) aborts the transfer
//!   with 0x05040001; a wrong toggle bit aborts it with 0x05030000. The
//!   request that caused the abort is not carried out; the client repeats
//!   it.
//! * An abort frame from the client ends a running transfer silently and is
//!   never answered.
//! * A segment request while no transfer runs is answered with 0x05040001.
//! * Abort frames carry the multiplexer of the running transfer; with none
//!   running, that of the request (0000h/00h for segment requests, which
//!   have none).
//! * An expedited download without size indication (e = 1, s = 0) writes as
//!   many bytes as the object's type has when that is at most 4, otherwise
//!   all 4.
//! * Timeout supervision: a transfer is aborted with 0x05040000 once
//!   [`SdoServer::timeout_ticks`] ticks pass without a valid request of the
//!   transfer. The check runs in [`SdoServer::poll`] and also when the late
//!   request arrives, so the outcome does not depend on the order of the
//!   two.
//!
//! # COB-IDs
//! Object 0x1200 sub 1 (client to server) and sub 2 (server to client) when
//! present, otherwise the predefined connection set 0x600 / 0x580 +
//! node-ID. A stored value of exactly 0x600 (sub 1) or 0x580 (sub 2) also
//! means "base + node-ID": many objdict.h files declare the base because
//! the node-ID is not known at compile time. Bit 31 set in either sub
//! disables the server (CiA 301 object 1200h: both COB-IDs must be valid); so
//! does an 11-bit COB-ID with bits 28..11 set.

use crate::config::{SDOS_BUFFER_SIZE, SDOS_DEFAULT_TIMEOUT};
use crate::error::{OdError, SdoAbort};
use crate::od::{ByteOrder, ObjectDictionary, WriteHooks};
use crate::port::{CanFrame, CanId, Ticks};
use crate::wire::sdo::{
    ClientFrame, DecodeError, EXPEDITED_MAX, ExpeditedData, Initiate, Multiplexer, REQUEST_BASE,
    RESPONSE_BASE, SEGMENT_MAX, SegmentData, ServerFrame,
};

/// SDO server parameter object of the default server.
pub const SERVER_PARAMETER_INDEX: u16 = 0x1200;

/// COB-ID bit 31: the COB-ID is not valid.
const COB_ID_INVALID: u32 = 0x8000_0000;
/// COB-ID bit 29: 29-bit identifier.
const COB_ID_EXTENDED: u32 = 0x2000_0000;

/// A segmented upload: `len` bytes of the buffer, `sent` of them sent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Upload {
    mux: Multiplexer,
    len: usize,
    sent: usize,
    /// Toggle bit the next request must carry.
    toggle: bool,
    last_rx: Ticks,
}

/// A segmented download: `received` bytes collected in the buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Download {
    mux: Multiplexer,
    /// Size stated by the client at initiate.
    size: Option<usize>,
    received: usize,
    /// Toggle bit the next segment must carry.
    toggle: bool,
    last_rx: Ticks,
}

/// The transfer in progress.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Transfer {
    Idle,
    Upload(Upload),
    Download(Download),
}

impl Transfer {
    fn mux(&self) -> Option<Multiplexer> {
        match self {
            Transfer::Idle => None,
            Transfer::Upload(u) => Some(u.mux),
            Transfer::Download(d) => Some(d.mux),
        }
    }

    fn last_rx(&self) -> Option<Ticks> {
        match self {
            Transfer::Idle => None,
            Transfer::Upload(u) => Some(u.last_rx),
            Transfer::Download(d) => Some(d.last_rx),
        }
    }
}

/// The default SDO server (object 0x1200).
#[derive(Clone, Debug)]
pub struct SdoServer {
    rx: Option<CanId>,
    tx: Option<CanId>,
    timeout_ticks: u32,
    transfer: Transfer,
    buf: [u8; SDOS_BUFFER_SIZE],
}

impl Default for SdoServer {
    fn default() -> Self {
        Self::new()
    }
}

impl SdoServer {
    /// An unconfigured server: it answers nothing until
    /// [`SdoServer::reconfigure`] gives it its COB-IDs.
    pub const fn new() -> Self {
        SdoServer {
            rx: None,
            tx: None,
            timeout_ticks: SDOS_DEFAULT_TIMEOUT,
            transfer: Transfer::Idle,
            buf: [0; SDOS_BUFFER_SIZE],
        }
    }

    /// Takes the COB-IDs from object 0x1200 (see the module documentation
    /// for the predefined connection set and the base-value rule). A
    /// running transfer is dropped without answer when the COB-IDs change,
    /// since its client can no longer be reached on them.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, node: u8) {
        let rx = cob_id(od, 1, REQUEST_BASE, node);
        let tx = cob_id(od, 2, RESPONSE_BASE, node);
        let (rx, tx) = match (rx, tx) {
            (Some(r), Some(t)) => (Some(r), Some(t)),
            _ => (None, None),
        };
        if (rx, tx) != (self.rx, self.tx) {
            self.transfer = Transfer::Idle;
        }
        self.rx = rx;
        self.tx = tx;
    }

    /// COB-ID of requests (client to server); `None` while the server is
    /// disabled.
    pub fn rx_id(&self) -> Option<CanId> {
        self.rx
    }

    /// COB-ID of responses (server to client); `None` while the server is
    /// disabled.
    pub fn tx_id(&self) -> Option<CanId> {
        self.tx
    }

    /// Timeout of a transfer in ticks of 100 µs (0: no supervision).
    pub fn timeout_ticks(&self) -> u32 {
        self.timeout_ticks
    }

    /// Sets the timeout (`tSdosParam.m_dwTimeOut`), in ticks of 100 µs; 0
    /// switches the supervision off. Applies to the running transfer too.
    pub fn set_timeout_ticks(&mut self, ticks: u32) {
        self.timeout_ticks = ticks;
    }

    /// True while a segmented transfer runs.
    pub fn is_busy(&self) -> bool {
        self.transfer != Transfer::Idle
    }

    /// Handles a frame received on [`SdoServer::rx_id`]; returns the
    /// response or abort to send. Writes go through
    /// [`ObjectDictionary::write`] with `hooks`, so that the modules of the
    /// stack can refuse them.
    pub fn on_frame(
        &mut self,
        od: &ObjectDictionary,
        hooks: &mut impl WriteHooks,
        frame: &CanFrame,
        now: Ticks,
    ) -> Option<CanFrame> {
        if self.rx != Some(frame.id) {
            return None;
        }
        let tx = self.tx?;
        let reply = match ClientFrame::from_can(frame) {
            Ok(req) => {
                if let (ClientFrame::Abort { code, .. }, Some(mux)) = (req, self.transfer.mux()) {
                    // The client aborts the running transfer.
                    od.notify_sdo_abort(mux.index, mux.sub, code);
                }
                self.handle(od, hooks, req, now)
            }
            Err(DecodeError::Length) => None,
            Err(DecodeError::UnsupportedCommand { mux, .. }) => {
                let mux = self.transfer.mux().unwrap_or(mux);
                Some(self.abort(mux, SdoAbort::UnknownCommand.code()))
            }
        };
        if let Some(ServerFrame::Abort { mux, code }) = reply {
            od.notify_sdo_abort(mux.index, mux.sub, code);
        }
        reply.map(|r| r.to_can(tx))
    }

    /// Timeout supervision; returns the abort frame (0x05040000) when the
    /// running transfer timed out (the object's callback sees
    /// kObdEvAbortSdo).
    pub fn poll(&mut self, od: &ObjectDictionary, now: Ticks) -> Option<CanFrame> {
        if !self.expired(now) {
            return None;
        }
        let mux = self.transfer.mux()?;
        let tx = self.tx?;
        od.notify_sdo_abort(mux.index, mux.sub, SdoAbort::Timeout.code());
        Some(self.abort(mux, SdoAbort::Timeout.code()).to_can(tx))
    }

    /// Drops a running transfer without answering (NMT stopped or reset).
    pub fn cancel(&mut self) {
        self.transfer = Transfer::Idle;
    }

    fn expired(&self, now: Ticks) -> bool {
        match self.transfer.last_rx() {
            Some(t) => self.timeout_ticks != 0 && now.since(t) >= self.timeout_ticks,
            None => false,
        }
    }

    /// Ends the transfer and builds the abort frame.
    fn abort(&mut self, mux: Multiplexer, code: u32) -> ServerFrame {
        self.transfer = Transfer::Idle;
        ServerFrame::Abort { mux, code }
    }

    fn handle(
        &mut self,
        od: &ObjectDictionary,
        hooks: &mut impl WriteHooks,
        req: ClientFrame,
        now: Ticks,
    ) -> Option<ServerFrame> {
        if let ClientFrame::Abort { .. } = req {
            self.transfer = Transfer::Idle;
            return None;
        }
        let continues = matches!(
            req,
            ClientFrame::DownloadSegment { .. } | ClientFrame::UploadSegment { .. }
        );
        if self.expired(now) {
            if let Some(mux) = self.transfer.mux() {
                if continues {
                    // The late segment belongs to the timed-out transfer:
                    // the answer is the abort that poll would have sent.
                    return Some(self.abort(mux, SdoAbort::Timeout.code()));
                }
                // A new request: the client has given up on the old
                // transfer; forget it and serve the request.
                self.transfer = Transfer::Idle;
            }
        }
        match (self.transfer, req) {
            (Transfer::Idle, ClientFrame::InitiateUpload { mux }) => {
                Some(self.initiate_upload(od, mux, now))
            }
            (Transfer::Idle, ClientFrame::InitiateDownload { mux, payload }) => {
                Some(self.initiate_download(od, hooks, mux, payload, now))
            }
            (Transfer::Upload(up), ClientFrame::UploadSegment { toggle }) => {
                Some(self.upload_segment(Upload { last_rx: now, ..up }, toggle))
            }
            (Transfer::Download(down), ClientFrame::DownloadSegment { toggle, data, last }) => {
                let down = Download {
                    last_rx: now,
                    ..down
                };
                Some(self.download_segment(od, hooks, down, toggle, &data, last))
            }
            (running, _) => {
                let mux = running.mux().unwrap_or_default();
                Some(self.abort(mux, SdoAbort::UnknownCommand.code()))
            }
        }
    }

    fn initiate_upload(
        &mut self,
        od: &ObjectDictionary,
        mux: Multiplexer,
        now: Ticks,
    ) -> ServerFrame {
        let len = match od.read(mux.index, mux.sub, ByteOrder::Wire, &mut self.buf) {
            Ok(n) => n,
            Err(e) => {
                let code = if self.exceeds_buffer(od, mux, e) {
                    SdoAbort::OutOfMemory.code()
                } else {
                    e.abort
                };
                return self.abort(mux, code);
            }
        };
        if (1..=EXPEDITED_MAX).contains(&len) {
            let data = self
                .buf
                .get(..len)
                .and_then(ExpeditedData::new)
                .unwrap_or(ExpeditedData::empty());
            return ServerFrame::InitiateUploadResponse {
                mux,
                payload: Initiate::Expedited { data, sized: true },
            };
        }
        // Longer values, and empty ones (an expedited transfer cannot say
        // "0 bytes"), go segmented.
        self.transfer = Transfer::Upload(Upload {
            mux,
            len,
            sent: 0,
            toggle: false,
            last_rx: now,
        });
        ServerFrame::InitiateUploadResponse {
            mux,
            payload: Initiate::Segmented {
                size: u32::try_from(len).ok(),
            },
        }
    }

    /// True when a failed read failed only because the value does not fit
    /// the transfer buffer.
    fn exceeds_buffer(&self, od: &ObjectDictionary, mux: Multiplexer, e: OdError) -> bool {
        e == OdError::TOO_LONG
            && od
                .find(mux.index, mux.sub)
                .and_then(|obj| od.size_of(&obj, ByteOrder::Wire))
                .is_ok_and(|n| n > self.buf.len())
    }

    /// `up` is the transfer with its timer restarted.
    fn upload_segment(&mut self, up: Upload, toggle: bool) -> ServerFrame {
        if toggle != up.toggle {
            return self.abort(up.mux, SdoAbort::ToggleBit.code());
        }
        let end = up.len.min(up.sent.saturating_add(SEGMENT_MAX));
        let Some(data) = self.buf.get(up.sent..end).and_then(SegmentData::new) else {
            // Unreachable: len never exceeds the buffer.
            return self.abort(up.mux, SdoAbort::General.code());
        };
        let last = end == up.len;
        self.transfer = if last {
            Transfer::Idle
        } else {
            Transfer::Upload(Upload {
                sent: end,
                toggle: !toggle,
                ..up
            })
        };
        ServerFrame::UploadSegmentResponse { toggle, data, last }
    }

    fn initiate_download(
        &mut self,
        od: &ObjectDictionary,
        hooks: &mut impl WriteHooks,
        mux: Multiplexer,
        payload: Initiate,
        now: Ticks,
    ) -> ServerFrame {
        match payload {
            Initiate::Expedited { data, sized } => {
                let n = if sized {
                    data.len()
                } else {
                    unsized_expedited_len(od, mux)
                };
                let bytes = data.padded().get(..n).unwrap_or(data.as_slice());
                match od.write(mux.index, mux.sub, ByteOrder::Wire, bytes, hooks) {
                    Ok(()) => ServerFrame::InitiateDownloadResponse { mux },
                    Err(e) => self.abort(mux, e.abort),
                }
            }
            Initiate::Segmented { size } => {
                let size = size.map(|s| usize::try_from(s).unwrap_or(usize::MAX));
                if let Err(e) = od.begin_write(mux.index, mux.sub, size) {
                    return self.abort(mux, e.abort);
                }
                if size.is_some_and(|s| s > self.buf.len()) {
                    return self.abort(mux, SdoAbort::LengthTooHigh.code());
                }
                self.transfer = Transfer::Download(Download {
                    mux,
                    size,
                    received: 0,
                    toggle: false,
                    last_rx: now,
                });
                ServerFrame::InitiateDownloadResponse { mux }
            }
        }
    }

    /// `down` is the transfer with its timer restarted.
    fn download_segment(
        &mut self,
        od: &ObjectDictionary,
        hooks: &mut impl WriteHooks,
        down: Download,
        toggle: bool,
        data: &SegmentData,
        last: bool,
    ) -> ServerFrame {
        let mux = down.mux;
        if toggle != down.toggle {
            return self.abort(mux, SdoAbort::ToggleBit.code());
        }
        let end = down.received.saturating_add(data.len());
        let Some(dst) = self.buf.get_mut(down.received..end) else {
            return self.abort(mux, SdoAbort::LengthTooHigh.code());
        };
        dst.copy_from_slice(data.as_slice());
        if down.size.is_some_and(|s| end > s || (last && end != s)) {
            return self.abort(mux, SdoAbort::LengthMismatch.code());
        }
        if !last {
            self.transfer = Transfer::Download(Download {
                received: end,
                toggle: !toggle,
                ..down
            });
            return ServerFrame::DownloadSegmentResponse { toggle };
        }
        self.transfer = Transfer::Idle;
        let value = self.buf.get(..end).unwrap_or(&[]);
        match od.write(mux.index, mux.sub, ByteOrder::Wire, value, hooks) {
            // The last segment is confirmed only once the value is stored.
            Ok(()) => ServerFrame::DownloadSegmentResponse { toggle },
            Err(e) => self.abort(mux, e.abort),
        }
    }
}

/// Bytes of an expedited download that does not state its size: the
/// object's width when it has a fixed one of at most 4 bytes, else all 4.
/// An unknown object gets 4; the write then reports why it does not exist.
fn unsized_expedited_len(od: &ObjectDictionary, mux: Multiplexer) -> usize {
    od.find(mux.index, mux.sub)
        .ok()
        .and_then(|obj| obj.data_type().wire_size())
        .filter(|w| *w <= EXPEDITED_MAX)
        .unwrap_or(EXPEDITED_MAX)
}

/// One COB-ID of 0x1200 (`sub` 1 or 2), or base + node-ID.
fn cob_id(od: &ObjectDictionary, sub: u8, base: u16, node: u8) -> Option<CanId> {
    let default = CanId::std(base.wrapping_add(u16::from(node)));
    let Ok(raw) = od.read_uint(SERVER_PARAMETER_INDEX, sub) else {
        return default;
    };
    let v = (raw & 0xFFFF_FFFF) as u32;
    if v & COB_ID_INVALID != 0 {
        return None;
    }
    if v == u32::from(base) {
        // The object holds the predefined base: it must show the COB-ID in
        // use (CiA 301), so the node-ID goes into the object too.
        if let Some(id) = default {
            let _ = od.poke_uint(SERVER_PARAMETER_INDEX, sub, u64::from(id.raw()));
        }
        return default;
    }
    if v & COB_ID_EXTENDED != 0 {
        CanId::ext(v & 0x1FFF_FFFF)
    } else {
        // Bit 30 (dynamic allocation) carries no meaning for the server.
        u16::try_from(v & !0x4000_0000).ok().and_then(CanId::std)
    }
}

#[cfg(test)]
mod tests;
