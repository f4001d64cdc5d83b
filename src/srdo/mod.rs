//! SRDO and GFC (CiA 304 / EN 50325-5; SYS TEC modules SRDO, SRDOSTC,
//! CCMSRDO). Placeholder interface; implemented in this folder.

use crate::error::{CopKernel, CopResult, OdError};
use crate::event::{ActionQueue, NmtState};
use crate::od::{Object, ObjectDictionary, Staged};
use crate::port::{CanPort, RxFrame, Ticks};

/// The SRDO module.
#[derive(Clone, Debug, Default)]
pub struct Srdo {}

impl Srdo {
    /// An empty module.
    pub const fn new() -> Self {
        Srdo {}
    }

    /// Finds the SRDO objects (0x1301.., 0x1381.., 0x13FE, 0x13FF) in the
    /// dictionary when the stack is created.
    pub fn init(&mut self, od: &ObjectDictionary) -> CopResult {
        let _ = od;
        Ok(())
    }

    /// Takes over the configuration after reset communication.
    pub fn reconfigure(&mut self, od: &ObjectDictionary, port: &mut impl CanPort) {
        let _ = (od, port);
    }

    /// Reacts to an NMT state change.
    pub fn on_state(&mut self, od: &ObjectDictionary, state: NmtState, node: u8, now: Ticks) {
        let _ = (od, state, node, now);
    }

    /// Offers a received frame; `true` when it was an SRDO or GFC frame.
    pub fn on_frame(
        &mut self,
        od: &ObjectDictionary,
        state: NmtState,
        frame: &RxFrame,
        q: &mut ActionQueue,
    ) -> bool {
        let _ = (od, state, frame, q);
        false
    }

    /// Timer checks; resumable: returns `true` when this cycle's checks are
    /// complete, `false` when it queued events and wants to be called again.
    pub fn poll(
        &mut self,
        od: &ObjectDictionary,
        state: NmtState,
        now: Ticks,
        q: &mut ActionQueue,
    ) -> bool {
        let _ = (od, state, now, q);
        true
    }

    /// Starts a new processing cycle (resets the resumable timer cursor).
    pub fn begin_cycle(&mut self) {}

    /// The driver lost received frames.
    pub fn on_rx_overrun(&mut self) {}

    /// Internal action after `AppSrdoError` was dispatched.
    pub fn check_handled(&mut self, slot: u8, q: &mut ActionQueue) {
        let _ = (slot, q);
    }

    /// Module hook: may refuse a write to 0x1300..0x13FF.
    pub fn check_write(
        &self,
        od: &ObjectDictionary,
        obj: &Object,
        value: &Staged,
        state: NmtState,
    ) -> Result<(), OdError> {
        let _ = (od, obj, value, state);
        Ok(())
    }

    /// Module hook: the write will happen now.
    pub fn before_store(&mut self, od: &ObjectDictionary, obj: &Object, value: &Staged) {
        let _ = (od, obj, value);
    }

    /// Module hook: the write happened.
    pub fn after_store(&mut self, od: &ObjectDictionary, obj: &Object) {
        let _ = (od, obj);
    }

    /// `CcmSendSrdo` for one SRDO.
    pub fn send(
        &mut self,
        od: &ObjectDictionary,
        port: &mut impl CanPort,
        state: NmtState,
        commu_index: u16,
        now: Ticks,
        q: &mut ActionQueue,
    ) -> CopResult {
        let _ = (od, port, state, commu_index, now, q);
        Err(CopKernel::SrdoNotExist)
    }
}
