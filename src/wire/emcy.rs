//! Emergency object (CiA 301 7.2.7.3.1): 8 bytes = error code (LE WORD),
//! error register (0x1001), 5 manufacturer-specific bytes.

use crate::port::{CanFrame, CanId};

/// Default EMCY COB-ID base (predefined connection set: 0x80 + node-ID).
pub const EMCY_BASE: u16 = 0x080;

/// One emergency message.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Emergency {
    /// Emergency error code (CiA 301 table 21).
    pub code: u16,
    /// Error register (object 0x1001).
    pub register: u8,
    /// Manufacturer-specific error field.
    pub manufacturer: [u8; 5],
}

/// Encodes an emergency frame.
pub fn encode(id: CanId, e: &Emergency) -> CanFrame {
    let c = e.code.to_le_bytes();
    let m = e.manufacturer;
    CanFrame::new(id, &[c[0], c[1], e.register, m[0], m[1], m[2], m[3], m[4]])
}

/// Decodes an emergency frame (consumer side); DLC must be 8.
pub fn decode(frame: &CanFrame) -> Option<Emergency> {
    if frame.len != 8 || frame.rtr {
        return None;
    }
    let d = frame.data;
    Some(Emergency {
        code: u16::from_le_bytes([d[0], d[1]]),
        register: d[2],
        manufacturer: [d[3], d[4], d[5], d[6], d[7]],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_is_code_register_manufacturer() {
        let e = Emergency {
            code: 0x8210,
            register: 0x11,
            manufacturer: [1, 2, 3, 4, 5],
        };
        let f = encode(CanId::std_masked(0x82), &e);
        // CiA 301 7.2.7.3.1: code LSB first, then error register.
        assert_eq!(f.payload(), &[0x10, 0x82, 0x11, 1, 2, 3, 4, 5]);
        assert_eq!(decode(&f), Some(e));
    }
}
