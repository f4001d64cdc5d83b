//! PDO and SYNC frame layouts (CiA 301): the bit-level placement of mapped
//! values in the 8-byte payload, the mapping entry and COB-ID formats of the
//! PDO parameter objects, and the SYNC frame. Pure functions, no state.
//!
//! Bit numbering follows CiA 301 §7.2.2 (PDO mapping): the payload is one
//! little-endian bit string; bit `n` is bit `n % 8` of byte `n / 8`; the
//! first mapped object starts at bit 0 of byte 0 and each further object
//! follows immediately after the previous one.

use crate::port::{CanFrame, CanId};

/// Largest PDO payload in bits (classical CAN: 8 bytes).
pub const MAX_BITS: u16 = 64;

/// Reads `bits` (1..=64) bits starting at bit `pos` of `payload`. `None`
/// when the field does not lie completely inside the payload.
pub fn extract_bits(payload: &[u8], pos: u16, bits: u8) -> Option<u64> {
    if bits == 0 || bits > 64 {
        return None;
    }
    let end = usize::from(pos) + usize::from(bits);
    if end > payload.len() * 8 {
        return None;
    }
    let mut v = 0u64;
    for i in 0..usize::from(bits) {
        let p = usize::from(pos) + i;
        let byte = *payload.get(p / 8)?;
        if byte >> (p % 8) & 1 != 0 {
            v |= 1u64 << i;
        }
    }
    Some(v)
}

/// Writes the low `bits` (1..=64) bits of `value` starting at bit `pos` of
/// `payload`; the other bits of the payload are left as they are. `None`
/// (and nothing written) when the field does not fit.
pub fn insert_bits(payload: &mut [u8], pos: u16, bits: u8, value: u64) -> Option<()> {
    if bits == 0 || bits > 64 {
        return None;
    }
    let end = usize::from(pos) + usize::from(bits);
    if end > payload.len() * 8 {
        return None;
    }
    for i in 0..usize::from(bits) {
        let p = usize::from(pos) + i;
        let byte = payload.get_mut(p / 8)?;
        let mask = 1u8 << (p % 8);
        if value >> i & 1 != 0 {
            *byte |= mask;
        } else {
            *byte &= !mask;
        }
    }
    Some(())
}

/// Bytes needed to carry `bits` bits (DLC of a PDO).
pub const fn bytes_for_bits(bits: u16) -> u8 {
    bits.div_ceil(8) as u8
}

/// One entry of a PDO mapping parameter (0x1600+ / 0x1A00+ subindex 1..):
/// CiA 301 §7.5.2.36 / §7.5.2.38, "structure of a mapping entry":
/// bits 31-16 index, bits 15-8 subindex, bits 7-0 object length in bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MapEntry {
    /// Index of the mapped object (or of a data type for dummy mapping).
    pub index: u16,
    /// Subindex of the mapped object.
    pub sub: u8,
    /// Length of the mapped object in bits.
    pub bits: u8,
}

impl MapEntry {
    /// Decodes the 32-bit value of a mapping subindex.
    pub const fn decode(v: u32) -> MapEntry {
        MapEntry {
            index: (v >> 16) as u16,
            sub: (v >> 8) as u8,
            bits: v as u8,
        }
    }

    /// The 32-bit value of a mapping subindex.
    pub const fn encode(self) -> u32 {
        (self.index as u32) << 16 | (self.sub as u32) << 8 | self.bits as u32
    }

    /// For a CiA 301 dummy entry (data type index 0x0001..=0x0007) the size
    /// of its type in bits; `None` for ordinary objects.
    pub const fn dummy_bits(self) -> Option<u8> {
        match self.index {
            0x0001 => Some(1),
            0x0002 | 0x0005 => Some(8),
            0x0003 | 0x0006 => Some(16),
            0x0004 | 0x0007 => Some(32),
            _ => None,
        }
    }
}

/// COB-ID bit 31 of PDO and SYNC COB-IDs: for PDOs "PDO does not exist /
/// is not valid" (`CANID_INVALID`).
pub const COB_INVALID: u32 = 0x8000_0000;
/// COB-ID bit 30: for TPDOs "no RTR allowed on this PDO"; for 0x1005
/// "this device generates SYNC" (`CANID_SYNC_PRODUCER`). Reserved for RPDOs.
pub const COB_NO_RTR: u32 = 0x4000_0000;
/// COB-ID bit 29: 29-bit CAN-ID (`CAN_FRAME_FORMAT_MASK`).
pub const COB_EXTENDED: u32 = 0x2000_0000;
/// The CAN-ID bits of a COB-ID.
pub const COB_ID_MASK: u32 = 0x1FFF_FFFF;

/// A PDO COB-ID value (CiA 301 §7.5.2.35 / §7.5.2.37) taken apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PdoCobId {
    /// Bit 31 clear: the PDO exists.
    pub valid: bool,
    /// Bit 30 clear: remote requests are answered (TPDO).
    pub rtr_allowed: bool,
    /// The identifier (11 or 29 bits).
    pub id: CanId,
}

/// Why a COB-ID value cannot be used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CobIdError {
    /// Bit 29 set, but the driver handles 11-bit identifiers only.
    ExtendedNotSupported,
    /// An 11-bit COB-ID with identifier bits above 0x7FF set.
    IdOutOfRange,
    /// A restricted identifier (CiA 301 §7.3.5).
    Restricted,
}

impl PdoCobId {
    /// Decodes a COB-ID value. When the PDO is marked valid the identifier
    /// must be usable: 11-bit unless `extended_ok`, in range, and not one
    /// of the identifiers CiA 301 §7.3.5 reserves. An invalid PDO's
    /// identifier is not checked (CiA 301 allows any value while bit 31 is
    /// set).
    pub fn decode(v: u32, extended_ok: bool) -> Result<PdoCobId, CobIdError> {
        let cob = PdoCobId {
            valid: v & COB_INVALID == 0,
            rtr_allowed: v & COB_NO_RTR == 0,
            id: CanId::from_cob_id(v),
        };
        if cob.valid {
            check_identifier(v, extended_ok)?;
        }
        Ok(cob)
    }
}

/// Checks the identifier part of a COB-ID for use on the bus.
pub fn check_identifier(v: u32, extended_ok: bool) -> Result<(), CobIdError> {
    if v & COB_EXTENDED != 0 {
        if !extended_ok {
            return Err(CobIdError::ExtendedNotSupported);
        }
        return Ok(());
    }
    let id = v & COB_ID_MASK;
    if id > 0x7FF {
        return Err(CobIdError::IdOutOfRange);
    }
    if is_restricted(id as u16) {
        return Err(CobIdError::Restricted);
    }
    Ok(())
}

/// True for the 11-bit identifiers CiA 301 §7.3.5 (restricted CAN-IDs)
/// forbids for PDOs, SYNC and other configurable COB-IDs: NMT, the reserved
/// ranges, the default SDO channels and NMT error control.
pub const fn is_restricted(id: u16) -> bool {
    matches!(
        id,
        0x000
            | 0x001..=0x07F
            | 0x101..=0x180
            | 0x581..=0x5FF
            | 0x601..=0x67F
            | 0x6E0..=0x6FF
            | 0x701..=0x77F
            | 0x780..=0x7FF
    )
}

/// Transmission types (sub 2 of the communication parameter), CiA 301
/// §7.5.2.35 (RPDO) and §7.5.2.37 (TPDO).
pub mod tx_type {
    /// Synchronous, acyclic: sent on the SYNC after an event (TPDO);
    /// actuated on the next SYNC (RPDO).
    pub const SYNC_ACYCLIC: u8 = 0;
    /// Highest cyclic synchronous type: sent on every n-th SYNC (1..=240).
    pub const SYNC_CYCLIC_MAX: u8 = 240;
    /// Synchronous, RTR only: sampled on SYNC, sent on a remote request.
    pub const SYNC_RTR: u8 = 252;
    /// Event-driven, RTR only: sampled and sent on a remote request.
    pub const EVENT_RTR: u8 = 253;
    /// Event-driven, manufacturer-specific.
    pub const EVENT_MANUFACTURER: u8 = 254;
    /// Event-driven, device-profile-specific.
    pub const EVENT_PROFILE: u8 = 255;

    /// True for the synchronous types 0..=240.
    pub const fn is_sync(t: u8) -> bool {
        t <= SYNC_CYCLIC_MAX
    }

    /// True for the event-driven types 254 and 255.
    pub const fn is_event(t: u8) -> bool {
        t >= EVENT_MANUFACTURER
    }

    /// Transmission types a TPDO accepts (241..=251 are reserved).
    pub const fn valid_for_tpdo(t: u8) -> bool {
        t <= SYNC_CYCLIC_MAX || t >= SYNC_RTR
    }

    /// Transmission types an RPDO accepts: 0..=240, 254, 255 (241..=253
    /// are reserved for RPDOs).
    pub const fn valid_for_rpdo(t: u8) -> bool {
        t <= SYNC_CYCLIC_MAX || t >= EVENT_MANUFACTURER
    }
}

/// Default COB-ID of the SYNC object (CiA 301 §7.5.2.5, object 0x1005).
pub const SYNC_DEFAULT_COB_ID: u32 = 0x80;

/// A received SYNC message (CiA 301 §7.2.5): DLC 0, or DLC 1 carrying the
/// synchronous counter (1..=240, when 0x1019 is non-zero at the producer).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sync {
    /// The counter byte, if the producer sends one.
    pub counter: Option<u8>,
}

/// Encodes a SYNC frame (the SYNC producer; tests).
pub fn encode_sync(id: CanId, counter: Option<u8>) -> CanFrame {
    match counter {
        Some(c) => CanFrame::new(id, &[c]),
        None => CanFrame::new(id, &[]),
    }
}

/// Decodes a SYNC frame on the SYNC COB-ID: a data frame of DLC 0 or 1.
/// Remote frames and longer frames are not SYNC messages.
pub fn decode_sync(frame: &CanFrame) -> Option<Sync> {
    if frame.rtr {
        return None;
    }
    match frame.len {
        0 => Some(Sync { counter: None }),
        1 => Some(Sync {
            counter: Some(frame.data[0]),
        }),
        _ => None,
    }
}

/// Encodes a PDO data frame with the first `len` bytes of `payload`.
pub fn encode_pdo(id: CanId, payload: &[u8; 8], len: u8) -> CanFrame {
    let n = usize::from(len.min(8));
    CanFrame::new(id, payload.get(..n).unwrap_or(payload))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mapping_entry_layout() {
        // CiA 301 §7.5.2.36: 0x60000108 maps 0x6000 sub 1, 8 bits.
        let e = MapEntry::decode(0x6000_0108);
        assert_eq!(
            e,
            MapEntry {
                index: 0x6000,
                sub: 0x01,
                bits: 8
            }
        );
        assert_eq!(e.encode(), 0x6000_0108);
        // A 32-bit object, subindex 0x12.
        assert_eq!(MapEntry::decode(0x2001_1220).bits, 32);
        assert_eq!(MapEntry::decode(0x2001_1220).sub, 0x12);
        // A BOOLEAN mapped as one bit.
        assert_eq!(MapEntry::decode(0x2100_0301).bits, 1);
    }

    #[test]
    fn byte_aligned_values_are_little_endian() {
        // CiA 301 §7.2.2: a UNSIGNED16 0x1234 then a UNSIGNED8 0x56 give the
        // payload 34 12 56.
        let mut p = [0u8; 8];
        insert_bits(&mut p, 0, 16, 0x1234).unwrap();
        insert_bits(&mut p, 16, 8, 0x56).unwrap();
        assert_eq!(&p[..3], &[0x34, 0x12, 0x56]);
        assert_eq!(extract_bits(&p, 0, 16), Some(0x1234));
        assert_eq!(extract_bits(&p, 16, 8), Some(0x56));
    }

    #[test]
    fn bit_fields_pack_lsb_first() {
        // Three BOOLEANs (1, 0, 1) then a UNSIGNED8 0xFF starting at bit 3:
        // byte 0 = 0b1111_1101, byte 1 = 0b0000_0111.
        let mut p = [0u8; 8];
        insert_bits(&mut p, 0, 1, 1).unwrap();
        insert_bits(&mut p, 1, 1, 0).unwrap();
        insert_bits(&mut p, 2, 1, 1).unwrap();
        insert_bits(&mut p, 3, 8, 0xFF).unwrap();
        assert_eq!(&p[..2], &[0b1111_1101, 0b0000_0111]);
        assert_eq!(extract_bits(&p, 2, 1), Some(1));
        assert_eq!(extract_bits(&p, 1, 1), Some(0));
        assert_eq!(extract_bits(&p, 3, 8), Some(0xFF));
        // Clearing a bit leaves its neighbours alone.
        insert_bits(&mut p, 0, 1, 0).unwrap();
        assert_eq!(p[0], 0b1111_1100);
    }

    #[test]
    fn whole_payload_and_bounds() {
        let mut p = [0u8; 8];
        insert_bits(&mut p, 0, 64, 0x0807_0605_0403_0201).unwrap();
        assert_eq!(p, [1, 2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(extract_bits(&p, 0, 64), Some(0x0807_0605_0403_0201));
        assert_eq!(insert_bits(&mut p, 60, 8, 0), None, "beyond 64 bits");
        assert_eq!(p, [1, 2, 3, 4, 5, 6, 7, 8], "refused insert writes nothing");
        assert_eq!(extract_bits(&p[..2], 8, 16), None, "beyond a short payload");
        assert_eq!(extract_bits(&p, 0, 0), None);
        assert_eq!(bytes_for_bits(0), 0);
        assert_eq!(bytes_for_bits(1), 1);
        assert_eq!(bytes_for_bits(9), 2);
        assert_eq!(bytes_for_bits(64), 8);
    }

    #[test]
    fn cob_id_flags() {
        // CiA 301 §7.5.2.37: 0xC0000181 = invalid, no RTR, 11-bit id 0x181.
        let c = PdoCobId::decode(0xC000_0181, false).unwrap();
        assert!(!c.valid && !c.rtr_allowed);
        assert_eq!(c.id, CanId::std_masked(0x181));
        let c = PdoCobId::decode(0x0000_0201, false).unwrap();
        assert!(c.valid && c.rtr_allowed);
        // 29-bit only when the driver supports it.
        assert_eq!(
            PdoCobId::decode(0x2000_1234, false),
            Err(CobIdError::ExtendedNotSupported)
        );
        assert!(
            PdoCobId::decode(0x2000_1234, true)
                .unwrap()
                .id
                .is_extended()
        );
        assert_eq!(
            PdoCobId::decode(0x0000_0800, false),
            Err(CobIdError::IdOutOfRange)
        );
        // An invalid PDO may carry any identifier.
        assert!(PdoCobId::decode(0x8000_0000, false).is_ok());
    }

    #[test]
    fn restricted_identifiers_of_cia301() {
        // CiA 301 §7.3.5, restricted CAN-IDs.
        for id in [
            0x000, 0x001, 0x07F, 0x101, 0x180, 0x581, 0x5FF, 0x601, 0x67F,
        ]
        .into_iter()
        .chain([0x6E0, 0x6FF, 0x701, 0x77F, 0x780, 0x7FF])
        {
            assert!(is_restricted(id), "{id:#x}");
        }
        for id in [
            0x080, 0x100, 0x181, 0x1FF, 0x201, 0x580, 0x600, 0x680, 0x6DF, 0x700,
        ] {
            assert!(!is_restricted(id), "{id:#x}");
        }
        assert_eq!(
            PdoCobId::decode(0x0000_0701, false),
            Err(CobIdError::Restricted)
        );
    }

    #[test]
    fn transmission_types() {
        assert!(tx_type::valid_for_tpdo(0) && tx_type::valid_for_tpdo(240));
        assert!(!tx_type::valid_for_tpdo(241) && !tx_type::valid_for_tpdo(251));
        assert!(tx_type::valid_for_tpdo(252) && tx_type::valid_for_tpdo(255));
        assert!(tx_type::valid_for_rpdo(240) && tx_type::valid_for_rpdo(254));
        assert!(!tx_type::valid_for_rpdo(252) && !tx_type::valid_for_rpdo(253));
        assert!(tx_type::is_sync(0) && !tx_type::is_sync(252));
        assert!(tx_type::is_event(254) && !tx_type::is_event(253));
    }

    #[test]
    fn sync_frames() {
        // CiA 301 §7.2.5: SYNC without data, or with one counter byte.
        let id = CanId::std_masked(0x080);
        let f = encode_sync(id, None);
        assert_eq!((f.len, f.rtr), (0, false));
        assert_eq!(decode_sync(&f), Some(Sync { counter: None }));
        let f = encode_sync(id, Some(7));
        assert_eq!(f.payload(), &[7]);
        assert_eq!(decode_sync(&f), Some(Sync { counter: Some(7) }));
        assert_eq!(decode_sync(&CanFrame::new(id, &[1, 2])), None);
        assert_eq!(decode_sync(&CanFrame::remote(id, 0)), None);
    }

    #[test]
    fn pdo_frame_length() {
        let f = encode_pdo(CanId::std_masked(0x181), &[1, 2, 3, 4, 5, 6, 7, 8], 3);
        assert_eq!(f.payload(), &[1, 2, 3]);
        let f = encode_pdo(CanId::std_masked(0x181), &[0; 8], 0);
        assert_eq!(f.len, 0);
    }
}
