//! The stack's side of the dynamic OD (SYS TEC CcmDyn): the dictionary
//! decides what a container does ([`crate::od::dynamic`]) and lays the
//! tables out in its pool ([`DynPool`]); the stack applies the result
//! through [`Target`]: its dictionary write path, its PDO module's pooled
//! channels and the reconfiguration of its modules.

use core::sync::atomic::AtomicU8;

use super::Stack;
use crate::error::{CopKernel, CopResult};
use crate::od::dynamic::{BuildInfo, DynPool, Installed, Target};
use crate::od::{ByteOrder, ObdEntry, ObjectDictionary};
use crate::pdo::{RxChannel, TxChannel};
use crate::port::{CanPort, Ticks};

impl Target for Stack {
    type RxChannel = RxChannel;
    type TxChannel = TxChannel;

    fn new_rx_channel() -> RxChannel {
        RxChannel::new()
    }

    fn new_tx_channel() -> TxChannel {
        TxChannel::new()
    }

    fn od(&self) -> &ObjectDictionary {
        Stack::od(self)
    }

    fn od_mut(&mut self) -> &mut ObjectDictionary {
        Stack::od_mut(self)
    }

    fn write(&mut self, at: (u16, u8), order: ByteOrder, data: &[u8], now: Ticks) -> CopResult {
        let (index, sub) = at;
        self.write_object(index, sub, order, data, now)
            .map_err(|e| e.kernel)
    }

    fn dynamic_od(&self) -> Option<&Installed> {
        Stack::dynamic_od(self)
    }

    fn set_dynamic_od(&mut self, d: Option<Installed>) {
        Stack::set_dynamic_od(self, d);
    }

    fn attach_pooled(
        &mut self,
        rx: Option<&'static mut [RxChannel]>,
        tx: Option<&'static mut [TxChannel]>,
    ) {
        self.pdo_mut().attach_pooled(rx, tx);
    }

    fn detach_pooled(&mut self, port: &mut impl CanPort) {
        self.pdo_mut().detach_pooled(port);
    }

    fn reload_configuration(&mut self, port: &mut impl CanPort, now: Ticks) {
        Stack::reload_configuration(self, port, now);
    }

    fn destroy_dynamic_od(
        &mut self,
        original_user: &'static [ObdEntry],
        port: &mut impl CanPort,
        now: Ticks,
    ) {
        Stack::destroy_dynamic_od(self, original_user, port, now);
    }
}

impl<const N: usize> DynPool<N> {
    /// `DynBuildOd` for Rust: applies `container` to `stack` (see
    /// [`crate::od::dynamic`]), with the variables of the process image in
    /// `image` when given. All or nothing: on `Err` the dictionary, the
    /// modules' parameters and the pool are as before.
    ///
    /// Errors: `kCopNoFreeInstance` when `stack` already has a dynamic OD
    /// or the pool is in use; `kCopDynInvalidConfig`, `kCopDynNoMemory`,
    /// `kCopCobIllegalCanId`, `kCopCobNoFreeEntry`, `kCopCobAlreadyExist`,
    /// `kCopObdIndexNotExist`, `kCopObdSubindexNotExist`,
    /// `kCopPdoErrorMapp`, or the code of a write the dictionary refused.
    pub fn build(
        &'static self,
        stack: &mut Stack,
        port: &mut impl CanPort,
        now: Ticks,
        container: &[u8],
        image: Option<&'static [AtomicU8]>,
    ) -> Result<BuildInfo, CopKernel> {
        self.build_in(stack, port, now, container, image)
    }

    /// `DynDestroyOd` for Rust: removes the dynamic OD of `stack` and
    /// resets the PDO module as seed manual 5.2 describes
    /// (the sequence is in `Stack::destroy_dynamic_od`), then gives the
    /// pool back. Also without a dynamic OD the PDO module is reset (as the
    /// original does). `kCopIllegalInstance` when the stack's dynamic OD
    /// lives in another pool.
    pub fn destroy(
        &'static self,
        stack: &mut Stack,
        port: &mut impl CanPort,
        now: Ticks,
    ) -> Result<(), CopKernel> {
        self.destroy_in(stack, port, now)
    }

    /// Gives the pool back after the stack that used it is gone (taking the
    /// stack by value makes sure it is).
    pub fn release(&'static self, stack: Stack) {
        // `stack` is dropped when this function returns.
        self.release_owned(stack.dynamic_od());
    }
}
