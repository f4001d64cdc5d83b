//! SDO server and client: CiA 301 SDO protocols.
pub(crate) mod block;
pub mod client;
pub mod server;
pub use client::SdoClient;
pub use server::SdoServer;
