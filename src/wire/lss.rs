//! Layer setting services (LSS, CiA 305): the requests an LSS master sends
//! on 0x7E5 and the answers of a slave on 0x7E4. Every frame has 8 bytes;
//! byte 0 is the command specifier, the rest its parameters (multi-byte
//! numbers little-endian), unused bytes 0.

use crate::port::{CanFrame, CanId};

/// COB-ID of the master's requests.
pub const MASTER_TO_SLAVE: u16 = 0x7E5;
/// COB-ID of the slaves' answers.
pub const SLAVE_TO_MASTER: u16 = 0x7E4;
/// The node-ID of a slave that has none (CiA 305 "not configured").
pub const UNCONFIGURED: u8 = 0xFF;

/// Command specifiers (CiA 305).
pub mod cs {
    /// Switch state global (byte 1: 0 waiting, 1 configuration).
    pub const SWITCH_GLOBAL: u8 = 0x04;
    /// Configure node-ID (request and answer).
    pub const CONFIGURE_NODE_ID: u8 = 0x11;
    /// Configure bit timing parameters (request and answer).
    pub const CONFIGURE_BIT_TIMING: u8 = 0x13;
    /// Activate bit timing parameters (no answer).
    pub const ACTIVATE_BIT_TIMING: u8 = 0x15;
    /// Store configuration (request and answer).
    pub const STORE_CONFIGURATION: u8 = 0x17;
    /// Switch state selective, first of four requests: vendor-ID.
    pub const SWITCH_SELECTIVE_VENDOR: u8 = 0x40;
    /// Switch state selective, last request: serial number.
    pub const SWITCH_SELECTIVE_SERIAL: u8 = 0x43;
    /// Answer to a complete switch state selective.
    pub const SWITCH_SELECTIVE_ANSWER: u8 = 0x44;
    /// Identify remote slave, first of six requests: vendor-ID.
    pub const IDENTIFY_VENDOR: u8 = 0x46;
    /// Identify remote slave, last request: serial number high.
    pub const IDENTIFY_SERIAL_HIGH: u8 = 0x4B;
    /// Identify non-configured remote slave.
    pub const IDENTIFY_NON_CONFIGURED: u8 = 0x4C;
    /// Answer "identify slave" (also of fastscan).
    pub const IDENTIFY_ANSWER: u8 = 0x4F;
    /// Answer "identify non-configured slave".
    pub const NON_CONFIGURED_ANSWER: u8 = 0x50;
    /// Fastscan.
    pub const FASTSCAN: u8 = 0x51;
    /// Inquire identity vendor-ID (request and answer; 0x5B product code,
    /// 0x5C revision number, 0x5D serial number follow).
    pub const INQUIRE_VENDOR: u8 = 0x5A;
    /// Inquire identity serial number.
    pub const INQUIRE_SERIAL: u8 = 0x5D;
    /// Inquire node-ID (request and answer).
    pub const INQUIRE_NODE_ID: u8 = 0x5E;
}

/// A request of the master, decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Request {
    /// Switch state global: `true` configuration, `false` waiting.
    SwitchGlobal(bool),
    /// One of the four switch state selective requests: which part of the
    /// LSS address (0 vendor-ID .. 3 serial number) and its value.
    SwitchSelective(u8, u32),
    /// Configure node-ID.
    ConfigureNodeId(u8),
    /// Configure bit timing: table selector, table index.
    ConfigureBitTiming(u8, u8),
    /// Activate bit timing: switch delay in ms.
    ActivateBitTiming(u16),
    /// Store configuration.
    StoreConfiguration,
    /// One of the six identify remote slave requests (0 vendor-ID,
    /// 1 product code, 2/3 revision low/high, 4/5 serial low/high) and its
    /// value.
    Identify(u8, u32),
    /// Identify non-configured remote slave.
    IdentifyNonConfigured,
    /// Fastscan: the ID number, the lowest bit checked (0..=31, or 0x80 for
    /// the start), the part of the LSS address compared now and the next.
    Fastscan {
        /// IDNumber.
        id: u32,
        /// BitChecked.
        bit: u8,
        /// LSSSub.
        sub: u8,
        /// LSSNext.
        next: u8,
    },
    /// Inquire one part of the LSS address (0 vendor-ID .. 3 serial number).
    Inquire(u8),
    /// Inquire node-ID.
    InquireNodeId,
}

/// The number in bytes 1..=4 of a request.
fn number(d: &[u8; 8]) -> u32 {
    u32::from_le_bytes([d[1], d[2], d[3], d[4]])
}

/// Decodes a frame on [`MASTER_TO_SLAVE`]; `None` for another identifier,
/// a remote frame, a DLC other than 8 or a specifier this slave does not
/// serve (a reserved one, or one of an LSS master's answers).
pub fn decode_request(frame: &CanFrame) -> Option<Request> {
    if frame.id != CanId::std_masked(MASTER_TO_SLAVE) || frame.rtr || frame.len != 8 {
        return None;
    }
    let d = &frame.data;
    Some(match d[0] {
        cs::SWITCH_GLOBAL => match d[1] {
            0 => Request::SwitchGlobal(false),
            1 => Request::SwitchGlobal(true),
            _ => return None,
        },
        c @ cs::SWITCH_SELECTIVE_VENDOR..=cs::SWITCH_SELECTIVE_SERIAL => {
            Request::SwitchSelective(c - cs::SWITCH_SELECTIVE_VENDOR, number(d))
        }
        cs::CONFIGURE_NODE_ID => Request::ConfigureNodeId(d[1]),
        cs::CONFIGURE_BIT_TIMING => Request::ConfigureBitTiming(d[1], d[2]),
        cs::ACTIVATE_BIT_TIMING => Request::ActivateBitTiming(u16::from_le_bytes([d[1], d[2]])),
        cs::STORE_CONFIGURATION => Request::StoreConfiguration,
        c @ cs::IDENTIFY_VENDOR..=cs::IDENTIFY_SERIAL_HIGH => {
            Request::Identify(c - cs::IDENTIFY_VENDOR, number(d))
        }
        cs::IDENTIFY_NON_CONFIGURED => Request::IdentifyNonConfigured,
        cs::FASTSCAN => Request::Fastscan {
            id: number(d),
            bit: d[5],
            sub: d[6],
            next: d[7],
        },
        c @ cs::INQUIRE_VENDOR..=cs::INQUIRE_SERIAL => Request::Inquire(c - cs::INQUIRE_VENDOR),
        cs::INQUIRE_NODE_ID => Request::InquireNodeId,
        _ => return None,
    })
}

/// A slave's answer: specifier `cs` followed by `params` (bytes beyond 7
/// are left out), zero-padded to 8 bytes on [`SLAVE_TO_MASTER`].
pub fn encode_answer(cs: u8, params: &[u8]) -> CanFrame {
    let mut data = [0u8; 8];
    data[0] = cs;
    for (to, from) in data.iter_mut().skip(1).zip(params) {
        *to = *from;
    }
    CanFrame::new(CanId::std_masked(SLAVE_TO_MASTER), &data)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn request(data: [u8; 8]) -> CanFrame {
        CanFrame::new(CanId::std_masked(MASTER_TO_SLAVE), &data)
    }

    #[test]
    fn requests_of_cia_305() {
        let cases = [
            (
                [0x04, 1, 0, 0, 0, 0, 0, 0],
                Some(Request::SwitchGlobal(true)),
            ),
            (
                [0x04, 0, 0, 0, 0, 0, 0, 0],
                Some(Request::SwitchGlobal(false)),
            ),
            ([0x04, 2, 0, 0, 0, 0, 0, 0], None),
            (
                [0x40, 0x78, 0x56, 0x34, 0x12, 0, 0, 0],
                Some(Request::SwitchSelective(0, 0x1234_5678)),
            ),
            (
                [0x43, 1, 0, 0, 0, 0, 0, 0],
                Some(Request::SwitchSelective(3, 1)),
            ),
            (
                [0x11, 0x22, 0, 0, 0, 0, 0, 0],
                Some(Request::ConfigureNodeId(0x22)),
            ),
            (
                [0x13, 0, 4, 0, 0, 0, 0, 0],
                Some(Request::ConfigureBitTiming(0, 4)),
            ),
            (
                [0x15, 0xE8, 0x03, 0, 0, 0, 0, 0],
                Some(Request::ActivateBitTiming(1000)),
            ),
            (
                [0x17, 0, 0, 0, 0, 0, 0, 0],
                Some(Request::StoreConfiguration),
            ),
            (
                [0x46, 4, 3, 2, 1, 0, 0, 0],
                Some(Request::Identify(0, 0x0102_0304)),
            ),
            (
                [0x4B, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0],
                Some(Request::Identify(5, u32::MAX)),
            ),
            (
                [0x4C, 0, 0, 0, 0, 0, 0, 0],
                Some(Request::IdentifyNonConfigured),
            ),
            (
                [0x51, 0, 0, 0, 0x80, 31, 0, 1],
                Some(Request::Fastscan {
                    id: 0x8000_0000,
                    bit: 31,
                    sub: 0,
                    next: 1,
                }),
            ),
            ([0x5A, 0, 0, 0, 0, 0, 0, 0], Some(Request::Inquire(0))),
            ([0x5D, 0, 0, 0, 0, 0, 0, 0], Some(Request::Inquire(3))),
            ([0x5E, 0, 0, 0, 0, 0, 0, 0], Some(Request::InquireNodeId)),
            // Answers of slaves and reserved specifiers are no requests.
            ([0x44, 0, 0, 0, 0, 0, 0, 0], None),
            ([0x4F, 0, 0, 0, 0, 0, 0, 0], None),
            ([0x5F, 0, 0, 0, 0, 0, 0, 0], None),
        ];
        for (data, expected) in cases {
            assert_eq!(decode_request(&request(data)), expected, "{data:02X?}");
        }
    }

    #[test]
    fn only_eight_byte_data_frames_on_0x7e5_are_requests() {
        let ok = [0x5E, 0, 0, 0, 0, 0, 0, 0];
        let short = CanFrame::new(CanId::std_masked(MASTER_TO_SLAVE), &ok[..7]);
        assert_eq!(decode_request(&short), None);
        let other = CanFrame::new(CanId::std_masked(SLAVE_TO_MASTER), &ok);
        assert_eq!(decode_request(&other), None);
        let mut remote = request(ok);
        remote.rtr = true;
        assert_eq!(decode_request(&remote), None);
    }

    #[test]
    fn answers_are_eight_bytes_on_0x7e4() {
        let a = encode_answer(cs::INQUIRE_VENDOR, &0x1234_5678u32.to_le_bytes());
        assert_eq!(a.id, CanId::std_masked(0x7E4));
        assert_eq!(a.payload(), &[0x5A, 0x78, 0x56, 0x34, 0x12, 0, 0, 0]);
        let b = encode_answer(cs::IDENTIFY_ANSWER, &[]);
        assert_eq!(b.payload(), &[0x4F, 0, 0, 0, 0, 0, 0, 0]);
    }
}
