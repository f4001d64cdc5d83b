//! The declaration of the C-style value enums (`tCopKernel`, `tNmtEvent`,
//! `kObdTyp*`, SDO abort codes, ...): one place that writes the enum with
//! its fixed numbers and the decoder from the number, so that a value list
//! is spelled once and the decoder cannot miss or misnumber a value.
//!
//! ```ignore
//! c_enum! {
//!     /// NMT states (`kNodeState*`).
//!     pub enum NmtState: u8, fn from_u8(u8) {
//!         /// Stopped.
//!         Stopped = 0x04,
//!         Operational = 0x05,
//!     }
//! }
//! ```
//!
//! gives `#[repr(u8)] pub enum NmtState` (deriving `Clone`, `Copy`, `Debug`,
//! `PartialEq`, `Eq`, `Hash`; further attributes pass through), the
//! method `code()` (the number), the associated constant `ALL` (every value
//! in declaration order) and
//! `pub const fn from_u8(u8) -> Option<NmtState>` (`None` for a number the
//! list does not have; the decoder's parameter may be wider than the
//! representation, as `DataType::from_code(u16)` is).

/// Declares a `#[repr]` value enum and its decoder (module docs).
macro_rules! c_enum {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident: $repr:ty, fn $decode:ident($arg:ty) {
            $($(#[$vmeta:meta])* $variant:ident = $value:literal,)+
        }
    ) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        #[repr($repr)]
        $vis enum $name {
            $($(#[$vmeta])* $variant = $value,)+
        }

        impl $name {
            /// The number (the C value).
            pub const fn code(self) -> $repr {
                self as $repr
            }

            /// Every value, in declaration order.
            pub const ALL: &'static [$name] = &[$($name::$variant),+];

            /// Decodes a number; `None` for one the enum does not have.
            pub const fn $decode(value: $arg) -> Option<$name> {
                match value {
                    $($value => Some($name::$variant),)+
                    _ => None,
                }
            }
        }
    };
}
