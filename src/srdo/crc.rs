//! The SRDO configuration CRC (object 0x13FF; seed manual 1.1.3).
//!
//! CRC-16 with G(x) = x^16 + x^12 + x^5 + 1, start value 0x0000, no
//! reflection, no final XOR: the catalogued CRC-16/XMODEM. The byte stream
//! of one SRDO, every multi-byte field little-endian (CANopen order, the
//! same on every CPU):
//!
//! | bytes | field |
//! |---|---|
//! | 1 | information direction (0x1301+n sub 1) |
//! | 2 | refresh time / SCT (sub 2) |
//! | 1 | SRVT (sub 3) |
//! | 4 | COB-ID 1 (sub 5) |
//! | 4 | COB-ID 2 (sub 6) |
//! | 1 | number of mapped entries (0x1381+n sub 0) |
//! | 1 + 4 per entry | subindex i, then mapping entry i, for i = 1..=count |
//!
//! The transmission type (sub 4) is not part of it; disabled SRDOs
//! (direction 0) are computed like any other.
//!
//! The CRC runs on a 256-entry table (`crc::Table<1>`, 512 bytes of
//! constant data): about 8 instructions per byte, so the longest stream
//! (13 + 5 * 16 = 93 bytes) stays below 1,000 instructions. The table-less
//! variant (`NoTable`) would save the 512 bytes but is about four times
//! slower and would exceed the 1,500-instruction budget of a configuration
//! check with 16 mapping entries.

use crc::{CRC_16_XMODEM, Crc, Table};

use super::{MAPP_OFFSET, read_u8, read_u16, read_u32};
use crate::error::CopKernel;
use crate::od::ObjectDictionary;

/// The CRC engine: CRC-16/XMODEM with a 256-entry table (see module docs).
static CRC16: Crc<u16, Table<1>> = Crc::<u16, Table<1>>::new(&CRC_16_XMODEM);

/// Longest byte stream of one SRDO: 13 bytes of parameters and sub 0, then
/// 5 bytes per mapping entry (at most 16 entries, CiA 304).
pub const MAX_STREAM: usize = 13 + 5 * 16;

/// CRC-16/XMODEM of a byte string.
pub fn crc16(bytes: &[u8]) -> u16 {
    CRC16.checksum(bytes)
}

/// Feeds the CRC byte stream of the SRDO with communication index
/// `commu_index` to `sink`, field by field, read from the dictionary.
/// `kCopSrdoErrorMapp` when a mapping entry the count names cannot be read.
pub(crate) fn stream(
    od: &ObjectDictionary,
    commu_index: u16,
    mut sink: impl FnMut(&[u8]),
) -> Result<(), CopKernel> {
    let mapp_index = commu_index + MAPP_OFFSET;
    let missing = CopKernel::SrdoNotExist;
    sink(&[read_u8(od, commu_index, 1).ok_or(missing)?]);
    sink(&read_u16(od, commu_index, 2).ok_or(missing)?.to_le_bytes());
    sink(&[read_u8(od, commu_index, 3).ok_or(missing)?]);
    sink(&read_u32(od, commu_index, 5).ok_or(missing)?.to_le_bytes());
    sink(&read_u32(od, commu_index, 6).ok_or(missing)?.to_le_bytes());
    let count = read_u8(od, mapp_index, 0).ok_or(CopKernel::SrdoErrorMapp)?;
    sink(&[count]);
    for sub in 1..=count {
        let entry = read_u32(od, mapp_index, sub).ok_or(CopKernel::SrdoErrorMapp)?;
        sink(&[sub]);
        sink(&entry.to_le_bytes());
    }
    Ok(())
}

/// The CRC of one SRDO as `CcmCalcSrdoCrc` reports it.
pub(crate) fn calc(od: &ObjectDictionary, commu_index: u16) -> Result<u16, CopKernel> {
    let mut digest = CRC16.digest();
    stream(od, commu_index, |b| digest.update(b))?;
    Ok(digest.finalize())
}

/// Copies the CRC byte stream of one SRDO into `out`; returns its length.
/// For diagnostics and tests (the stream is what the CRC covers).
pub fn stream_bytes(
    od: &ObjectDictionary,
    commu_index: u16,
    out: &mut [u8; MAX_STREAM],
) -> Result<usize, CopKernel> {
    let mut n = 0usize;
    stream(od, commu_index, |b| {
        for byte in b {
            if let Some(slot) = out.get_mut(n) {
                *slot = *byte;
            }
            n += 1;
        }
    })?;
    Ok(n.min(MAX_STREAM))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xmodem_check_value() {
        // SAFETY_BEHAVIOUR.md section 3: CRC-16/XMODEM of "123456789" is 0x31C3.
        assert_eq!(crc16(b"123456789"), 0x31C3);
        assert_eq!(crc16(&[]), 0x0000, "start value 0x0000, no final XOR");
    }
}
