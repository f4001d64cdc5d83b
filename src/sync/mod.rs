//! SYNC (CiA 301 7.2.5): the producer of this node (SYS TEC SYNC,
//! `CcmConfigSyncProducer`, objects 0x1005 and 0x1006). The consumer
//! belongs to the PDOs it triggers and lives in [`crate::pdo`].

pub mod producer;

pub use producer::SyncProducer;
