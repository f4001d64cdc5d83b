//! Network management: the NMT slave's commands (SYS TEC NMTS), the NMT
//! master (NMTM) with node guarding of its slaves, the life guarding
//! slave (LGS), which watches the master's guard requests, the error
//! behaviour (0x1029), the state a communication error leads to, and the
//! LSS slave (LSSS, CiA 305), which lets a master set the node-ID.
//!
//! The slave's state machine is driven by the stack ([`crate::ccm`]): it
//! decodes NMT commands into the transitions of [`slave`] and runs them in
//! order through its action queue.

pub mod error_behaviour;
pub mod lifeguard;
pub mod lss;
pub mod master;
pub mod slave;

pub use lifeguard::LifeGuardSlave;
pub use master::NmtMaster;
pub use slave::NmtCommand;

/// Where the supervision of a cyclic message stands (the heartbeat
/// consumer's per producer, the life guarding slave's of its master's guard
/// requests).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum Supervision {
    /// Nothing received since the start or the last reset: not supervised
    /// yet.
    #[default]
    Waiting,
    /// The messages arrive in time.
    Active,
    /// The time passed without one; reported once.
    Lost,
}
