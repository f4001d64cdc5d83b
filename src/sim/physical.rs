//! The physical model of the simulated bus: bit time, frame length with
//! bit stuffing, arbitration by identifier, transmit and receive queues of
//! bounded size (a [`SimBus`](super::SimBus) made by
//! [`SimBus::with_model`](super::SimBus::with_model)).
//!
//! The frame layout is the one of ISO 11898-1:2015 clause 10.4.2 (data and
//! remote frames in base and extended format), bit stuffing the one of
//! clause 10.5 and the CRC the one of clause 10.4.2.6. The functions here
//! only count bits; the queues and the clock live in the bus.

use std::collections::{HashMap, VecDeque};

use crate::error::CopKernel;
use crate::port::{CanFrame, CanId, Priority, RxFrame};

/// Nanoseconds of one tick (100 µs).
pub const NS_PER_TICK: u64 = 100_000;

/// Bits of the intermission between two frames (ISO 11898-1:2015 10.4.5:
/// three recessive bits after the end of frame before the next SOF).
pub const INTERMISSION_BITS: u32 = 3;

/// Bits after the CRC sequence, never stuffed (ISO 11898-1:2015 10.4.2.6 -
/// 10.4.2.8): CRC delimiter 1, ACK slot 1, ACK delimiter 1, end of frame 7.
const TAIL_BITS: u32 = 1 + 1 + 1 + 7;

/// The CRC-15 generator polynomial x^15 + x^14 + x^10 + x^8 + x^7 + x^4 +
/// x^3 + 1 (ISO 11898-1:2015 10.4.2.6), without the x^15 term.
const CRC15_POLY: u16 = 0x4599;

/// The lowest and highest bit rate the model takes, in bit/s (CiA 301
/// names 10 kbit/s to 1 Mbit/s).
pub const BIT_RATE_RANGE: core::ops::RangeInclusive<u32> = 10_000..=1_000_000;

/// The bus parameters and the queue sizes of every node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BusModel {
    /// Bits per second, 10 000 ..= 1 000 000.
    pub bit_rate: u32,
    /// Frames the high receive buffer holds (identifiers subscribed with
    /// `Priority::High`: SRDO and GFC).
    pub rx_high: usize,
    /// Frames the low receive buffer holds (every other identifier).
    pub rx_low: usize,
    /// Frames the high transmit buffer holds (`Priority::High`: SRDO, GFC,
    /// NMT).
    pub tx_high: usize,
    /// Frames the low transmit buffer holds.
    pub tx_low: usize,
}

impl BusModel {
    /// A bus of `bit_rate` bit/s with the buffer sizes of a SYS TEC driver
    /// configuration with `CDRV_USE_HIGHBUFF`: 16 high and 10 low receive
    /// buffers, the same for transmission. `None` outside
    /// [`BIT_RATE_RANGE`].
    pub fn new(bit_rate: u32) -> Option<BusModel> {
        BIT_RATE_RANGE.contains(&bit_rate).then_some(BusModel {
            bit_rate,
            rx_high: 16,
            rx_low: 10,
            tx_high: 16,
            tx_low: 10,
        })
    }

    /// Checks the parameters: the bit rate in range, every buffer at least
    /// one frame (`kCopInvalidParam` otherwise).
    pub fn check(&self) -> Result<(), CopKernel> {
        let sizes = [self.rx_high, self.rx_low, self.tx_high, self.tx_low];
        if BIT_RATE_RANGE.contains(&self.bit_rate) && sizes.iter().all(|&n| n > 0) {
            Ok(())
        } else {
            Err(CopKernel::InvalidParam)
        }
    }

    /// The time `bits` bits take on this bus, in ns (rounded up).
    pub fn bits_ns(&self, bits: u32) -> u64 {
        let rate = u64::from(self.bit_rate.max(1));
        (u64::from(bits) * 1_000_000_000).div_ceil(rate)
    }
}

/// The CRC-15 register after shifting in `bits` (ISO 11898-1:2015
/// 10.4.2.6: the register starts at 0; each bit XOR the register's top bit
/// decides whether the shifted register is XORed with the polynomial).
pub fn crc15(bits: &[bool]) -> u16 {
    let mut reg: u16 = 0;
    for &b in bits {
        let top = reg & 0x4000 != 0;
        reg = (reg << 1) & 0x7FFF;
        if b != top {
            reg ^= CRC15_POLY;
        }
    }
    reg
}

/// How many stuff bits a transmitter inserts into `bits` (ISO 11898-1:2015
/// 10.5: after five consecutive bits of the same value a bit of the
/// opposite value; that stuff bit is the first of the next run).
pub fn stuff_bits(bits: &[bool]) -> u32 {
    let mut stuffed = 0;
    let mut last: Option<bool> = None;
    let mut run = 0u32;
    for &b in bits {
        if last == Some(b) {
            run += 1;
        } else {
            last = Some(b);
            run = 1;
        }
        if run == 5 {
            stuffed += 1;
            last = Some(!b);
            run = 1;
        }
    }
    stuffed
}

fn push_bits(out: &mut Vec<bool>, value: u32, count: u32) {
    for i in (0..count).rev() {
        out.push((value >> i) & 1 != 0);
    }
}

/// The bits of a frame from SOF to the end of the CRC sequence, before
/// stuffing (ISO 11898-1:2015 10.4.2.2 - 10.4.2.6), dominant as `false`.
/// Base format: SOF, 11 identifier bits, RTR, IDE, r0, DLC; extended
/// format: SOF, 11 base identifier bits, SRR, IDE, 18 extension bits, RTR,
/// r1, r0, DLC. Then the data bytes (none in a remote frame), most
/// significant bit first, then the 15 CRC bits.
pub fn stuffed_region(f: &CanFrame) -> Vec<bool> {
    let mut bits = Vec::with_capacity(54 + 64 + 15);
    bits.push(false); // SOF
    let id = f.id.id();
    if f.id.is_extended() {
        push_bits(&mut bits, id >> 18, 11);
        bits.push(true); // SRR, recessive
        bits.push(true); // IDE, recessive: extended format
        push_bits(&mut bits, id & 0x3_FFFF, 18);
        bits.push(f.rtr);
        bits.push(false); // r1
        bits.push(false); // r0
    } else {
        push_bits(&mut bits, id, 11);
        bits.push(f.rtr);
        bits.push(false); // IDE, dominant: base format
        bits.push(false); // r0
    }
    push_bits(&mut bits, u32::from(f.len & 0x0F), 4);
    if !f.rtr {
        for &byte in f.payload() {
            push_bits(&mut bits, u32::from(byte), 8);
        }
    }
    let crc = crc15(&bits);
    push_bits(&mut bits, u32::from(crc), 15);
    bits
}

/// The length of a frame on the bus in bits, SOF to the end of the end of
/// frame field, stuff bits included (without the intermission).
pub fn frame_bits(f: &CanFrame) -> u32 {
    let region = stuffed_region(f);
    let n = u32::try_from(region.len()).unwrap_or(u32::MAX);
    n + stuff_bits(&region) + TAIL_BITS
}

/// A frame as it went over the bus.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BusFrame {
    /// The sending node (`usize::MAX`: injected from outside).
    pub from: usize,
    /// When the sender queued it, ns of bus time.
    pub queued_ns: u64,
    /// The start of frame, ns of bus time.
    pub start_ns: u64,
    /// The end of the end of frame field, ns of bus time.
    pub end_ns: u64,
    /// Bits on the bus including stuff bits and the intermission.
    pub bits: u32,
    /// The frame (in the bus log: as the fault filter delivered it).
    pub frame: CanFrame,
}

/// Counters of the bus since it was made.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BusStats {
    /// Frames that went over the bus.
    pub frames: u64,
    /// Their bits, stuff bits and intermission included.
    pub bits: u64,
    /// The time the bus was busy with them, ns.
    pub busy_ns: u64,
    /// The bus time since it was made, ns.
    pub elapsed_ns: u64,
    /// Frames a full transmit buffer refused.
    pub tx_refused: u64,
    /// Received frames lost in a full high buffer, summed over the nodes.
    pub rx_lost_high: u64,
    /// Received frames lost in a full low buffer, summed over the nodes.
    pub rx_lost_low: u64,
}

impl BusStats {
    /// The share of the time the bus was busy, in percent.
    pub fn load_percent(&self) -> f64 {
        if self.elapsed_ns == 0 {
            0.0
        } else {
            self.busy_ns as f64 * 100.0 / self.elapsed_ns as f64
        }
    }
}

/// A frame waiting in a transmit buffer.
#[derive(Clone, Copy, Debug)]
pub(super) struct Pending {
    pub(super) frame: CanFrame,
    pub(super) queued_ns: u64,
}

/// One node's buffers on a physical bus.
#[derive(Default)]
pub(super) struct NodeQueues {
    pub(super) tx_high: VecDeque<Pending>,
    pub(super) tx_low: VecDeque<Pending>,
    pub(super) rx_high: VecDeque<RxFrame>,
    pub(super) rx_low: VecDeque<RxFrame>,
    /// The identifiers the node receives and the buffer each goes to (the
    /// driver's identifier filter, `CdrvDefineCanId`): a frame with any
    /// other identifier never reaches a buffer.
    pub(super) ids: HashMap<CanId, Priority>,
}

impl NodeQueues {
    /// The frame the node's controller offers to arbitration: the oldest of
    /// the high buffer, otherwise the oldest of the low buffer (the driver
    /// empties its high buffer first).
    pub(super) fn head(&self) -> Option<&Pending> {
        self.tx_high.front().or_else(|| self.tx_low.front())
    }

    /// Takes the frame [`NodeQueues::head`] showed.
    pub(super) fn pop_head(&mut self) -> Option<Pending> {
        self.tx_high.pop_front().or_else(|| self.tx_low.pop_front())
    }

    /// The oldest received frame, the high buffer first.
    pub(super) fn receive(&mut self) -> Option<RxFrame> {
        self.rx_high.pop_front().or_else(|| self.rx_low.pop_front())
    }

    pub(super) fn rx_len(&self) -> usize {
        self.rx_high.len() + self.rx_low.len()
    }
}

/// The winner of an arbitration among the offered frames `(node, frame)`:
/// the lowest identifier (ISO 11898-1:2015 10.4.2.2: a dominant bit
/// overwrites a recessive one, so the node that sends a recessive bit and
/// sees a dominant one withdraws). A base-format frame wins over an
/// extended one with the same 11 base bits (its IDE bit is dominant where
/// the extended frame has a recessive SRR bit), a data frame over a remote
/// frame with the same identifier (RTR). Equal frames: the lower node.
pub fn arbitration_winner<'a, I>(offers: I) -> Option<usize>
where
    I: IntoIterator<Item = (usize, &'a CanFrame)>,
{
    offers
        .into_iter()
        .min_by_key(|(node, f)| (arbitration_key(f), *node))
        .map(|(node, _)| node)
}

/// The arbitration field as a number in which a lower value wins: the
/// bits from the first identifier bit to RTR in bus order, dominant = 0.
fn arbitration_key(f: &CanFrame) -> u64 {
    let id = u64::from(f.id.id());
    let rtr = u64::from(f.rtr);
    if f.id.is_extended() {
        // base 11, SRR 1, IDE 1, extension 18, RTR 1
        ((id >> 18) << 21) | (0b11 << 19) | ((id & 0x3_FFFF) << 1) | rtr
    } else {
        // base 11, RTR, IDE 0; padded to the extended width
        ((id << 21) | (rtr << 20)) & !(1 << 19)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn std_frame(id: u16, data: &[u8]) -> CanFrame {
        CanFrame::new(CanId::std_masked(id), data)
    }

    #[test]
    fn stuffing_counts_the_stuff_bit_in_the_next_run() {
        // ISO 11898-1:2015 10.5: five equal bits, then a complement.
        let zeros5 = [false; 5];
        assert_eq!(stuff_bits(&zeros5), 1);
        assert_eq!(stuff_bits(&zeros5[..4]), 0);
        // 00000 [1] 1111 [0]: the inserted 1 and four 1s make a run of five.
        let mut bits = vec![false; 5];
        bits.extend([true; 4]);
        assert_eq!(stuff_bits(&bits), 2);
        // Alternating bits are never stuffed.
        let alt: Vec<bool> = (0..64).map(|i| i % 2 == 0).collect();
        assert_eq!(stuff_bits(&alt), 0);
    }

    #[test]
    fn all_dominant_frame_has_six_stuff_bits() {
        // Identifier 0, DLC 0: SOF + 11 + RTR + IDE + r0 + 4 DLC = 19
        // dominant bits; the CRC of all-zero bits is 0, 15 more: 34
        // dominant bits, a stuff bit after every fifth: 6. With 10 tail
        // bits: 50, with the intermission 53.
        let f = std_frame(0, &[]);
        let region = stuffed_region(&f);
        assert_eq!(region.len(), 34);
        assert!(region.iter().all(|b| !b));
        assert_eq!(crc15(&region[..19]), 0);
        assert_eq!(frame_bits(&f), 50);
    }

    #[test]
    fn crc_sequence_checks_to_zero() {
        // The receiver shifts the received CRC sequence through the same
        // register and gets 0 (ISO 11898-1:2015 10.4.2.6).
        for (id, data) in [
            (0x101u16, &[0x01u8, 0x02, 0x03, 0x04][..]),
            (0x702, &[0x05]),
            (0x7E5, &[0xFF; 8]),
        ] {
            let region = stuffed_region(&std_frame(id, data));
            assert_eq!(crc15(&region), 0, "frame {id:03X}");
        }
        assert_ne!(crc15(&[true]), 0);
    }

    #[test]
    fn known_frames_have_their_length() {
        // CRCs worked out by polynomial long division of the bit strings of
        // ISO 11898-1:2015 10.4.2 (independently of crc15), stuff bits by
        // hand. Heartbeat of node 5, operational (0x705, [05]):
        // 0 111 00000[1] 101 000 00[1]0 1 00000[1] 101, CRC 0x68BF =
        // 110100010 11111[0] 1: 42 bits, 4 stuff bits, 10 tail bits.
        let hb = std_frame(0x705, &[0x05]);
        let region = stuffed_region(&hb);
        assert_eq!(region.len(), 42);
        assert_eq!(crc15(&region[..27]), 0x68BF);
        assert_eq!(stuff_bits(&region), 4);
        assert_eq!(frame_bits(&hb), 56);
        // NMT start all (0x000, [01 00]): CRC 0x6197, 5 stuff bits.
        let nmt = std_frame(0x000, &[0x01, 0x00]);
        assert_eq!(crc15(&stuffed_region(&nmt)[..35]), 0x6197);
        assert_eq!(frame_bits(&nmt), 50 + 5 + 10);
        // An SRDO-sized PDO (0x181, 11 22 .. 88): CRC 0x0B7F, 4 stuff bits.
        let pdo = std_frame(0x181, &[0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88]);
        assert_eq!(crc15(&stuffed_region(&pdo)[..83]), 0x0B7F);
        assert_eq!(frame_bits(&pdo), 98 + 4 + 10);
    }

    #[test]
    fn lengths_stay_within_the_worst_case_bound() {
        // Unstuffed length 47 + 8n (base) / 67 + 8n (extended) with the
        // intermission; at most one stuff bit per four bits of the stuffed
        // region after the first: 34 + 8n - 1 (base), 54 + 8n - 1
        // (extended) (Davis, Burns, Bril, Lukkien 2007, eq. 2).
        let mut x: u32 = 0x1234_5678;
        // Fewer under Miri (no unsafe code here; the run stays short).
        let runs = if cfg!(miri) { 40 } else { 2000 };
        for _ in 0..runs {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            let n = (x % 9) as usize;
            let data: Vec<u8> = (0..n).map(|i| (x >> (i % 4 * 8)) as u8).collect();
            let ext = x & 0x8000 != 0;
            let id = if ext {
                CanId::ext(x & 0x1FFF_FFFF).unwrap()
            } else {
                CanId::std_masked((x & 0x7FF) as u16)
            };
            let f = CanFrame::new(id, &data);
            let n = n as u32;
            let g = if ext { 54 } else { 34 };
            let bits = frame_bits(&f) + INTERMISSION_BITS;
            assert!(bits >= g + 13 + 8 * n, "{f:?}");
            assert!(bits <= g + 13 + 8 * n + (g + 8 * n - 1) / 4, "{f:?}");
        }
    }

    #[test]
    fn remote_frame_carries_no_data() {
        let r = CanFrame::remote(CanId::std_masked(0x705), 1);
        assert_eq!(stuffed_region(&r).len(), 34);
    }

    #[test]
    fn lowest_identifier_wins_arbitration() {
        let a = std_frame(0x181, &[0; 8]);
        let b = std_frame(0x101, &[0; 8]);
        let c = std_frame(0x700, &[0]);
        assert_eq!(arbitration_winner([(0, &a), (1, &b), (2, &c)]), Some(1));
        // Base format over extended with the same base identifier.
        let e = CanFrame::new(CanId::ext(0x101 << 18).unwrap(), &[]);
        assert_eq!(arbitration_winner([(0, &e), (1, &b)]), Some(1));
        // Data over remote with the same identifier.
        let r = CanFrame::remote(CanId::std_masked(0x101), 8);
        assert_eq!(arbitration_winner([(0, &r), (1, &b)]), Some(1));
        // A lower base identifier wins over an extended one.
        let e_low = CanFrame::new(CanId::ext(0x100 << 18).unwrap(), &[]);
        assert_eq!(arbitration_winner([(0, &e_low), (1, &b)]), Some(0));
        assert_eq!(arbitration_winner(Vec::<(usize, &CanFrame)>::new()), None);
    }

    #[test]
    fn bit_time_of_a_frame() {
        let m = BusModel::new(1_000_000).unwrap();
        assert_eq!(m.bits_ns(53), 53_000);
        let slow = BusModel::new(125_000).unwrap();
        assert_eq!(slow.bits_ns(1), 8_000);
        assert!(BusModel::new(9_999).is_none());
        assert!(BusModel::new(1_000_001).is_none());
        let mut bad = m;
        bad.rx_low = 0;
        assert_eq!(bad.check(), Err(CopKernel::InvalidParam));
    }
}
