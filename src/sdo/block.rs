//! Sub-block bookkeeping of SDO block transfer (CiA 301 SDO block download
//! and block upload protocols), shared by the server and the client: the
//! sending side ([`BlockTx`], server upload and client download) and the
//! receiving side ([`BlockRx`], server download and client upload). Only
//! sequence numbers, positions and the CRC live here; where the bytes come
//! from and go to is the caller's business.
//!
//! # Decisions
//! * Segment `i` of the transfer (counted from 0 over all sub-blocks)
//!   carries bytes `7 i .. 7 i + 7`; an empty value travels as one segment
//!   without data (end frame n = 7).
//! * The receiver confirms a sub-block when the segment with
//!   seqno = blksize or with c = 1 arrives, whether or not every segment
//!   before it arrived: ackseq is the last segment received in order, and
//!   the sender starts the next sub-block with the segment after it
//!   (CiA 301: the client retransmits from ackseq + 1). Segments after a
//!   gap are dropped, repeated ones ignored.
//! * When the segment that ends a sub-block is itself lost, nothing would
//!   trigger the confirmation: the receiver confirms what it has once no
//!   segment arrived for half the transfer timeout, if at least one segment
//!   of the sub-block arrived (otherwise it cannot tell a lost
//!   confirmation from a lost sub-block, and a confirmation could make the
//!   sender skip data; the transfer then times out).
//! * A segment with seqno 0 or above the block size aborts with 0x05040003;
//!   a confirmation naming more segments than were sent with 0x05040003; a
//!   block size outside 1..=127 with 0x05040002.
//! * The sender accepts a confirmation at any time, also before it sent the
//!   whole sub-block (some receivers confirm at the first gap).

use crate::error::SdoAbort;
use crate::wire::sdo::{BLKSIZE_MAX, BlockSegment, SEGMENT_MAX, block_crc};

/// True for a block size CiA 301 allows (1..=127).
pub(crate) fn valid_blksize(blksize: u8) -> bool {
    (1..=BLKSIZE_MAX).contains(&blksize)
}

/// Segments that `len` bytes take (at least one).
pub(crate) fn segments_for(len: usize) -> usize {
    len.div_ceil(SEGMENT_MAX).max(1)
}

/// Unused bytes of the last segment (the end frame's n).
pub(crate) fn unused_in_last(len: usize) -> u8 {
    let n = segments_for(len)
        .saturating_mul(SEGMENT_MAX)
        .saturating_sub(len);
    // n <= 7 by construction.
    n as u8
}

/// The next segment a [`BlockTx`] sends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Planned {
    /// Sequence number within the sub-block.
    pub seqno: u8,
    /// First data byte.
    pub start: usize,
    /// One past the last data byte.
    pub end: usize,
    /// c: the last segment of the transfer.
    pub last: bool,
}

/// The sending side of a block transfer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BlockTx {
    len: usize,
    total: usize,
    /// Segments confirmed by the receiver.
    acked: usize,
    blksize: u8,
    /// Segments of the current sub-block handed to the driver.
    sent: u8,
    crc: u16,
    /// Bytes already in `crc` (retransmitted segments are not counted twice).
    crc_upto: usize,
}

impl BlockTx {
    /// `len` bytes in sub-blocks of `blksize` segments.
    pub(crate) fn new(len: usize, blksize: u8) -> Self {
        BlockTx {
            len,
            total: segments_for(len),
            acked: 0,
            blksize,
            sent: 0,
            crc: 0,
            crc_upto: 0,
        }
    }

    /// The next segment of the current sub-block; `None` when the
    /// sub-block is out and the confirmation is due.
    pub(crate) fn next(&self) -> Option<Planned> {
        let index = self.acked.saturating_add(usize::from(self.sent));
        if self.sent >= self.blksize || index >= self.total {
            return None;
        }
        let start = index.saturating_mul(SEGMENT_MAX);
        Some(Planned {
            seqno: self.sent.saturating_add(1),
            start,
            end: self.len.min(start.saturating_add(SEGMENT_MAX)),
            last: index.saturating_add(1) == self.total,
        })
    }

    /// The segment for `p` with `data` (its bytes).
    pub(crate) fn segment(p: &Planned, data: &[u8]) -> BlockSegment {
        BlockSegment::new(p.seqno, p.last, data).unwrap_or(BlockSegment {
            seqno: p.seqno,
            last: p.last,
            data: [0; SEGMENT_MAX],
        })
    }

    /// Records that `p` (from [`BlockTx::next`]) went out with `data`.
    pub(crate) fn mark_sent(&mut self, p: &Planned, data: &[u8]) {
        self.sent = self.sent.saturating_add(1);
        if p.start == self.crc_upto {
            self.crc = block_crc(self.crc, data);
            self.crc_upto = p.end;
        }
    }

    /// A confirmation: `Ok(true)` when every segment is confirmed (the end
    /// frame is due), `Ok(false)` when the next sub-block starts.
    pub(crate) fn on_ack(&mut self, ackseq: u8, blksize: u8) -> Result<bool, SdoAbort> {
        if ackseq > self.sent {
            return Err(SdoAbort::InvalidSequenceNumber);
        }
        self.acked = self.acked.saturating_add(usize::from(ackseq));
        if self.acked >= self.total {
            return Ok(true);
        }
        if !valid_blksize(blksize) {
            return Err(SdoAbort::InvalidBlockSize);
        }
        self.blksize = blksize;
        self.sent = 0;
        Ok(false)
    }

    /// n of the end frame.
    pub(crate) fn unused(&self) -> u8 {
        unused_in_last(self.len)
    }

    /// CRC of every byte sent.
    pub(crate) fn crc(&self) -> u16 {
        self.crc
    }
}

/// What the receiver does with a segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Verdict {
    /// `Some(i)`: the segment is segment `i` of the transfer, received in
    /// order; its data is to be kept. `None`: dropped.
    pub accept: Option<usize>,
    /// The sub-block is over: send the confirmation
    /// ([`BlockRx::confirm`]).
    pub confirm: bool,
}

/// The receiving side of a block transfer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct BlockRx {
    blksize: u8,
    /// Segments accepted in earlier sub-blocks.
    base: usize,
    /// Last seqno of the current sub-block received in order (0: none).
    last_good: u8,
    /// A segment of the current sub-block arrived (in order or not).
    seen: bool,
    /// The segment with c = 1 arrived in order.
    complete: bool,
}

impl BlockRx {
    /// Sub-blocks of `blksize` segments.
    pub(crate) fn new(blksize: u8) -> Self {
        BlockRx {
            blksize,
            base: 0,
            last_good: 0,
            seen: false,
            complete: false,
        }
    }

    /// Judges a received segment.
    pub(crate) fn on_segment(&mut self, seg: &BlockSegment) -> Result<Verdict, SdoAbort> {
        if seg.seqno == 0 || seg.seqno > self.blksize {
            return Err(SdoAbort::InvalidSequenceNumber);
        }
        self.seen = true;
        let ends_sub_block = seg.seqno == self.blksize || seg.last;
        if seg.seqno == self.last_good.saturating_add(1) {
            self.last_good = seg.seqno;
            self.complete = seg.last;
            Ok(Verdict {
                accept: Some(
                    self.base
                        .saturating_add(usize::from(seg.seqno).saturating_sub(1)),
                ),
                confirm: ends_sub_block,
            })
        } else if seg.seqno <= self.last_good {
            // A repetition: already have it.
            Ok(Verdict {
                accept: None,
                confirm: false,
            })
        } else {
            // A gap: the segments before it were lost.
            Ok(Verdict {
                accept: None,
                confirm: ends_sub_block,
            })
        }
    }

    /// True when a sub-block started but stalled: its confirmation may be
    /// sent without waiting for its last segment.
    pub(crate) fn stalled(&self) -> bool {
        self.seen
    }

    /// Closes the current sub-block: returns ackseq and opens the next
    /// sub-block with `blksize` segments.
    pub(crate) fn confirm(&mut self, blksize: u8) -> u8 {
        let ackseq = self.last_good;
        self.base = self.base.saturating_add(usize::from(ackseq));
        self.last_good = 0;
        self.seen = false;
        self.blksize = blksize;
        ackseq
    }

    /// True once the last segment arrived in order (and was confirmed):
    /// the end frame is next.
    pub(crate) fn complete(&self) -> bool {
        self.complete
    }

    /// Segments received in order so far (after [`BlockRx::confirm`]).
    pub(crate) fn segments(&self) -> usize {
        self.base.saturating_add(usize::from(self.last_good))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seg(seqno: u8, last: bool) -> BlockSegment {
        BlockSegment::new(seqno, last, &[seqno; 7]).unwrap()
    }

    #[test]
    fn sender_plans_sub_blocks_and_the_last_segment() {
        // 20 bytes, blksize 2: segments 0..3 (7 + 7 + 6), n = 1.
        let mut tx = BlockTx::new(20, 2);
        let p = tx.next().unwrap();
        assert_eq!((p.seqno, p.start, p.end, p.last), (1, 0, 7, false));
        tx.mark_sent(&p, &[0; 7]);
        let p = tx.next().unwrap();
        assert_eq!((p.seqno, p.start, p.end, p.last), (2, 7, 14, false));
        tx.mark_sent(&p, &[0; 7]);
        assert_eq!(tx.next(), None);
        assert_eq!(tx.on_ack(2, 2), Ok(false));
        let p = tx.next().unwrap();
        assert_eq!((p.seqno, p.start, p.end, p.last), (1, 14, 20, true));
        tx.mark_sent(&p, &[0; 6]);
        assert_eq!(tx.next(), None);
        assert_eq!(tx.on_ack(1, 2), Ok(true));
        assert_eq!(tx.unused(), 1);
    }

    #[test]
    fn sender_retransmits_after_ackseq_and_counts_the_crc_once() {
        let data: Vec<u8> = (0..30).collect();
        let mut tx = BlockTx::new(30, 4);
        for _ in 0..4 {
            let p = tx.next().unwrap();
            tx.mark_sent(&p, &data[p.start..p.end]);
        }
        // Segment 2 lost: the receiver confirms 1.
        assert_eq!(tx.on_ack(1, 4), Ok(false));
        let p = tx.next().unwrap();
        assert_eq!((p.seqno, p.start), (1, 7));
        let mut sent = Vec::new();
        while let Some(p) = tx.next() {
            tx.mark_sent(&p, &data[p.start..p.end]);
            sent.push(p);
        }
        assert_eq!(sent.len(), 4, "segments 1..4 of the transfer again");
        assert!(sent[3].last);
        assert_eq!(tx.on_ack(4, 4), Ok(true));
        assert_eq!(tx.crc(), block_crc(0, &data));
    }

    #[test]
    fn sender_refuses_bad_confirmations() {
        let mut tx = BlockTx::new(100, 3);
        let p = tx.next().unwrap();
        tx.mark_sent(&p, &[0; 7]);
        assert_eq!(tx.on_ack(2, 3), Err(SdoAbort::InvalidSequenceNumber));
        assert_eq!(tx.on_ack(1, 0), Err(SdoAbort::InvalidBlockSize));
        let mut tx = BlockTx::new(100, 3);
        assert_eq!(tx.on_ack(0, 128), Err(SdoAbort::InvalidBlockSize));
    }

    #[test]
    fn empty_value_is_one_segment_without_data() {
        let tx = BlockTx::new(0, 5);
        let p = tx.next().unwrap();
        assert_eq!((p.seqno, p.start, p.end, p.last), (1, 0, 0, true));
        assert_eq!(tx.unused(), 7);
        assert_eq!(unused_in_last(7), 0);
        assert_eq!(unused_in_last(8), 6);
    }

    #[test]
    fn receiver_confirms_at_blksize_and_at_the_last_segment() {
        let mut rx = BlockRx::new(3);
        for (s, i) in [(1, 0), (2, 1)] {
            assert_eq!(
                rx.on_segment(&seg(s, false)),
                Ok(Verdict {
                    accept: Some(i),
                    confirm: false
                })
            );
        }
        assert_eq!(
            rx.on_segment(&seg(3, false)),
            Ok(Verdict {
                accept: Some(2),
                confirm: true
            })
        );
        assert_eq!(rx.confirm(3), 3);
        assert_eq!(
            rx.on_segment(&seg(1, true)),
            Ok(Verdict {
                accept: Some(3),
                confirm: true
            })
        );
        assert!(rx.complete());
        assert_eq!(rx.confirm(3), 1);
        assert_eq!(rx.segments(), 4);
    }

    #[test]
    fn receiver_drops_after_a_gap_and_confirms_the_last_in_order() {
        let mut rx = BlockRx::new(4);
        rx.on_segment(&seg(1, false)).unwrap();
        // 2 lost; 3 dropped, 4 ends the sub-block.
        assert_eq!(
            rx.on_segment(&seg(3, false)),
            Ok(Verdict {
                accept: None,
                confirm: false
            })
        );
        assert_eq!(
            rx.on_segment(&seg(4, false)),
            Ok(Verdict {
                accept: None,
                confirm: true
            })
        );
        assert_eq!(rx.confirm(4), 1);
        // The retransmission starts at seqno 1 = segment 1 of the transfer.
        assert_eq!(rx.on_segment(&seg(1, false)).unwrap().accept, Some(1));
        // A repetition is ignored.
        assert_eq!(
            rx.on_segment(&seg(1, false)),
            Ok(Verdict {
                accept: None,
                confirm: false
            })
        );
        assert!(!rx.complete());
    }

    #[test]
    fn receiver_refuses_invalid_sequence_numbers() {
        let mut rx = BlockRx::new(4);
        assert_eq!(
            rx.on_segment(&BlockSegment::decode(&[0x00, 0, 0, 0, 0, 0, 0, 0])),
            Err(SdoAbort::InvalidSequenceNumber)
        );
        assert_eq!(
            rx.on_segment(&seg(5, false)),
            Err(SdoAbort::InvalidSequenceNumber)
        );
        assert!(!rx.stalled());
        rx.on_segment(&seg(1, false)).unwrap();
        assert!(rx.stalled());
    }
}
