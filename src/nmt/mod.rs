//! Network management: the NMT slave's commands (SYS TEC NMTS), the NMT
//! master (NMTM) with node guarding of its slaves, and the life guarding
//! slave (LGS), which watches the master's guard requests.
//!
//! The slave's state machine is driven by the stack ([`crate::ccm`]): it
//! decodes NMT commands into the transitions of [`slave`] and runs them in
//! order through its action queue.

pub mod lifeguard;
pub mod master;
pub mod slave;

pub use lifeguard::LifeGuardSlave;
pub use master::NmtMaster;
pub use slave::NmtCommand;
