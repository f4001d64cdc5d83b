//! A reference dictionary with every storage kind and access variant
//! (host builds): the fixture of the fuzz targets, the benchmarks and
//! tests that need "a realistic device" rather than a minimal one.
//!
//! Its variables are process-wide statics; users that run in parallel
//! threads must serialise themselves.

use core::sync::atomic::AtomicU8;

use crate::od::{Access, DataType, ObdEntry, ObdSubEntry, ObdVarEntry, ObjectDictionary, decl};

crate::od_rom!(static S1000: u32 = 0x0001_0191 => UInt32, R);
crate::od_ram!(static S1001, ERR_REG: u8 = 0 => UInt8, R);
static NAME: &[u8] = b"cop reference device";
static S1008: [ObdSubEntry; 1] = [ObdSubEntry::rom_string(0, Access::R, NAME)];
crate::od_ram!(static S1017, HB: u16 = 0 => UInt16, SRW);
static ID_VENDOR: [u8; 4] = 0x0000_0123u32.to_ne_bytes();
static ID_PRODUCT: [u8; 4] = 0x0000_0456u32.to_ne_bytes();
static ID_REVISION: [u8; 4] = 0x0001_0000u32.to_ne_bytes();
static ID_SERIAL: [u8; 4] = 0x0000_0789u32.to_ne_bytes();
static S1018: [ObdSubEntry; 5] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[4]),
    ObdSubEntry::rom(1, DataType::UInt32, Access::R, &ID_VENDOR),
    ObdSubEntry::rom(2, DataType::UInt32, Access::R, &ID_PRODUCT),
    ObdSubEntry::rom(3, DataType::UInt32, Access::R, &ID_REVISION),
    ObdSubEntry::rom(4, DataType::UInt32, Access::R, &ID_SERIAL),
];

static V2003: [AtomicU8; 65] = decl::zeroed();
static V2005: [AtomicU8; 4] = decl::zeroed();
static E2005: ObdVarEntry = ObdVarEntry::new();
static V2006: [AtomicU8; 300] = decl::zeroed();
static E2006: ObdVarEntry = ObdVarEntry::new();
static V2007: [AtomicU8; 8] = decl::zeroed();

crate::od_ram!(static S2000, V2000: u8 = 0 => UInt8, PRW);
crate::od_ram!(static S2001, V2001: i16 = 0 => Int16, PRW, range(-100, 100));
crate::od_ram!(static S2002, V2002: u32 => UInt32, PRW);
static S2003: [ObdSubEntry; 1] = [ObdSubEntry::ram_string(0, Access::RW, &V2003, c"hello")];
static S2004: [ObdSubEntry; 1] = [ObdSubEntry::rom_string(0, Access::R, b"constant text")];
static S2005: [ObdSubEntry; 1] = decl::var_object(DataType::UInt32, Access::PRW, &E2005, 4);
static S2006: [ObdSubEntry; 1] = decl::var_object(DataType::Domain, Access::RW, &E2006, 0);
static S2007: [ObdSubEntry; 2] = [
    ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[8]),
    ObdSubEntry::ram_array(1, DataType::UInt8, Access::PRW, &V2007, 1, Some(&[0])),
];
crate::od_ram!(static S2008, V2008: u64 => UInt64, RW);
crate::od_ram!(static S2009, V2009: f32 = 0.0 => Real32, RW, range(-1.0, 1.0));
crate::od_ram!(static S200A, V200A: u8 => UInt8, W);
crate::od_ram!(static S200B, V200B: [u8; 8] => TimeOfDay, RW);

// Two receive and two transmit PDOs: RPDO 1 (0x200 + node-ID, type 255)
// maps 0x2000 and 0x2002; TPDO 1 (0x180 + node-ID, type 255) maps 0x2001;
// PDO 2 of each direction is invalid (bit 31) and unmapped.
crate::pdo_commu!(static S1400, V1400 = 0x200, 255, 0, 0);
crate::pdo_commu!(static S1401, V1401 = 0x8000_0300, 255, 0, 0);
crate::pdo_mapp!(static S1600, V1600 = [0x2000_0008, 0x2002_0020]);
crate::pdo_mapp!(static S1601, V1601 = []);
crate::pdo_commu!(static S1800, V1800 = 0x180, 255, 0, 0);
crate::pdo_commu!(static S1801, V1801 = 0x8000_0280, 255, 0, 0);
crate::pdo_mapp!(static S1A00, V1A00 = [0x2001_0010]);
crate::pdo_mapp!(static S1A01, V1A01 = []);

static GENERIC: [ObdEntry; 13] = [
    ObdEntry::new(0x1000, &S1000, None),
    ObdEntry::new(0x1001, &S1001, None),
    ObdEntry::new(0x1008, &S1008, None),
    ObdEntry::new(0x1017, &S1017, None),
    ObdEntry::new(0x1018, &S1018, None),
    ObdEntry::new(0x1400, &S1400, None),
    ObdEntry::new(0x1401, &S1401, None),
    ObdEntry::new(0x1600, &S1600, None),
    ObdEntry::new(0x1601, &S1601, None),
    ObdEntry::new(0x1800, &S1800, None),
    ObdEntry::new(0x1801, &S1801, None),
    ObdEntry::new(0x1A00, &S1A00, None),
    ObdEntry::new(0x1A01, &S1A01, None),
];

/// Element array of 0x2007 (8 × U8, subindices 1..8).
pub fn array_2007() -> &'static [AtomicU8; 8] {
    &V2007
}

static MANUFACTURER: [ObdEntry; 12] = [
    ObdEntry::new(0x2000, &S2000, None),
    ObdEntry::new(0x2001, &S2001, None),
    ObdEntry::new(0x2002, &S2002, None),
    ObdEntry::new(0x2003, &S2003, None),
    ObdEntry::new(0x2004, &S2004, None),
    ObdEntry::new(0x2005, &S2005, None),
    ObdEntry::new(0x2006, &S2006, None),
    ObdEntry::new(0x2007, &S2007, None),
    ObdEntry::new(0x2008, &S2008, None),
    ObdEntry::new(0x2009, &S2009, None),
    ObdEntry::new(0x200A, &S200A, None),
    ObdEntry::new(0x200B, &S200B, None),
];

/// The reference dictionary (USERDEF 0x2005 and DOMAIN 0x2006 attached).
pub fn dictionary() -> ObjectDictionary {
    E2005.attach(&V2005);
    E2006.attach(&V2006);
    // The tables above are sorted and well-formed; a failure here would be
    // a bug in this file, caught by its own test.
    ObjectDictionary::new(&GENERIC, &MANUFACTURER, &[]).unwrap_or(ObjectDictionary::empty())
}

/// Part tables, for building the same dictionary through the C path.
pub fn parts() -> (&'static [ObdEntry], &'static [ObdEntry]) {
    E2005.attach(&V2005);
    E2006.attach(&V2006);
    (&GENERIC, &MANUFACTURER)
}

/// A small deterministic generator (xorshift64*) for the randomised
/// unit tests.
#[cfg(test)]
pub(crate) struct Rng(pub(crate) u64);

#[cfg(test)]
impl Rng {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    pub(crate) fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::od::{ByteOrder, NoHooks};

    #[test]
    fn reference_dictionary_is_valid_and_usable() {
        let od = dictionary();
        assert_eq!(od.len(), 25);
        // The stack restores the defaults at reset; do the same here.
        od.restore_defaults(0x1000, 0xFFFF);
        let mut b = [0u8; 64];
        assert_eq!(od.read(0x2003, 0, ByteOrder::Wire, &mut b), Ok(5));
        assert_eq!(&b[..5], b"hello");
        od.write(0x2007, 8, ByteOrder::Wire, &[0xAB], &mut NoHooks)
            .unwrap();
        assert_eq!(od.read(0x2007, 8, ByteOrder::Wire, &mut b), Ok(1));
        assert_eq!(b[0], 0xAB);
        assert!(od.read(0x2007, 9, ByteOrder::Wire, &mut b).is_err());
        assert_eq!(
            od.write(
                0x2001,
                0,
                ByteOrder::Wire,
                &101i16.to_le_bytes(),
                &mut NoHooks
            ),
            Err(crate::OdError::TOO_HIGH)
        );
        assert_eq!(
            od.read(0x200A, 0, ByteOrder::Wire, &mut b),
            Err(crate::OdError::READ)
        );
    }
}
