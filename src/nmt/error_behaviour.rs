//! Error behaviour (object 0x1029, CiA 301 7.5.2.32): the NMT state the
//! node enters when it detects a communication error.
//!
//! The stack counts three events as a communication error of this node
//! (the list of CiA 301 7.5.2.32): its heartbeat consumer reports a
//! producer lost, its life guarding slave reports the master lost, and the
//! CAN driver reports bus-off. Each event asks sub 1 of 0x1029 once:
//!
//! | sub 1 | reaction |
//! |---|---|
//! | 0x00 | PRE-OPERATIONAL, when the node is OPERATIONAL (the CiA 301 default) |
//! | 0x01 | the NMT state does not change |
//! | 0x02 | STOPPED, from PRE-OPERATIONAL or OPERATIONAL |
//!
//! A write of any other value (CiA 301 reserves 0x03..=0x7F and leaves
//! 0x80..=0xFF to manufacturers; this stack defines none of them) is
//! refused with abort 0x06090030. A dictionary default of such a value
//! reacts as 0x00. Further subindices (error classes of device profiles)
//! are objects only. Without 0x1029 the state never changes on these
//! events, as before this object was evaluated.
//!
//! The change goes through the stack's action queue like a received NMT
//! command: the application sees the error event first (heartbeat or life
//! guarding callback), then the NMT event of the new state.

use crate::error::OdError;
use crate::event::NmtState;
use crate::od::{Object, ObjectDictionary, Staged};

/// Error behaviour object.
pub const ERROR_BEHAVIOUR_INDEX: u16 = 0x1029;
/// Its subindex of the communication error class.
pub const COMMUNICATION_ERROR_SUB: u8 = 1;

/// What sub 1 of 0x1029 asks for on a communication error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reaction {
    /// 0x00: PRE-OPERATIONAL, only from OPERATIONAL.
    PreOperational,
    /// 0x01: no change of the NMT state.
    Keep,
    /// 0x02: STOPPED.
    Stopped,
}

impl Reaction {
    /// The reaction a value of sub 1 stands for; `None` for values this
    /// stack does not define.
    pub const fn of(value: u64) -> Option<Reaction> {
        match value {
            0 => Some(Reaction::PreOperational),
            1 => Some(Reaction::Keep),
            2 => Some(Reaction::Stopped),
            _ => None,
        }
    }

    /// The state a node in `current` enters; `None` when it stays.
    pub const fn target(self, current: NmtState) -> Option<NmtState> {
        match (self, current) {
            (Reaction::PreOperational, NmtState::Operational) => Some(NmtState::PreOperational),
            (Reaction::Stopped, NmtState::Operational | NmtState::PreOperational) => {
                Some(NmtState::Stopped)
            }
            _ => None,
        }
    }
}

/// The reaction the dictionary asks for: `None` without 0x1029 (or its
/// sub 1), [`Reaction::PreOperational`] for a value this stack does not
/// define.
pub fn reaction(od: &ObjectDictionary) -> Option<Reaction> {
    let v = od
        .read_uint(ERROR_BEHAVIOUR_INDEX, COMMUNICATION_ERROR_SUB)
        .ok()?;
    Some(Reaction::of(v).unwrap_or(Reaction::PreOperational))
}

/// Refuses a write of a value without a defined reaction to the
/// communication error class (0x06090030, `kCopInvalidParam`).
pub fn check_write(obj: &Object, value: &Staged) -> Result<(), OdError> {
    if obj.index() == ERROR_BEHAVIOUR_INDEX
        && obj.sub() == COMMUNICATION_ERROR_SUB
        && value.as_u64().and_then(Reaction::of).is_none()
    {
        return Err(OdError::VALUE_RANGE);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reactions_by_state() {
        use NmtState::*;
        let all = [Initialisation, PreOperational, Operational, Stopped];
        let pre = all.map(|s| Reaction::PreOperational.target(s));
        assert_eq!(pre, [None, None, Some(PreOperational), None]);
        let keep = all.map(|s| Reaction::Keep.target(s));
        assert_eq!(keep, [None; 4]);
        let stop = all.map(|s| Reaction::Stopped.target(s));
        assert_eq!(stop, [None, Some(Stopped), Some(Stopped), None]);
    }

    #[test]
    fn values_with_a_reaction() {
        assert_eq!(Reaction::of(0), Some(Reaction::PreOperational));
        assert_eq!(Reaction::of(1), Some(Reaction::Keep));
        assert_eq!(Reaction::of(2), Some(Reaction::Stopped));
        for v in [3, 0x7F, 0x80, 0xFF, 0x100] {
            assert_eq!(Reaction::of(v), None, "{v:#x}");
        }
    }
}
