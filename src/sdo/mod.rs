//! SDO server (and, later, client): CiA 301 7.2.4.
pub mod server;
pub use server::SdoServer;
