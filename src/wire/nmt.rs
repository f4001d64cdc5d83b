//! NMT module control (CiA 301 7.2.8.3.1) and error control (boot-up,
//! heartbeat, node guarding; CiA 301 7.2.8.3.2).

use crate::port::{CanFrame, CanId};

/// COB-ID of NMT module control.
pub const NMT_COB_ID: u16 = 0x000;
/// Base COB-ID of NMT error control (boot-up, heartbeat, guarding).
pub const ERROR_CONTROL_BASE: u16 = 0x700;

c_enum! {
    /// Command specifiers of NMT module control.
    pub enum NmtCs: u8, fn from_u8(u8) {
        /// Start remote node.
        Start = 0x01,
        /// Stop remote node.
        Stop = 0x02,
        /// Enter pre-operational.
        EnterPreOperational = 0x80,
        /// Reset node.
        ResetNode = 0x81,
        /// Reset communication.
        ResetCommunication = 0x82,
    }
}

/// A decoded NMT module control frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NmtCommandFrame {
    /// Command.
    pub cs: NmtCs,
    /// Addressed node, 0 = all nodes.
    pub node: u8,
}

/// Decodes an NMT module control frame: id 0x000, DLC 2, byte 0 command
/// specifier, byte 1 node-ID. Anything else is not an NMT command.
pub fn decode_command(frame: &CanFrame) -> Option<NmtCommandFrame> {
    if frame.id != CanId::std_masked(NMT_COB_ID) || frame.rtr || frame.len != 2 {
        return None;
    }
    Some(NmtCommandFrame {
        cs: NmtCs::from_u8(frame.data[0])?,
        node: frame.data[1],
    })
}

/// Encodes an NMT module control frame (master side).
pub fn encode_command(cs: NmtCs, node: u8) -> CanFrame {
    CanFrame::new(CanId::std_masked(NMT_COB_ID), &[cs as u8, node])
}

/// The error control COB-ID of a node.
pub const fn error_control_id(node: u8) -> CanId {
    CanId::std_masked(ERROR_CONTROL_BASE + node as u16)
}

/// Boot-up message: id 0x700 + node-ID, one data byte 0x00 (CiA 301).
/// Some old modules sent id 0x080 + node-ID without data; this library
/// follows CiA 301.
pub fn encode_bootup(node: u8) -> CanFrame {
    CanFrame::new(error_control_id(node), &[0x00])
}

/// Heartbeat message: id 0x700 + node-ID, one byte NMT state.
pub fn encode_heartbeat(node: u8, state: u8) -> CanFrame {
    CanFrame::new(error_control_id(node), &[state & 0x7F])
}

/// Node guarding answer: state with the toggle bit in bit 7.
pub fn encode_guard_reply(node: u8, state: u8, toggle: bool) -> CanFrame {
    CanFrame::new(
        error_control_id(node),
        &[(state & 0x7F) | if toggle { 0x80 } else { 0 }],
    )
}

/// A decoded error control frame (heartbeat consumer, boot-up detection).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ErrorControl {
    /// Producer node-ID.
    pub node: u8,
    /// NMT state byte (0x00 = boot-up), toggle bit removed.
    pub state: u8,
}

/// Decodes a heartbeat or boot-up frame (id 0x701..0x77F, DLC 1).
pub fn decode_error_control(frame: &CanFrame) -> Option<ErrorControl> {
    let id = frame.id;
    if id.is_extended() || frame.rtr || frame.len != 1 {
        return None;
    }
    let raw = id.id();
    if !(0x701..=0x77F).contains(&raw) {
        return None;
    }
    Some(ErrorControl {
        node: (raw - 0x700) as u8,
        state: frame.data[0] & 0x7F,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn start_all_nodes_frame() {
        // Seed 004 "Initialisierung des Netzwerks": id 0000, data 01 00.
        let f = encode_command(NmtCs::Start, 0);
        assert_eq!(f.id.id(), 0x000);
        assert_eq!(f.payload(), &[0x01, 0x00]);
        assert_eq!(
            decode_command(&f),
            Some(NmtCommandFrame {
                cs: NmtCs::Start,
                node: 0
            })
        );
    }

    #[test]
    fn wrong_dlc_is_not_a_command() {
        let f = CanFrame::new(CanId::std_masked(0), &[0x01]);
        assert_eq!(decode_command(&f), None);
        let f = CanFrame::new(CanId::std_masked(0), &[0x03, 0x00]);
        assert_eq!(decode_command(&f), None);
    }

    #[test]
    fn bootup_is_0x700_plus_id_with_one_zero_byte() {
        let f = encode_bootup(2);
        assert_eq!(f.id.id(), 0x702);
        assert_eq!(f.payload(), &[0x00]);
        assert_eq!(
            decode_error_control(&f),
            Some(ErrorControl { node: 2, state: 0 })
        );
    }

    #[test]
    fn heartbeat_carries_state() {
        let f = encode_heartbeat(0x10, 0x05);
        assert_eq!(f.id.id(), 0x710);
        assert_eq!(f.payload(), &[0x05]);
    }
}
