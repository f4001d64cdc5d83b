//! Emergency (CiA 301 7.2.7): the producer of this node with the error
//! register and the pre-defined error field (SYS TEC EMCP, objects 0x1001,
//! 0x1003, 0x1014, 0x1015) and the consumer of other nodes' emergencies
//! (EMCC). The frame layout is in [`crate::wire::emcy`].

pub mod consumer;
pub mod producer;

pub use consumer::EmcyConsumer;
pub use producer::EmcyProducer;
