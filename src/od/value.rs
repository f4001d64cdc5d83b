//! Conversions between a variable in memory (CPU byte order, C type width)
//! and its CANopen wire form (little-endian, type width).

use core::sync::atomic::{AtomicU8, Ordering};

use super::types::{DataType, Encoding};
use crate::error::OdError;

/// Copies a RAM variable into `out` (which must have the same length).
#[inline]
pub fn load(mem: &[AtomicU8], out: &mut [u8]) {
    for (o, m) in out.iter_mut().zip(mem) {
        *o = m.load(Ordering::Relaxed);
    }
}

/// Copies `data` into a RAM variable (lengths equal).
#[inline]
pub fn store(mem: &[AtomicU8], data: &[u8]) {
    for (m, d) in mem.iter().zip(data) {
        m.store(*d, Ordering::Relaxed);
    }
}

/// Reads a native unsigned integer of 1, 2, 4 or 8 bytes.
pub fn native_to_u64(bytes: &[u8]) -> Option<u64> {
    Some(match bytes.len() {
        1 => u64::from(*bytes.first()?),
        2 => u64::from(u16::from_ne_bytes(bytes.try_into().ok()?)),
        4 => u64::from(u32::from_ne_bytes(bytes.try_into().ok()?)),
        8 => u64::from_ne_bytes(bytes.try_into().ok()?),
        _ => return None,
    })
}

/// Writes `v` as a native integer of `size` (1, 2, 4, 8) bytes into `out`.
pub fn u64_to_native(v: u64, size: usize, out: &mut [u8]) -> Option<()> {
    let dst = out.get_mut(..size)?;
    match size {
        1 => dst.copy_from_slice(&[v as u8]),
        2 => dst.copy_from_slice(&(v as u16).to_ne_bytes()),
        4 => dst.copy_from_slice(&(v as u32).to_ne_bytes()),
        8 => dst.copy_from_slice(&v.to_ne_bytes()),
        _ => return None,
    }
    Some(())
}

/// Little-endian value of up to 8 bytes.
pub fn le_to_u64(bytes: &[u8]) -> u64 {
    bytes
        .iter()
        .take(8)
        .rev()
        .fold(0u64, |acc, b| (acc << 8) | u64::from(*b))
}

/// Sign-extends the low `bytes * 8` bits of `v`.
pub fn sign_extend(v: u64, bytes: usize) -> u64 {
    if bytes == 0 || bytes >= 8 {
        return v;
    }
    let shift = 64 - 8 * bytes as u32;
    (((v << shift) as i64) >> shift) as u64
}

/// True when a variable of `size` bytes can hold values of type `typ`.
pub fn size_fits(typ: DataType, size: usize) -> bool {
    match typ.encoding() {
        Encoding::Numeric { wire, .. } => matches!(size, 1 | 2 | 4 | 8) && size >= wire,
        Encoding::Time => size >= 6,
        Encoding::Bytes => true,
    }
}

/// Converts a native variable to wire bytes; returns the wire length.
pub fn native_to_wire(typ: DataType, native: &[u8], out: &mut [u8]) -> Result<usize, OdError> {
    match typ.encoding() {
        Encoding::Numeric { wire, .. } => {
            let v = native_to_u64(native).ok_or(OdError::LENGTH)?;
            let dst = out.get_mut(..wire).ok_or(OdError::TOO_LONG)?;
            let le = v.to_le_bytes();
            dst.copy_from_slice(le.get(..wire).ok_or(OdError::LENGTH)?);
            Ok(wire)
        }
        Encoding::Time => {
            let ms =
                native_to_u64(native.get(..4).ok_or(OdError::LENGTH)?).ok_or(OdError::LENGTH)?;
            let days =
                native_to_u64(native.get(4..6).ok_or(OdError::LENGTH)?).ok_or(OdError::LENGTH)?;
            let dst = out.get_mut(..6).ok_or(OdError::TOO_LONG)?;
            let (ms_dst, days_dst) = dst.split_at_mut(4);
            ms_dst.copy_from_slice(&((ms as u32) & 0x0FFF_FFFF).to_le_bytes());
            days_dst.copy_from_slice(&(days as u16).to_le_bytes());
            Ok(6)
        }
        Encoding::Bytes => {
            let dst = out.get_mut(..native.len()).ok_or(OdError::TOO_LONG)?;
            dst.copy_from_slice(native);
            Ok(native.len())
        }
    }
}

/// Converts wire bytes of a fixed-size type into a native variable of
/// `size` bytes written to `out`. The length must match the type exactly.
pub fn wire_to_native(
    typ: DataType,
    wire_bytes: &[u8],
    size: usize,
    out: &mut [u8],
) -> Result<(), OdError> {
    match typ.encoding() {
        Encoding::Numeric { wire, signed } => {
            if wire_bytes.len() != wire {
                return Err(if wire_bytes.len() > wire {
                    OdError::TOO_LONG
                } else {
                    OdError::TOO_SHORT
                });
            }
            let mut v = le_to_u64(wire_bytes);
            if signed {
                v = sign_extend(v, wire);
            }
            u64_to_native(v, size, out).ok_or(OdError::LENGTH)
        }
        Encoding::Time => {
            if wire_bytes.len() != 6 {
                return Err(if wire_bytes.len() > 6 {
                    OdError::TOO_LONG
                } else {
                    OdError::TOO_SHORT
                });
            }
            let (ms_wire, days_wire) = wire_bytes.split_at(4);
            let ms = le_to_u64(ms_wire) & 0x0FFF_FFFF;
            let days = le_to_u64(days_wire);
            let dst = out.get_mut(..size).ok_or(OdError::LENGTH)?;
            dst.fill(0);
            let (ms_dst, rest) = dst.split_at_mut(4);
            u64_to_native(ms, 4, ms_dst).ok_or(OdError::LENGTH)?;
            u64_to_native(days, 2, rest).ok_or(OdError::LENGTH)?;
            Ok(())
        }
        Encoding::Bytes => Err(OdError::LENGTH),
    }
}

/// Compares two native values of `typ` (same size). `None` when the type
/// has no order (strings) or the size is unusual.
pub fn compare(typ: DataType, a: &[u8], b: &[u8]) -> Option<core::cmp::Ordering> {
    let size = a.len();
    let x = native_to_u64(a)?;
    let y = native_to_u64(b)?;
    match typ {
        DataType::Real32 => f32::from_bits(x as u32).partial_cmp(&f32::from_bits(y as u32)),
        DataType::Real64 => f64::from_bits(x).partial_cmp(&f64::from_bits(y)),
        t if t.is_signed() => {
            let wire = t.wire_size().unwrap_or(size);
            let sx = sign_extend(x, wire.min(size)) as i64;
            let sy = sign_extend(y, wire.min(size)) as i64;
            Some(sx.cmp(&sy))
        }
        t if t.is_numeric() => Some(x.cmp(&y)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn u16_round_trip_is_little_endian_on_the_wire() {
        let native = 0x1234u16.to_ne_bytes();
        let mut wire = [0u8; 8];
        let n = native_to_wire(DataType::UInt16, &native, &mut wire).unwrap();
        // CiA 301 7.1.1: least significant byte first (seed 004 example 3).
        assert_eq!(&wire[..n], &[0x34, 0x12]);
        let mut back = [0u8; 2];
        wire_to_native(DataType::UInt16, &wire[..2], 2, &mut back).unwrap();
        assert_eq!(back, native);
    }

    #[test]
    fn int24_in_a_32_bit_variable_is_sign_extended() {
        let mut native = [0u8; 4];
        wire_to_native(DataType::Int24, &[0xFE, 0xFF, 0xFF], 4, &mut native).unwrap();
        assert_eq!(i32::from_ne_bytes(native), -2);
        let mut wire = [0u8; 8];
        assert_eq!(
            native_to_wire(DataType::Int24, &native, &mut wire).unwrap(),
            3
        );
        assert_eq!(&wire[..3], &[0xFE, 0xFF, 0xFF]);
    }

    #[test]
    fn wrong_lengths_are_refused() {
        let mut native = [0u8; 4];
        assert_eq!(
            wire_to_native(DataType::UInt32, &[1, 2], 4, &mut native),
            Err(OdError::TOO_SHORT)
        );
        assert_eq!(
            wire_to_native(DataType::UInt8, &[1, 2], 1, &mut native),
            Err(OdError::TOO_LONG)
        );
    }

    #[test]
    fn signed_and_float_comparison() {
        let a = (-5i16).to_ne_bytes();
        let b = 3i16.to_ne_bytes();
        assert_eq!(
            compare(DataType::Int16, &a, &b),
            Some(core::cmp::Ordering::Less)
        );
        let f = 1.5f32.to_ne_bytes();
        let g = (-2.0f32).to_ne_bytes();
        assert_eq!(
            compare(DataType::Real32, &f, &g),
            Some(core::cmp::Ordering::Greater)
        );
    }

    #[test]
    fn time_of_day_wire_form() {
        let mut native = [0u8; 8];
        native[..4].copy_from_slice(&0x0123_4567u32.to_ne_bytes());
        native[4..6].copy_from_slice(&0x0102u16.to_ne_bytes());
        let mut wire = [0u8; 8];
        assert_eq!(
            native_to_wire(DataType::TimeOfDay, &native, &mut wire).unwrap(),
            6
        );
        assert_eq!(&wire[..6], &[0x67, 0x45, 0x23, 0x01, 0x02, 0x01]);
    }
}
