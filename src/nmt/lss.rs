//! LSS slave (layer setting services, CiA 305; SYS TEC module LSSS): an
//! LSS master finds this node by its LSS address (vendor-ID, product code,
//! revision number and serial number, object 0x1018 sub 1..4) and gives it
//! a node-ID.
//!
//! The slave is in the LSS state *waiting* or *configuration*. It serves:
//!
//! | request | state | answer |
//! |---|---|---|
//! | switch state global (0x04) | any | none |
//! | switch state selective (0x40..0x43, all four parts equal) | waiting | 0x44, then configuration |
//! | identify remote slave (0x46..0x4B, vendor and product equal, revision and serial in range) | any | 0x4F |
//! | identify non-configured remote slave (0x4C) | any, without node-ID | 0x50 |
//! | fastscan (0x51) | waiting, without node-ID | 0x4F for each matching step |
//! | configure node-ID (0x11) | configuration | 0x11 with 0 (taken) or 1 (out of 1..=127) |
//! | configure bit timing (0x13) | configuration | 0x13 with 1: not supported |
//! | activate bit timing (0x15) | configuration | none (nothing to activate) |
//! | store configuration (0x17) | configuration | 0x17 with 1: not supported |
//! | inquire identity (0x5A..0x5D), inquire node-ID (0x5E) | configuration | the value |
//!
//! # Node-ID
//! The node-ID configured is *pending*: it becomes the node's node-ID at
//! the next reset communication (or reset node). A node started without a
//! node-ID (`0xFF`, "not configured") takes it as soon as the master
//! switches the LSS state back to waiting, with a reset communication (the
//! application sees its NMT events) — the way `CcmProcessLssInitState`
//! ends. Inquire node-ID answers the node-ID in use (0xFF while none).
//!
//! # Behaviour decisions
//! * Bit timing and storage are not served: the SYS TEC driver interface
//!   has no call to change the bit rate, and the store image keeps object
//!   values, not LSS settings. Configure bit timing and store
//!   configuration answer error 1 ("not supported", CiA 305); an
//!   application that keeps the node-ID itself reads it with
//!   `CcmLsssGetNodeId`.
//! * Configure node-ID 0xFF (back to "not configured") answers error 1:
//!   a node keeps a node-ID once it has one.
//! * Switch state selective and identify remote slave take their parts in
//!   the order of their specifiers; a part out of order starts the
//!   sequence again.

use crate::port::CanFrame;
pub use crate::wire::lss::UNCONFIGURED;
use crate::wire::lss::{Request, cs, encode_answer};

/// Which objects give the LSS address: 0x1018 sub 1..=4.
pub const IDENTITY_INDEX: u16 = 0x1018;

/// Error code of a configure answer: taken.
const OK: u8 = 0;
/// Error code of a configure answer: out of range / not supported.
const REFUSED: u8 = 1;

/// Part `n` of the LSS address (0 vendor-ID .. 3 serial number; 0 beyond).
fn part_of(address: [u32; 4], n: u8) -> u32 {
    address.get(usize::from(n)).copied().unwrap_or(0)
}

/// What the stack does after a request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// The frame to send on 0x7E4.
    pub answer: Option<CanFrame>,
    /// A node without node-ID takes the pending one now (reset
    /// communication).
    pub take_node_id: bool,
}

impl Outcome {
    const NONE: Outcome = Outcome {
        answer: None,
        take_node_id: false,
    };

    fn answer(cs: u8, params: &[u8]) -> Outcome {
        Outcome {
            answer: Some(encode_answer(cs, params)),
            take_node_id: false,
        }
    }
}

/// The LSS slave.
#[derive(Clone, Debug, Default)]
pub struct LssSlave {
    configuration: bool,
    pending: u8,
    /// Parts of a switch state selective matched so far, in order.
    selective: u8,
    /// Identify remote slave: the parts received (bit n: part n) and their
    /// values.
    identify_seen: u8,
    identify: [u32; 6],
    /// Fastscan: the part of the LSS address compared now.
    scan: Option<u8>,
}

impl LssSlave {
    /// A slave in the waiting state whose pending node-ID is `node` (the
    /// node-ID of `CcmInitCANopen`, 0xFF for none).
    pub fn new(node: u8) -> LssSlave {
        LssSlave {
            pending: node,
            ..LssSlave::default()
        }
    }

    /// True in the LSS configuration state.
    pub fn in_configuration(&self) -> bool {
        self.configuration
    }

    /// The pending node-ID (0xFF: none).
    pub fn pending_node_id(&self) -> u8 {
        self.pending
    }

    /// Serves one request. `address` is the LSS address (0x1018 sub 1..=4),
    /// `node` the node-ID in use (0xFF while none).
    pub fn on_request(&mut self, req: Request, address: [u32; 4], node: u8) -> Outcome {
        match req {
            Request::SwitchGlobal(configuration) => {
                let leaving = self.configuration && !configuration;
                self.configuration = configuration;
                self.selective = 0;
                self.scan = None;
                Outcome {
                    answer: None,
                    take_node_id: leaving && node == UNCONFIGURED && self.pending != UNCONFIGURED,
                }
            }
            Request::SwitchSelective(part, value) => self.switch_selective(part, value, address),
            Request::Identify(part, value) => self.identify(part, value, address),
            Request::IdentifyNonConfigured if self.pending == UNCONFIGURED => {
                Outcome::answer(cs::NON_CONFIGURED_ANSWER, &[])
            }
            Request::Fastscan { id, bit, sub, next } => self.fastscan(id, bit, sub, next, address),
            _ if !self.configuration => Outcome::NONE,
            Request::ConfigureNodeId(n) => {
                let taken = (1..=127).contains(&n);
                if taken {
                    self.pending = n;
                }
                Outcome::answer(
                    cs::CONFIGURE_NODE_ID,
                    &[if taken { OK } else { REFUSED }, 0],
                )
            }
            Request::ConfigureBitTiming(..) => {
                Outcome::answer(cs::CONFIGURE_BIT_TIMING, &[REFUSED, 0])
            }
            Request::StoreConfiguration => Outcome::answer(cs::STORE_CONFIGURATION, &[REFUSED, 0]),
            Request::Inquire(part) => Outcome::answer(
                cs::INQUIRE_VENDOR + part,
                &part_of(address, part).to_le_bytes(),
            ),
            Request::InquireNodeId => Outcome::answer(cs::INQUIRE_NODE_ID, &[node]),
            Request::ActivateBitTiming(_) | Request::IdentifyNonConfigured => Outcome::NONE,
        }
    }

    fn switch_selective(&mut self, part: u8, value: u32, address: [u32; 4]) -> Outcome {
        let expected = if part == 0 { 0 } else { self.selective };
        if self.configuration || part != expected || value != part_of(address, part) {
            self.selective = 0;
            return Outcome::NONE;
        }
        self.selective = part + 1;
        if self.selective < 4 {
            return Outcome::NONE;
        }
        self.selective = 0;
        self.configuration = true;
        Outcome::answer(cs::SWITCH_SELECTIVE_ANSWER, &[])
    }

    fn identify(&mut self, part: u8, value: u32, address: [u32; 4]) -> Outcome {
        if part == 0 {
            self.identify_seen = 0;
        }
        if self.identify_seen != (1 << part) - 1 {
            self.identify_seen = 0;
            return Outcome::NONE;
        }
        self.identify_seen |= 1 << part;
        if let Some(slot) = self.identify.get_mut(usize::from(part)) {
            *slot = value;
        }
        if part < 5 {
            return Outcome::NONE;
        }
        self.identify_seen = 0;
        let [vendor, product, rev_low, rev_high, serial_low, serial_high] = self.identify;
        let [my_vendor, my_product, my_rev, my_serial] = address;
        let found = vendor == my_vendor
            && product == my_product
            && (rev_low..=rev_high).contains(&my_rev)
            && (serial_low..=serial_high).contains(&my_serial);
        if found {
            Outcome::answer(cs::IDENTIFY_ANSWER, &[])
        } else {
            Outcome::NONE
        }
    }

    /// CiA 305 fastscan: bit 0x80 starts it (every slave without node-ID
    /// in the waiting state answers); then the master compares bits `bit`
    /// ..=31 of part `sub` of the LSS address, and a slave whose bits are
    /// equal answers. A full match (`bit` 0) moves the comparison to part
    /// `next`; a `next` below `sub` ends it: the slave enters the
    /// configuration state.
    fn fastscan(&mut self, id: u32, bit: u8, sub: u8, next: u8, address: [u32; 4]) -> Outcome {
        if self.configuration || self.pending != UNCONFIGURED {
            return Outcome::NONE;
        }
        if bit == 0x80 {
            self.scan = Some(0);
            return Outcome::answer(cs::IDENTIFY_ANSWER, &[]);
        }
        if bit > 31 || sub > 3 || next > 3 || self.scan != Some(sub) {
            return Outcome::NONE;
        }
        let mask = u32::MAX << bit;
        if (id ^ part_of(address, sub)) & mask != 0 {
            return Outcome::NONE;
        }
        if bit == 0 {
            if next < sub {
                self.scan = None;
                self.configuration = true;
            } else {
                self.scan = Some(next);
            }
        }
        Outcome::answer(cs::IDENTIFY_ANSWER, &[])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ADDRESS: [u32; 4] = [0x0000_0123, 0x0000_4567, 0x0002_0001, 0x1234_5678];

    fn answer_cs(o: Outcome) -> Option<u8> {
        o.answer.map(|f| f.data[0])
    }

    fn configured(node: u8) -> LssSlave {
        let mut s = LssSlave::new(node);
        s.on_request(Request::SwitchGlobal(true), ADDRESS, node);
        s
    }

    #[test]
    fn switch_selective_needs_all_four_parts_in_order() {
        let mut s = LssSlave::new(5);
        for (part, value) in ADDRESS.iter().enumerate().take(3) {
            let o = s.on_request(Request::SwitchSelective(part as u8, *value), ADDRESS, 5);
            assert_eq!(o, Outcome::NONE);
        }
        let o = s.on_request(Request::SwitchSelective(3, ADDRESS[3]), ADDRESS, 5);
        assert_eq!(answer_cs(o), Some(0x44));
        assert!(s.in_configuration());

        // One part different, or a part left out: no answer, still waiting.
        for skip in 0..4 {
            let mut s = LssSlave::new(5);
            let mut last = Outcome::NONE;
            for (part, value) in ADDRESS.iter().enumerate() {
                let v = if part == skip { value ^ 1 } else { *value };
                last = s.on_request(Request::SwitchSelective(part as u8, v), ADDRESS, 5);
            }
            assert_eq!(last, Outcome::NONE, "part {skip} different");
            assert!(!s.in_configuration());
        }
        let mut s = LssSlave::new(5);
        s.on_request(Request::SwitchSelective(0, ADDRESS[0]), ADDRESS, 5);
        s.on_request(Request::SwitchSelective(2, ADDRESS[2]), ADDRESS, 5);
        let o = s.on_request(Request::SwitchSelective(3, ADDRESS[3]), ADDRESS, 5);
        assert_eq!(o, Outcome::NONE);
    }

    #[test]
    fn configuration_services_only_in_the_configuration_state() {
        let mut s = LssSlave::new(5);
        for r in [
            Request::ConfigureNodeId(7),
            Request::InquireNodeId,
            Request::Inquire(0),
            Request::StoreConfiguration,
            Request::ConfigureBitTiming(0, 3),
        ] {
            assert_eq!(s.on_request(r, ADDRESS, 5), Outcome::NONE, "{r:?}");
        }
        assert_eq!(s.pending_node_id(), 5);
    }

    #[test]
    fn configure_node_id_sets_the_pending_node_id() {
        let mut s = configured(5);
        let o = s.on_request(Request::ConfigureNodeId(0x22), ADDRESS, 5);
        // CiA 305: answer 0x11, error code 0, spec error 0.
        assert_eq!(o.answer.unwrap().data, [0x11, 0, 0, 0, 0, 0, 0, 0]);
        assert_eq!(s.pending_node_id(), 0x22);
        for bad in [0, 128, 0xFF] {
            let o = s.on_request(Request::ConfigureNodeId(bad), ADDRESS, 5);
            assert_eq!(o.answer.unwrap().data[..2], [0x11, 1], "{bad}");
            assert_eq!(s.pending_node_id(), 0x22);
        }
        // A configured node keeps its node-ID until reset communication.
        let o = s.on_request(Request::SwitchGlobal(false), ADDRESS, 5);
        assert!(!o.take_node_id);
    }

    #[test]
    fn a_node_without_node_id_takes_it_when_the_master_switches_to_waiting() {
        let mut s = configured(UNCONFIGURED);
        let o = s.on_request(Request::SwitchGlobal(false), ADDRESS, UNCONFIGURED);
        assert!(!o.take_node_id, "no node-ID configured yet");
        s.on_request(Request::SwitchGlobal(true), ADDRESS, UNCONFIGURED);
        s.on_request(Request::ConfigureNodeId(9), ADDRESS, UNCONFIGURED);
        // Configuration again: not yet.
        let o = s.on_request(Request::SwitchGlobal(true), ADDRESS, UNCONFIGURED);
        assert!(!o.take_node_id);
        let o = s.on_request(Request::SwitchGlobal(false), ADDRESS, UNCONFIGURED);
        assert!(o.take_node_id);
        assert_eq!(o.answer, None);
    }

    #[test]
    fn inquire_answers_the_lss_address_and_the_node_id() {
        let mut s = configured(5);
        for part in 0..4u8 {
            let o = s.on_request(Request::Inquire(part), ADDRESS, 5);
            let d = o.answer.unwrap().data;
            assert_eq!(d[0], 0x5A + part);
            assert_eq!(
                u32::from_le_bytes([d[1], d[2], d[3], d[4]]),
                ADDRESS[usize::from(part)]
            );
        }
        let o = s.on_request(Request::InquireNodeId, ADDRESS, 5);
        assert_eq!(o.answer.unwrap().data, [0x5E, 5, 0, 0, 0, 0, 0, 0]);
    }

    #[test]
    fn bit_timing_and_store_are_answered_not_supported() {
        let mut s = configured(5);
        let o = s.on_request(Request::ConfigureBitTiming(0, 2), ADDRESS, 5);
        assert_eq!(o.answer.unwrap().data[..2], [0x13, 1]);
        let o = s.on_request(Request::StoreConfiguration, ADDRESS, 5);
        assert_eq!(o.answer.unwrap().data[..2], [0x17, 1]);
        assert_eq!(
            s.on_request(Request::ActivateBitTiming(10), ADDRESS, 5),
            Outcome::NONE
        );
    }

    #[test]
    fn identify_remote_slave_by_ranges() {
        let ask = |s: &mut LssSlave, parts: [u32; 6]| {
            let mut last = Outcome::NONE;
            for (p, v) in parts.iter().enumerate() {
                last = s.on_request(Request::Identify(p as u8, *v), ADDRESS, 5);
            }
            answer_cs(last)
        };
        let mut s = LssSlave::new(5);
        let [v, p, r, n] = ADDRESS;
        assert_eq!(ask(&mut s, [v, p, r, r, n, n]), Some(0x4F));
        assert_eq!(ask(&mut s, [v, p, 0, u32::MAX, 0, u32::MAX]), Some(0x4F));
        assert_eq!(ask(&mut s, [v, p, r + 1, u32::MAX, 0, u32::MAX]), None);
        assert_eq!(ask(&mut s, [v, p, 0, u32::MAX, 0, n - 1]), None);
        assert_eq!(ask(&mut s, [v + 1, p, 0, u32::MAX, 0, u32::MAX]), None);
        assert_eq!(ask(&mut s, [v, p ^ 1, 0, u32::MAX, 0, u32::MAX]), None);
        // In the configuration state too.
        let mut s = configured(5);
        assert_eq!(ask(&mut s, [v, p, r, r, n, n]), Some(0x4F));
        // A part left out: no answer.
        let mut s = LssSlave::new(5);
        for p in [0u8, 1, 2, 3, 5] {
            let o = s.on_request(Request::Identify(p, 0), ADDRESS, 5);
            assert_eq!(o, Outcome::NONE);
        }
    }

    #[test]
    fn identify_non_configured_only_without_node_id() {
        let mut s = LssSlave::new(UNCONFIGURED);
        let o = s.on_request(Request::IdentifyNonConfigured, ADDRESS, UNCONFIGURED);
        assert_eq!(answer_cs(o), Some(0x50));
        let mut s = LssSlave::new(5);
        let o = s.on_request(Request::IdentifyNonConfigured, ADDRESS, 5);
        assert_eq!(o, Outcome::NONE);
    }

    /// The master's side of CiA 305 fastscan, the way it searches: each
    /// part bit by bit from bit 31, a bit set where the slave stays silent.
    fn scan(s: &mut LssSlave) -> Option<[u32; 4]> {
        let mut step = |id, bit, sub, next| {
            answer_cs(s.on_request(
                Request::Fastscan { id, bit, sub, next },
                ADDRESS,
                UNCONFIGURED,
            )) == Some(0x4F)
        };
        if !step(0, 0x80, 0, 0) {
            return None;
        }
        let mut found = [0u32; 4];
        for sub in 0..4u8 {
            let next = sub;
            for bit in (0..32u8).rev() {
                if !step(found[usize::from(sub)], bit, sub, next) {
                    found[usize::from(sub)] |= 1 << bit;
                }
            }
            if !step(found[usize::from(sub)], 0, sub, (sub + 1) & 3) {
                return None;
            }
        }
        Some(found)
    }

    #[test]
    fn fastscan_finds_the_lss_address_and_selects_the_slave() {
        let mut s = LssSlave::new(UNCONFIGURED);
        assert_eq!(scan(&mut s), Some(ADDRESS));
        assert!(s.in_configuration());
        // A slave with a node-ID takes no part.
        let mut s = LssSlave::new(5);
        let o = s.on_request(
            Request::Fastscan {
                id: 0,
                bit: 0x80,
                sub: 0,
                next: 0,
            },
            ADDRESS,
            5,
        );
        assert_eq!(o, Outcome::NONE);
        // Without the start (bit 0x80) no step is answered.
        let mut s = LssSlave::new(UNCONFIGURED);
        let o = s.on_request(
            Request::Fastscan {
                id: ADDRESS[0],
                bit: 0,
                sub: 0,
                next: 1,
            },
            ADDRESS,
            UNCONFIGURED,
        );
        assert_eq!(o, Outcome::NONE);
    }
}
