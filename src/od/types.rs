//! CANopen data types (`tObdType`, CiA 301 numbers) and access attributes
//! (`tObdAccess`). The numbers are part of the source contract: ODBuilder
//! writes them as bare literals into objdict.h.

c_enum! {
    /// Data type of an object (`kObdTyp*`).
    #[allow(missing_docs)]
    pub enum DataType: u8, fn from_code(u16) {
        Bool = 0x01,
        Int8 = 0x02,
        Int16 = 0x03,
        Int32 = 0x04,
        UInt8 = 0x05,
        UInt16 = 0x06,
        UInt32 = 0x07,
        Real32 = 0x08,
        VString = 0x09,
        OString = 0x0A,
        UString = 0x0B,
        TimeOfDay = 0x0C,
        TimeDiff = 0x0D,
        Domain = 0x0F,
        Int24 = 0x10,
        Real64 = 0x11,
        Int40 = 0x12,
        Int48 = 0x13,
        Int56 = 0x14,
        Int64 = 0x15,
        UInt24 = 0x16,
        UInt40 = 0x18,
        UInt48 = 0x19,
        UInt56 = 0x1A,
        UInt64 = 0x1B,
    }
}

/// How the bytes of a type are converted between the variable in memory
/// (CPU byte order, C type width) and the wire (CANopen, little-endian).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    /// An integer or float: `wire` bytes little-endian on the bus, stored as
    /// a native integer of the variable's width (≥ `wire`).
    Numeric {
        /// Bytes on the wire.
        wire: usize,
        /// Sign-extend when the variable is wider than the wire value.
        signed: bool,
    },
    /// TIME_OF_DAY / TIME_DIFFERENCE: 6 bytes on the wire, a `tTimeOfDay`
    /// {DWORD ms; WORD days} in memory.
    Time,
    /// Strings and domains: bytes copied unchanged.
    Bytes,
}

impl DataType {
    /// Byte conversion rule for this type.
    pub const fn encoding(self) -> Encoding {
        use DataType::*;
        const fn signed(wire: usize) -> Encoding {
            Encoding::Numeric { wire, signed: true }
        }
        const fn unsigned(wire: usize) -> Encoding {
            Encoding::Numeric {
                wire,
                signed: false,
            }
        }
        match self {
            Bool | UInt8 => unsigned(1),
            Int8 => signed(1),
            Int16 => signed(2),
            UInt16 => unsigned(2),
            Int24 => signed(3),
            UInt24 => unsigned(3),
            Int32 => signed(4),
            UInt32 | Real32 => unsigned(4),
            Int40 => signed(5),
            UInt40 => unsigned(5),
            Int48 => signed(6),
            UInt48 => unsigned(6),
            Int56 => signed(7),
            UInt56 => unsigned(7),
            Int64 => signed(8),
            UInt64 | Real64 => unsigned(8),
            TimeOfDay | TimeDiff => Encoding::Time,
            VString | OString | UString | Domain => Encoding::Bytes,
        }
    }

    /// Size on the wire for fixed-size types; `None` for strings/domains.
    pub const fn wire_size(self) -> Option<usize> {
        match self.encoding() {
            Encoding::Numeric { wire, .. } => Some(wire),
            Encoding::Time => Some(6),
            Encoding::Bytes => None,
        }
    }

    /// True for types with a numeric value (range checks, PDO mapping).
    pub const fn is_numeric(self) -> bool {
        matches!(self.encoding(), Encoding::Numeric { .. })
    }

    /// True for signed integers (range checks compare signed).
    pub const fn is_signed(self) -> bool {
        matches!(self.encoding(), Encoding::Numeric { signed: true, .. })
    }

    /// True for REAL32/REAL64 (range checks compare as floats).
    pub const fn is_float(self) -> bool {
        matches!(self, DataType::Real32 | DataType::Real64)
    }
}

/// Access attributes of a subindex (`tObdAccess`, bit mask).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Access(pub u8);

#[allow(missing_docs)]
impl Access {
    pub const READ: u8 = 0x01;
    pub const WRITE: u8 = 0x02;
    pub const CONST: u8 = 0x04;
    pub const PDO: u8 = 0x08;
    pub const ARRAY: u8 = 0x10;
    pub const RANGE: u8 = 0x20;
    pub const VAR: u8 = 0x40;
    pub const STORE: u8 = 0x80;

    // The named combinations of cop.h (kObdAcc*), each the OR of its letters:
    // R read, W write, C const, G range, V var, P pdo, S store.
    pub const R: Access = Access(0x01);
    pub const W: Access = Access(0x02);
    pub const RW: Access = Access(0x03);
    pub const CR: Access = Access(0x05);
    pub const GR: Access = Access(0x21);
    pub const GW: Access = Access(0x22);
    pub const GRW: Access = Access(0x23);
    pub const VR: Access = Access(0x41);
    pub const VW: Access = Access(0x42);
    pub const VRW: Access = Access(0x43);
    pub const VPR: Access = Access(0x49);
    pub const VPW: Access = Access(0x4A);
    pub const VPRW: Access = Access(0x4B);
    pub const VGR: Access = Access(0x61);
    pub const VGW: Access = Access(0x62);
    pub const VGRW: Access = Access(0x63);
    pub const VGPR: Access = Access(0x69);
    pub const VGPW: Access = Access(0x6A);
    pub const VGPRW: Access = Access(0x6B);
    pub const SR: Access = Access(0x81);
    pub const SW: Access = Access(0x82);
    pub const SRW: Access = Access(0x83);
    pub const SCR: Access = Access(0x85);
    pub const SGR: Access = Access(0xA1);
    pub const SGW: Access = Access(0xA2);
    pub const SGRW: Access = Access(0xA3);
    pub const SVR: Access = Access(0xC1);
    pub const SVW: Access = Access(0xC2);
    pub const SVRW: Access = Access(0xC3);
    pub const SVPR: Access = Access(0xC9);
    pub const SVPW: Access = Access(0xCA);
    pub const SVPRW: Access = Access(0xCB);
    pub const SVGR: Access = Access(0xE1);
    pub const SVGW: Access = Access(0xE2);
    pub const SVGRW: Access = Access(0xE3);
    pub const SVGPR: Access = Access(0xE9);
    pub const SVGPW: Access = Access(0xEA);
    pub const SVGPRW: Access = Access(0xEB);
    /// Read-only, mappable (a common combination for inputs).
    pub const PR: Access = Access(0x09);
    /// Read-write, mappable.
    pub const PRW: Access = Access(0x0B);

    /// Readable.
    pub const fn readable(self) -> bool {
        self.0 & Self::READ != 0
    }
    /// Writable (and not constant).
    pub const fn writable(self) -> bool {
        self.0 & Self::WRITE != 0 && self.0 & Self::CONST == 0
    }
    /// Mappable into a PDO/SRDO.
    pub const fn mappable(self) -> bool {
        self.0 & Self::PDO != 0
    }
    /// Range-checked on write.
    pub const fn ranged(self) -> bool {
        self.0 & Self::RANGE != 0
    }
    /// Stored in non-volatile memory by store/restore.
    pub const fn stored(self) -> bool {
        self.0 & Self::STORE != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn type_codes_are_cia301_numbers() {
        // SYSTEC_API.md section 6 / CiA 301 table of static data types.
        assert_eq!(DataType::UInt16.code(), 0x06);
        assert_eq!(DataType::Domain.code(), 0x0F);
        assert_eq!(DataType::UInt64.code(), 0x1B);
        for c in 0u16..0x20 {
            if let Some(t) = DataType::from_code(c) {
                assert_eq!(u16::from(t.code()), c);
            }
        }
        assert_eq!(DataType::from_code(0x0E), None);
        assert_eq!(DataType::from_code(0x17), None);
    }

    #[test]
    fn access_combinations_match_cop_h() {
        assert_eq!(Access::VPRW.0, 0x4B);
        assert_eq!(Access::SRW.0, 0x83);
        assert_eq!(Access::CR.0, 0x05);
        assert!(!Access::CR.writable());
        assert!(Access::SVGPRW.mappable() && Access::SVGPRW.ranged());
    }

    #[test]
    fn wire_sizes() {
        assert_eq!(DataType::Int24.wire_size(), Some(3));
        assert_eq!(DataType::TimeOfDay.wire_size(), Some(6));
        assert_eq!(DataType::VString.wire_size(), None);
        assert!(DataType::Int56.is_signed());
        assert!(!DataType::Real32.is_signed());
    }
}
