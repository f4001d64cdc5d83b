//! NMT slave (SYS TEC NMTS, CiA 301 7.3.2): what an NMT command asks of
//! this node and in which order the stack carries it out.
//!
//! A command — received (`NMT` frame, [`crate::wire::nmt`]), local
//! (`CcmNmtsExecCommand`) or sent by this node's master to itself — becomes
//! a [`Transition`]. The stack queues its steps in the action queue: the
//! internal work ([`Internal`]) and the NMT events of the application's
//! callback, one after the other, so that the application sees each event
//! when the node is in the state the event describes.

use crate::event::{ActionQueue, Event, Internal, NmtEvent, NmtState};
use crate::wire::nmt::NmtCs;

c_enum! {
    /// Local NMT commands (`tNmtCommand`, `CcmNmtsExecCommand`).
    pub enum NmtCommand: u16, fn from_u16(u16) {
        /// kNmtCommInitialize.
        Initialize = 0x0000,
        /// kNmtCommStartRemoteNode / kNmtCommEnterOperational.
        StartRemoteNode = 0x0001,
        /// kNmtCommStopRemoteNode / kNmtCommEnterStopped.
        StopRemoteNode = 0x0002,
        /// kNmtCommEnterPreOperational.
        EnterPreOperational = 0x0080,
        /// kNmtCommResetNode.
        ResetNode = 0x0081,
        /// kNmtCommResetCommunication.
        ResetCommunication = 0x0082,
        /// kNmtCommInitBeforePost.
        InitBeforePost = 0x0101,
        /// kNmtCommEnterPostPreOperational.
        EnterPostPreOperational = 0x0180,
    }
}

impl NmtCommand {
    /// The NMT command specifier the local command stands for; `None` for
    /// the two steps of the start-up sequence (kNmtCommInitialize,
    /// kNmtCommInitBeforePost), which the stack runs itself.
    pub const fn specifier(self) -> Option<NmtCs> {
        Some(match self {
            NmtCommand::StartRemoteNode => NmtCs::Start,
            NmtCommand::StopRemoteNode => NmtCs::Stop,
            NmtCommand::EnterPreOperational | NmtCommand::EnterPostPreOperational => {
                NmtCs::EnterPreOperational
            }
            NmtCommand::ResetNode => NmtCs::ResetNode,
            NmtCommand::ResetCommunication => NmtCs::ResetCommunication,
            NmtCommand::Initialize | NmtCommand::InitBeforePost => return None,
        })
    }
}

/// What an NMT command specifier asks of the slave.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Transition {
    /// Enter this state.
    Enter(NmtState),
    /// Reset the node (application and communication objects, `node`) or
    /// the communication objects only.
    Reset {
        /// Reset node rather than reset communication.
        node: bool,
    },
}

impl Transition {
    /// The transition of a command specifier (CiA 301 figure 48).
    pub const fn of(cs: NmtCs) -> Transition {
        match cs {
            NmtCs::Start => Transition::Enter(NmtState::Operational),
            NmtCs::Stop => Transition::Enter(NmtState::Stopped),
            NmtCs::EnterPreOperational => Transition::Enter(NmtState::PreOperational),
            NmtCs::ResetNode => Transition::Reset { node: true },
            NmtCs::ResetCommunication => Transition::Reset { node: false },
        }
    }
}

/// Queues the change from `current` to `target`: the state change, then
/// its NMT event. Nothing when the node is in `target` already; a change
/// to INITIALISATION is only ever part of a reset ([`queue_reset`]).
pub fn queue_state(queue: &mut ActionQueue, current: NmtState, target: NmtState) {
    if current == target {
        return;
    }
    let ev = match target {
        NmtState::Operational => NmtEvent::EnterOperational,
        NmtState::Stopped => NmtEvent::EnterStopped,
        NmtState::PreOperational => NmtEvent::EnterPreOperational,
        NmtState::Initialisation => return,
    };
    queue.schedule(Internal::EnterState(target));
    queue.emit(Event::Nmt(ev));
}

/// Queues a reset: node (application and communication objects) or
/// communication only, each reset with its NMT events, then the modules'
/// reconfiguration. When the node is connected the stack ends it with the
/// boot-up message and PRE-OPERATIONAL.
pub fn queue_reset(queue: &mut ActionQueue, node: bool) {
    queue.schedule(Internal::EnterState(NmtState::Initialisation));
    if node {
        queue.schedule(Internal::RestoreApplication);
        queue.emit(Event::Nmt(NmtEvent::ResetNode));
    }
    queue.emit(Event::Nmt(NmtEvent::PreResetCommunication));
    queue.schedule(Internal::RestoreCommunication);
    queue.emit(Event::Nmt(NmtEvent::ResetCommunication));
    queue.schedule(Internal::Reconfigure);
    queue.emit(Event::Nmt(NmtEvent::PostResetCommunication));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::event::Action;

    #[test]
    fn local_commands_map_to_their_specifiers() {
        let cases = [
            (0x0001, Some(NmtCs::Start)),
            (0x0002, Some(NmtCs::Stop)),
            (0x0080, Some(NmtCs::EnterPreOperational)),
            (0x0180, Some(NmtCs::EnterPreOperational)),
            (0x0081, Some(NmtCs::ResetNode)),
            (0x0082, Some(NmtCs::ResetCommunication)),
            (0x0000, None),
            (0x0101, None),
        ];
        for (v, cs) in cases {
            let cmd = NmtCommand::from_u16(v).unwrap();
            assert_eq!(cmd as u16, v);
            assert_eq!(cmd.specifier(), cs, "{v:#06x}");
        }
        assert_eq!(NmtCommand::from_u16(0x0003), None);
    }

    fn drain(q: &mut ActionQueue) -> Vec<Action> {
        core::iter::from_fn(|| q.pop()).collect()
    }

    #[test]
    fn a_state_change_is_the_change_then_its_event() {
        let mut q = ActionQueue::new();
        queue_state(&mut q, NmtState::PreOperational, NmtState::Operational);
        assert_eq!(
            drain(&mut q),
            [
                Action::Do(Internal::EnterState(NmtState::Operational)),
                Action::Emit(Event::Nmt(NmtEvent::EnterOperational)),
            ]
        );
        queue_state(&mut q, NmtState::Stopped, NmtState::Stopped);
        queue_state(&mut q, NmtState::Stopped, NmtState::Initialisation);
        assert!(q.is_empty());
    }

    #[test]
    fn reset_node_restores_the_application_first() {
        let mut q = ActionQueue::new();
        queue_reset(&mut q, true);
        let node = drain(&mut q);
        queue_reset(&mut q, false);
        let comm = drain(&mut q);
        assert_eq!(
            node.get(..3).unwrap(),
            [
                Action::Do(Internal::EnterState(NmtState::Initialisation)),
                Action::Do(Internal::RestoreApplication),
                Action::Emit(Event::Nmt(NmtEvent::ResetNode)),
            ]
        );
        // Reset communication is the rest of reset node.
        assert_eq!(node.get(3..).unwrap(), comm.get(1..).unwrap());
        assert_eq!(
            comm.last(),
            Some(&Action::Emit(Event::Nmt(NmtEvent::PostResetCommunication)))
        );
        assert_eq!(
            Transition::of(NmtCs::ResetNode),
            Transition::Reset { node: true }
        );
        assert_eq!(
            Transition::of(NmtCs::Stop),
            Transition::Enter(NmtState::Stopped)
        );
    }
}
