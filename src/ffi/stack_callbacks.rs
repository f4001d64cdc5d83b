//! OBD callbacks of the stack that the application's objdict.h names
//! (`SrdoCbConfig`, `HbpCbConfigHeartbeat`, ...). The table stores their
//! addresses, so they must exist; the protocol modules follow their objects
//! through the dictionary's write hooks instead, so these functions only
//! acknowledge.

use super::types::tCopKernel;
use crate::od::table::ObdCbParam;

macro_rules! stack_callbacks {
    ($($name:ident),* $(,)?) => {
        $(
            #[doc = concat!("`", stringify!($name), "`: accepts every event (the module acts through the dictionary hooks).")]
            ///
            /// # Safety
            /// Called by the stack with a valid parameter block.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn $name(
                #[cfg(multi_instance)]
                #[allow(unused_variables)]
                InstanceHandle: super::types::tCopInstanceHdl,
                pParam_p: *mut ObdCbParam,
            ) -> tCopKernel {
                let _ = pParam_p;
                0
            }
        )*
    };
}

stack_callbacks!(
    SrdoCbConfig,
    SrdoCbConfigMapp,
    SdosCbConfigServer,
    SdocCbConfigClient,
    PdoCbConfigCommu,
    PdoCbConfigMapp,
    PdoCbCfgSyncId,
    PdoCbCfgSyncCycle,
    PdoCbCfgSyncWindow,
    EmcpCbPreDefinedErrorField,
    EmcpCbConfigEmergencyId,
    NmtsCbConfigLifeGuarding,
    HbcCbConfigHeartbeat,
    HbpCbConfigHeartbeat,
    CcmCbStore,
    CcmCbRestore,
);
