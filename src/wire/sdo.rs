//! SDO frame layouts (CiA 301 SDO protocols): expedited, segmented and block
//! transfer, abort. Pure encoding and decoding in both directions, so that
//! the SDO server and an SDO client share one implementation of the byte
//! layout.
//!
//! Every SDO frame carries 8 data bytes. Byte 0 is the command byte: the
//! command specifier in bits 7..5 and protocol flags below it; initiate and
//! abort frames carry the multiplexer (index little-endian, subindex) in
//! bytes 1..3 and data, size or abort code in bytes 4..7; segment frames
//! carry up to 7 data bytes in bytes 1..7.
//!
//! Reserved bits are ignored when decoding and sent as 0 (CiA 301: "not
//! used, always 0"), so that a peer that sets them still interoperates.
//! The reserved command specifier 7 decodes as
//! [`DecodeError::UnsupportedCommand`].
//!
//! # Block transfer
//! Block download uses ccs = 6 / scs = 5, block upload ccs = 5 / scs = 6
//! (CiA 301 SDO block download and block upload protocols); the low bits of
//! byte 0 select the step (initiate, sub-block confirmation, start, end).
//! Inside a sub-block the frames are segments whose byte 0 is
//! `c << 7 | seqno`: any value of byte 0 is a valid segment, so a segment
//! cannot be told from a command by its bytes. The receiving side decodes
//! a frame as [`SubBlockFrame`] while a sub-block runs and as
//! [`ClientFrame`] / [`ServerFrame`] otherwise. The CRC of the data is
//! [`block_crc`].

use crc::{CRC_16_XMODEM, Crc, NoTable};

use crate::port::{CanFrame, CanId};

/// Base COB-ID of the default SDO server's requests (client to server) in
/// the predefined connection set; the server listens on base + node-ID.
pub const REQUEST_BASE: u16 = 0x600;
/// Base COB-ID of the default SDO server's responses (server to client).
pub const RESPONSE_BASE: u16 = 0x580;
/// Every SDO frame has exactly this many data bytes (CiA 301 SDO protocols).
pub const FRAME_LEN: usize = 8;
/// Most data bytes an expedited transfer carries.
pub const EXPEDITED_MAX: usize = 4;
/// Most data bytes one segment carries.
pub const SEGMENT_MAX: usize = 7;

// Command specifiers (bits 7..5 of byte 0). The client's (ccs) and the
// server's (scs) numbering differ for the same service, which is why both
// directions have their own frame type below.
const CCS_DOWNLOAD_SEGMENT: u8 = 0;
const CCS_INITIATE_DOWNLOAD: u8 = 1;
const CCS_INITIATE_UPLOAD: u8 = 2;
const CCS_UPLOAD_SEGMENT: u8 = 3;
const SCS_UPLOAD_SEGMENT: u8 = 0;
const SCS_DOWNLOAD_SEGMENT: u8 = 1;
const SCS_INITIATE_UPLOAD: u8 = 2;
const SCS_INITIATE_DOWNLOAD: u8 = 3;
const CS_ABORT: u8 = 4;
const CCS_BLOCK_UPLOAD: u8 = 5;
const CCS_BLOCK_DOWNLOAD: u8 = 6;
const SCS_BLOCK_DOWNLOAD: u8 = 5;
const SCS_BLOCK_UPLOAD: u8 = 6;

// Sub-commands of block transfer (cs / ss, the low bits of byte 0).
const BLOCK_INITIATE: u8 = 0;
const BLOCK_END: u8 = 1;
const BLOCK_ACK: u8 = 2;
const BLOCK_START: u8 = 3;
/// cc / sc: the sender supports the CRC.
const BLOCK_CRC: u8 = 0x04;
/// s: the size is indicated (block download initiate, block upload
/// initiate response).
const BLOCK_SIZE: u8 = 0x02;
/// c of a sub-block segment: no more segments follow.
const BLOCK_LAST: u8 = 0x80;
/// Highest sequence number and block size (CiA 301: 0 < blksize < 128).
pub const BLKSIZE_MAX: u8 = 127;

// Flag bits of byte 0.
const TOGGLE: u8 = 0x10;
const EXPEDITED: u8 = 0x02;
const SIZE_INDICATED: u8 = 0x01;
const LAST_SEGMENT: u8 = 0x01;

/// The object a transfer addresses: index and subindex.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Multiplexer {
    /// Object index.
    pub index: u16,
    /// Subindex.
    pub sub: u8,
}

impl Multiplexer {
    /// Index and subindex.
    pub const fn new(index: u16, sub: u8) -> Self {
        Multiplexer { index, sub }
    }

    /// Reads bytes 1..3 of a frame. Only initiate, abort and block-initiate
    /// frames have a multiplexer there; for segments these are data bytes.
    pub const fn from_frame(data: &[u8; FRAME_LEN]) -> Self {
        Multiplexer {
            index: u16::from_le_bytes([data[1], data[2]]),
            sub: data[3],
        }
    }

    fn put(self, out: &mut [u8; FRAME_LEN]) {
        let [lo, hi] = self.index.to_le_bytes();
        out[1] = lo;
        out[2] = hi;
        out[3] = self.sub;
    }
}

/// Up to `N` data bytes (an expedited value: `N` = 4, a segment: `N` = 7).
/// The length is checked on construction, so an over-long value cannot be
/// built and every encoder is total.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Chunk<const N: usize> {
    bytes: [u8; N],
    len: u8,
}

/// The data of an expedited transfer.
pub type ExpeditedData = Chunk<EXPEDITED_MAX>;
/// The data of one segment.
pub type SegmentData = Chunk<SEGMENT_MAX>;

impl<const N: usize> Chunk<N> {
    /// No data.
    pub const fn empty() -> Self {
        Chunk {
            bytes: [0; N],
            len: 0,
        }
    }

    /// Copies `data`; `None` when it is longer than `N` bytes.
    pub fn new(data: &[u8]) -> Option<Self> {
        let mut bytes = [0u8; N];
        bytes.get_mut(..data.len())?.copy_from_slice(data);
        Some(Chunk {
            bytes,
            len: u8::try_from(data.len()).ok()?,
        })
    }

    /// The data bytes.
    pub fn as_slice(&self) -> &[u8] {
        self.bytes.get(..usize::from(self.len)).unwrap_or(&[])
    }

    /// All `N` bytes, unused ones zero.
    pub const fn padded(&self) -> &[u8; N] {
        &self.bytes
    }

    /// Number of data bytes.
    pub const fn len(&self) -> usize {
        self.len as usize
    }

    /// True when there is no data.
    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Number of unused bytes: the `n` field of the command byte.
    const fn unused(&self) -> u8 {
        // len <= N <= 7 by construction.
        (N as u8).saturating_sub(self.len)
    }

    /// Builds a chunk from `N` frame bytes of which the last `unused` carry
    /// no data.
    fn from_frame(src: &[u8], unused: u8) -> Self {
        let mut bytes = [0u8; N];
        let len = N.saturating_sub(usize::from(unused));
        for (b, s) in bytes.iter_mut().zip(src).take(len) {
            *b = *s;
        }
        Chunk {
            bytes,
            // len <= N <= 7.
            len: len as u8,
        }
    }
}

/// What an initiate frame (download request or upload response) says about
/// the data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Initiate {
    /// e = 1: the data travels in this frame.
    Expedited {
        /// The data. When `sized` is false all four bytes are given and the
        /// receiver decides how many belong to the value.
        data: ExpeditedData,
        /// s: the frame states the number of bytes. An empty `data` cannot
        /// be stated (the field encodes 1..4) and is sent as not sized.
        sized: bool,
    },
    /// e = 0: segments follow.
    Segmented {
        /// s = 1: the total number of bytes.
        size: Option<u32>,
    },
}

impl Initiate {
    /// An expedited transfer of `data` (1..=4 bytes) with its size stated.
    pub fn expedited(data: &[u8]) -> Option<Self> {
        Some(Initiate::Expedited {
            data: ExpeditedData::new(data)?,
            sized: true,
        })
    }

    fn encode(self, cs: u8, out: &mut [u8; FRAME_LEN]) {
        match self {
            Initiate::Expedited { data, sized } => {
                let mut cmd = (cs << 5) | EXPEDITED;
                if sized && !data.is_empty() {
                    cmd |= SIZE_INDICATED | (data.unused() << 2);
                }
                out[0] = cmd;
                out[4..8].copy_from_slice(data.padded());
            }
            Initiate::Segmented { size } => {
                out[0] = cs << 5;
                if let Some(n) = size {
                    out[0] |= SIZE_INDICATED;
                    out[4..8].copy_from_slice(&n.to_le_bytes());
                }
            }
        }
    }

    fn decode(data: &[u8; FRAME_LEN]) -> Self {
        let cmd = data[0];
        let tail = &data[4..8];
        if cmd & EXPEDITED != 0 {
            if cmd & SIZE_INDICATED != 0 {
                Initiate::Expedited {
                    data: ExpeditedData::from_frame(tail, (cmd >> 2) & 0x03),
                    sized: true,
                }
            } else {
                Initiate::Expedited {
                    data: ExpeditedData::from_frame(tail, 0),
                    sized: false,
                }
            }
        } else if cmd & SIZE_INDICATED != 0 {
            Initiate::Segmented {
                size: Some(u32::from_le_bytes([data[4], data[5], data[6], data[7]])),
            }
        } else {
            Initiate::Segmented { size: None }
        }
    }
}

/// A frame from the SDO client to the server.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClientFrame {
    /// Initiate SDO download (ccs = 1).
    InitiateDownload {
        /// Addressed object.
        mux: Multiplexer,
        /// Expedited data or announced size.
        payload: Initiate,
    },
    /// Download SDO segment (ccs = 0).
    DownloadSegment {
        /// Toggle bit t (0 in the first segment).
        toggle: bool,
        /// Segment data.
        data: SegmentData,
        /// c: no more segments follow.
        last: bool,
    },
    /// Initiate SDO upload (ccs = 2).
    InitiateUpload {
        /// Addressed object.
        mux: Multiplexer,
    },
    /// Upload SDO segment request (ccs = 3).
    UploadSegment {
        /// Toggle bit t (0 in the first request).
        toggle: bool,
    },
    /// Abort SDO transfer (cs = 4).
    Abort {
        /// Object of the aborted transfer.
        mux: Multiplexer,
        /// Abort code (CiA 301 abort codes, [`crate::error::SdoAbort`]).
        code: u32,
    },
    /// Initiate SDO block download (ccs = 6, cs = 0).
    BlockDownloadInitiate {
        /// Addressed object.
        mux: Multiplexer,
        /// cc: the client supports the CRC.
        crc: bool,
        /// s = 1: the number of bytes (bytes 4..7).
        size: Option<u32>,
    },
    /// End SDO block download (ccs = 6, cs = 1).
    BlockDownloadEnd {
        /// n: bytes of the last segment that carry no data (0..=7).
        unused: u8,
        /// CRC of the whole data (0 when no CRC was agreed).
        crc: u16,
    },
    /// Initiate SDO block upload (ccs = 5, cs = 0).
    BlockUploadInitiate {
        /// Addressed object.
        mux: Multiplexer,
        /// cc: the client supports the CRC.
        crc: bool,
        /// Segments per sub-block the client accepts (valid: 1..=127).
        blksize: u8,
        /// Protocol switch threshold: a value of at most this many bytes may
        /// be answered with the SDO upload protocol instead (0: no switch).
        pst: u8,
    },
    /// Start SDO block upload (ccs = 5, cs = 3).
    BlockUploadStart,
    /// SDO block upload sub-block confirmation (ccs = 5, cs = 2).
    BlockUploadAck {
        /// Sequence number of the last segment received in order (0: none).
        ackseq: u8,
        /// Segments in the next sub-block.
        blksize: u8,
    },
    /// End SDO block upload response (ccs = 5, cs = 1).
    BlockUploadEndResponse,
}

/// A frame from the SDO server to the client.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ServerFrame {
    /// Initiate SDO download response (scs = 3).
    InitiateDownloadResponse {
        /// Object being written.
        mux: Multiplexer,
    },
    /// Download SDO segment response (scs = 1).
    DownloadSegmentResponse {
        /// Toggle bit of the acknowledged segment.
        toggle: bool,
    },
    /// Initiate SDO upload response (scs = 2).
    InitiateUploadResponse {
        /// Object being read.
        mux: Multiplexer,
        /// Expedited data or the size of the segmented transfer.
        payload: Initiate,
    },
    /// Upload SDO segment response (scs = 0).
    UploadSegmentResponse {
        /// Toggle bit of the answered request.
        toggle: bool,
        /// Segment data.
        data: SegmentData,
        /// c: no more segments follow.
        last: bool,
    },
    /// Abort SDO transfer (cs = 4).
    Abort {
        /// Object of the aborted transfer.
        mux: Multiplexer,
        /// Abort code.
        code: u32,
    },
    /// Initiate SDO block download response (scs = 5, ss = 0).
    BlockDownloadInitiateResponse {
        /// Object being written.
        mux: Multiplexer,
        /// sc: the server supports the CRC.
        crc: bool,
        /// Segments per sub-block the server accepts.
        blksize: u8,
    },
    /// SDO block download sub-block confirmation (scs = 5, ss = 2).
    BlockDownloadAck {
        /// Sequence number of the last segment received in order (0: none).
        ackseq: u8,
        /// Segments in the next sub-block.
        blksize: u8,
    },
    /// End SDO block download response (scs = 5, ss = 1).
    BlockDownloadEndResponse,
    /// Initiate SDO block upload response (scs = 6, ss = 0).
    BlockUploadInitiateResponse {
        /// Object being read.
        mux: Multiplexer,
        /// sc: the server supports the CRC.
        crc: bool,
        /// s = 1: the number of bytes.
        size: Option<u32>,
    },
    /// End SDO block upload request (scs = 6, ss = 1).
    BlockUploadEnd {
        /// n: bytes of the last segment that carry no data (0..=7).
        unused: u8,
        /// CRC of the whole data (0 when no CRC was agreed).
        crc: u16,
    },
}

/// Why 8 bytes are not a frame of this module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecodeError {
    /// A remote frame or a data length other than 8.
    Length,
    /// The reserved command specifier 7, or the unused step 3 of block
    /// download responses (scs = 5).
    UnsupportedCommand {
        /// The command specifier (bits 7..5 of byte 0).
        cs: u8,
        /// Bytes 1..3 (the multiplexer, in block-initiate frames).
        mux: Multiplexer,
    },
}

/// The 8 data bytes of an SDO frame; `Err(Length)` for remote frames and
/// frames with another data length.
pub fn frame_bytes(frame: &CanFrame) -> Result<&[u8; FRAME_LEN], DecodeError> {
    if frame.rtr || usize::from(frame.len) != FRAME_LEN {
        return Err(DecodeError::Length);
    }
    Ok(&frame.data)
}

fn segment(cs: u8, toggle: bool, data: &SegmentData, last: bool) -> [u8; FRAME_LEN] {
    let mut out = [0u8; FRAME_LEN];
    out[0] = (cs << 5) | (data.unused() << 1);
    if toggle {
        out[0] |= TOGGLE;
    }
    if last {
        out[0] |= LAST_SEGMENT;
    }
    out[1..8].copy_from_slice(data.padded());
    out
}

fn decode_segment(data: &[u8; FRAME_LEN]) -> (bool, SegmentData, bool) {
    let cmd = data[0];
    (
        cmd & TOGGLE != 0,
        SegmentData::from_frame(&data[1..8], (cmd >> 1) & 0x07),
        cmd & LAST_SEGMENT != 0,
    )
}

fn toggle_only(cs: u8, toggle: bool) -> [u8; FRAME_LEN] {
    let mut out = [0u8; FRAME_LEN];
    out[0] = cs << 5;
    if toggle {
        out[0] |= TOGGLE;
    }
    out
}

fn abort(mux: Multiplexer, code: u32) -> [u8; FRAME_LEN] {
    let mut out = [0u8; FRAME_LEN];
    out[0] = CS_ABORT << 5;
    mux.put(&mut out);
    out[4..8].copy_from_slice(&code.to_le_bytes());
    out
}

fn abort_code(data: &[u8; FRAME_LEN]) -> u32 {
    u32::from_le_bytes([data[4], data[5], data[6], data[7]])
}

fn with_mux(mux: Multiplexer, mut out: [u8; FRAME_LEN]) -> [u8; FRAME_LEN] {
    mux.put(&mut out);
    out
}

/// Byte 0 of a block frame: specifier, flags and step.
const fn block_cmd(cs: u8, step: u8, crc: bool) -> u8 {
    (cs << 5) | step | if crc { BLOCK_CRC } else { 0 }
}

/// An initiate frame of block transfer with optional size.
fn block_initiate(cs: u8, mux: Multiplexer, crc: bool, size: Option<u32>) -> [u8; FRAME_LEN] {
    let mut out = [0u8; FRAME_LEN];
    out[0] = block_cmd(cs, BLOCK_INITIATE, crc);
    if let Some(n) = size {
        out[0] |= BLOCK_SIZE;
        out[4..8].copy_from_slice(&n.to_le_bytes());
    }
    with_mux(mux, out)
}

/// An end frame (n in bits 4..2, CRC in bytes 1..2).
fn block_end(cs: u8, unused: u8, crc: u16) -> [u8; FRAME_LEN] {
    let mut out = [0u8; FRAME_LEN];
    out[0] = (cs << 5) | ((unused & 0x07) << 2) | BLOCK_END;
    out[1..3].copy_from_slice(&crc.to_le_bytes());
    out
}

/// A sub-block confirmation (ackseq in byte 1, blksize in byte 2).
fn block_ack(cs: u8, ackseq: u8, blksize: u8) -> [u8; FRAME_LEN] {
    let mut out = [0u8; FRAME_LEN];
    out[0] = (cs << 5) | BLOCK_ACK;
    out[1] = ackseq;
    out[2] = blksize;
    out
}

fn block_size(data: &[u8; FRAME_LEN]) -> Option<u32> {
    (data[0] & BLOCK_SIZE != 0).then(|| u32::from_le_bytes([data[4], data[5], data[6], data[7]]))
}

const fn end_unused(data: &[u8; FRAME_LEN]) -> u8 {
    (data[0] >> 2) & 0x07
}

const fn end_crc(data: &[u8; FRAME_LEN]) -> u16 {
    u16::from_le_bytes([data[1], data[2]])
}

/// The block-transfer frames of the side that sends the data (client in a
/// download, server in an upload; specifier 6 in both directions):
/// initiate with the size, and end with the CRC.
#[derive(Clone, Copy)]
enum SenderBlock {
    Initiate {
        mux: Multiplexer,
        crc: bool,
        size: Option<u32>,
    },
    End {
        unused: u8,
        crc: u16,
    },
}

impl SenderBlock {
    #[inline(always)]
    fn encode(self, cs: u8) -> [u8; FRAME_LEN] {
        match self {
            SenderBlock::Initiate { mux, crc, size } => block_initiate(cs, mux, crc, size),
            SenderBlock::End { unused, crc } => block_end(cs, unused, crc),
        }
    }

    #[inline(always)]
    fn decode(data: &[u8; FRAME_LEN]) -> Self {
        if data[0] & 0x01 == BLOCK_END {
            SenderBlock::End {
                unused: end_unused(data),
                crc: end_crc(data),
            }
        } else {
            SenderBlock::Initiate {
                mux: Multiplexer::from_frame(data),
                crc: data[0] & BLOCK_CRC != 0,
                size: block_size(data),
            }
        }
    }
}

/// The block-transfer frames of the side that receives the data (server
/// in a download, client in an upload; specifier 5 in both directions):
/// initiate with the block size (and, from the client, the protocol
/// switch threshold), the sub-block confirmation, the end response, and
/// the client's start.
#[derive(Clone, Copy)]
enum ReceiverBlock {
    Initiate {
        mux: Multiplexer,
        crc: bool,
        blksize: u8,
        pst: u8,
    },
    Ack {
        ackseq: u8,
        blksize: u8,
    },
    End,
    Start,
}

impl ReceiverBlock {
    #[inline(always)]
    fn encode(self, cs: u8) -> [u8; FRAME_LEN] {
        let mut out = [0u8; FRAME_LEN];
        match self {
            ReceiverBlock::Initiate {
                mux,
                crc,
                blksize,
                pst,
            } => {
                out[0] = block_cmd(cs, BLOCK_INITIATE, crc);
                out[4] = blksize;
                out[5] = pst;
                mux.put(&mut out);
            }
            ReceiverBlock::Ack { ackseq, blksize } => return block_ack(cs, ackseq, blksize),
            ReceiverBlock::End => out[0] = block_cmd(cs, BLOCK_END, false),
            ReceiverBlock::Start => out[0] = block_cmd(cs, BLOCK_START, false),
        }
        out
    }

    #[inline(always)]
    fn decode(data: &[u8; FRAME_LEN]) -> Self {
        match data[0] & 0x03 {
            BLOCK_INITIATE => ReceiverBlock::Initiate {
                mux: Multiplexer::from_frame(data),
                crc: data[0] & BLOCK_CRC != 0,
                blksize: data[4],
                pst: data[5],
            },
            BLOCK_END => ReceiverBlock::End,
            BLOCK_ACK => ReceiverBlock::Ack {
                ackseq: data[1],
                blksize: data[2],
            },
            _ => ReceiverBlock::Start,
        }
    }
}

/// The error of a frame with an unsupported command specifier `cs`.
fn unsupported(cs: u8, data: &[u8; FRAME_LEN]) -> DecodeError {
    DecodeError::UnsupportedCommand {
        cs,
        mux: Multiplexer::from_frame(data),
    }
}

/// `from_can` and `to_can` of a frame type with `decode` and `encode`.
macro_rules! can_conversions {
    ($frame:ty) => {
        impl $frame {
            /// Decodes a received CAN frame (see [`frame_bytes`]).
            pub fn from_can(frame: &CanFrame) -> Result<Self, DecodeError> {
                Self::decode(frame_bytes(frame)?)
            }

            /// A CAN frame with this content.
            pub fn to_can(&self, id: CanId) -> CanFrame {
                CanFrame::new(id, &self.encode())
            }
        }
    };
}

impl ClientFrame {
    /// The 8 data bytes of this frame.
    pub fn encode(&self) -> [u8; FRAME_LEN] {
        match *self {
            ClientFrame::InitiateDownload { mux, payload } => {
                let mut out = [0u8; FRAME_LEN];
                payload.encode(CCS_INITIATE_DOWNLOAD, &mut out);
                with_mux(mux, out)
            }
            ClientFrame::DownloadSegment { toggle, data, last } => {
                segment(CCS_DOWNLOAD_SEGMENT, toggle, &data, last)
            }
            ClientFrame::InitiateUpload { mux } => {
                with_mux(mux, toggle_only(CCS_INITIATE_UPLOAD, false))
            }
            ClientFrame::UploadSegment { toggle } => toggle_only(CCS_UPLOAD_SEGMENT, toggle),
            ClientFrame::Abort { mux, code } => abort(mux, code),
            ClientFrame::BlockDownloadInitiate { mux, crc, size } => {
                SenderBlock::Initiate { mux, crc, size }.encode(CCS_BLOCK_DOWNLOAD)
            }
            ClientFrame::BlockDownloadEnd { unused, crc } => {
                SenderBlock::End { unused, crc }.encode(CCS_BLOCK_DOWNLOAD)
            }
            ClientFrame::BlockUploadInitiate {
                mux,
                crc,
                blksize,
                pst,
            } => ReceiverBlock::Initiate {
                mux,
                crc,
                blksize,
                pst,
            }
            .encode(CCS_BLOCK_UPLOAD),
            ClientFrame::BlockUploadStart => ReceiverBlock::Start.encode(CCS_BLOCK_UPLOAD),
            ClientFrame::BlockUploadAck { ackseq, blksize } => {
                ReceiverBlock::Ack { ackseq, blksize }.encode(CCS_BLOCK_UPLOAD)
            }
            ClientFrame::BlockUploadEndResponse => ReceiverBlock::End.encode(CCS_BLOCK_UPLOAD),
        }
    }

    /// Decodes 8 data bytes.
    pub fn decode(data: &[u8; FRAME_LEN]) -> Result<Self, DecodeError> {
        Ok(match data[0] >> 5 {
            CCS_DOWNLOAD_SEGMENT => {
                let (toggle, data, last) = decode_segment(data);
                ClientFrame::DownloadSegment { toggle, data, last }
            }
            CCS_INITIATE_DOWNLOAD => ClientFrame::InitiateDownload {
                mux: Multiplexer::from_frame(data),
                payload: Initiate::decode(data),
            },
            CCS_INITIATE_UPLOAD => ClientFrame::InitiateUpload {
                mux: Multiplexer::from_frame(data),
            },
            CCS_UPLOAD_SEGMENT => ClientFrame::UploadSegment {
                toggle: data[0] & TOGGLE != 0,
            },
            CS_ABORT => ClientFrame::Abort {
                mux: Multiplexer::from_frame(data),
                code: abort_code(data),
            },
            CCS_BLOCK_UPLOAD => match ReceiverBlock::decode(data) {
                ReceiverBlock::Initiate {
                    mux,
                    crc,
                    blksize,
                    pst,
                } => ClientFrame::BlockUploadInitiate {
                    mux,
                    crc,
                    blksize,
                    pst,
                },
                ReceiverBlock::End => ClientFrame::BlockUploadEndResponse,
                ReceiverBlock::Ack { ackseq, blksize } => {
                    ClientFrame::BlockUploadAck { ackseq, blksize }
                }
                ReceiverBlock::Start => ClientFrame::BlockUploadStart,
            },
            CCS_BLOCK_DOWNLOAD => match SenderBlock::decode(data) {
                SenderBlock::End { unused, crc } => ClientFrame::BlockDownloadEnd { unused, crc },
                SenderBlock::Initiate { mux, crc, size } => {
                    ClientFrame::BlockDownloadInitiate { mux, crc, size }
                }
            },
            cs => return Err(unsupported(cs, data)),
        })
    }
}

can_conversions!(ClientFrame);

impl ServerFrame {
    /// The 8 data bytes of this frame.
    pub fn encode(&self) -> [u8; FRAME_LEN] {
        match *self {
            ServerFrame::InitiateDownloadResponse { mux } => {
                with_mux(mux, toggle_only(SCS_INITIATE_DOWNLOAD, false))
            }
            ServerFrame::DownloadSegmentResponse { toggle } => {
                toggle_only(SCS_DOWNLOAD_SEGMENT, toggle)
            }
            ServerFrame::InitiateUploadResponse { mux, payload } => {
                let mut out = [0u8; FRAME_LEN];
                payload.encode(SCS_INITIATE_UPLOAD, &mut out);
                with_mux(mux, out)
            }
            ServerFrame::UploadSegmentResponse { toggle, data, last } => {
                segment(SCS_UPLOAD_SEGMENT, toggle, &data, last)
            }
            ServerFrame::Abort { mux, code } => abort(mux, code),
            ServerFrame::BlockDownloadInitiateResponse { mux, crc, blksize } => {
                ReceiverBlock::Initiate {
                    mux,
                    crc,
                    blksize,
                    pst: 0,
                }
                .encode(SCS_BLOCK_DOWNLOAD)
            }
            ServerFrame::BlockDownloadAck { ackseq, blksize } => {
                ReceiverBlock::Ack { ackseq, blksize }.encode(SCS_BLOCK_DOWNLOAD)
            }
            ServerFrame::BlockDownloadEndResponse => ReceiverBlock::End.encode(SCS_BLOCK_DOWNLOAD),
            ServerFrame::BlockUploadInitiateResponse { mux, crc, size } => {
                SenderBlock::Initiate { mux, crc, size }.encode(SCS_BLOCK_UPLOAD)
            }
            ServerFrame::BlockUploadEnd { unused, crc } => {
                SenderBlock::End { unused, crc }.encode(SCS_BLOCK_UPLOAD)
            }
        }
    }

    /// Decodes 8 data bytes.
    pub fn decode(data: &[u8; FRAME_LEN]) -> Result<Self, DecodeError> {
        Ok(match data[0] >> 5 {
            SCS_UPLOAD_SEGMENT => {
                let (toggle, data, last) = decode_segment(data);
                ServerFrame::UploadSegmentResponse { toggle, data, last }
            }
            SCS_DOWNLOAD_SEGMENT => ServerFrame::DownloadSegmentResponse {
                toggle: data[0] & TOGGLE != 0,
            },
            SCS_INITIATE_UPLOAD => ServerFrame::InitiateUploadResponse {
                mux: Multiplexer::from_frame(data),
                payload: Initiate::decode(data),
            },
            SCS_INITIATE_DOWNLOAD => ServerFrame::InitiateDownloadResponse {
                mux: Multiplexer::from_frame(data),
            },
            CS_ABORT => ServerFrame::Abort {
                mux: Multiplexer::from_frame(data),
                code: abort_code(data),
            },
            SCS_BLOCK_DOWNLOAD => match ReceiverBlock::decode(data) {
                ReceiverBlock::Initiate {
                    mux, crc, blksize, ..
                } => ServerFrame::BlockDownloadInitiateResponse { mux, crc, blksize },
                ReceiverBlock::End => ServerFrame::BlockDownloadEndResponse,
                ReceiverBlock::Ack { ackseq, blksize } => {
                    ServerFrame::BlockDownloadAck { ackseq, blksize }
                }
                // Step 3 is the client's start; no server sends it.
                ReceiverBlock::Start => return Err(unsupported(SCS_BLOCK_DOWNLOAD, data)),
            },
            SCS_BLOCK_UPLOAD => match SenderBlock::decode(data) {
                SenderBlock::End { unused, crc } => ServerFrame::BlockUploadEnd { unused, crc },
                SenderBlock::Initiate { mux, crc, size } => {
                    ServerFrame::BlockUploadInitiateResponse { mux, crc, size }
                }
            },
            cs => return Err(unsupported(cs, data)),
        })
    }
}

can_conversions!(ServerFrame);

/// One segment of a sub-block (CiA 301 download / upload SDO block segment
/// protocols), the same layout in both directions: byte 0 is c (bit 7, no
/// more segments follow) and seqno (bits 6..0), bytes 1..7 are data. How
/// many bytes of the last segment are data is said only by the end frame
/// that follows, so a segment always carries all seven.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlockSegment {
    /// Sequence number within the sub-block, 1..=127 in a valid segment
    /// (decoding keeps whatever bits 6..0 hold).
    pub seqno: u8,
    /// c: the last segment of the transfer.
    pub last: bool,
    /// The seven data bytes (unused ones of the last segment included).
    pub data: [u8; SEGMENT_MAX],
}

impl BlockSegment {
    /// A segment with `data` (at most 7 bytes, padded with 0); `None` for a
    /// longer `data` or a sequence number outside 1..=127.
    pub fn new(seqno: u8, last: bool, data: &[u8]) -> Option<Self> {
        if !(1..=BLKSIZE_MAX).contains(&seqno) {
            return None;
        }
        let mut bytes = [0u8; SEGMENT_MAX];
        bytes.get_mut(..data.len())?.copy_from_slice(data);
        Some(BlockSegment {
            seqno,
            last,
            data: bytes,
        })
    }

    /// The 8 data bytes of this frame.
    pub fn encode(&self) -> [u8; FRAME_LEN] {
        let mut out = [0u8; FRAME_LEN];
        out[0] = (self.seqno & 0x7F) | if self.last { BLOCK_LAST } else { 0 };
        out[1..8].copy_from_slice(&self.data);
        out
    }

    /// Reads 8 data bytes as a segment (every byte pattern is one).
    pub fn decode(data: &[u8; FRAME_LEN]) -> Self {
        let mut bytes = [0u8; SEGMENT_MAX];
        bytes.copy_from_slice(&data[1..8]);
        BlockSegment {
            seqno: data[0] & 0x7F,
            last: data[0] & BLOCK_LAST != 0,
            data: bytes,
        }
    }

    /// A CAN frame with this content.
    pub fn to_can(&self, id: CanId) -> CanFrame {
        CanFrame::new(id, &self.encode())
    }
}

/// A frame received while a sub-block runs: a segment, or the abort that
/// ends the transfer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubBlockFrame {
    /// A segment.
    Segment(BlockSegment),
    /// Abort SDO transfer. Byte 0 = 0x80 would be a segment with c = 1 and
    /// the invalid sequence number 0; read as the abort it also is, a peer
    /// can end the transfer in the middle of a sub-block.
    Abort {
        /// Object of the aborted transfer.
        mux: Multiplexer,
        /// Abort code.
        code: u32,
    },
}

impl SubBlockFrame {
    /// Decodes 8 data bytes received inside a sub-block.
    pub fn decode(data: &[u8; FRAME_LEN]) -> Self {
        if data[0] == CS_ABORT << 5 {
            SubBlockFrame::Abort {
                mux: Multiplexer::from_frame(data),
                code: abort_code(data),
            }
        } else {
            SubBlockFrame::Segment(BlockSegment::decode(data))
        }
    }

    /// Decodes a received CAN frame (see [`frame_bytes`]).
    pub fn from_can(frame: &CanFrame) -> Result<Self, DecodeError> {
        Ok(Self::decode(frame_bytes(frame)?))
    }
}

/// The CRC engine of block transfer. Table-less: the CRC runs over at most
/// one segment per call (about 40 instructions per byte), so the 512-byte
/// table would buy little.
static BLOCK_CRC16: Crc<u16, NoTable> = Crc::<u16, NoTable>::new(&CRC_16_XMODEM);

/// Continues the CRC of SDO block transfer over `data`; start with 0.
///
/// CiA 301 (SDO block transfer, CRC calculation) defines the CRC as
/// CRC-16 with the generator polynomial x^16 + x^12 + x^5 + 1 (0x1021),
/// initial value 0, most significant bit first, no final XOR, taken over
/// the data bytes only: the catalogued CRC-16/XMODEM. Because the result
/// is the register itself, feeding the data in pieces gives the same value
/// as feeding it at once.
pub fn block_crc(crc: u16, data: &[u8]) -> u16 {
    let mut digest = BLOCK_CRC16.digest_with_initial(crc);
    digest.update(data);
    digest.finalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    const M6200: Multiplexer = Multiplexer::new(0x6200, 1);

    /// `frame` encodes to `bytes` and `bytes` decode to `frame`.
    fn both_ways<F: PartialEq + core::fmt::Debug>(
        encode: fn(&F) -> [u8; FRAME_LEN],
        decode: fn(&[u8; FRAME_LEN]) -> Result<F, DecodeError>,
        bytes: [u8; FRAME_LEN],
        frame: F,
    ) {
        assert_eq!(encode(&frame), bytes);
        assert_eq!(decode(&bytes), Ok(frame));
    }

    /// [`both_ways`] for a client (request) frame.
    fn client(bytes: [u8; FRAME_LEN], frame: ClientFrame) {
        both_ways(ClientFrame::encode, ClientFrame::decode, bytes, frame);
    }

    /// [`both_ways`] for a server (response) frame.
    fn server(bytes: [u8; FRAME_LEN], frame: ServerFrame) {
        both_ways(ServerFrame::encode, ServerFrame::decode, bytes, frame);
    }

    #[test]
    fn seed_004_example_1_expedited_write_u8() {
        // Seed 004 "Beispiel 1": 602 2F 00 62 01 FF 00 00 00 -> 582 60 00 62 01 00 00 00 00.
        let req = [0x2F, 0x00, 0x62, 0x01, 0xFF, 0x00, 0x00, 0x00];
        let decoded = ClientFrame::decode(&req).unwrap();
        assert_eq!(
            decoded,
            ClientFrame::InitiateDownload {
                mux: M6200,
                payload: Initiate::expedited(&[0xFF]).unwrap(),
            }
        );
        assert_eq!(decoded.encode(), req);
        let resp = ServerFrame::InitiateDownloadResponse { mux: M6200 };
        assert_eq!(
            resp.encode(),
            [0x60, 0x00, 0x62, 0x01, 0x00, 0x00, 0x00, 0x00]
        );
    }

    #[test]
    fn seed_004_example_2_expedited_read_u8() {
        // Seed 004 "Beispiel 2": 602 40 00 60 01 00.. -> 582 4F 00 60 01 01 00 00 00.
        let req = [0x40, 0x00, 0x60, 0x01, 0, 0, 0, 0];
        let mux = Multiplexer::new(0x6000, 1);
        assert_eq!(
            ClientFrame::decode(&req).unwrap(),
            ClientFrame::InitiateUpload { mux }
        );
        assert_eq!(ClientFrame::InitiateUpload { mux }.encode(), req);
        let resp = ServerFrame::InitiateUploadResponse {
            mux,
            payload: Initiate::expedited(&[0x01]).unwrap(),
        };
        let bytes = [0x4F, 0x00, 0x60, 0x01, 0x01, 0x00, 0x00, 0x00];
        assert_eq!(resp.encode(), bytes);
        assert_eq!(ServerFrame::decode(&bytes).unwrap(), resp);
    }

    #[test]
    fn seed_004_example_3_expedited_read_u16() {
        // Seed 004 "Beispiel 3": the request's index high byte is printed as
        // 0x40, a typo: the text and the response name 0x6401, so the
        // request is 602 40 01 64 01 00 00 00 00 -> 582 4B 01 64 01 34 12 00 00.
        let mux = Multiplexer::new(0x6401, 1);
        assert_eq!(
            ClientFrame::InitiateUpload { mux }.encode(),
            [0x40, 0x01, 0x64, 0x01, 0, 0, 0, 0]
        );
        let resp = ServerFrame::InitiateUploadResponse {
            mux,
            payload: Initiate::expedited(&0x1234u16.to_le_bytes()).unwrap(),
        };
        assert_eq!(
            resp.encode(),
            [0x4B, 0x01, 0x64, 0x01, 0x34, 0x12, 0x00, 0x00]
        );
    }

    #[test]
    fn seed_004_command_code_table() {
        // Seed 004 appendix "Übersicht einiger SDO-Befehlscodes".
        let mux = Multiplexer::default();
        let up = |d: &[u8]| {
            ServerFrame::InitiateUploadResponse {
                mux,
                payload: Initiate::expedited(d).unwrap(),
            }
            .encode()[0]
        };
        let down = |d: &[u8]| {
            ClientFrame::InitiateDownload {
                mux,
                payload: Initiate::expedited(d).unwrap(),
            }
            .encode()[0]
        };
        assert_eq!(ClientFrame::InitiateUpload { mux }.encode()[0], 0x40);
        assert_eq!(up(&[1, 2, 3, 4]), 0x43);
        assert_eq!(up(&[1, 2]), 0x4B);
        assert_eq!(up(&[1]), 0x4F);
        assert_eq!(down(&[1, 2, 3, 4]), 0x23);
        assert_eq!(down(&[1]), 0x2F);
        assert_eq!(
            ServerFrame::InitiateDownloadResponse { mux }.encode()[0],
            0x60
        );
        assert_eq!(ServerFrame::Abort { mux, code: 0 }.encode()[0], 0x80);
        // 3 bytes (CiA 301 SDO download initiate protocol: n = 1): 0x27 / 0x47.
        assert_eq!(down(&[1, 2, 3]), 0x27);
        assert_eq!(up(&[1, 2, 3]), 0x47);
    }

    #[test]
    fn expedited_without_size_gives_all_four_bytes() {
        // CiA 301 SDO download initiate protocol: e = 1, s = 0 -> 0x22; the data size is unspecified.
        let f = ClientFrame::decode(&[0x22, 0x00, 0x20, 0x00, 1, 2, 3, 4]).unwrap();
        assert_eq!(
            f,
            ClientFrame::InitiateDownload {
                mux: Multiplexer::new(0x2000, 0),
                payload: Initiate::Expedited {
                    data: ExpeditedData::new(&[1, 2, 3, 4]).unwrap(),
                    sized: false,
                },
            }
        );
        assert_eq!(f.encode()[0], 0x22);
    }

    #[test]
    fn segmented_initiate_with_and_without_size() {
        // CiA 301 SDO download / upload initiate protocols: e = 0, s = 1 -> size in bytes 4..7.
        let sized = [0x21, 0x01, 0x20, 0x00, 0x2C, 0x01, 0x00, 0x00];
        let f = ClientFrame::decode(&sized).unwrap();
        assert_eq!(
            f,
            ClientFrame::InitiateDownload {
                mux: Multiplexer::new(0x2001, 0),
                payload: Initiate::Segmented { size: Some(300) },
            }
        );
        assert_eq!(f.encode(), sized);
        let unsized_ = [0x20, 0x01, 0x20, 0x00, 0, 0, 0, 0];
        assert_eq!(
            ClientFrame::decode(&unsized_).unwrap(),
            ClientFrame::InitiateDownload {
                mux: Multiplexer::new(0x2001, 0),
                payload: Initiate::Segmented { size: None },
            }
        );
        // Server side: 0x41 + size (initiate upload response, segmented).
        let resp = ServerFrame::InitiateUploadResponse {
            mux: Multiplexer::new(0x1008, 0),
            payload: Initiate::Segmented { size: Some(10) },
        };
        assert_eq!(
            resp.encode(),
            [0x41, 0x08, 0x10, 0x00, 0x0A, 0x00, 0x00, 0x00]
        );
    }

    #[test]
    fn download_segments_carry_toggle_size_and_last_flag() {
        // CiA 301 SDO download segment protocol: ccs = 0, t = bit 4, n = bits 3..1, c = bit 0.
        let full = SegmentData::new(&[1, 2, 3, 4, 5, 6, 7]).unwrap();
        let f = ClientFrame::DownloadSegment {
            toggle: false,
            data: full,
            last: false,
        };
        assert_eq!(f.encode(), [0x00, 1, 2, 3, 4, 5, 6, 7]);
        let f = ClientFrame::DownloadSegment {
            toggle: true,
            data: SegmentData::new(&[9, 8]).unwrap(),
            last: true,
        };
        // n = 5 -> 0x0A, t -> 0x10, c -> 0x01.
        let bytes = [0x1B, 9, 8, 0, 0, 0, 0, 0];
        assert_eq!(f.encode(), bytes);
        assert_eq!(ClientFrame::decode(&bytes).unwrap(), f);
        // Responses: scs = 1 -> 0x20 / 0x30.
        assert_eq!(
            ServerFrame::DownloadSegmentResponse { toggle: false }.encode(),
            [0x20, 0, 0, 0, 0, 0, 0, 0]
        );
        assert_eq!(
            ServerFrame::decode(&[0x30, 0, 0, 0, 0, 0, 0, 0]).unwrap(),
            ServerFrame::DownloadSegmentResponse { toggle: true }
        );
    }

    #[test]
    fn upload_segments() {
        // CiA 301 SDO upload segment protocol: request ccs = 3 -> 0x60 / 0x70; response scs = 0.
        assert_eq!(
            ClientFrame::decode(&[0x70, 0, 0, 0, 0, 0, 0, 0]).unwrap(),
            ClientFrame::UploadSegment { toggle: true }
        );
        assert_eq!(
            ClientFrame::UploadSegment { toggle: false }.encode(),
            [0x60, 0, 0, 0, 0, 0, 0, 0]
        );
        let last = ServerFrame::UploadSegmentResponse {
            toggle: true,
            data: SegmentData::new(b"abc").unwrap(),
            last: true,
        };
        // n = 4 -> 0x08, t -> 0x10, c -> 0x01.
        assert_eq!(last.encode(), [0x19, b'a', b'b', b'c', 0, 0, 0, 0]);
        let empty = ServerFrame::UploadSegmentResponse {
            toggle: false,
            data: SegmentData::empty(),
            last: true,
        };
        // n = 7: no data at all (zero-length value).
        assert_eq!(empty.encode(), [0x0F, 0, 0, 0, 0, 0, 0, 0]);
        assert_eq!(
            ServerFrame::decode(&[0x0F, 0, 0, 0, 0, 0, 0, 0]).unwrap(),
            empty
        );
    }

    #[test]
    fn abort_frame_layout() {
        // CiA 301 SDO abort transfer protocol: 0x80, multiplexer, abort code little-endian.
        let f = ServerFrame::Abort {
            mux: Multiplexer::new(0x1018, 5),
            code: 0x0609_0011,
        };
        let bytes = [0x80, 0x18, 0x10, 0x05, 0x11, 0x00, 0x09, 0x06];
        assert_eq!(f.encode(), bytes);
        assert_eq!(ServerFrame::decode(&bytes).unwrap(), f);
        assert_eq!(
            ClientFrame::decode(&bytes).unwrap(),
            ClientFrame::Abort {
                mux: Multiplexer::new(0x1018, 5),
                code: 0x0609_0011
            }
        );
    }

    #[test]
    fn reserved_specifier_is_unsupported() {
        // CiA 301: command specifier 7 is reserved in both directions.
        let r = ClientFrame::decode(&[0xE0, 0x00, 0x10, 0x02, 0, 0, 0, 0]);
        assert_eq!(
            r,
            Err(DecodeError::UnsupportedCommand {
                cs: 7,
                mux: Multiplexer::new(0x1000, 2)
            })
        );
        assert!(ServerFrame::decode(&[0xE0, 0, 0, 0, 0, 0, 0, 0]).is_err());
        // scs = 5 with ss = 3 is no block download response.
        assert!(ServerFrame::decode(&[0xA3, 0, 0, 0, 0, 0, 0, 0]).is_err());
    }

    #[test]
    fn block_download_initiate_and_response() {
        // CiA 301 initiate SDO block download protocol: ccs = 6 (bits 7..5),
        // cc = bit 2, s = bit 1, cs = 0; size in bytes 4..7. 300 bytes to
        // 0x2000.0 with CRC: C6 00 20 00 2C 01 00 00.
        let mux = Multiplexer::new(0x2000, 0);
        let sized = ClientFrame::BlockDownloadInitiate {
            mux,
            crc: true,
            size: Some(300),
        };
        client([0xC6, 0x00, 0x20, 0x00, 0x2C, 0x01, 0x00, 0x00], sized);
        // Neither CRC nor size: C0.
        let bare = ClientFrame::BlockDownloadInitiate {
            mux,
            crc: false,
            size: None,
        };
        client([0xC0, 0x00, 0x20, 0x00, 0, 0, 0, 0], bare);
        // Response: scs = 5, sc = bit 2, ss = 0, blksize in byte 4: A4 .. 7F.
        let resp = ServerFrame::BlockDownloadInitiateResponse {
            mux,
            crc: true,
            blksize: 127,
        };
        server([0xA4, 0x00, 0x20, 0x00, 0x7F, 0x00, 0x00, 0x00], resp);
    }

    #[test]
    fn block_confirmation_and_end_alike_in_both_directions() {
        // CiA 301 download / upload SDO block segment and end protocols: the
        // receiver of the data confirms a sub-block with 5 in bits 7..5 and
        // 2 in bits 1..0, ackseq in byte 1, blksize in byte 2 (A2); the
        // sender ends with 6 in bits 7..5, n in bits 4..2, 1 in bits 1..0
        // and the CRC in bytes 1..2 (little-endian); the receiver answers
        // 5 / 1 (A1). Download: the server confirms, the client ends;
        // upload: the other way round.
        let ack = |bytes, ackseq, blksize| {
            server(bytes, ServerFrame::BlockDownloadAck { ackseq, blksize });
            client(bytes, ClientFrame::BlockUploadAck { ackseq, blksize });
        };
        let end = |bytes, unused, crc| {
            client(bytes, ClientFrame::BlockDownloadEnd { unused, crc });
            server(bytes, ServerFrame::BlockUploadEnd { unused, crc });
        };
        ack([0xA2, 0x05, 0x06, 0, 0, 0, 0, 0], 5, 6);
        // n = 3: 0xCD.
        end([0xCD, 0x34, 0x12, 0, 0, 0, 0, 0], 3, 0x1234);
        ack([0xA2, 0x7F, 0x7F, 0, 0, 0, 0, 0], 127, 127);
        // n = 6: 0xD9.
        end([0xD9, 0xC3, 0x31, 0, 0, 0, 0, 0], 6, 0x31C3);
        let done = [0xA1, 0, 0, 0, 0, 0, 0, 0];
        server(done, ServerFrame::BlockDownloadEndResponse);
        client(done, ClientFrame::BlockUploadEndResponse);
    }

    #[test]
    fn block_upload_frames() {
        // CiA 301 initiate SDO block upload protocol: ccs = 5, cc = bit 2,
        // cs = 0, blksize in byte 4, pst in byte 5. 0x1008.0, 127
        // segments, pst 21: A4 08 10 00 7F 15 00 00.
        let mux = Multiplexer::new(0x1008, 0);
        let req = ClientFrame::BlockUploadInitiate {
            mux,
            crc: true,
            blksize: 127,
            pst: 21,
        };
        client([0xA4, 0x08, 0x10, 0x00, 0x7F, 0x15, 0x00, 0x00], req);
        // Response: scs = 6, sc = bit 2, s = bit 1, ss = 0, size 42.
        let resp = ServerFrame::BlockUploadInitiateResponse {
            mux,
            crc: true,
            size: Some(42),
        };
        server([0xC6, 0x08, 0x10, 0x00, 0x2A, 0x00, 0x00, 0x00], resp);
        // Start: ccs = 5, cs = 3: A3.
        client([0xA3, 0, 0, 0, 0, 0, 0, 0], ClientFrame::BlockUploadStart);
    }

    #[test]
    fn block_segments_and_sub_block_abort() {
        // CiA 301 SDO block segment: c = bit 7, seqno = bits 6..0, 7 data bytes.
        let s = BlockSegment::new(5, false, &[1, 2, 3, 4, 5, 6, 7]).unwrap();
        assert_eq!(s.encode(), [0x05, 1, 2, 3, 4, 5, 6, 7]);
        let last = BlockSegment::new(3, true, b"ab").unwrap();
        assert_eq!(last.encode(), [0x83, b'a', b'b', 0, 0, 0, 0, 0]);
        assert_eq!(BlockSegment::decode(&last.encode()), last);
        assert_eq!(
            SubBlockFrame::decode(&[0xFF, 9, 9, 9, 9, 9, 9, 9]),
            SubBlockFrame::Segment(BlockSegment {
                seqno: 127,
                last: true,
                data: [9; 7]
            })
        );
        assert!(BlockSegment::new(0, false, &[]).is_none());
        assert!(BlockSegment::new(128, false, &[]).is_none());
        assert!(BlockSegment::new(1, false, &[0; 8]).is_none());
        // 0x80 is the abort (seqno 0 is not a valid segment).
        assert_eq!(
            SubBlockFrame::decode(&[0x80, 0x00, 0x20, 0x00, 0x03, 0x00, 0x04, 0x05]),
            SubBlockFrame::Abort {
                mux: Multiplexer::new(0x2000, 0),
                code: 0x0504_0003
            }
        );
        let id = CanId::std_masked(0x602);
        assert_eq!(
            SubBlockFrame::from_can(&CanFrame::new(id, &[0x01, 2, 3])),
            Err(DecodeError::Length)
        );
    }

    #[test]
    fn block_crc_is_crc16_xmodem() {
        // CiA 301 block CRC: x^16 + x^12 + x^5 + 1, initial value 0; the
        // catalogued check value of CRC-16/XMODEM over "123456789" is 0x31C3.
        assert_eq!(block_crc(0, b"123456789"), 0x31C3);
        assert_eq!(block_crc(0, &[]), 0);
        // Piecewise (segment by segment) equals at once.
        let data: Vec<u8> = (0..=255u8).collect();
        let mut crc = 0;
        for c in data.chunks(7) {
            crc = block_crc(crc, c);
        }
        assert_eq!(crc, block_crc(0, &data));
        // Hand-computed single byte: 0x01 -> 0x1021 (the polynomial itself).
        assert_eq!(block_crc(0, &[0x01]), 0x1021);
    }

    #[test]
    fn reserved_bits_are_ignored() {
        // Initiate upload with reserved bits 3..0 set still reads 0x6000.1.
        assert_eq!(
            ClientFrame::decode(&[0x4F, 0x00, 0x60, 0x01, 0, 0, 0, 0]).unwrap(),
            ClientFrame::InitiateUpload {
                mux: Multiplexer::new(0x6000, 1)
            }
        );
    }

    #[test]
    fn only_eight_byte_data_frames_are_sdo_frames() {
        let id = CanId::std_masked(0x602);
        let short = CanFrame::new(id, &[0x40, 0x00, 0x60, 0x01]);
        assert_eq!(ClientFrame::from_can(&short), Err(DecodeError::Length));
        assert_eq!(
            ClientFrame::from_can(&CanFrame::remote(id, 8)),
            Err(DecodeError::Length)
        );
        let ok = ClientFrame::InitiateUpload {
            mux: Multiplexer::new(0x6000, 1),
        }
        .to_can(id);
        assert_eq!(ok.len, 8);
        assert_eq!(
            ClientFrame::from_can(&ok),
            Ok(ClientFrame::InitiateUpload {
                mux: Multiplexer::new(0x6000, 1)
            })
        );
    }

    #[test]
    fn chunk_refuses_overlong_data() {
        assert!(ExpeditedData::new(&[0; 5]).is_none());
        assert!(SegmentData::new(&[0; 8]).is_none());
        assert_eq!(SegmentData::new(&[7; 7]).unwrap().len(), 7);
        // An empty expedited value cannot state its size (n encodes 1..4).
        let f = ServerFrame::InitiateUploadResponse {
            mux: Multiplexer::default(),
            payload: Initiate::Expedited {
                data: ExpeditedData::empty(),
                sized: true,
            },
        };
        assert_eq!(f.encode()[0], 0x42);
    }

    #[test]
    fn round_trip_every_segment_length() {
        for n in 0..=SEGMENT_MAX {
            let data = SegmentData::new(&[0xA5; SEGMENT_MAX][..n]).unwrap();
            for (toggle, last) in [(false, false), (true, true), (true, false)] {
                let c = ClientFrame::DownloadSegment { toggle, data, last };
                assert_eq!(ClientFrame::decode(&c.encode()).unwrap(), c);
                let s = ServerFrame::UploadSegmentResponse { toggle, data, last };
                assert_eq!(ServerFrame::decode(&s.encode()).unwrap(), s);
            }
        }
        for n in 1..=EXPEDITED_MAX {
            let p = Initiate::expedited(&[1, 2, 3, 4][..n]).unwrap();
            let s = ServerFrame::InitiateUploadResponse {
                mux: M6200,
                payload: p,
            };
            assert_eq!(ServerFrame::decode(&s.encode()).unwrap(), s);
        }
    }
}
