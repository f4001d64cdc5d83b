//! Unit tests of SDO block download and block upload in the server. Byte
//! vectors follow the CiA 301 SDO block download / block upload protocols:
//! initiate download C6 (ccs 6, cc, s) -> A4 (scs 5, sc) + blksize in byte
//! 4; segments c << 7 | seqno; confirmation A2 ackseq blksize; end
//! C1 | n << 2 + CRC -> A1. Upload: A4 (ccs 5, cc) + blksize, pst -> C6
//! (scs 6, sc, s) + size; start A3; confirmation A2 ackseq blksize; end
//! C1 | n << 2 + CRC -> A1.

use super::*;
use crate::config::SDO_BLOCKSIZE_DOWNLOAD;
use crate::wire::sdo::{BlockSegment, block_crc};

/// Segments per sub-block the server grants.
const B: u8 = SDO_BLOCKSIZE_DOWNLOAD;

fn text(len: usize) -> Vec<u8> {
    (0..len).map(|i| b'a' + (i % 26) as u8).collect()
}

fn init_download(index: u16, crc: bool, size: Option<usize>) -> [u8; 8] {
    let mut f = [0xC0, index as u8, (index >> 8) as u8, 0, 0, 0, 0, 0];
    if crc {
        f[0] |= 0x04;
    }
    if let Some(n) = size {
        f[0] |= 0x02;
        f[4..].copy_from_slice(&(n as u32).to_le_bytes());
    }
    f
}

fn end_download(unused: u8, crc: u16) -> [u8; 8] {
    let [lo, hi] = crc.to_le_bytes();
    [0xC1 | (unused << 2), lo, hi, 0, 0, 0, 0, 0]
}

fn ack(ackseq: u8, blksize: u8) -> [u8; 8] {
    [0xA2, ackseq, blksize, 0, 0, 0, 0, 0]
}

/// n of the end frame for `len` bytes.
/// `reply` is the abort of the transfer of 0x2004.0 (the test domain)
/// with `code`.
#[track_caller]
fn aborted(reply: Option<[u8; 8]>, code: SdoAbort) {
    assert_eq!(reply, Some(abort_bytes(0x2004, 0, code)));
}

fn unused(len: usize) -> u8 {
    (len.div_ceil(7).max(1) * 7 - len) as u8
}

/// What 0x2004 holds before a download that must fail.
const KEEP: &[u8] = b"keep";

impl Rig {
    /// A rig whose 0x2004 holds [`KEEP`].
    fn keeping() -> Rig {
        let rig = Rig::new(test_od!());
        rig.set(0x2004, 0, KEEP);
        rig
    }

    /// 0x2004 still holds [`KEEP`] and nothing was stored.
    fn kept(&self) {
        assert_eq!(self.read(0x2004, 0), KEEP);
        assert_eq!(self.hooks.stores, 0);
    }

    fn seg(&mut self, seqno: u8, last: bool, data: &[u8]) -> Option<[u8; 8]> {
        self.req(BlockSegment::new(seqno, last, data).unwrap().encode())
    }

    /// Sends segments `first..` of `data` as one sub-block of `blksize`
    /// (seqno 1..), leaving out the seqnos in `skip`; returns the
    /// confirmation (there must be at most one).
    fn sub_block(
        &mut self,
        data: &[u8],
        first: usize,
        blksize: u8,
        skip: &[u8],
    ) -> Option<[u8; 8]> {
        let chunks: Vec<&[u8]> = if data.is_empty() {
            vec![&[]]
        } else {
            data.chunks(7).collect()
        };
        let mut reply = None;
        for k in 0..usize::from(blksize) {
            let i = first + k;
            if i >= chunks.len() {
                break;
            }
            let seqno = k as u8 + 1;
            if skip.contains(&seqno) {
                continue;
            }
            if let Some(r) = self.seg(seqno, i + 1 == chunks.len(), chunks[i]) {
                assert!(reply.is_none(), "one confirmation per sub-block");
                reply = Some(r);
            }
        }
        reply
    }

    /// Starts a block download of `announced` bytes (with CRC) to 0x2004.0
    /// and sends `data` as its first sub-block; returns the confirmation.
    fn first_sub_block(&mut self, announced: usize, data: &[u8]) -> Option<[u8; 8]> {
        self.req(init_download(0x2004, true, Some(announced)))
            .unwrap();
        self.sub_block(data, 0, B, &[])
    }

    /// A whole block download of `data` to `index`.0 with CRC; returns the
    /// answer to the end frame.
    fn block_download(&mut self, index: u16, data: &[u8]) -> [u8; 8] {
        let r = self
            .req(init_download(index, true, Some(data.len())))
            .unwrap();
        assert_eq!(r, [0xA4, index as u8, (index >> 8) as u8, 0, B, 0, 0, 0]);
        let total = data.len().div_ceil(7).max(1);
        let mut first = 0;
        while first < total {
            let n = (total - first).min(usize::from(B));
            let r = self.sub_block(data, first, B, &[]).unwrap();
            assert_eq!(r, ack(n as u8, B));
            first += n;
        }
        self.req(end_download(unused(data.len()), block_crc(0, data)))
            .unwrap()
    }

    /// Starts a block upload of 0x2004.0 in sub-blocks of `blksize` (no
    /// protocol switch), up to the client's start request (answered by
    /// segments, not by a response).
    fn start_upload(&mut self, blksize: u8) {
        self.req(init_upload(0x2004, blksize, 0)).unwrap();
        assert_eq!(self.req([0xA3, 0, 0, 0, 0, 0, 0, 0]), None);
    }

    /// A rig whose 0x2004 holds `data`, its block upload started in
    /// sub-blocks of `blksize` ([`Rig::start_upload`]).
    fn uploading(data: &[u8], blksize: u8) -> Rig {
        let mut rig = Rig::new(test_od!());
        rig.set(0x2004, 0, data);
        rig.start_upload(blksize);
        rig
    }

    /// Hands out every pending upload segment as the stack would.
    fn drain_segments(&mut self) -> Vec<BlockSegment> {
        let mut out = Vec::new();
        while let Some(f) = self.server.pending_segment() {
            assert_eq!((f.id, f.len), (CanId::std_masked(RESP), 8));
            out.push(BlockSegment::decode(&f.data));
            self.server.segment_sent(self.now);
        }
        out
    }
}

#[test]
fn block_download_collects_sub_blocks_and_writes_once() {
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, b"old");
    let data = text(2 * usize::from(B) * 7 + 3);
    assert!(data.len() <= SDOS_BUFFER_SIZE);
    let r = rig.req(init_download(0x2004, true, Some(data.len())));
    assert_eq!(r, Some([0xA4, 0x04, 0x20, 0x00, B, 0, 0, 0]));
    for sub in 0..2 {
        let r = rig.sub_block(&data, sub * usize::from(B), B, &[]);
        assert_eq!(r, Some(ack(B, B)));
    }
    // The last sub-block ends early with c = 1.
    assert_eq!(
        rig.sub_block(&data, 2 * usize::from(B), B, &[]),
        Some(ack(1, B))
    );
    // Nothing is written before the end frame.
    assert_eq!(rig.read(0x2004, 0), b"old".to_vec());
    assert_eq!(rig.hooks.stores, 0);
    let crc = block_crc(0, &data);
    // n = 4 -> 0xD1.
    assert_eq!(end_download(4, crc)[0], 0xD1);
    assert_eq!(
        rig.req(end_download(4, crc)),
        Some([0xA1, 0, 0, 0, 0, 0, 0, 0])
    );
    assert_eq!(rig.read(0x2004, 0), data);
    assert_eq!((rig.hooks.checks, rig.hooks.stores), (1, 1));
    assert!(!rig.server.is_busy());
}

#[test]
fn block_download_of_every_small_length() {
    for len in [0usize, 1, 6, 7, 8, 13, 14, 15] {
        let mut rig = Rig::new(test_od!());
        let data = text(len);
        assert_eq!(
            rig.block_download(0x2004, &data),
            [0xA1, 0, 0, 0, 0, 0, 0, 0]
        );
        assert_eq!(rig.read(0x2004, 0), data, "length {len}");
    }
}

#[test]
fn lost_segment_is_asked_for_again() {
    if B < 3 {
        return; // the scenario needs a sub-block of 3 or more segments
    }
    let mut rig = Rig::new(test_od!());
    // B + 2 segments.
    let data = text(usize::from(B) * 7 + 10);
    rig.req(init_download(0x2004, true, Some(data.len())))
        .unwrap();
    // Segment 2 is lost: 3..B are dropped and B ends the sub-block with
    // ackseq = 1.
    assert_eq!(rig.sub_block(&data, 0, B, &[2]), Some(ack(1, B)));
    // The client sends again from segment 2 of the transfer (index 1).
    assert_eq!(rig.sub_block(&data, 1, B, &[]), Some(ack(B, B)));
    assert_eq!(
        rig.sub_block(&data, 1 + usize::from(B), B, &[]),
        Some(ack(1, B))
    );
    let end = end_download(unused(data.len()), block_crc(0, &data));
    assert_eq!(rig.req(end), Some([0xA1, 0, 0, 0, 0, 0, 0, 0]));
    assert_eq!(rig.read(0x2004, 0), data);
    assert_eq!(rig.hooks.stores, 1);
}

#[test]
fn lost_last_segment_is_confirmed_after_half_the_timeout() {
    let mut rig = Rig::new(test_od!());
    let data = text(20);
    rig.req(init_download(0x2004, true, Some(20))).unwrap();
    // The segment with c = 1 (seqno 3) never arrives.
    assert_eq!(rig.seg(1, false, &data[..7]), None);
    assert_eq!(rig.seg(2, false, &data[7..14]), None);
    let half = SDOS_DEFAULT_TIMEOUT / 2;
    assert_eq!(rig.server.poll(&rig.od, rig.now.plus(half - 1)), None);
    let r = rig.server.poll(&rig.od, rig.now.plus(half)).unwrap();
    assert_eq!(r.data, ack(2, B));
    // Only once: no segment of the next sub-block arrived yet.
    assert_eq!(rig.server.poll(&rig.od, rig.now.plus(half + 1)), None);
    rig.now = rig.now.plus(half + 1);
    assert_eq!(rig.seg(1, true, &data[14..]), Some(ack(1, B)));
    let end = end_download(unused(20), block_crc(0, &data));
    assert_eq!(rig.req(end), Some([0xA1, 0, 0, 0, 0, 0, 0, 0]));
    assert_eq!(rig.read(0x2004, 0), data);
}

#[test]
fn wrong_sequence_numbers_abort_with_0x05040003() {
    let mut rig = Rig::keeping();
    rig.req(init_download(0x2004, true, Some(30))).unwrap();
    // seqno 0 (byte 0 = 0x00) is no segment number.
    aborted(
        rig.req([0x00, 1, 2, 3, 4, 5, 6, 7]),
        SdoAbort::InvalidSequenceNumber,
    );
    assert!(!rig.server.is_busy());
    if B < 127 {
        rig.req(init_download(0x2004, true, Some(30))).unwrap();
        rig.seg(1, false, &[0; 7]);
        aborted(
            rig.seg(B + 1, false, &[0; 7]),
            SdoAbort::InvalidSequenceNumber,
        );
    }
    rig.kept();
}

#[test]
fn crc_error_aborts_with_0x05040004_and_writes_nothing() {
    let mut rig = Rig::keeping();
    let data = text(12);
    assert_eq!(rig.first_sub_block(12, &data), Some(ack(2, B)));
    let wrong = block_crc(0, &data) ^ 0x0001;
    aborted(rig.req(end_download(unused(12), wrong)), SdoAbort::CrcError);
    rig.kept();
    // A client without CRC support (cc = 0) sends 0: not checked.
    rig.req(init_download(0x2004, false, Some(12))).unwrap();
    rig.sub_block(&data, 0, B, &[]).unwrap();
    assert_eq!(
        rig.req(end_download(unused(12), 0)),
        Some([0xA1, 0, 0, 0, 0, 0, 0, 0])
    );
    assert_eq!(rig.read(0x2004, 0), data);
}

#[test]
fn size_mismatch_aborts_with_0x06070010() {
    let mut rig = Rig::keeping();
    // 20 announced, 13 sent: found at the end frame.
    let short = text(13);
    assert_eq!(rig.first_sub_block(20, &short), Some(ack(2, B)));
    aborted(
        rig.req(end_download(unused(13), block_crc(0, &short))),
        SdoAbort::LengthMismatch,
    );
    // 8 announced, a third segment (bytes 14..) is more than that: at once.
    if B >= 3 {
        rig.req(init_download(0x2004, true, Some(8))).unwrap();
        assert_eq!(rig.seg(1, false, &[1; 7]), None);
        assert_eq!(rig.seg(2, false, &[2; 7]), None);
        aborted(rig.seg(3, true, &[3]), SdoAbort::LengthMismatch);
    }
    rig.kept();
}

#[test]
fn download_longer_than_the_buffer_is_0x06070012() {
    let mut rig = Rig::new(test_od!());
    // Stated at initiate.
    aborted(
        rig.req(init_download(0x2004, true, Some(SDOS_BUFFER_SIZE + 1))),
        SdoAbort::LengthTooHigh,
    );
    // Not stated: the segment that starts beyond the buffer.
    let data = text(SDOS_BUFFER_SIZE + 7);
    rig.req(init_download(0x2004, true, None)).unwrap();
    let total = data.len().div_ceil(7);
    let mut first = 0;
    let mut last = None;
    while first < total {
        last = rig.sub_block(&data, first, B, &[]);
        if last.is_some_and(|r| r[0] == 0x80) {
            break;
        }
        first += usize::from(B);
    }
    aborted(last, SdoAbort::LengthTooHigh);
    assert!(!rig.server.is_busy());
}

#[test]
fn block_download_refused_by_the_dictionary() {
    let mut rig = Rig::new(test_od!());
    // Read-only object: refused at initiate, like a segmented download.
    assert_eq!(
        rig.req(init_download(0x2002, true, Some(4))),
        Some(abort_bytes(0x2002, 0, SdoAbort::WriteReadOnly))
    );
    // A U16 with range 10..=1000 given 2000: the write at the end refuses.
    let v = 2000u16.to_le_bytes();
    rig.req(init_download(0x2001, true, Some(2))).unwrap();
    assert_eq!(rig.sub_block(&v, 0, B, &[]), Some(ack(1, B)));
    assert_eq!(
        rig.req(end_download(5, block_crc(0, &v))),
        Some(abort_bytes(0x2001, 0, SdoAbort::ValueTooHigh))
    );
    assert_eq!(rig.read(0x2001, 0), 100u16.to_le_bytes().to_vec());
}

#[test]
fn abort_and_short_frames_inside_a_sub_block() {
    let mut rig = Rig::new(test_od!());
    let data = text(20);
    rig.req(init_download(0x2004, true, Some(20))).unwrap();
    rig.seg(1, false, &data[..7]);
    // DLC 7: not an SDO frame, ignored; the transfer goes on.
    let seven = CanFrame::new(CanId::std_masked(REQ), &[0x02, 1, 2, 3, 4, 5, 6]);
    assert_eq!(
        rig.server
            .on_frame(&rig.od, &mut rig.hooks, &seven, rig.now),
        None
    );
    assert_eq!(rig.seg(2, false, &data[7..14]), None);
    // 0x80: the client's abort, never answered.
    assert_eq!(
        rig.req([0x80, 0x04, 0x20, 0x00, 0x00, 0x00, 0x04, 0x05]),
        None
    );
    assert!(!rig.server.is_busy());
}

#[test]
fn unexpected_request_before_the_end_frame_is_0x05040001() {
    let mut rig = Rig::new(test_od!());
    let data = text(5);
    assert_eq!(rig.first_sub_block(5, &data), Some(ack(1, B)));
    // An upload request where the end frame belongs.
    aborted(
        rig.req([0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0]),
        SdoAbort::UnknownCommand,
    );
}

#[test]
fn block_download_timeout() {
    let mut rig = Rig::new(test_od!());
    rig.req(init_download(0x2004, true, Some(20))).unwrap();
    let start = rig.now;
    // No segment at all: no early confirmation, the timeout aborts.
    assert_eq!(
        rig.server
            .poll(&rig.od, start.plus(SDOS_DEFAULT_TIMEOUT / 2)),
        None
    );
    let r = rig
        .server
        .poll(&rig.od, start.plus(SDOS_DEFAULT_TIMEOUT))
        .unwrap();
    assert_eq!(r.data, abort_bytes(0x2004, 0, SdoAbort::Timeout));
    // A segment after the timeout (without poll) gets the same answer.
    rig.req(init_download(0x2004, true, Some(20))).unwrap();
    rig.now = rig.now.plus(SDOS_DEFAULT_TIMEOUT);
    aborted(rig.seg(1, false, &[0; 7]), SdoAbort::Timeout);
}

/// Block upload initiate request.
fn init_upload(index: u16, blksize: u8, pst: u8) -> [u8; 8] {
    [0xA4, index as u8, (index >> 8) as u8, 0, blksize, pst, 0, 0]
}

#[test]
fn block_upload_in_sub_blocks_with_crc() {
    let mut rig = Rig::new(test_od!());
    let data = text(100);
    rig.set(0x2004, 0, &data);
    let r = rig.req(init_upload(0x2004, 5, 0));
    assert_eq!(r, Some([0xC6, 0x04, 0x20, 0x00, 100, 0, 0, 0]));
    // Nothing goes out before the start request.
    assert_eq!(rig.server.pending_segment(), None);
    assert_eq!(rig.req([0xA3, 0, 0, 0, 0, 0, 0, 0]), None);
    let mut got = Vec::new();
    let mut end = None;
    for sub in 0..3 {
        let segs = rig.drain_segments();
        assert_eq!(segs.len(), 5, "sub-block {sub}");
        for (k, s) in segs.iter().enumerate() {
            assert_eq!(s.seqno as usize, k + 1);
            assert_eq!(s.last, sub == 2 && k == 4);
            got.extend_from_slice(&s.data);
        }
        end = rig.req(ack(5, 5));
        assert_eq!(end.is_some(), sub == 2);
    }
    // 15 segments, 105 bytes: n = 5 -> D5, CRC of the 100 data bytes.
    let [lo, hi] = block_crc(0, &data).to_le_bytes();
    assert_eq!(end, Some([0xD5, lo, hi, 0, 0, 0, 0, 0]));
    got.truncate(100);
    assert_eq!(got, data);
    assert!(rig.server.is_busy());
    assert_eq!(rig.req([0xA1, 0, 0, 0, 0, 0, 0, 0]), None);
    assert!(!rig.server.is_busy());
}

#[test]
fn block_upload_sends_again_after_ackseq() {
    let data = text(30);
    let mut rig = Rig::uploading(&data, 3);
    assert_eq!(rig.drain_segments().len(), 3);
    // The client got segment 1 only.
    assert_eq!(rig.req(ack(1, 3)), None);
    let segs = rig.drain_segments();
    assert_eq!(segs.len(), 3);
    assert_eq!(segs[0].seqno, 1);
    assert_eq!(&segs[0].data, &data[7..14]);
    // A confirmation in the middle of a sub-block (some clients confirm at
    // the first gap): only one segment of the next sub-block went out.
    assert_eq!(rig.req(ack(3, 3)), None);
    let f = rig.server.pending_segment().unwrap();
    rig.server.segment_sent(rig.now);
    assert_eq!(
        &f.data[1..],
        &data[28..30]
            .iter()
            .chain(&[0; 5])
            .copied()
            .collect::<Vec<_>>()[..]
    );
    assert_eq!(f.data[0], 0x81, "segment 5 of 5, c = 1");
    // A confirmation naming more segments than were sent: 0x05040003.
    aborted(rig.req(ack(2, 3)), SdoAbort::InvalidSequenceNumber);
}

#[test]
fn block_upload_final_crc_counts_each_byte_once() {
    let data = text(21);
    let mut rig = Rig::uploading(&data, 3);
    rig.drain_segments();
    assert_eq!(rig.req(ack(0, 3)), None);
    rig.drain_segments();
    let end = rig.req(ack(3, 3)).unwrap();
    let [lo, hi] = block_crc(0, &data).to_le_bytes();
    assert_eq!(end, [0xC1, lo, hi, 0, 0, 0, 0, 0]);
}

#[test]
fn invalid_block_sizes_are_0x05040002() {
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, &text(40));
    for blksize in [0u8, 128] {
        aborted(
            rig.req(init_upload(0x2004, blksize, 0)),
            SdoAbort::InvalidBlockSize,
        );
    }
    // In a confirmation of a running upload.
    rig.start_upload(2);
    rig.drain_segments();
    aborted(rig.req(ack(2, 128)), SdoAbort::InvalidBlockSize);
    rig.start_upload(2);
    rig.drain_segments();
    aborted(rig.req(ack(2, 0)), SdoAbort::InvalidBlockSize);
}

#[test]
fn protocol_switch_below_the_threshold() {
    let mut rig = Rig::new(test_od!());
    // 1 byte, pst 4: expedited upload response (CiA 301: 0x4F).
    rig.set(0x2000, 0, &[0x5A]);
    assert_eq!(
        rig.req(init_upload(0x2000, 10, 4)),
        Some([0x4F, 0x00, 0x20, 0x00, 0x5A, 0, 0, 0])
    );
    assert!(!rig.server.is_busy());
    // 20 bytes, pst 21: segmented upload (0x41 + size), then the segments.
    let data = text(20);
    rig.set(0x2004, 0, &data);
    assert_eq!(
        rig.req(init_upload(0x2004, 10, 21)),
        Some([0x41, 0x04, 0x20, 0x00, 20, 0, 0, 0])
    );
    assert_eq!(rig.upload_segments(20), data);
    // 20 bytes, pst 19 or 0: block upload.
    for pst in [19, 0] {
        assert_eq!(rig.req(init_upload(0x2004, 10, pst)).unwrap()[0], 0xC6);
        rig.req([0x80, 0x04, 0x20, 0x00, 0, 0, 0, 0]);
    }
}

#[test]
fn block_upload_sends_the_snapshot() {
    let mut rig = Rig::new(test_od!());
    let before = text(40);
    rig.set(0x2004, 0, &before);
    rig.req(init_upload(0x2004, 127, 0)).unwrap();
    // The application changes the value during the transfer.
    rig.set(0x2004, 0, b"changed");
    rig.req([0xA3, 0, 0, 0, 0, 0, 0, 0]);
    let segs = rig.drain_segments();
    assert_eq!(segs.len(), 6);
    let got: Vec<u8> = segs.iter().flat_map(|s| s.data).take(40).collect();
    assert_eq!(got, before);
}

#[test]
fn block_upload_larger_than_the_buffer_and_of_nothing() {
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, &text(SDOS_BUFFER_SIZE + 1));
    aborted(rig.req(init_upload(0x2004, 127, 0)), SdoAbort::OutOfMemory);
    assert_eq!(
        rig.req(init_upload(0x2FFF, 127, 0)),
        Some(abort_bytes(0x2FFF, 0, SdoAbort::ObjectNotExist))
    );
    // An empty string: one segment without data, n = 7 (0xDD), CRC 0.
    rig.set(0x2004, 0, b"");
    assert_eq!(
        rig.req(init_upload(0x2004, 127, 0)),
        Some([0xC6, 0x04, 0x20, 0x00, 0, 0, 0, 0])
    );
    rig.req([0xA3, 0, 0, 0, 0, 0, 0, 0]);
    let segs = rig.drain_segments();
    assert_eq!(segs.len(), 1);
    assert_eq!(segs[0].encode(), [0x81, 0, 0, 0, 0, 0, 0, 0]);
    assert_eq!(rig.req(ack(1, 127)), Some([0xDD, 0, 0, 0, 0, 0, 0, 0]));
}

#[test]
fn block_upload_steps_out_of_order_are_0x05040001() {
    let mut rig = Rig::new(test_od!());
    rig.set(0x2004, 0, &text(30));
    rig.req(init_upload(0x2004, 3, 0)).unwrap();
    // A confirmation before the start request.
    aborted(rig.req(ack(0, 3)), SdoAbort::UnknownCommand);
    // A start request while no transfer runs.
    assert_eq!(
        rig.req([0xA3, 0, 0, 0, 0, 0, 0, 0]),
        Some(abort_bytes(0, 0, SdoAbort::UnknownCommand))
    );
}

#[test]
fn block_upload_timeout_runs_from_the_last_segment_sent() {
    let mut rig = Rig::uploading(&text(30), 3);
    // The driver takes the sub-block late.
    rig.now = rig.now.plus(SDOS_DEFAULT_TIMEOUT - 1);
    rig.drain_segments();
    assert_eq!(
        rig.server
            .poll(&rig.od, rig.now.plus(SDOS_DEFAULT_TIMEOUT - 1)),
        None
    );
    let r = rig
        .server
        .poll(&rig.od, rig.now.plus(SDOS_DEFAULT_TIMEOUT))
        .unwrap();
    assert_eq!(r.data, abort_bytes(0x2004, 0, SdoAbort::Timeout));
    assert_eq!(rig.server.pending_segment(), None);
}
