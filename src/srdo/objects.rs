//! Declaring the SRDO objects in Rust, mirroring the C macros of manual
//! 2.10.1 (`OBD_CREATE_SRDO_GFC_PARAM`, `OBD_CREATE_SRDO_COMMU`,
//! `OBD_BEGIN_SRDO_MAPP` ... `OBD_END_SRDO_MAPP`,
//! `OBD_CREATE_SRDO_CFG_VALID`, `OBD_BEGIN_SRDO_CRC` ... `OBD_END_SRDO_CRC`).
//! The C objdef.h produces the same layout:
//!
//! | object | sub | type | access | storage |
//! |---|---|---|---|---|
//! | 0x1300 | 0 | U8 | RW | RAM, default 0 |
//! | 0x1301+n | 0 | U8 | const 6 | |
//! | | 1 direction | U8 | SRW | RAM |
//! | | 2 refresh time / SCT | U16 | SRW | RAM |
//! | | 3 SRVT | U8 | SRW | RAM |
//! | | 4 transmission type | U8 | const 254 | |
//! | | 5, 6 COB-IDs | U32 | SRW | RAM |
//! | 0x1381+n | 0 | U8 | SRW (const with static mapping) | RAM |
//! | | 1..=`SRDO_MAX_MAPPENTRIES` | U32 | SRW (const with static mapping) | RAM |
//! | 0x13FE | 0 | U8 | RW | RAM, default 0 |
//! | 0x13FF | 0 | U8 | const count | |
//! | | 1..=count | U16 | RW | RAM |
//!
//! Each macro declares a module holding the variables, the subindex table
//! `SUBS` and the index `INDEX`; [`srdo_obd_entry!`](crate::srdo_obd_entry)
//! turns such a module into the `ObdEntry` of a part table,
//! [`srdo_obd_entries!`](crate::srdo_obd_entries) several into an array:
//!
//! ```
//! use cop::od::ObdEntry;
//! cop::obd_create_srdo_gfc_param!(pub mod gfc);
//! cop::obd_create_srdo_commu!(pub mod srdo1, 0x1301, 1, 25, 20, 0x101, 0x102);
//! cop::obd_create_srdo_mapp!(pub mod srdo1_mapp, 0x1381, [0x6200_0110, 0x6201_0110]);
//! cop::obd_create_srdo_cfg_valid!(pub mod cfg_valid);
//! cop::obd_create_srdo_crc!(pub mod checksums, [0x0000]);
//! static PART: [ObdEntry; 5] =
//!     cop::srdo_obd_entries![gfc, srdo1, srdo1_mapp, cfg_valid, checksums];
//! static GFC: ObdEntry = cop::srdo_obd_entry!(gfc);
//! assert_eq!(PART[0].index(), GFC.index());
//! ```

use core::sync::atomic::AtomicU8;

use crate::config::SRDO_MAX_MAPPENTRIES;
use crate::od::{Access, DataType, ObdSubEntry};

/// Subindices of a communication parameter (0..=6).
pub const COMMU_SUBS: usize = 7;
/// Subindices of a mapping parameter (0..=`SRDO_MAX_MAPPENTRIES`).
pub const MAPP_SUBS: usize = 1 + SRDO_MAX_MAPPENTRIES;

/// Fills arrays of subindex descriptions before each element is set.
const PLACEHOLDER: ObdSubEntry = ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[0]);

crate::od::decl::param_blocks! {
    /// The variables of one communication parameter (CPU byte order).
    pub struct CommuVars;
    /// Default values of one communication parameter (CPU byte order).
    pub struct CommuDefaults;
    {
        /// Sub 1, information direction.
        direction: 1,
        /// Sub 2, refresh time / SCT in ms.
        sct: 2,
        /// Sub 3, SRVT in ms.
        srvt: 1,
        /// Sub 5, COB-ID 1.
        cob1: 4,
        /// Sub 6, COB-ID 2.
        cob2: 4,
    }
}

impl CommuDefaults {
    /// The defaults `OBD_CREATE_SRDO_COMMU(ind, num, dir, sct, srvt, cob1,
    /// cob2)` gives.
    pub const fn new(direction: u8, sct_ms: u16, srvt_ms: u8, cob1: u32, cob2: u32) -> Self {
        CommuDefaults {
            direction: [direction],
            sct: sct_ms.to_ne_bytes(),
            srvt: [srvt_ms],
            cob1: cob1.to_ne_bytes(),
            cob2: cob2.to_ne_bytes(),
        }
    }
}

/// The subindex table of 0x1301+n.
pub const fn commu_subs(
    vars: &'static CommuVars,
    defaults: &'static CommuDefaults,
) -> [ObdSubEntry; COMMU_SUBS] {
    [
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &[6]),
        ObdSubEntry::param(1, DataType::UInt8, &vars.direction, &defaults.direction),
        ObdSubEntry::param(2, DataType::UInt16, &vars.sct, &defaults.sct),
        ObdSubEntry::param(3, DataType::UInt8, &vars.srvt, &defaults.srvt),
        ObdSubEntry::rom(4, DataType::UInt8, Access::R, &[254]),
        ObdSubEntry::param(5, DataType::UInt32, &vars.cob1, &defaults.cob1),
        ObdSubEntry::param(6, DataType::UInt32, &vars.cob2, &defaults.cob2),
    ]
}

crate::od::decl::param_blocks! {
    /// The variables of one mapping parameter (CPU byte order).
    pub struct MappVars;
    /// Default values of one mapping parameter (CPU byte order).
    pub struct MappDefaults;
    {
        /// Sub 0, number of mapped entries.
        count: 1,
        /// Subs 1.., four bytes each.
        entries: 4 * SRDO_MAX_MAPPENTRIES,
    }
}

impl MappDefaults {
    /// Sub 0 = number of `entries`, subs 1.. = `entries`, the rest 0. At
    /// most `SRDO_MAX_MAPPENTRIES` entries (more fail to compile).
    // Indexing is bounded by the loop condition and the assertion, which
    // is evaluated at compile time for every static using it.
    #[allow(clippy::indexing_slicing)]
    pub const fn new(entries: &[u32]) -> Self {
        assert!(entries.len() <= SRDO_MAX_MAPPENTRIES);
        let mut bytes = [0u8; 4 * SRDO_MAX_MAPPENTRIES];
        let mut i = 0;
        while i < entries.len() {
            let b = entries[i].to_ne_bytes();
            bytes[4 * i] = b[0];
            bytes[4 * i + 1] = b[1];
            bytes[4 * i + 2] = b[2];
            bytes[4 * i + 3] = b[3];
            i += 1;
        }
        MappDefaults {
            count: [entries.len() as u8],
            entries: bytes,
        }
    }
}

/// The subindex table of 0x1381+n: RAM variables with dynamic mapping,
/// constants (the defaults) with static mapping.
// Indexing is bounded by the loop condition.
#[allow(clippy::indexing_slicing)]
pub const fn mapp_subs(
    vars: &'static MappVars,
    defaults: &'static MappDefaults,
) -> [ObdSubEntry; MAPP_SUBS] {
    let mut subs = [PLACEHOLDER; MAPP_SUBS];
    subs[0] = if crate::config::SRDO_USE_STATIC_MAPPING {
        ObdSubEntry::rom(0, DataType::UInt8, Access::R, &defaults.count)
    } else {
        ObdSubEntry::param(0, DataType::UInt8, &vars.count, &defaults.count)
    };
    let mut i = 0;
    while i < SRDO_MAX_MAPPENTRIES {
        let var = vars.entries.as_slice().split_at(4 * i).1.split_at(4).0;
        let def = defaults.entries.as_slice().split_at(4 * i).1.split_at(4).0;
        let sub = (i + 1) as u8;
        subs[i + 1] = if crate::config::SRDO_USE_STATIC_MAPPING {
            ObdSubEntry::rom(sub, DataType::UInt32, Access::R, def)
        } else {
            ObdSubEntry::param(sub, DataType::UInt32, var, def)
        };
        i += 1;
    }
    subs
}

/// One RW UNSIGNED8 subindex 0 with default 0 (0x1300, 0x13FE).
const fn byte_subs(var: &'static [AtomicU8; 1]) -> [ObdSubEntry; 1] {
    [ObdSubEntry::ram(
        0,
        DataType::UInt8,
        Access::RW,
        var,
        Some(&[0]),
    )]
}

/// The subindex table of 0x1300 (GFC parameter, default 0).
pub const fn gfc_param_subs(var: &'static [AtomicU8; 1]) -> [ObdSubEntry; 1] {
    byte_subs(var)
}

/// The subindex table of 0x13FE (configuration valid, default 0).
pub const fn cfg_valid_subs(var: &'static [AtomicU8; 1]) -> [ObdSubEntry; 1] {
    byte_subs(var)
}

/// The CRC defaults in CPU byte order, two bytes per entry: `B` is twice
/// the number of entries (another `B` fails to compile).
// Indexing is bounded by the assertion and the loop condition.
#[allow(clippy::indexing_slicing)]
pub const fn crc_defaults<const B: usize>(crcs: &[u16]) -> [u8; B] {
    assert!(2 * crcs.len() == B, "two bytes per CRC entry");
    let mut out = [0u8; B];
    let mut i = 0;
    while i < crcs.len() {
        let b = crcs[i].to_ne_bytes();
        out[2 * i] = b[0];
        out[2 * i + 1] = b[1];
        i += 1;
    }
    out
}

/// The subindex table of 0x13FF with `S - 1` CRC entries: sub 0 the
/// constant `count`, subs 1.. U16 RW variables of two bytes each in `vars`
/// with defaults in `defaults`.
// Indexing is bounded by the loop condition.
#[allow(clippy::indexing_slicing)]
pub const fn crc_subs<const S: usize>(
    count: &'static [u8; 1],
    vars: &'static [AtomicU8],
    defaults: &'static [u8],
) -> [ObdSubEntry; S] {
    let mut subs = [PLACEHOLDER; S];
    subs[0] = ObdSubEntry::rom(0, DataType::UInt8, Access::R, count);
    let mut i = 0;
    while i + 1 < S {
        let var = vars.split_at(2 * i).1.split_at(2).0;
        let def = defaults.split_at(2 * i).1.split_at(2).0;
        subs[i + 1] = ObdSubEntry::ram((i + 1) as u8, DataType::UInt16, Access::RW, var, Some(def));
        i += 1;
    }
    subs
}

/// The one-byte objects 0x1300 and 0x13FE in a module `$m`: the object
/// `$crate::srdo::$index` with the subindex table `objects::$subs`.
#[doc(hidden)]
#[macro_export]
macro_rules! __obd_srdo_byte_object {
    ($vis:vis mod $m:ident, $index:ident, $subs:ident) => {
        #[allow(missing_docs)]
        $vis mod $m {
            pub const INDEX: u16 = $crate::srdo::$index;
            pub static VALUE: [::core::sync::atomic::AtomicU8; 1] = $crate::od::decl::zeroed();
            pub static SUBS: [$crate::od::ObdSubEntry; 1] =
                $crate::srdo::objects::$subs(&VALUE);
        }
    };
}

/// A parameter object (0x1301.., 0x1381..) in a module `$m`: the index,
/// the variables `objects::$vars`, the defaults `objects::$defaults` made
/// of the arguments and the subindex table (`$count` entries) that
/// `objects::$subs` lays over both.
#[doc(hidden)]
#[macro_export]
macro_rules! __obd_srdo_param_object {
    ($vis:vis mod $m:ident, $index:expr, $vars:ident, $defaults:ident($($arg:expr),*),
        $count:ident, $subs:ident) => {
        #[allow(missing_docs)]
        $vis mod $m {
            pub const INDEX: u16 = $index;
            pub static VARS: $crate::srdo::objects::$vars = $crate::srdo::objects::$vars::new();
            pub static DEFAULTS: $crate::srdo::objects::$defaults =
                $crate::srdo::objects::$defaults::new($($arg),*);
            pub static SUBS: [$crate::od::ObdSubEntry; $crate::srdo::objects::$count] =
                $crate::srdo::objects::$subs(&VARS, &DEFAULTS);
        }
    };
}

/// `OBD_CREATE_SRDO_GFC_PARAM()`: object 0x1300 in a module `$m`.
#[macro_export]
macro_rules! obd_create_srdo_gfc_param {
    ($vis:vis mod $m:ident) => {
        $crate::__obd_srdo_byte_object!($vis mod $m, GFC_PARAM_INDEX, gfc_param_subs);
    };
}

/// `OBD_CREATE_SRDO_COMMU(ind, num, dir, sct, srvt, cob1, cob2)`: the
/// communication parameter `$index` (0x1301..=0x1340) in a module `$m`.
#[macro_export]
macro_rules! obd_create_srdo_commu {
    ($vis:vis mod $m:ident, $index:expr, $dir:expr, $sct:expr, $srvt:expr, $cob1:expr, $cob2:expr) => {
        $crate::__obd_srdo_param_object!(
            $vis mod $m, $index, CommuVars, CommuDefaults($dir, $sct, $srvt, $cob1, $cob2),
            COMMU_SUBS, commu_subs
        );
    };
}

/// `OBD_BEGIN_SRDO_MAPP(ind, num, cnt)` ... `OBD_END_SRDO_MAPP(ind)`: the
/// mapping parameter `$index` (0x1381..=0x13C0) in a module `$m`, with the
/// listed default entries (sub 0 = their number).
#[macro_export]
macro_rules! obd_create_srdo_mapp {
    ($vis:vis mod $m:ident, $index:expr, [$($entry:expr),* $(,)?]) => {
        $crate::__obd_srdo_param_object!(
            $vis mod $m, $index, MappVars, MappDefaults(&[$($entry),*]), MAPP_SUBS, mapp_subs
        );
    };
}

/// `OBD_CREATE_SRDO_CFG_VALID()`: object 0x13FE in a module `$m`.
#[macro_export]
macro_rules! obd_create_srdo_cfg_valid {
    ($vis:vis mod $m:ident) => {
        $crate::__obd_srdo_byte_object!($vis mod $m, CONFIG_VALID_INDEX, cfg_valid_subs);
    };
}

/// `OBD_BEGIN_SRDO_CRC(cnt)` ... `OBD_END_SRDO_CRC()`: object 0x13FF in a
/// module `$m`, one entry per listed default CRC (sub n = SRDO 0x1300 + n,
/// gaps included).
#[macro_export]
macro_rules! obd_create_srdo_crc {
    ($vis:vis mod $m:ident, [$($crc:expr),* $(,)?]) => {
        #[allow(missing_docs)]
        $vis mod $m {
            pub const INDEX: u16 = $crate::srdo::CRC_INDEX;
            pub const COUNT: usize = [$($crc as u16),*].len();
            pub static COUNT_VALUE: [u8; 1] = [COUNT as u8];
            pub static VARS: [::core::sync::atomic::AtomicU8; 2 * COUNT] =
                $crate::od::decl::zeroed();
            pub static DEFAULTS: [u8; 2 * COUNT] =
                $crate::srdo::objects::crc_defaults::<{ 2 * COUNT }>(&[$($crc),*]);
            pub static SUBS: [$crate::od::ObdSubEntry; COUNT + 1] =
                $crate::srdo::objects::crc_subs::<{ COUNT + 1 }>(&COUNT_VALUE, &VARS, &DEFAULTS);
        }
    };
}

/// The `ObdEntry` of a module declared by one of the SRDO macros.
#[macro_export]
macro_rules! srdo_obd_entry {
    ($m:path) => {{
        use $m as m;
        $crate::od::ObdEntry::new(m::INDEX, &m::SUBS, None)
    }};
}

/// The array of the `ObdEntry`s of several modules declared by the SRDO
/// macros, in the order given (`srdo_obd_entry!` of each).
#[macro_export]
macro_rules! srdo_obd_entries {
    ($($m:path),+ $(,)?) => {
        [$($crate::srdo_obd_entry!($m)),+]
    };
}

#[cfg(test)]
mod tests {
    use crate::od::{ByteOrder, ObdEntry, ObjectDictionary};

    crate::obd_create_srdo_crc!(mod crcs, [0x1234, 0xBEEF, 0x00FF]);
    static PART: [ObdEntry; 1] = crate::srdo_obd_entries![crcs];

    /// `OBD_BEGIN_SRDO_CRC` ... `OBD_END_SRDO_CRC` (manual 2.10.1): sub 0 the
    /// count, sub n the default CRC of SRDO n, restored as the default.
    #[test]
    fn crc_object_holds_the_listed_defaults() {
        let od = ObjectDictionary::new(&PART, &[], &[]).unwrap();
        od.restore_defaults(0x1000, 0x1FFF);
        assert_eq!(od.read_uint(0x13FF, 0), Ok(3));
        for (sub, crc) in [(1, 0x1234), (2, 0xBEEF), (3, 0x00FF)] {
            assert_eq!(od.read_uint(0x13FF, sub), Ok(crc), "sub {sub}");
            let mut le = [0u8; 2];
            assert_eq!(od.read(0x13FF, sub, ByteOrder::Wire, &mut le), Ok(2));
            assert_eq!(u16::from_le_bytes(le), crc as u16);
        }
        let mut expected = [0u8; 6];
        for (i, crc) in [0x1234u16, 0xBEEF, 0x00FF].iter().enumerate() {
            expected[2 * i..2 * i + 2].copy_from_slice(&crc.to_ne_bytes());
        }
        assert_eq!(crcs::DEFAULTS, expected);
    }
}
