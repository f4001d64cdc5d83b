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

use super::MAPP_OFFSET;
use crate::error::CopKernel;
use crate::od::{MAX_FIXED, ObjectDictionary};

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
/// `commu_index` to `sink`, field by field, read from the dictionary (one
/// index lookup per object, its subindices through the entry handle).
/// `kCopSrdoErrorMapp` when a mapping entry the count names cannot be read.
pub(crate) fn stream(
    od: &ObjectDictionary,
    commu_index: u16,
    mut sink: impl FnMut(&[u8]),
) -> Result<(), CopKernel> {
    let missing = CopKernel::SrdoNotExist;
    let bad = CopKernel::SrdoErrorMapp;
    let commu = od.entry(commu_index).map_err(|_| missing)?;
    let param = |sub| commu.read_uint(sub).map_err(|_| missing);
    sink(&[param(1)? as u8]);
    sink(&(param(2)? as u16).to_le_bytes());
    sink(&[param(3)? as u8]);
    sink(&(param(5)? as u32).to_le_bytes());
    sink(&(param(6)? as u32).to_le_bytes());
    let mapp = od.entry(commu_index + MAPP_OFFSET).map_err(|_| bad)?;
    let count = mapp.read_uint(0).map_err(|_| bad)? as u8;
    sink(&[count]);
    // (An exclusive range: `1..=count` compiles to a slower loop.)
    for sub in (1..u16::from(count) + 1).map(|s| s as u8) {
        // The entry's four bytes as they are on the wire (little-endian;
        // a narrower type is padded with zeros), without making a number of
        // them first.
        let mut wire = [0u8; MAX_FIXED];
        mapp.read_wire(sub, &mut wire).map_err(|_| bad)?;
        let [a, b, c, d, ..] = wire;
        sink(&[sub]);
        sink(&[a, b, c, d]);
    }
    Ok(())
}

/// The CRC of one SRDO as `CcmCalcSrdoCrc` reports it, computed field by
/// field as the stream produces them, with the engine's table
/// (CRC-16/XMODEM: most significant bit first, start value and final XOR
/// from the algorithm). A table step shifts the next byte out of the top of
/// the register, so the four-byte fields (COB-IDs, mapping entries) go in
/// two bytes at a time: XORed into the register together, then stepped out
/// one after the other.
pub(crate) fn calc(od: &ObjectDictionary, commu_index: u16) -> Result<u16, CopKernel> {
    let [table] = CRC16.table();
    let step = |crc: u16| (crc << 8) ^ table.get(usize::from(crc >> 8)).copied().unwrap_or(0);
    let byte = |crc: u16, a: u8| step(crc ^ u16::from(a) << 8);
    let pair = |crc: u16, a: u8, b: u8| step(step(crc ^ u16::from_be_bytes([a, b])));
    let mut crc = CRC16.algorithm.init;
    stream(od, commu_index, |bytes| {
        crc = match *bytes {
            [a, b, c, d] => pair(pair(crc, a, b), c, d),
            _ => bytes.iter().fold(crc, |c, &b| byte(c, b)),
        }
    })?;
    Ok(crc ^ CRC16.algorithm.xorout)
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

    // req: SB-3-CRC-VECTORS
    #[test]
    fn xmodem_check_value() {
        // SAFETY_BEHAVIOUR.md section 3: CRC-16/XMODEM of "123456789" is 0x31C3.
        assert_eq!(crc16(b"123456789"), 0x31C3);
        assert_eq!(crc16(&[]), 0x0000, "start value 0x0000, no final XOR");
    }
}
