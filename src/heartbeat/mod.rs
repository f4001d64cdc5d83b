//! Heartbeat (CiA 301 7.2.8.3.2): the producer of this node (SYS TEC HBP,
//! object 0x1017) and the consumer that supervises other nodes (HBC,
//! object 0x1016).

pub mod consumer;
pub mod producer;

pub use consumer::{CONSUMER_TIME_INDEX, HeartbeatConsumer};
pub use producer::{HeartbeatProducer, PRODUCER_TIME_INDEX};
