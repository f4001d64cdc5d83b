//! SDO server (placeholder interface; the protocol is implemented in this file).

use crate::od::{ObjectDictionary, WriteHooks};
use crate::port::{CanFrame, CanId, Ticks};

/// The SDO server of object 0x1200.
#[derive(Clone, Debug, Default)]
pub struct SdoServer {
    rx: Option<CanId>,
    tx: Option<CanId>,
}

impl SdoServer {
    /// An unconfigured server.
    pub const fn new() -> Self {
        SdoServer { rx: None, tx: None }
    }

    /// Reads 0x1200 (or uses the predefined connection set 0x600/0x580 +
    /// node-ID when the object is absent).
    pub fn reconfigure(&mut self, od: &ObjectDictionary, node: u8) {
        let _ = od;
        self.rx = CanId::std(0x600 + u16::from(node));
        self.tx = CanId::std(0x580 + u16::from(node));
    }

    /// COB-ID of requests (client to server).
    pub fn rx_id(&self) -> Option<CanId> {
        self.rx
    }

    /// Handles a request; returns the response to send.
    pub fn on_frame(
        &mut self,
        od: &ObjectDictionary,
        hooks: &mut impl WriteHooks,
        frame: &CanFrame,
        now: Ticks,
    ) -> Option<CanFrame> {
        let _ = (od, hooks, frame, now);
        None
    }

    /// Timeout supervision; returns an abort frame when a transfer timed out.
    pub fn poll(&mut self, now: Ticks) -> Option<CanFrame> {
        let _ = now;
        None
    }

    /// Drops a running transfer without answering (NMT stopped or reset).
    pub fn cancel(&mut self) {}
}
