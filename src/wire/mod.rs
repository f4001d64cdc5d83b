//! Frame layouts of each protocol: pure functions from values to frames and
//! back, without state. Byte layouts cite CiA 301 / CiA 304.

pub mod emcy;
pub mod lss;
pub mod nmt;
pub mod pdo;
pub mod sdo;
pub mod srdo;
pub mod time;
