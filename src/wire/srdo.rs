//! SRDO and GFC frames (CiA 304 / EN 50325-5; seed manual L-1077d
//! sections 1.1, 1.3, 1.4).
//!
//! An SRDO is two CAN data frames: COB-ID 1 (odd) carries the normal data,
//! COB-ID 2 = COB-ID 1 + 1 carries the same data bit-inverted. Both frames
//! have the same DLC. The GFC is a frame with CAN id 0x001 and no data.
//! Everything here is a pure function of its arguments.

use crate::port::{CanFrame, CanId};

// Object indices of the safety objects (CiA 304; seed manual L-1077d 1.5).
/// Global Fail-Safe Command parameter (0 = GFC off, 1 = on).
pub const GFC_PARAM_INDEX: u16 = 0x1300;
/// Communication index of SRDO n is `COMMU_BASE + n` (n = 1..=64).
pub const COMMU_BASE: u16 = 0x1300;
/// First SRDO communication parameter.
pub const COMMU_FIRST: u16 = 0x1301;
/// Last SRDO communication parameter.
pub const COMMU_LAST: u16 = 0x1340;
/// Distance from an SRDO's communication to its mapping parameter.
pub const MAPP_OFFSET: u16 = 0x80;
/// First SRDO mapping parameter.
pub const MAPP_FIRST: u16 = 0x1381;
/// Last SRDO mapping parameter.
pub const MAPP_LAST: u16 = 0x13C0;
/// Configuration valid.
pub const CONFIG_VALID_INDEX: u16 = 0x13FE;
/// Safety configuration checksums (sub n = SRDO n).
pub const CRC_INDEX: u16 = 0x13FF;

/// Lowest valid SRDO COB-ID (manual 1.1.1: "Werte im Bereich von 0x101 –
/// 0x180").
pub const COB_ID_MIN: u16 = 0x101;
/// Highest valid SRDO COB-ID.
pub const COB_ID_MAX: u16 = 0x180;
/// Number of COB-IDs in the SRDO range (0x101..=0x180).
pub const COB_ID_COUNT: usize = (COB_ID_MAX - COB_ID_MIN + 1) as usize;
/// Bits 31..11 of an SRDO COB-ID are reserved and must be 0 (manual
/// table 3).
pub const COB_ID_RESERVED_MASK: u32 = 0xFFFF_F800;
/// CAN id of the Global Fail-Safe Command (manual table 7).
pub const GFC_ID: u16 = 0x001;
/// Largest SRDO payload in bytes (one CAN frame).
pub const MAX_DATA: usize = 8;

/// Why a pair of SRDO COB-IDs is not acceptable.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CobIdError {
    /// A reserved bit (31..11) is set.
    ReservedBits,
    /// Outside 0x101..=0x180.
    OutOfRange,
    /// COB-ID 1 is even (it must be odd).
    NotOdd,
    /// COB-ID 2 is not COB-ID 1 + 1.
    NotConsecutive,
}

/// A checked pair of SRDO COB-IDs: COB-ID 1 odd in 0x101..=0x17F, COB-ID 2
/// the following even id (manual 1.1, rule 1 and table 3). Invalid pairs
/// cannot be constructed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SrdoCobIds {
    normal: u16,
}

impl SrdoCobIds {
    /// Checks the two COB-ID values of object 0x1301+n sub 5 and 6.
    pub const fn new(cob1: u32, cob2: u32) -> Result<SrdoCobIds, CobIdError> {
        if cob1 & COB_ID_RESERVED_MASK != 0 || cob2 & COB_ID_RESERVED_MASK != 0 {
            return Err(CobIdError::ReservedBits);
        }
        let (c1, c2) = (cob1 as u16, cob2 as u16);
        if c1 < COB_ID_MIN || c1 > COB_ID_MAX || c2 < COB_ID_MIN || c2 > COB_ID_MAX {
            return Err(CobIdError::OutOfRange);
        }
        if c1 & 1 == 0 {
            return Err(CobIdError::NotOdd);
        }
        if c2 != c1 + 1 {
            return Err(CobIdError::NotConsecutive);
        }
        Ok(SrdoCobIds { normal: c1 })
    }

    /// The predefined connection set for SRDO 1 of `node` (1..=64): COB-ID 1
    /// = 0xFF + 2 * node, COB-ID 2 = 0x100 + 2 * node (manual table 8:
    /// node 1 uses 0x101/0x102, node 64 uses 0x17F/0x180). `None` for
    /// nodes outside 1..=64.
    pub const fn predefined(node: u8) -> Option<SrdoCobIds> {
        if node == 0 || node > 64 {
            return None;
        }
        Some(SrdoCobIds {
            normal: 0xFF + 2 * node as u16,
        })
    }

    /// COB-ID 1 (normal data).
    pub const fn normal(self) -> u16 {
        self.normal
    }

    /// COB-ID 2 (inverted data).
    pub const fn inverted(self) -> u16 {
        self.normal + 1
    }
}

/// Whether a COB-ID in the SRDO range carries normal or inverted data: odd
/// ids carry normal data, even ids inverted data (manual 1.1, rule 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Half {
    /// COB-ID 1, normal data.
    Normal,
    /// COB-ID 2, inverted data.
    Inverted,
}

/// Position of an 11-bit id inside the SRDO range (0 for 0x101) and which
/// half it carries; `None` outside 0x101..=0x180 or for 29-bit ids.
#[inline]
pub fn classify(id: CanId) -> Option<(usize, Half)> {
    if id.is_extended() {
        return None;
    }
    let raw = id.id();
    if raw < u32::from(COB_ID_MIN) || raw > u32::from(COB_ID_MAX) {
        return None;
    }
    let half = if raw & 1 == 1 {
        Half::Normal
    } else {
        Half::Inverted
    };
    Some(((raw - u32::from(COB_ID_MIN)) as usize, half))
}

/// Bit mask of the first `dlc` payload bytes of a frame read as a
/// little-endian `u64` (byte 0 in bits 0..7).
#[inline]
pub const fn payload_mask(dlc: u8) -> u64 {
    if dlc >= 8 {
        u64::MAX
    } else {
        (1u64 << (8 * dlc as u32)) - 1
    }
}

/// The payload of a frame as a little-endian `u64` (unused bytes 0).
#[inline]
pub fn payload_u64(frame: &CanFrame) -> u64 {
    u64::from_le_bytes(frame.data) & payload_mask(frame.len)
}

/// True when `inverted` is the bitwise complement of `normal` in every one
/// of the first `dlc` bytes (manual 1.1, rule 2). One XOR and one compare.
#[inline]
pub const fn is_complement(normal: u64, inverted: u64, dlc: u8) -> bool {
    let mask = payload_mask(dlc);
    (normal ^ inverted) & mask == mask
}

/// The two frames of an SRDO: normal data under COB-ID 1 and the given
/// inverted data under COB-ID 2, both with DLC `dlc` (≤ 8). The caller
/// supplies both halves as read from the mapped variables; checking that
/// they are complements is the caller's job ([`is_complement`]).
#[inline]
pub fn encode(ids: SrdoCobIds, normal: u64, inverted: u64, dlc: u8) -> (CanFrame, CanFrame) {
    let len = dlc.min(8);
    // The bytes beyond the DLC are zero (the `CanFrame` invariant).
    let mask = payload_mask(len);
    let frame = |id: u16, v: u64| CanFrame {
        id: CanId::std_masked(id),
        rtr: false,
        len,
        data: (v & mask).to_le_bytes(),
    };
    (frame(ids.normal(), normal), frame(ids.inverted(), inverted))
}

/// The GFC frame: id 0x001, DLC 0 (manual 1.3 and table 7).
pub fn encode_gfc() -> CanFrame {
    CanFrame::new(CanId::std_masked(GFC_ID), &[])
}

/// True for a frame with the GFC id (whatever its DLC).
#[inline]
pub fn is_gfc_id(frame: &CanFrame) -> bool {
    frame.id == CanId::std_masked(GFC_ID)
}

/// True for a valid GFC: id 0x001, data frame, DLC 0.
#[inline]
pub fn is_valid_gfc(frame: &CanFrame) -> bool {
    is_gfc_id(frame) && !frame.rtr && frame.len == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    // req: M-1.4-PREDEF
    #[test]
    fn predefined_connection_set_matches_manual_table_8() {
        // Manual L-1077d table 8: node 1 -> 0x101/0x102, node 32 -> 0x13F/0x140,
        // node 33 -> 0x141/0x142, node 64 -> 0x17F/0x180.
        for (node, c1, c2) in [
            (1u8, 0x101u16, 0x102u16),
            (32, 0x13F, 0x140),
            (33, 0x141, 0x142),
            (64, 0x17F, 0x180),
        ] {
            let ids = SrdoCobIds::predefined(node).unwrap();
            assert_eq!((ids.normal(), ids.inverted()), (c1, c2), "node {node}");
        }
        assert_eq!(SrdoCobIds::predefined(0), None);
        assert_eq!(SrdoCobIds::predefined(65), None);
    }

    // req: M-1.1-COBID
    #[test]
    fn cob_id_rules_of_manual_1_1_1() {
        assert!(SrdoCobIds::new(0x101, 0x102).is_ok());
        assert!(SrdoCobIds::new(0x17F, 0x180).is_ok());
        use CobIdError::{NotConsecutive, NotOdd, OutOfRange, ReservedBits};
        let refused = [
            (0x100, 0x101, OutOfRange), // below 0x101
            (0x181, 0x182, OutOfRange), // above 0x180
            // Each identifier is checked on its own: a valid first one does
            // not let an out-of-range second one through.
            (0x101, 0x100, OutOfRange),
            (0x17F, 0x181, OutOfRange),
            (0x102, 0x103, NotOdd),
            (0x101, 0x104, NotConsecutive),
            // Bits 31 and 11 are reserved (table 3).
            (0x8000_0101, 0x102, ReservedBits),
            (0x101, 0x0000_0902, ReservedBits),
        ];
        for (normal, inverted, error) in refused {
            let got = SrdoCobIds::new(normal, inverted);
            assert_eq!(got, Err(error), "{normal:#x} / {inverted:#x}");
        }
    }

    #[test]
    fn classify_splits_normal_and_inverted() {
        assert_eq!(classify(CanId::std_masked(0x101)), Some((0, Half::Normal)));
        assert_eq!(
            classify(CanId::std_masked(0x102)),
            Some((1, Half::Inverted))
        );
        assert_eq!(
            classify(CanId::std_masked(0x180)),
            Some((127, Half::Inverted))
        );
        assert_eq!(classify(CanId::std_masked(0x100)), None);
        assert_eq!(classify(CanId::std_masked(0x181)), None);
        assert_eq!(classify(CanId::ext(0x101).unwrap()), None);
    }

    // req: M-1.1-INVERTED
    #[test]
    fn complement_check_is_bitwise_over_dlc_bytes() {
        assert!(is_complement(0x0000_1234, 0xFFFF_EDCB, 2));
        assert!(is_complement(0x12, 0xED, 1));
        assert!(!is_complement(0x12, 0xEC, 1), "one bit not inverted");
        // Bytes beyond the DLC do not take part.
        assert!(is_complement(0xAA12, 0x55ED, 1));
        assert!(is_complement(u64::MAX, 0, 8));
        assert!(!is_complement(u64::MAX, 1, 8));
        assert!(
            is_complement(0, 0, 0),
            "an empty SRDO is trivially inverted"
        );
    }

    // req: M-1.1-ORDER, M-1.1-INVERTED
    #[test]
    fn encode_puts_normal_then_inverted_with_equal_dlc() {
        let ids = SrdoCobIds::new(0x101, 0x102).unwrap();
        let (f1, f2) = encode(ids, 0x0000_BEEF, !0x0000_BEEFu64, 2);
        // Manual 1.1: frame 1 normal data, frame 2 the bitwise inverse.
        assert_eq!(f1.id.id(), 0x101);
        assert_eq!(f1.payload(), &[0xEF, 0xBE]);
        assert_eq!(f2.id.id(), 0x102);
        assert_eq!(f2.payload(), &[0x10, 0x41]);
        assert_eq!(payload_u64(&f1), 0xBEEF);
        assert_eq!(payload_u64(&f2), 0x4110);
    }

    // req: M-1.3-GFC
    #[test]
    fn gfc_is_id_1_without_data() {
        let f = encode_gfc();
        // Manual 1.3 / table 7: CAN id 1, no data.
        assert_eq!(f.id.id(), 0x001);
        assert_eq!(f.len, 0);
        assert!(is_valid_gfc(&f));
        let long = CanFrame::new(CanId::std_masked(1), &[0]);
        assert!(is_gfc_id(&long));
        assert!(!is_valid_gfc(&long));
        assert!(!is_valid_gfc(&CanFrame::remote(CanId::std_masked(1), 0)));
        let other = CanFrame::new(CanId::std_masked(2), &[]);
        assert!(!is_gfc_id(&other) && !is_valid_gfc(&other));
    }
}
