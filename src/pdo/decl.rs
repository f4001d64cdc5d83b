//! Declaring PDO parameter objects in a Rust dictionary with the layout
//! that objdef.h gives `OBD_CREATE_RXPDO_COMMU` / `OBD_CREATE_TXPDO_COMMU`
//! (sub 0 constant 5; sub 1 COB-ID U32, 2 transmission type U8, 3 inhibit
//! time U16, 5 event timer U16, all SRW) and `OBD_CREATE_RXPDO_MAPP` /
//! `OBD_CREATE_TXPDO_MAPP` (sub 0 count U8 SRW, subs 1..=PDO_MAX_MAPPENTRIES
//! U32 SRW).
//!
//! ```
//! use cop::od::{ObdEntry, ObdSubEntry};
//! use cop::pdo::decl::*;
//! use cop::pdo::PDO_MAX_MAPPENTRIES;
//!
//! static V1800: CommuVars = CommuVars::new();
//! static D1800: CommuDefaults = CommuDefaults::new(0x180, 255, 0, 0);
//! static S1800: [ObdSubEntry; 5] = commu_subs(&V1800, &D1800);
//! static V1A00: MappVars = MappVars::new();
//! static D1A00: MappDefaults = MappDefaults::new(&[0x2000_0108]);
//! static S1A00: [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] = mapp_subs(&V1A00, &D1A00);
//! static GENERIC: [ObdEntry; 2] =
//!     [ObdEntry::new(0x1800, &S1800, None), ObdEntry::new(0x1A00, &S1A00, None)];
//! ```
//!
//! The same two objects with [`pdo_commu!`](crate::pdo_commu) and
//! [`pdo_mapp!`](crate::pdo_mapp):
//!
//! ```
//! use cop::od::ObdEntry;
//!
//! cop::pdo_commu!(static S1800, V1800 = 0x180, 255, 0, 0);
//! cop::pdo_mapp!(static S1A00, V1A00 = [0x2000_0108]);
//! static GENERIC: [ObdEntry; 2] =
//!     [ObdEntry::new(0x1800, &S1800, None), ObdEntry::new(0x1A00, &S1A00, None)];
//! ```

use core::sync::atomic::AtomicU8;

use super::PDO_MAX_MAPPENTRIES;
use crate::od::{Access, DataType, ObdSubEntry, decl};

crate::od::decl::default_is_new!(MappVars);

/// Highest subindex of a communication parameter object.
static COMMU_SUB0: [u8; 1] = [5];

crate::od::decl::param_blocks! {
    /// The variables of a communication parameter object.
    pub struct CommuVars;
    /// The defaults of a communication parameter object (CPU byte order).
    pub struct CommuDefaults;
    {
        /// Sub 1, COB-ID.
        cob_id: 4,
        /// Sub 2, transmission type.
        tx_type: 1,
        /// Sub 3, inhibit time (100 µs).
        inhibit: 2,
        /// Sub 5, event timer (ms).
        event: 2,
    }
}

impl CommuDefaults {
    /// COB-ID, transmission type, inhibit time (100 µs), event timer (ms).
    pub const fn new(cob_id: u32, tx_type: u8, inhibit: u16, event: u16) -> Self {
        CommuDefaults {
            cob_id: cob_id.to_ne_bytes(),
            tx_type: [tx_type],
            inhibit: inhibit.to_ne_bytes(),
            event: event.to_ne_bytes(),
        }
    }
}

/// The subindex table of a communication parameter object.
pub const fn commu_subs(v: &'static CommuVars, d: &'static CommuDefaults) -> [ObdSubEntry; 5] {
    [
        ObdSubEntry::rom(0, DataType::UInt8, Access::CR, &COMMU_SUB0),
        ObdSubEntry::param(1, DataType::UInt32, &v.cob_id, &d.cob_id),
        ObdSubEntry::param(2, DataType::UInt8, &v.tx_type, &d.tx_type),
        ObdSubEntry::param(3, DataType::UInt16, &v.inhibit, &d.inhibit),
        ObdSubEntry::param(5, DataType::UInt16, &v.event, &d.event),
    ]
}

/// The variables of a mapping parameter object.
#[derive(Debug)]
pub struct MappVars {
    /// Sub 0, number of mapped objects.
    pub count: [AtomicU8; 1],
    /// Subs 1.., the entries.
    pub entries: [[AtomicU8; 4]; PDO_MAX_MAPPENTRIES],
}

impl MappVars {
    /// Zeroed variables (the defaults apply at reset communication).
    pub const fn new() -> Self {
        MappVars {
            count: decl::zeroed(),
            entries: [const { decl::zeroed() }; PDO_MAX_MAPPENTRIES],
        }
    }
}

/// The defaults of a mapping parameter object (CPU byte order).
#[derive(Debug)]
pub struct MappDefaults {
    count: [u8; 1],
    entries: [[u8; 4]; PDO_MAX_MAPPENTRIES],
}

impl MappDefaults {
    /// The default mapping: these entries (at most `PDO_MAX_MAPPENTRIES`;
    /// more are cut), the count is their number.
    // Indexing is bounded by the loop condition; `get` is not usable for
    // assignment in a const fn.
    #[allow(clippy::indexing_slicing)]
    pub const fn new(entries: &[u32]) -> Self {
        let mut d = MappDefaults {
            count: [0],
            entries: [[0; 4]; PDO_MAX_MAPPENTRIES],
        };
        let mut i = 0;
        while i < entries.len() && i < PDO_MAX_MAPPENTRIES {
            d.entries[i] = entries[i].to_ne_bytes();
            i += 1;
        }
        d.count = [i as u8];
        d
    }
}

/// The subindex table of a mapping parameter object.
// Indexing is bounded by the loop condition (see `MappDefaults::new`).
#[allow(clippy::indexing_slicing)]
pub const fn mapp_subs(
    v: &'static MappVars,
    d: &'static MappDefaults,
) -> [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1] {
    let mut subs = [const { ObdSubEntry::rom(0, DataType::UInt8, Access::CR, &COMMU_SUB0) };
        PDO_MAX_MAPPENTRIES + 1];
    subs[0] = ObdSubEntry::param(0, DataType::UInt8, &v.count, &d.count);
    let mut i = 0;
    while i < PDO_MAX_MAPPENTRIES {
        subs[i + 1] = ObdSubEntry::param(
            (i + 1) as u8,
            DataType::UInt32,
            &v.entries[i],
            &d.entries[i],
        );
        i += 1;
    }
    subs
}

/// Declares a communication parameter object (0x1400+n / 0x1800+n): the
/// variables `static $var: CommuVars` and the subindex table `static
/// $subs: [ObdSubEntry; 5]` with the defaults COB-ID, transmission type,
/// inhibit time (100 µs) and event timer (ms), as
/// [`CommuDefaults::new`] takes them.
#[macro_export]
macro_rules! pdo_commu {
    ($vis:vis static $subs:ident, $var:ident = $cob:expr, $tx_type:expr, $inhibit:expr, $event:expr) => {
        $vis static $var: $crate::pdo::decl::CommuVars = $crate::pdo::decl::CommuVars::new();
        $vis static $subs: [$crate::od::ObdSubEntry; 5] = {
            static DEFAULTS: $crate::pdo::decl::CommuDefaults =
                $crate::pdo::decl::CommuDefaults::new($cob, $tx_type, $inhibit, $event);
            $crate::pdo::decl::commu_subs(&$var, &DEFAULTS)
        };
    };
}

/// Declares a mapping parameter object (0x1600+n / 0x1A00+n): the
/// variables `static $var: MappVars` and the subindex table `static $subs:
/// [ObdSubEntry; PDO_MAX_MAPPENTRIES + 1]` with the default entries
/// (`index << 16 | subindex << 8 | bits`, as [`MappDefaults::new`] takes
/// them).
#[macro_export]
macro_rules! pdo_mapp {
    ($vis:vis static $subs:ident, $var:ident = [$($entry:expr),* $(,)?]) => {
        $vis static $var: $crate::pdo::decl::MappVars = $crate::pdo::decl::MappVars::new();
        $vis static $subs: [$crate::od::ObdSubEntry; $crate::pdo::PDO_MAX_MAPPENTRIES + 1] = {
            static DEFAULTS: $crate::pdo::decl::MappDefaults =
                $crate::pdo::decl::MappDefaults::new(&[$($entry),*]);
            $crate::pdo::decl::mapp_subs(&$var, &DEFAULTS)
        };
    };
}
