//! Helpers for declaring a dictionary in Rust: variables as `static`
//! arrays of `AtomicU8` (so the stack and the application can share them
//! without `unsafe`), default values in CPU byte order.
//!
//! ```
//! use core::sync::atomic::AtomicU8;
//! use cop::od::{decl, Access, DataType, ObdEntry, ObdSubEntry};
//!
//! static PRODUCER_HB: [AtomicU8; 2] = decl::zeroed();
//! static PRODUCER_HB_DEF: [u8; 2] = 100u16.to_ne_bytes();
//! static SUBS_1017: [ObdSubEntry; 1] =
//!     [ObdSubEntry::ram(0, DataType::UInt16, Access::SRW, &PRODUCER_HB, Some(&PRODUCER_HB_DEF))];
//! static GENERIC: [ObdEntry; 1] = [ObdEntry::new(0x1017, &SUBS_1017, None)];
//! ```
//!
//! The same object in one line with [`od_ram!`](crate::od_ram) (and a
//! constant with [`od_rom!`](crate::od_rom)):
//!
//! ```
//! use cop::od::ObdEntry;
//!
//! cop::od_ram!(static SUBS_1017, PRODUCER_HB: u16 = 100 => UInt16, SRW);
//! cop::od_rom!(static SUBS_1000: u32 = 0x0001_0191 => UInt32, R);
//! static GENERIC: [ObdEntry; 2] = [
//!     ObdEntry::new(0x1000, &SUBS_1000, None),
//!     ObdEntry::new(0x1017, &SUBS_1017, None),
//! ];
//! assert_eq!(cop::od::decl::get(&PRODUCER_HB), [0, 0]); // defaults apply at reset
//! ```

use core::sync::atomic::{AtomicU8, Ordering};

use crate::od::{Access, DataType, ObdSubEntry, ObdVarEntry};

/// The subindex table of a one-value object: subindex 0 alone, the RAM
/// variable `var` without default (it keeps what it holds at a reset).
pub const fn ram_object(
    typ: DataType,
    access: Access,
    var: &'static [AtomicU8],
) -> [ObdSubEntry; 1] {
    [ObdSubEntry::ram(0, typ, access, var, None)]
}

/// The subindex table of a one-value object whose variable the application
/// attaches (USERDEF / DOMAIN): subindex 0 alone, `size` bytes, without
/// default.
pub const fn var_object(
    typ: DataType,
    access: Access,
    entry: &'static ObdVarEntry,
    size: u32,
) -> [ObdSubEntry; 1] {
    [ObdSubEntry::var(0, typ, access, entry, size, None)]
}

/// A variable of `N` bytes, all zero.
pub const fn zeroed<const N: usize>() -> [AtomicU8; N] {
    [const { AtomicU8::new(0) }; N]
}

/// A variable of `N` bytes with an initial content.
// Indexing is bounded by the loop condition; `get_mut` is not usable in a
// const fn.
#[allow(clippy::indexing_slicing)]
pub const fn init<const N: usize>(v: [u8; N]) -> [AtomicU8; N] {
    let mut a = zeroed::<N>();
    let mut i = 0;
    while i < N {
        a[i] = AtomicU8::new(v[i]);
        i += 1;
    }
    a
}

/// Reads a variable's bytes (native order) into an array.
pub fn get<const N: usize>(v: &[AtomicU8; N]) -> [u8; N] {
    let mut out = [0u8; N];
    for (o, b) in out.iter_mut().zip(v.iter()) {
        *o = b.load(Ordering::Relaxed);
    }
    out
}

/// Sets a variable's bytes (native order).
pub fn set<const N: usize>(v: &[AtomicU8; N], bytes: [u8; N]) {
    for (b, x) in v.iter().zip(bytes) {
        b.store(x, Ordering::Relaxed);
    }
}

/// The three values of a ranged entry (default, low, high; each `N`
/// bytes, CPU byte order) one after the other, as
/// [`ObdSubEntry::ram_range`](crate::od::ObdSubEntry::ram_range) takes
/// them. `M` must be `3 * N` (checked when the constant is evaluated).
// Indexing is bounded by the loop condition and the check; `get_mut` is
// not usable in a const fn.
#[allow(clippy::indexing_slicing)]
pub const fn limits<const N: usize, const M: usize>(
    default: [u8; N],
    low: [u8; N],
    high: [u8; N],
) -> [u8; M] {
    // Evaluated at compile time in a static: a misuse is a build error.
    #[allow(clippy::panic)]
    if M != 3 * N {
        panic!("limits: the result holds three values");
    }
    let mut out = [0u8; M];
    let mut i = 0;
    while i < N {
        out[i] = default[i];
        out[N + i] = low[i];
        out[2 * N + i] = high[i];
        i += 1;
    }
    out
}

/// `impl Default` as `new()` for the variable blocks of the declaration
/// helpers (PDO and SRDO parameter objects).
macro_rules! default_is_new {
    ($($block:ty),* $(,)?) => {
        $(
            impl Default for $block {
                fn default() -> Self {
                    Self::new()
                }
            }
        )*
    };
}
pub(crate) use default_is_new;

/// Declares the two blocks of a parameter object (PDO and SRDO
/// communication and mapping parameters) from one list of its variable
/// subindices and their sizes in bytes, so that a variable and its default
/// cannot differ in size: `$vars`, the variables (`[AtomicU8; N]` each,
/// public, zeroed by `new()` and `Default`), and `$defaults`, their
/// defaults (`[u8; N]` each, private; the declaring module writes the
/// constructor).
macro_rules! param_blocks {
    (
        $(#[$vmeta:meta])* pub struct $vars:ident;
        $(#[$dmeta:meta])* pub struct $defaults:ident;
        { $($(#[$fmeta:meta])* $field:ident: $len:expr,)+ }
    ) => {
        $(#[$vmeta])*
        #[derive(Debug)]
        pub struct $vars {
            $($(#[$fmeta])* pub $field: [::core::sync::atomic::AtomicU8; $len],)+
        }

        impl $vars {
            /// Zeroed variables (the defaults apply at reset communication).
            pub const fn new() -> Self {
                $vars {
                    $($field: $crate::od::decl::zeroed(),)+
                }
            }
        }

        $crate::od::decl::default_is_new!($vars);

        $(#[$dmeta])*
        #[derive(Debug)]
        pub struct $defaults {
            $($field: [u8; $len],)+
        }
    };
}
pub(crate) use param_blocks;

/// Declares a one-subindex object (subindex 0) whose value is a RAM
/// variable: `static $subs: [ObdSubEntry; 1]` and the variable `static
/// $var: [AtomicU8; size_of::<$t>()]`, with the default `$default` (of the
/// Rust type `$t`, stored in CPU byte order) or none.
///
/// `od_ram!(static S1005, SYNC_COB: u32 = 0x80 => UInt32, SRW);` is
/// `ObdSubEntry::ram(0, DataType::UInt32, Access::SRW, &SYNC_COB,
/// Some(&0x80u32.to_ne_bytes()))`; without `= default` the entry has no
/// default; a trailing `range(low, high)` makes it a ranged entry
/// ([`ObdSubEntry::ram_range`](crate::od::ObdSubEntry::ram_range)). `$typ` names a [`DataType`](crate::od::DataType) variant,
/// `$access` an [`Access`](crate::od::Access) constant.
#[macro_export]
macro_rules! od_ram {
    ($vis:vis static $subs:ident, $var:ident: $t:ty = $default:expr => $typ:ident, $access:ident) => {
        $vis static $var: [::core::sync::atomic::AtomicU8; ::core::mem::size_of::<$t>()] =
            $crate::od::decl::zeroed();
        $vis static $subs: [$crate::od::ObdSubEntry; 1] = {
            static DEFAULT: [u8; ::core::mem::size_of::<$t>()] = <$t>::to_ne_bytes($default);
            [$crate::od::ObdSubEntry::ram(
                0,
                $crate::od::DataType::$typ,
                $crate::od::Access::$access,
                &$var,
                Some(&DEFAULT),
            )]
        };
    };
    ($vis:vis static $subs:ident, $var:ident: $t:ty = $default:expr => $typ:ident, $access:ident,
        range($low:expr, $high:expr)) => {
        $vis static $var: [::core::sync::atomic::AtomicU8; ::core::mem::size_of::<$t>()] =
            $crate::od::decl::zeroed();
        $vis static $subs: [$crate::od::ObdSubEntry; 1] = {
            static LIMITS: [u8; 3 * ::core::mem::size_of::<$t>()] = $crate::od::decl::limits(
                <$t>::to_ne_bytes($default),
                <$t>::to_ne_bytes($low),
                <$t>::to_ne_bytes($high),
            );
            [$crate::od::ObdSubEntry::ram_range(
                0,
                $crate::od::DataType::$typ,
                $crate::od::Access::$access,
                &$var,
                &LIMITS,
            )]
        };
    };
    ($vis:vis static $subs:ident, $var:ident: $t:ty => $typ:ident, $access:ident) => {
        $vis static $var: [::core::sync::atomic::AtomicU8; ::core::mem::size_of::<$t>()] =
            $crate::od::decl::zeroed();
        $vis static $subs: [$crate::od::ObdSubEntry; 1] = $crate::od::decl::ram_object(
            $crate::od::DataType::$typ,
            $crate::od::Access::$access,
            &$var,
        );
    };
}

/// Declares a one-subindex constant object (subindex 0): `static $subs:
/// [ObdSubEntry; 1]` holding `$value` of the Rust type `$t` (CPU byte
/// order), as [`od_ram!`](crate::od_ram) does for variables.
#[macro_export]
macro_rules! od_rom {
    ($vis:vis static $subs:ident: $t:ty = $value:expr => $typ:ident, $access:ident) => {
        $vis static $subs: [$crate::od::ObdSubEntry; 1] = {
            static VALUE: [u8; ::core::mem::size_of::<$t>()] = <$t>::to_ne_bytes($value);
            [$crate::od::ObdSubEntry::rom(
                0,
                $crate::od::DataType::$typ,
                $crate::od::Access::$access,
                &VALUE,
            )]
        };
    };
}
