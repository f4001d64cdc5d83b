//! The node tables of a master application (`CcmDefineSlaveTab`,
//! `CcmEmccDefineProducerTab`), kept by address and read again when they
//! change. Below the registry: it knows the stack and the driver port, not
//! the instances.

use super::driver::CdrvPort;
use super::ptr;
use super::types::BYTE;
use crate::ccm::Stack;

/// The node tables of a master application, kept as the application gave
/// them: `CcmDefineSlaveTab` and `CcmEmccDefineProducerTab` take the
/// address of an application array (`BYTE GENERIC*`) that the SYS TEC
/// master applications fill later, slave by slave, after the call (entries
/// 0 are free). The tables are read again before each `CcmProcess`,
/// `CcmConfigLgm`, `CcmTriggerNodeGuard` and `CcmNmtmGetSlaveInfo`; a table whose
/// used entries changed is defined again (nodes listed before keep their
/// state). A changed table that is refused (an invalid or repeated
/// node-ID, too many entries) leaves the previous list in force and is
/// tried again while it differs.
#[derive(Clone, Copy)]
pub struct AppTables {
    pub(super) slaves: *const BYTE,
    pub(super) slave_count: u8,
    pub(super) producers: *const BYTE,
    pub(super) producer_count: u8,
}

impl Default for AppTables {
    fn default() -> Self {
        AppTables {
            slaves: core::ptr::null(),
            slave_count: 0,
            producers: core::ptr::null(),
            producer_count: 0,
        }
    }
}

impl AppTables {
    /// Defines the tables again whose used entries changed since.
    #[inline(always)]
    pub fn sync(&self, stack: &mut Stack, port: &mut CdrvPort) {
        // Most nodes define neither table: nothing to compare in a cycle.
        if self.slave_count != 0 || self.producer_count != 0 {
            self.compare(stack, port);
        }
    }

    /// [`AppTables::sync`] with a table defined (out of line: the cycle
    /// without tables stays small).
    #[inline(never)]
    fn compare(&self, stack: &mut Stack, port: &mut CdrvPort) {
        let t = *self;
        if t.slave_count != 0 {
            // SAFETY: CcmDefineSlaveTab's contract: the table stays valid
            // for `bNumOfSlaves_p` bytes while it is defined (until the next
            // CcmDefineSlaveTab or CcmShutDownCANopen), as in the original,
            // which keeps the pointer.
            if let Ok(nodes) = unsafe { ptr::slice_or_empty(t.slaves, usize::from(t.slave_count)) }
            {
                if !stack.nmtm().same_slaves(nodes) {
                    let _ = stack.nmtm_mut().define_slaves(nodes);
                }
            }
        }
        if t.producer_count != 0 {
            // SAFETY: CcmEmccDefineProducerTab's contract, as above.
            if let Ok(nodes) =
                unsafe { ptr::slice_or_empty(t.producers, usize::from(t.producer_count)) }
            {
                if !stack.emcc_producers_are(nodes) {
                    let _ = stack.define_emcc_producers(port, nodes);
                }
            }
        }
    }
}
