//! The SDO servers (SYS TEC SDOS; CiA 301 SDO protocols, objects
//! 0x1200..0x127F): expedited, segmented and block upload and download.
//!
//! [`SdoServer`] is one server channel; [`SdoServers`] holds the default
//! server 0x1200 and the additional servers 0x1201.. up to
//! [`SDO_MAX_SERVER_IN_OBD`]. Each channel has its own COB-IDs, transfer,
//! timeout and buffer, so transfers on different servers run side by side.
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
//! * Block transfer follows the same two rules: a block upload sends its
//!   sub-blocks from the snapshot, a block download collects the sub-blocks
//!   and writes once when the end frame has been checked (size, CRC).
//!
//! # Abort codes
//! Everything about the object (existence, access, length, range, refusals
//! by a module or the application) is the dictionary's [`OdError::abort`],
//! passed through unchanged. The server itself decides only the protocol
//! codes: toggle bit (0x05030000), timeout (0x05040000), unknown or
//! unexpected command (0x05040001), block size outside 1..=127
//! (0x05040002), sequence number 0, above the block size or beyond what was
//! sent (0x05040003), CRC of a block download (0x05040004), upload too
//! large for the buffer (0x05040005), download longer than the buffer
//! (0x06070012) and a download whose data length differs from the size
//! stated at initiate (0x06070010).
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
//!   transfer (in a block upload: since the last segment of a sub-block
//!   went out). The check runs in [`SdoServer::poll`] and also when the late
//!   request arrives, so the outcome does not depend on the order of the
//!   two.
//!
//! # Block transfer
//! * Block download: the server offers [`SDO_BLOCKSIZE_DOWNLOAD`] segments
//!   per sub-block and the CRC (it is used when the client supports it
//!   too). Sub-block bookkeeping, confirmation and retransmission follow
//!   `super::block`: a lost segment is asked for again through ackseq; a
//!   lost last segment of a sub-block is confirmed after half the timeout
//!   without segments.
//! * Block upload: the client's blksize is used as given (1..=127, else
//!   0x05040002). When the client allows a protocol switch (pst > 0) and
//!   the value has at most pst bytes, the server answers with the SDO
//!   upload protocol instead (expedited up to 4 bytes, else segmented), as
//!   CiA 301 allows. The segments of a sub-block are not answers to one
//!   request each: the stack takes them with [`SdoServer::pending_segment`]
//!   while the driver accepts frames and confirms each with
//!   [`SdoServer::segment_sent`]; the rest follows in the next cycle.
//! * While a sub-block of a download runs, every frame is a segment (CiA
//!   301 gives segments no command specifier); only 0x80 in byte 0 (seqno
//!   0 with c = 1, never a valid segment) is read as the client's abort.
//!
//! # COB-IDs
//! Object 0x1200 sub 1 (client to server) and sub 2 (server to client) when
//! present, otherwise the predefined connection set 0x600 / 0x580 +
//! node-ID. A stored value of exactly 0x600 (sub 1) or 0x580 (sub 2) also
//! means "base + node-ID": many objdict.h files declare the base because
//! the node-ID is not known at compile time. Bit 31 set in either sub
//! disables the server (CiA 301 object 1200h: both COB-IDs must be valid); so
//! does an 11-bit COB-ID with bits 28..11 set or an identifier of another
//! service ([`super::usable_cob_id`]: never an SRDO or GFC identifier).
//!
//! An additional server 0x1201.. has no predefined connection (CiA 301
//! 7.5.2.33): it answers only while its object exists with two valid
//! COB-IDs, taken as they stand (0x600 / 0x580 there are identifiers, not
//! bases). Its sub 3, the node-ID of the client, is information for the
//! client and changes nothing here. Where two servers are given the same
//! request COB-ID, the one with the lower index takes the frames.

use super::block::{BlockRx, BlockTx, valid_blksize};
use crate::config::{
    SDO_BLOCKSIZE_DOWNLOAD, SDO_MAX_SERVER_IN_OBD, SDOS_BUFFER_SIZE, SDOS_DEFAULT_TIMEOUT,
};
use crate::error::{OdError, SdoAbort};
use crate::od::{ByteOrder, ObjectDictionary, WriteHooks};
use crate::port::{CanFrame, CanId, Ticks};
use crate::wire::sdo::{
    BlockSegment, ClientFrame, DecodeError, EXPEDITED_MAX, ExpeditedData, Initiate, Multiplexer,
    REQUEST_BASE, RESPONSE_BASE, SEGMENT_MAX, SegmentData, ServerFrame, SubBlockFrame, block_crc,
    frame_bytes,
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

/// Where a block download stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum BlockDownPhase {
    /// Sub-blocks arrive: every frame is a segment.
    SubBlock,
    /// The last segment is confirmed: the end frame is next.
    End,
}

/// A block download: segments collected in the buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct BlockDownload {
    mux: Multiplexer,
    /// Size stated by the client at initiate.
    size: Option<usize>,
    /// Both sides support the CRC.
    crc: bool,
    rx: BlockRx,
    phase: BlockDownPhase,
    /// CRC of the full segments received in order (the last one, whose
    /// length the end frame tells, is added then).
    crc_acc: u16,
    last_rx: Ticks,
}

/// Where a block upload stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum BlockUpPhase {
    /// Initiate answered, the client's start request is next.
    Start,
    /// Sub-blocks go out and are confirmed.
    SubBlock,
    /// End frame sent, the client's end response is next.
    End,
}

/// A block upload of `len` bytes of the buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct BlockUpload {
    mux: Multiplexer,
    len: usize,
    /// Both sides support the CRC.
    crc: bool,
    tx: BlockTx,
    phase: BlockUpPhase,
    last_rx: Ticks,
}

/// The transfer in progress.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Transfer {
    Idle,
    Upload(Upload),
    Download(Download),
    BlockDown(BlockDownload),
    BlockUp(BlockUpload),
}

impl Transfer {
    fn mux(&self) -> Option<Multiplexer> {
        match self {
            Transfer::Idle => None,
            Transfer::Upload(u) => Some(u.mux),
            Transfer::Download(d) => Some(d.mux),
            Transfer::BlockDown(d) => Some(d.mux),
            Transfer::BlockUp(u) => Some(u.mux),
        }
    }

    fn last_rx(&self) -> Option<Ticks> {
        match self {
            Transfer::Idle => None,
            Transfer::Upload(u) => Some(u.last_rx),
            Transfer::Download(d) => Some(d.last_rx),
            Transfer::BlockDown(d) => Some(d.last_rx),
            Transfer::BlockUp(u) => Some(u.last_rx),
        }
    }

    /// True for the requests that continue the running transfer (rather
    /// than start a new one).
    fn continued_by(&self, req: &ClientFrame) -> bool {
        matches!(
            req,
            ClientFrame::DownloadSegment { .. }
                | ClientFrame::UploadSegment { .. }
                | ClientFrame::BlockDownloadEnd { .. }
                | ClientFrame::BlockUploadStart
                | ClientFrame::BlockUploadAck { .. }
                | ClientFrame::BlockUploadEndResponse
        )
    }
}

/// One SDO server channel (object 0x1200, or 0x1201.. for an additional
/// server).
#[derive(Clone, Debug)]
pub struct SdoServer {
    /// Its server parameter object.
    index: u16,
    rx: Option<CanId>,
    tx: Option<CanId>,
    timeout_ticks: u32,
    transfer: Transfer,
    /// A frame the driver refused (a full transmit buffer), sent again
    /// before anything else of this channel.
    held: Option<CanFrame>,
    buf: [u8; SDOS_BUFFER_SIZE],
}

crate::od::decl::default_is_new!(SdoServer);

impl SdoServer {
    /// The default server (0x1200), unconfigured: it answers nothing until
    /// [`SdoServer::reconfigure`] gives it its COB-IDs.
    pub const fn new() -> Self {
        SdoServer::with_index(SERVER_PARAMETER_INDEX)
    }

    /// The server of parameter object `index` (0x1200..=0x127F),
    /// unconfigured.
    pub const fn with_index(index: u16) -> Self {
        SdoServer {
            index,
            rx: None,
            tx: None,
            timeout_ticks: SDOS_DEFAULT_TIMEOUT,
            transfer: Transfer::Idle,
            held: None,
            buf: [0; SDOS_BUFFER_SIZE],
        }
    }

    /// Takes the COB-IDs from its parameter object (see the module
    /// documentation for the predefined connection set of 0x1200 and the
    /// base-value rule). A running transfer is dropped without answer when
    /// the COB-IDs change, since its client can no longer be reached on
    /// them.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, node: u8) {
        let rx = cob_id(od, self.index, 1, REQUEST_BASE, node);
        let tx = cob_id(od, self.index, 2, RESPONSE_BASE, node);
        let (rx, tx) = match (rx, tx) {
            (Some(r), Some(t)) => (Some(r), Some(t)),
            _ => (None, None),
        };
        if (rx, tx) != (self.rx, self.tx) {
            self.transfer = Transfer::Idle;
            self.held = None;
        }
        self.rx = rx;
        self.tx = tx;
    }

    /// Its server parameter object (0x1200 for the default server).
    pub fn index(&self) -> u16 {
        self.index
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

    /// True while a segmented or block transfer runs.
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
        let reply = if let Transfer::BlockDown(
            d @ BlockDownload {
                phase: BlockDownPhase::SubBlock,
                ..
            },
        ) = self.transfer
        {
            let bytes = frame_bytes(frame).ok()?;
            match SubBlockFrame::decode(bytes) {
                SubBlockFrame::Abort { code, .. } => {
                    od.notify_sdo_abort(d.mux.index, d.mux.sub, code);
                    self.transfer = Transfer::Idle;
                    None
                }
                SubBlockFrame::Segment(seg) => self.block_download_segment(d, &seg, now),
            }
        } else {
            match ClientFrame::from_can(frame) {
                Ok(req) => {
                    if let (ClientFrame::Abort { code, .. }, Some(mux)) = (req, self.transfer.mux())
                    {
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
            }
        };
        if let Some(ServerFrame::Abort { mux, code }) = reply {
            od.notify_sdo_abort(mux.index, mux.sub, code);
        }
        reply.map(|r| r.to_can(tx))
    }

    /// True when no transfer runs: [`SdoServer::poll`] and
    /// [`SdoServer::pending_segment`] have nothing to do.
    #[inline]
    pub fn at_rest(&self) -> bool {
        matches!(self.transfer, Transfer::Idle) && self.held.is_none()
    }

    /// Keeps `f`, which the driver refused, for [`SdoServer::take_held`]:
    /// a full transmit buffer delays the answer to the next cycle instead
    /// of losing it (and the client's transfer with it). One frame: a
    /// client waits for each answer; a newer one (an abort) replaces it.
    pub fn hold(&mut self, f: CanFrame) {
        self.held = Some(f);
    }

    /// The frame [`SdoServer::hold`] kept, to be sent before anything else
    /// of this channel.
    pub fn take_held(&mut self) -> Option<CanFrame> {
        self.held.take()
    }

    /// True while a refused frame waits: the channel sends nothing else.
    pub fn holding(&self) -> bool {
        self.held.is_some()
    }

    /// Timeout supervision; returns the abort frame (0x05040000) when the
    /// running transfer timed out (the object's callback sees
    /// kObdEvAbortSdo).
    pub fn poll(&mut self, od: &ObjectDictionary, now: Ticks) -> Option<CanFrame> {
        let tx = self.tx?;
        if !self.expired(now) {
            return self.stalled_sub_block(now).map(|r| r.to_can(tx));
        }
        let mux = self.transfer.mux()?;
        od.notify_sdo_abort(mux.index, mux.sub, SdoAbort::Timeout.code());
        Some(self.abort(mux, SdoAbort::Timeout.code()).to_can(tx))
    }

    /// The next segment of a block upload waiting for the driver; the
    /// stack sends it and then calls [`SdoServer::segment_sent`]. `None`
    /// when no sub-block is being sent.
    pub fn pending_segment(&self) -> Option<CanFrame> {
        let Transfer::BlockUp(u) = self.transfer else {
            return None;
        };
        if self.held.is_some() {
            return None;
        }
        if u.phase != BlockUpPhase::SubBlock {
            return None;
        }
        let p = u.tx.next()?;
        let data = self.buf.get(p.start..p.end)?;
        Some(BlockTx::segment(&p, data).to_can(self.tx?))
    }

    /// The segment of [`SdoServer::pending_segment`] went to the driver.
    /// The timeout of the confirmation runs from the last segment of a
    /// sub-block.
    pub fn segment_sent(&mut self, now: Ticks) {
        let Transfer::BlockUp(mut u) = self.transfer else {
            return;
        };
        let Some(p) = u.tx.next() else {
            return;
        };
        let data = self.buf.get(p.start..p.end).unwrap_or(&[]);
        u.tx.mark_sent(&p, data);
        if u.tx.next().is_none() {
            u.last_rx = now;
        }
        self.transfer = Transfer::BlockUp(u);
    }

    /// Drops a running transfer without answering (NMT stopped or reset).
    pub fn cancel(&mut self) {
        self.transfer = Transfer::Idle;
        self.held = None;
    }

    fn expired(&self, now: Ticks) -> bool {
        match self.transfer.last_rx() {
            Some(t) => self.timeout_ticks != 0 && now.since(t) >= self.timeout_ticks,
            None => false,
        }
    }

    /// Ends the transfer and builds the abort frame.
    /// Starts a segmented or block download after the checks of its
    /// initiate request: the object must be writable with the announced
    /// size, and the size must fit the buffer. `start` gives the transfer
    /// and the reply for the size; a refusal is the abort instead.
    fn start_download(
        &mut self,
        od: &ObjectDictionary,
        mux: Multiplexer,
        size: Option<u32>,
        start: impl FnOnce(Option<usize>) -> (Transfer, ServerFrame),
    ) -> ServerFrame {
        let size = size.map(|s| usize::try_from(s).unwrap_or(usize::MAX));
        if let Err(e) = od.begin_write(mux.index, mux.sub, size) {
            return self.abort(mux, e.abort);
        }
        if size.is_some_and(|s| s > self.buf.len()) {
            return self.abort(mux, SdoAbort::LengthTooHigh.code());
        }
        let (transfer, reply) = start(size);
        self.transfer = transfer;
        reply
    }

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
        let continues = self.transfer.continued_by(&req);
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
            (Transfer::Idle, ClientFrame::BlockDownloadInitiate { mux, crc, size }) => {
                Some(self.block_download_initiate(od, mux, crc, size, now))
            }
            (
                Transfer::BlockDown(
                    d @ BlockDownload {
                        phase: BlockDownPhase::End,
                        ..
                    },
                ),
                ClientFrame::BlockDownloadEnd { unused, crc },
            ) => Some(self.block_download_end(od, hooks, d, unused, crc)),
            (
                Transfer::Idle,
                ClientFrame::BlockUploadInitiate {
                    mux,
                    crc,
                    blksize,
                    pst,
                },
            ) => Some(self.block_upload_initiate(od, mux, crc, blksize, pst, now)),
            (
                Transfer::BlockUp(
                    u @ BlockUpload {
                        phase: BlockUpPhase::Start,
                        ..
                    },
                ),
                ClientFrame::BlockUploadStart,
            ) => {
                self.transfer = Transfer::BlockUp(BlockUpload {
                    phase: BlockUpPhase::SubBlock,
                    last_rx: now,
                    ..u
                });
                None
            }
            (
                Transfer::BlockUp(
                    u @ BlockUpload {
                        phase: BlockUpPhase::SubBlock,
                        ..
                    },
                ),
                ClientFrame::BlockUploadAck { ackseq, blksize },
            ) => self.block_upload_ack(u, ackseq, blksize, now),
            (
                Transfer::BlockUp(BlockUpload {
                    phase: BlockUpPhase::End,
                    ..
                }),
                ClientFrame::BlockUploadEndResponse,
            ) => {
                self.transfer = Transfer::Idle;
                None
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
        match self.snapshot(od, mux) {
            Ok(len) => self.upload_response(mux, len, now),
            Err(code) => self.abort(mux, code),
        }
    }

    /// Reads the value into the buffer; its length, or the abort code.
    fn snapshot(&mut self, od: &ObjectDictionary, mux: Multiplexer) -> Result<usize, u32> {
        od.read(mux.index, mux.sub, ByteOrder::Wire, &mut self.buf)
            .map_err(|e| {
                if self.exceeds_buffer(od, mux, e) {
                    SdoAbort::OutOfMemory.code()
                } else {
                    e.abort
                }
            })
    }

    /// The SDO upload protocol's answer for `len` bytes in the buffer.
    fn upload_response(&mut self, mux: Multiplexer, len: usize, now: Ticks) -> ServerFrame {
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
            Initiate::Segmented { size } => self.start_download(od, mux, size, |size| {
                let down = Download {
                    mux,
                    size,
                    received: 0,
                    toggle: false,
                    last_rx: now,
                };
                let reply = ServerFrame::InitiateDownloadResponse { mux };
                (Transfer::Download(down), reply)
            }),
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

impl SdoServer {
    fn block_download_initiate(
        &mut self,
        od: &ObjectDictionary,
        mux: Multiplexer,
        crc: bool,
        size: Option<u32>,
        now: Ticks,
    ) -> ServerFrame {
        self.start_download(od, mux, size, |size| {
            let reply = ServerFrame::BlockDownloadInitiateResponse {
                mux,
                crc: true,
                blksize: SDO_BLOCKSIZE_DOWNLOAD,
            };
            let down = BlockDownload {
                mux,
                size,
                crc,
                rx: BlockRx::new(SDO_BLOCKSIZE_DOWNLOAD),
                phase: BlockDownPhase::SubBlock,
                crc_acc: 0,
                last_rx: now,
            };
            (Transfer::BlockDown(down), reply)
        })
    }

    /// A segment of a block download (`d` is the transfer before it).
    fn block_download_segment(
        &mut self,
        mut d: BlockDownload,
        seg: &BlockSegment,
        now: Ticks,
    ) -> Option<ServerFrame> {
        if self.expired(now) {
            return Some(self.abort(d.mux, SdoAbort::Timeout.code()));
        }
        d.last_rx = now;
        let verdict = match d.rx.on_segment(seg) {
            Ok(v) => v,
            Err(code) => return Some(self.abort(d.mux, code.code())),
        };
        if let Some(index) = verdict.accept {
            let start = index.saturating_mul(SEGMENT_MAX);
            if index > 0 && start >= self.buf.len() {
                return Some(self.abort(d.mux, SdoAbort::LengthTooHigh.code()));
            }
            if index > 0 && d.size.is_some_and(|s| start >= s) {
                return Some(self.abort(d.mux, SdoAbort::LengthMismatch.code()));
            }
            // The padding of the last segment may not fit: only the bytes
            // the end frame declares as data have to.
            let room = self.buf.len().saturating_sub(start).min(SEGMENT_MAX);
            let src = seg.data.get(..room).unwrap_or(&[]);
            if let Some(dst) = self.buf.get_mut(start..start.saturating_add(room)) {
                dst.copy_from_slice(src);
            }
            if !seg.last {
                d.crc_acc = block_crc(d.crc_acc, &seg.data);
            }
        }
        self.transfer = Transfer::BlockDown(d);
        if verdict.confirm {
            return Some(self.confirm_sub_block(d));
        }
        None
    }

    /// Confirms the running sub-block of `d` (ackseq = last segment in
    /// order) and opens the next one.
    fn confirm_sub_block(&mut self, mut d: BlockDownload) -> ServerFrame {
        let ackseq = d.rx.confirm(SDO_BLOCKSIZE_DOWNLOAD);
        if d.rx.complete() {
            d.phase = BlockDownPhase::End;
        }
        self.transfer = Transfer::BlockDown(d);
        ServerFrame::BlockDownloadAck {
            ackseq,
            blksize: SDO_BLOCKSIZE_DOWNLOAD,
        }
    }

    /// The confirmation of a sub-block whose last segment did not come
    /// (see [`super::block`]): due half a timeout after the last segment.
    fn stalled_sub_block(&mut self, now: Ticks) -> Option<ServerFrame> {
        let Transfer::BlockDown(d) = self.transfer else {
            return None;
        };
        let half = self.timeout_ticks / 2;
        if d.phase != BlockDownPhase::SubBlock
            || !d.rx.stalled()
            || half == 0
            || now.since(d.last_rx) < half
        {
            return None;
        }
        Some(self.confirm_sub_block(BlockDownload { last_rx: now, ..d }))
    }

    /// The end frame of a block download: checks length and CRC, then
    /// writes the value with one dictionary write.
    fn block_download_end(
        &mut self,
        od: &ObjectDictionary,
        hooks: &mut impl WriteHooks,
        d: BlockDownload,
        unused: u8,
        crc: u16,
    ) -> ServerFrame {
        let mux = d.mux;
        let padded = d.rx.segments().saturating_mul(SEGMENT_MAX);
        let len = padded.saturating_sub(usize::from(unused));
        if len > self.buf.len() {
            return self.abort(mux, SdoAbort::LengthTooHigh.code());
        }
        if d.size.is_some_and(|s| s != len) {
            return self.abort(mux, SdoAbort::LengthMismatch.code());
        }
        let last_start = padded.saturating_sub(SEGMENT_MAX);
        let tail = self.buf.get(last_start..len).unwrap_or(&[]);
        if d.crc && block_crc(d.crc_acc, tail) != crc {
            return self.abort(mux, SdoAbort::CrcError.code());
        }
        self.transfer = Transfer::Idle;
        let value = self.buf.get(..len).unwrap_or(&[]);
        match od.write(mux.index, mux.sub, ByteOrder::Wire, value, hooks) {
            // Confirmed only once the value is stored.
            Ok(()) => ServerFrame::BlockDownloadEndResponse,
            Err(e) => self.abort(mux, e.abort),
        }
    }

    fn block_upload_initiate(
        &mut self,
        od: &ObjectDictionary,
        mux: Multiplexer,
        crc: bool,
        blksize: u8,
        pst: u8,
        now: Ticks,
    ) -> ServerFrame {
        if !valid_blksize(blksize) {
            return self.abort(mux, SdoAbort::InvalidBlockSize.code());
        }
        let len = match self.snapshot(od, mux) {
            Ok(n) => n,
            Err(code) => return self.abort(mux, code),
        };
        if pst > 0 && len <= usize::from(pst) {
            // Protocol switch (CiA 301): the SDO upload protocol is cheaper
            // for a value this short.
            return self.upload_response(mux, len, now);
        }
        self.transfer = Transfer::BlockUp(BlockUpload {
            mux,
            len,
            crc,
            tx: BlockTx::new(len, blksize),
            phase: BlockUpPhase::Start,
            last_rx: now,
        });
        ServerFrame::BlockUploadInitiateResponse {
            mux,
            crc: true,
            size: u32::try_from(len).ok(),
        }
    }

    /// The client's confirmation of a sub-block: the next sub-block goes
    /// out (through [`SdoServer::pending_segment`]), or the end frame.
    fn block_upload_ack(
        &mut self,
        mut u: BlockUpload,
        ackseq: u8,
        blksize: u8,
        now: Ticks,
    ) -> Option<ServerFrame> {
        u.last_rx = now;
        match u.tx.on_ack(ackseq, blksize) {
            Err(code) => Some(self.abort(u.mux, code.code())),
            Ok(false) => {
                self.transfer = Transfer::BlockUp(u);
                None
            }
            Ok(true) => {
                u.phase = BlockUpPhase::End;
                self.transfer = Transfer::BlockUp(u);
                let crc = if u.crc {
                    // Every byte went out at least once, so the sender's
                    // running CRC covers the whole value.
                    u.tx.crc()
                } else {
                    0
                };
                Some(ServerFrame::BlockUploadEnd {
                    unused: u.tx.unused(),
                    crc,
                })
            }
        }
    }
}

/// The node's SDO servers: the default server 0x1200 and the additional
/// servers 0x1201.. up to [`SDO_MAX_SERVER_IN_OBD`], one channel each
/// whether or not its object exists (a channel without its object answers
/// nothing).
#[derive(Clone, Debug)]
pub struct SdoServers {
    channels: [SdoServer; SDO_MAX_SERVER_IN_OBD],
}

crate::od::decl::default_is_new!(SdoServers);

impl SdoServers {
    /// Every channel unconfigured.
    pub fn new() -> Self {
        SdoServers {
            channels: core::array::from_fn(|n| {
                SdoServer::with_index(SERVER_PARAMETER_INDEX + n as u16)
            }),
        }
    }

    /// [`SdoServer::reconfigure`] of every channel.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, node: u8) {
        for s in &mut self.channels {
            s.reconfigure(od, node);
        }
    }

    /// [`SdoServer::cancel`] of every channel.
    pub fn cancel(&mut self) {
        for s in &mut self.channels {
            s.cancel();
        }
    }

    /// True when no channel has a transfer running.
    #[inline]
    pub fn at_rest(&self) -> bool {
        self.channels.iter().all(SdoServer::at_rest)
    }

    /// The channel whose request COB-ID is `id` (the lowest index where
    /// several have it).
    #[inline]
    pub fn receiving(&mut self, id: CanId) -> Option<&mut SdoServer> {
        self.channels.iter_mut().find(|s| s.rx_id() == Some(id))
    }

    /// The channels in the order of their objects, 0x1200 first.
    pub fn channels(&self) -> &[SdoServer] {
        &self.channels
    }

    /// As [`SdoServers::channels`], to poll or send.
    pub fn channels_mut(&mut self) -> &mut [SdoServer] {
        &mut self.channels
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

/// One COB-ID of server parameter object `index` (`sub` 1 or 2); for the
/// default server 0x1200 also base + node-ID.
fn cob_id(od: &ObjectDictionary, index: u16, sub: u8, base: u16, node: u8) -> Option<CanId> {
    let default = if index == SERVER_PARAMETER_INDEX {
        CanId::std(base.wrapping_add(u16::from(node)))
    } else {
        None
    };
    let Ok(raw) = od.read_uint(index, sub) else {
        return default;
    };
    let v = (raw & 0xFFFF_FFFF) as u32;
    if v & COB_ID_INVALID != 0 || !super::usable_cob_id(v) {
        return None;
    }
    if v == u32::from(base) {
        if let Some(id) = default {
            // The object holds the predefined base: it must show the COB-ID
            // in use (CiA 301), so the node-ID goes into the object too.
            let _ = od.poke_uint(index, sub, u64::from(id.raw()));
            return default;
        }
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
