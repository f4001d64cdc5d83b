//! The RAM the stack's types take on the target, as symbol sizes.
//!
//! Built for `armebv7r-none-eabihf` by `scripts/bench.sh`; each exported
//! array is exactly `size_of` the named type long, so
//! `arm-none-eabi-nm -S` of the archive reads the target's layout (4-byte
//! pointers, ARM alignment) without running anything. Never linked into an
//! application.

#![no_std]

use core::mem::size_of;

macro_rules! sizes {
    ($($name:ident: $t:ty;)*) => {$(
        #[doc = concat!("`size_of::<", stringify!($t), ">()` bytes.")]
        #[unsafe(no_mangle)]
        #[used]
        pub static $name: [u8; size_of::<$t>()] = [0; size_of::<$t>()];
    )*};
}

sizes! {
    COP_SIZEOF_INSTANCE: cop::ffi::global::Instance;
    COP_SIZEOF_STACK: cop::ccm::Stack;
    COP_SIZEOF_SRDO: cop::srdo::Srdo;
    COP_SIZEOF_PDO: cop::pdo::Pdo;
    COP_SIZEOF_SDO_SERVER: cop::sdo::SdoServer;
    COP_SIZEOF_SDO_CLIENT: cop::sdo::SdoClient;
    COP_SIZEOF_ACTION_QUEUE: cop::event::ActionQueue;
    COP_SIZEOF_HBC: cop::heartbeat::HeartbeatConsumer;
    COP_SIZEOF_NMTM: cop::nmt::NmtMaster;
    COP_SIZEOF_EMCY: cop::emcy::EmcyProducer;
    COP_SIZEOF_OD: cop::od::ObjectDictionary;
}
