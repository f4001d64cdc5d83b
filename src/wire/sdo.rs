//! SDO frame layouts (CiA 301 SDO protocols): expedited and segmented transfer,
//! abort. Pure encoding and decoding in both directions, so that the SDO
//! server and an SDO client share one implementation of the byte layout.
//!
//! Every SDO frame carries 8 data bytes. Byte 0 is the command byte: the
//! command specifier in bits 7..5 and protocol flags below it; initiate and
//! abort frames carry the multiplexer (index little-endian, subindex) in
//! bytes 1..3 and data, size or abort code in bytes 4..7; segment frames
//! carry up to 7 data bytes in bytes 1..7.
//!
//! Reserved bits are ignored when decoding and sent as 0 (CiA 301: "not
//! used, always 0"), so that a peer that sets them still interoperates.
//! Block transfer (command specifiers 5 and 6) is not implemented and
//! decodes as [`DecodeError::UnsupportedCommand`], like the reserved
//! specifier 7.

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
}

/// Why 8 bytes are not a frame of this module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecodeError {
    /// A remote frame or a data length other than 8.
    Length,
    /// Block transfer (5, 6) or the reserved command specifier 7.
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
            cs => {
                return Err(DecodeError::UnsupportedCommand {
                    cs,
                    mux: Multiplexer::from_frame(data),
                });
            }
        })
    }

    /// Decodes a received CAN frame (see [`frame_bytes`]).
    pub fn from_can(frame: &CanFrame) -> Result<Self, DecodeError> {
        Self::decode(frame_bytes(frame)?)
    }

    /// A CAN frame with this content.
    pub fn to_can(&self, id: CanId) -> CanFrame {
        CanFrame::new(id, &self.encode())
    }
}

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
            cs => {
                return Err(DecodeError::UnsupportedCommand {
                    cs,
                    mux: Multiplexer::from_frame(data),
                });
            }
        })
    }

    /// Decodes a received CAN frame (see [`frame_bytes`]).
    pub fn from_can(frame: &CanFrame) -> Result<Self, DecodeError> {
        Self::decode(frame_bytes(frame)?)
    }

    /// A CAN frame with this content.
    pub fn to_can(&self, id: CanId) -> CanFrame {
        CanFrame::new(id, &self.encode())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const M6200: Multiplexer = Multiplexer::new(0x6200, 1);

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
    fn block_transfer_and_reserved_specifier_are_unsupported() {
        // CiA 301 SDO block protocols: block upload ccs = 5 (0xA0), block download ccs = 6 (0xC0).
        for (b0, cs) in [(0xA0u8, 5u8), (0xC6, 6), (0xE0, 7)] {
            let r = ClientFrame::decode(&[b0, 0x00, 0x10, 0x02, 0, 0, 0, 0]);
            assert_eq!(
                r,
                Err(DecodeError::UnsupportedCommand {
                    cs,
                    mux: Multiplexer::new(0x1000, 2)
                })
            );
            assert!(ServerFrame::decode(&[b0, 0, 0, 0, 0, 0, 0, 0]).is_err());
        }
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
