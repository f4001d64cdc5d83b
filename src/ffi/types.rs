//! C types shared with the application, in the exact layout of the SYS TEC
//! headers (see include/cop_types.h, which declares the same structures and
//! whose C tests assert the same sizes and offsets).
//!
//! ABI decisions (README "ABI"): `DWORD` is 32 bits on every target,
//! `tFastByte` is a DWORD, `tTime` is a DWORD (ticks of 100 µs), enumerated
//! types inside shared structures have explicit widths, `tObdSize` follows
//! `OBD_SUPPORTED_OBJ_SIZE`.

use core::ffi::c_void;

use super::instance::app_fn;
pub use super::instance::{tCopInstanceHdl, tCopPtrInstance};

/// Compile-time checks of a C structure's field offsets against the
/// layout of the SYS TEC header (`assert_offsets!(tFoo { m_bField: 4 })`).
macro_rules! assert_offsets {
    ($t:ty { $($field:ident: $offset:expr),+ $(,)? }) => {
        $(static_assertions::const_assert_eq!(core::mem::offset_of!($t, $field), $offset);)+
    };
}
pub(crate) use assert_offsets;

/// `BYTE`.
pub type BYTE = u8;
/// `QWORD` (64 bits).
pub type QWORD = u64;
/// `WORD`.
pub type WORD = u16;
/// `DWORD` (32 bits everywhere).
pub type DWORD = u32;
/// `BOOL`.
pub type BOOL = u8;
/// `tCopKernel` (returned as a 32-bit integer).
pub type tCopKernel = u32;
/// `tFastByte` (a DWORD).
pub type tFastByte = u32;
/// `tTime` (a DWORD of 100 µs ticks).
pub type tTime = u32;
/// `tNmtEvent`.
pub type tNmtEvent = tFastByte;
/// `tNmtCommand`.
pub type tNmtCommand = WORD;
/// `tProgMonEvent`.
pub type tProgMonEvent = tFastByte;
/// `tCcmInitCall`.
pub type tCcmInitCall = tFastByte;
/// `tObdSize`.
pub type tObdSize = crate::od::ObdSize;
pub use crate::od::table::obd_size_len;
/// `tCanId`: WORD for CAN 2.0A, DWORD for CAN 2.0B (`CDRV_CAN_SPEC`).
#[cfg(not(cdrv_can20b))]
pub type tCanId = WORD;
/// `tCanId`: WORD for CAN 2.0A, DWORD for CAN 2.0B (`CDRV_CAN_SPEC`).
#[cfg(cdrv_can20b)]
pub type tCanId = DWORD;

/// `tCobHdl`: WORD with `COB_MORE_THAN_128_ENTRIES`, else BYTE (cob.h).
#[cfg(cob_hdl_word)]
pub type tCobHdl = WORD;
/// `tCobHdl`: WORD with `COB_MORE_THAN_128_ENTRIES`, else BYTE (cob.h).
#[cfg(not(cob_hdl_word))]
pub type tCobHdl = BYTE;
/// Table bit of a `tCobHdl` (`kCobHdlTxTable`); the index is below it.
#[cfg(cob_hdl_word)]
pub const COB_HDL_TX_TABLE: tCobHdl = 0x8000;
/// Table bit of a `tCobHdl` (`kCobHdlTxTable`); the index is below it.
#[cfg(not(cob_hdl_word))]
pub const COB_HDL_TX_TABLE: tCobHdl = 0x80;

/// `tCobParam` (cob.h): one communication object.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tCobParam {
    /// CAN identifier.
    pub m_CobId: tCanId,
    /// `tCobType`.
    pub m_bCobType: BYTE,
    /// Frame length.
    pub m_bSize: BYTE,
    /// `tCobCallback` of the entry.
    pub m_fpCallback:
        Option<unsafe extern "C" fn(pArg_p: *mut c_void, Event_p: tFastByte) -> tCopKernel>,
    /// Argument of the callback.
    pub m_pArg: *mut c_void,
    /// Handle: selects the entry.
    pub m_CobHdl: tCobHdl,
    /// Frame data.
    pub m_pbData: *mut BYTE,
    /// Where the received length is kept.
    pub m_pbRecvdSize: *mut BYTE,
}

/// Message type bits (`tMsgTypBit`).
pub mod msg_type {
    /// kMtbRecv.
    pub const RECV: u8 = 0x01;
    /// kMtbRtr.
    pub const RTR: u8 = 0x02;
    /// kMtbHighPrio.
    pub const HIGH_PRIO: u8 = 0x40;
    /// kMtbExtend (29-bit identifier).
    pub const EXTEND: u8 = 0x80;
}

/// Driver status bits (`tCdrvStatus`) the stack evaluates.
pub mod cdrv_status {
    /// kCdrvBusOff.
    pub const BUS_OFF: u16 = 0x0010;
    /// kCdrvOverrun.
    pub const OVERRUN: u16 = 0x0020;
    /// kCdrvRxBuffHighOverrun.
    pub const RX_BUFF_HIGH_OVERRUN: u16 = 0x0400;
    /// kCdrvRxBuffLowOverrun.
    pub const RX_BUFF_LOW_OVERRUN: u16 = 0x1000;
}

/// `tCdrvMsg`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tCdrvMsg {
    /// Identifier.
    pub m_CanId: tCanId,
    /// `tMsgTyp`.
    pub m_MsgType: BYTE,
    /// DLC.
    pub m_bSize: BYTE,
    /// Channel.
    pub m_bChannel_p: BYTE,
    /// Data.
    pub m_bData: [BYTE; 8],
    /// Receive time (ticks), with `CDRV_TIMESTAMP` only.
    #[cfg(cdrv_timestamp)]
    pub m_Time: tTime,
}

/// `tCdrvHwParam`: a union of controller-specific structures; the C
/// header makes it exactly two pointers wide.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tCdrvHwParam {
    /// The union's storage (passed through to the driver untouched).
    pub m_apvRaw: [*mut c_void; 2],
}

/// `tCdrvEnableInt`.
pub type tCdrvEnableInt = Option<unsafe extern "C" fn(bEnable_p: BYTE)>;

/// `tCdrvBuffInit`.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tCdrvBuffInit {
    /// Buffer base.
    pub m_pBufferBase: *mut tCdrvMsg,
    /// Number of entries (`tCdrvBuffIndex`, a WORD on 16/32-bit targets).
    pub m_MaxEntries: WORD,
}

/// `tCdrvInitParam` (high-priority buffers always present).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tCdrvInitParam {
    /// Bit rate index (`tCdrvBaudIndex`, one byte).
    pub m_BaudIndex: BYTE,
    /// Bit rate table.
    pub m_pBdiTable: *const c_void,
    /// Size of the table.
    pub m_wSizeOfBdiTab: WORD,
    /// Acceptance mask.
    pub m_dwAmr: DWORD,
    /// Acceptance code.
    pub m_dwAcr: DWORD,
    /// Controller parameters.
    pub m_HwParam: tCdrvHwParam,
    /// High-priority receive buffer.
    pub m_RxBuffHigh: tCdrvBuffInit,
    /// High-priority transmit buffer.
    pub m_TxBuffHigh: tCdrvBuffInit,
    /// Receive buffer.
    pub m_RxBuffLow: tCdrvBuffInit,
    /// Transmit buffer.
    pub m_TxBuffLow: tCdrvBuffInit,
    /// Interrupt enable function.
    pub m_fpEnableInterrupt: tCdrvEnableInt,
}

/// `tCcmNmtEventCallback`.
pub type tCcmNmtEventCallback = app_fn!(fn(tNmtEvent) -> tCopKernel);
/// `tObdInitRam`.
pub type tObdInitRam = Option<unsafe extern "C" fn(pInitParam_p: *mut c_void) -> tCopKernel>;
/// `tCcmErrorCallback`.
pub type tCcmErrorCallback = app_fn!(fn(*mut c_void, tCopKernel) -> tCopKernel);

/// `tNmtErrCtrlEvent`.
pub type tNmtErrCtrlEvent = tFastByte;
/// `tAppNmtmEventCallback`.
pub type tAppNmtmEventCallback = app_fn!(fn(BYTE, tNmtErrCtrlEvent) -> tCopKernel);
/// `tAppHbcEventCallback`.
pub type tAppHbcEventCallback = app_fn!(fn(BYTE, tNmtErrCtrlEvent) -> tCopKernel);

/// `tAppEmccEventCallback` (`CcmInitEmccEx`): producer node-ID and the
/// received emergency.
pub type tAppEmccEventCallback = app_fn!(fn(BYTE, *mut tEmcParam) -> tCopKernel);

/// `tPdoCallback`: called with the communication
/// index after an RPDO's data reached its variables or after a TPDO was
/// sent.
pub type tPdoCallback = app_fn!(fn(WORD) -> tCopKernel);

/// `tObdPart`: `kObdPart*` bits.
pub type tObdPart = tFastByte;

/// `tTimeOfDay` (`CcmTspSend`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tTimeOfDay {
    /// Milliseconds after midnight.
    pub m_dwMs: DWORD,
    /// Days since 1 January 1984.
    pub m_wDays: WORD,
}

/// `tHbcProdParam` (`CcmHbcDefineProducerTab`; field names as in cop.h).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tHbcProdParam {
    /// Heartbeat time of the producer in ms.
    pub wHeartbeatTime_p: WORD,
    /// Producer node-ID.
    pub bProducerNodeId_p: BYTE,
    /// Subindex of 0x1016 (1..) the entry occupies.
    pub bSubindex_p: BYTE,
}

/// `tNmtmSlaveParam` (`CcmConfigLgm`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tNmtmSlaveParam {
    /// Guard time in ms.
    pub m_wLifeguardTime: WORD,
    /// Life time factor.
    pub m_bLifeguardFactor: BYTE,
}

/// `tNmtmSlaveInfo` (`CcmNmtmGetSlaveInfo`; layout of the vendored SYS TEC
/// `nmtm.h`: three bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tNmtmSlaveInfo {
    /// `tNmtmSlaveState` bits (`kNmtm*`).
    pub m_bSlaveState: BYTE,
    /// Guarding answers missed in a row.
    pub m_bLostMsgCount: BYTE,
    /// NMT state the slave reported (kNodeState*), 0 = boot-up or unknown.
    pub m_bSlaveNodeState: BYTE,
}

/// `tSdocState`.
pub type tSdocState = tFastByte;
/// `tSdocType`.
pub type tSdocType = tFastByte;

/// `tSdocParam` (`CcmSdocDefineClientTab`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tSdocParam {
    /// Which fields are valid (kSdocValidFlag*).
    pub m_bValidFlags: BYTE,
    /// Timeout in ticks (0 = default).
    pub m_TimeOut: tTime,
    /// Client index (0x1280 + n).
    pub m_wClientIndex: WORD,
    /// COB-ID server -> client.
    pub m_dwRxCanId: DWORD,
    /// COB-ID client -> server.
    pub m_dwTxCanId: DWORD,
    /// Node-ID of the server.
    pub m_bServerNodeId: BYTE,
}

/// `tSdocCbFinishParam`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tSdocCbFinishParam {
    /// Client index.
    pub m_wClientIndex: WORD,
    /// Final state.
    pub m_SdocState: tSdocState,
    /// Abort code (0 when finished).
    pub m_dwAbortCode: DWORD,
}

/// `tSdocCbFinished`.
pub type tSdocCbFinished = app_fn!(fn(*mut tSdocCbFinishParam));

/// `tSdocTransferParam` (`CcmSdocStartTransfer`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tSdocTransferParam {
    /// Client index.
    pub m_wClientIndex: WORD,
    /// Remote object index.
    pub m_wObjIndex: WORD,
    /// Remote subindex.
    pub m_bObjSubIndex: BYTE,
    /// Data to send / buffer to fill.
    pub m_pData: *mut c_void,
    /// Bytes to send / buffer size.
    pub m_DataLen: tObdSize,
    /// Timeout in ticks (0 = the client's).
    pub m_TimeOut: tTime,
    /// kSdocTypeSegDown / kSdocTypeSegUp (block types are refused).
    pub m_SdocType: tSdocType,
    /// Called when the transfer ends (may be NULL: poll CcmSdocGetState).
    pub m_pfnCbFinished: tSdocCbFinished,
}

/// `tCcmInitParam` (single instance, `COP_USE_CDRV_FUNCTION_POINTER` off).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tCcmInitParam {
    /// Node-ID.
    pub m_bInitNodeId: BYTE,
    /// Bit rate index (one byte).
    pub m_BaudIndex: BYTE,
    /// Bit rate table.
    pub m_pBdiTable: *const c_void,
    /// Size of the table.
    pub m_wSizeOfBdiTab: WORD,
    /// Acceptance mask.
    pub m_dwAmr: DWORD,
    /// Acceptance code.
    pub m_dwAcr: DWORD,
    /// Controller parameters.
    pub m_HwParam: tCdrvHwParam,
    /// Interrupt enable function.
    pub m_fpCanInterruptEnable: tCdrvEnableInt,
    /// NMT callback.
    pub m_fpNmtEventCallback: tCcmNmtEventCallback,
    /// The dictionary's init function (`ObdInitRam` from objdef.h).
    pub m_fpObdInitRam: tObdInitRam,
}

/// `AppSrdoEvent`.
pub type tSrdoEventCallback = app_fn!(fn(WORD) -> tCopKernel);
/// `AppProgMonEvent`.
pub type tProgMonCallback = app_fn!(fn(tProgMonEvent) -> tCopKernel);

/// The application's SRDO callbacks, collected by objdef.h when the
/// dictionary declares SRDO objects (so applications without SRDOs need
/// not define them).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tSrdoAppCallbacks {
    /// `AppSrdoEvent`.
    pub m_fpSrdoEvent: tSrdoEventCallback,
    /// `AppSrdoError`.
    pub m_fpSrdoError: app_fn!(fn(WORD, tCopKernel) -> tCopKernel),
    /// `AppGfcEvent` (NULL when `SRDO_USE_GFC` is FALSE).
    pub m_fpGfcEvent: app_fn!(fn() -> tCopKernel),
    /// `AppProgMonEvent` (NULL when `SRDO_USE_PROGMONITOR` is FALSE).
    pub m_fpProgMonEvent: tProgMonCallback,
}

/// What `ObdInitRam` (generated by objdef.h) hands to the stack. Private
/// between this library and its own objdef.h.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tObdRamParam {
    /// Generic part (0x1000–0x1FFF), ends with index 0xFFFF.
    pub m_pGenericPart: *const crate::od::ObdEntry,
    /// Manufacturer part (0x2000–0x5FFF).
    pub m_pManufacturerPart: *const crate::od::ObdEntry,
    /// Device part (0x6000–0x9FFF).
    pub m_pDevicePart: *const crate::od::ObdEntry,
    /// User part (may be NULL).
    pub m_pUserPart: *const crate::od::ObdEntry,
    /// Address of the configuration signature the application was built
    /// against (see include/cop_config.h).
    pub m_pbAbiSignature: *const BYTE,
    /// SRDO callbacks (NULL without SRDO objects).
    pub m_pSrdoCallbacks: *const tSrdoAppCallbacks,
    /// Driver buffers (obdcfg.h `CDRV_MAX_*_BUFF_ENTRIES_*`).
    pub m_RxBuffHigh: tCdrvBuffInit,
    /// See `m_RxBuffHigh`.
    pub m_TxBuffHigh: tCdrvBuffInit,
    /// See `m_RxBuffHigh`.
    pub m_RxBuffLow: tCdrvBuffInit,
    /// See `m_RxBuffHigh`.
    pub m_TxBuffLow: tCdrvBuffInit,
    /// `SRDO_MAX_SRDO_IN_OBD` of the application's obdcfg.h.
    pub m_wSrdoCount: WORD,
}

impl tObdRamParam {
    /// An all-NULL parameter block.
    pub const fn zeroed() -> Self {
        let b = tCdrvBuffInit {
            m_pBufferBase: core::ptr::null_mut(),
            m_MaxEntries: 0,
        };
        tObdRamParam {
            m_pGenericPart: core::ptr::null(),
            m_pManufacturerPart: core::ptr::null(),
            m_pDevicePart: core::ptr::null(),
            m_pUserPart: core::ptr::null(),
            m_pbAbiSignature: core::ptr::null(),
            m_pSrdoCallbacks: core::ptr::null(),
            m_RxBuffHigh: b,
            m_TxBuffHigh: b,
            m_RxBuffLow: b,
            m_TxBuffLow: b,
            m_wSrdoCount: 0,
        }
    }
}

/// `tSrdoTabParam` (manual 2.11.1); the table entries are private to the
/// library, the pointer is kept opaque.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tSrdoTabParam {
    /// `tSrdoTabEntry MEM*` (opaque).
    pub m_pSrdoTable: *mut c_void,
    /// `tSrdoIndex` (a BYTE): number of entries.
    pub m_SrdoCount: BYTE,
}

/// `tSrdoInitParam` (single instance, manual 2.11.1).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tSrdoInitParam {
    /// The SRDO table.
    pub m_SrdoTabParam: tSrdoTabParam,
    /// Granularity the application expects (`SRDO_GRANULARITY`).
    pub m_bGranularity: BYTE,
    /// 0x13FE configuration valid.
    pub m_pbSrdoConfigValid: *mut BYTE,
}

/// `tSrdoCommuParam`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tSrdoCommuParam {
    /// Direction (0 invalid, 1 Tx, 2 Rx).
    pub m_bDirection: BYTE,
    /// Refresh time / SCT in ms.
    pub m_wSct: WORD,
}

/// `tSrdoMappParam` (dynamic mapping only).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tSrdoMappParam {
    /// Number of mapped objects.
    pub m_bNoOfMappedObjects: BYTE,
    /// Pointers to the mapped variables.
    pub m_apMappedVariable: [*mut c_void; crate::config::SRDO_MAX_MAPPENTRIES],
}

/// `tVarCallback`.
pub type tVarCallback = app_fn!(fn(*mut c_void) -> tCopKernel);

/// `tVarParam` (`CcmDefineVarTab`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tVarParam {
    /// Which fields are valid (kVarValid*).
    pub m_bValidFlag: BYTE,
    /// Index.
    pub m_wIndex: WORD,
    /// Subindex.
    pub m_bSubindex: BYTE,
    /// Size of the variable.
    pub m_Size: tObdSize,
    /// The variable.
    pub m_pData: *mut c_void,
    /// Callback after a write.
    pub m_fpCallback: tVarCallback,
    /// Callback argument.
    pub m_pArg: *mut c_void,
}

/// `kVarValid*` flags.
pub(crate) mod var_valid {
    /// kVarValidSize.
    pub(crate) const SIZE: u8 = 0x01;
    /// kVarValidData.
    pub(crate) const DATA: u8 = 0x02;
    /// kVarValidCallback.
    pub(crate) const CALLBACK: u8 = 0x04;
    /// kVarValidArg.
    pub(crate) const ARG: u8 = 0x08;
}

/// `tEmcParam`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct tEmcParam {
    /// Emergency error code.
    pub m_wEmcyErrorCode: WORD,
    /// Error register.
    pub m_bErrorRegister: BYTE,
    /// Manufacturer-specific field.
    pub m_abManufactErrorCode: [BYTE; 5],
    /// Additional information.
    pub m_wAdditionalInfo: WORD,
}

// Layout checks. Sizes for a 32-bit target (the product: TMS570) and for a
// 64-bit host (tests) differ only where pointers appear.
static_assertions::const_assert_eq!(core::mem::size_of::<tSrdoCommuParam>(), 4);
static_assertions::const_assert_eq!(core::mem::size_of::<tHbcProdParam>(), 4);
static_assertions::const_assert_eq!(core::mem::size_of::<tSdocParam>(), 24);
static_assertions::const_assert_eq!(core::mem::size_of::<tSdocCbFinishParam>(), 12);
static_assertions::const_assert_eq!(core::mem::size_of::<tNmtmSlaveParam>(), 4);
static_assertions::const_assert_eq!(core::mem::size_of::<tNmtmSlaveInfo>(), 3);
static_assertions::const_assert_eq!(core::mem::size_of::<tEmcParam>(), 10);
static_assertions::const_assert_eq!(core::mem::size_of::<tTimeOfDay>(), 8);
static_assertions::const_assert_eq!(
    core::mem::size_of::<tCdrvHwParam>(),
    2 * core::mem::size_of::<*mut c_void>()
);
#[cfg(all(not(cdrv_can20b), not(cdrv_timestamp)))]
static_assertions::const_assert_eq!(core::mem::size_of::<tCdrvMsg>(), 14);
#[cfg(all(not(cdrv_can20b), cdrv_timestamp))]
static_assertions::const_assert_eq!(core::mem::size_of::<tCdrvMsg>(), 20);
#[cfg(all(cdrv_can20b, not(cdrv_timestamp)))]
static_assertions::const_assert_eq!(core::mem::size_of::<tCdrvMsg>(), 16);
static_assertions::const_assert_eq!(
    core::mem::offset_of!(tCdrvMsg, m_bData),
    5 + if cfg!(cdrv_can20b) { 2 } else { 0 }
);
#[cfg(target_pointer_width = "32")]
static_assertions::const_assert_eq!(core::mem::size_of::<tCcmInitParam>(), 40);
#[cfg(target_pointer_width = "64")]
static_assertions::const_assert_eq!(core::mem::size_of::<tCcmInitParam>(), 72);
#[cfg(target_pointer_width = "32")]
static_assertions::const_assert_eq!(
    core::mem::size_of::<tSrdoMappParam>(),
    4 + 4 * crate::config::SRDO_MAX_MAPPENTRIES
);

/// `tCopStoreDriver` (`cop_types.h`): the application's non-volatile
/// memory for store / restore.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct tCopStoreDriver {
    /// Handed to every function.
    pub m_pArg: *mut c_void,
    /// Usable bytes.
    pub m_dwSize: DWORD,
    /// Write granularity.
    pub m_dwAlign: DWORD,
    /// Configuration key of the images.
    pub m_dwConfigKey: DWORD,
    /// Optional: called by `CcmInitStore`.
    pub m_fpOpen: Option<unsafe extern "C" fn(pArg_p: *mut c_void) -> tCopKernel>,
    /// Reads.
    pub m_fpRead: Option<
        unsafe extern "C" fn(
            pArg_p: *mut c_void,
            dwOffset_p: DWORD,
            pbData_p: *mut BYTE,
            dwSize_p: DWORD,
        ) -> tCopKernel,
    >,
    /// Writes erased memory.
    pub m_fpWrite: Option<
        unsafe extern "C" fn(
            pArg_p: *mut c_void,
            dwOffset_p: DWORD,
            pbData_p: *const BYTE,
            dwSize_p: DWORD,
        ) -> tCopKernel,
    >,
    /// Erases.
    pub m_fpErase: Option<
        unsafe extern "C" fn(pArg_p: *mut c_void, dwOffset_p: DWORD, dwSize_p: DWORD) -> tCopKernel,
    >,
    /// Makes writes durable.
    pub m_fpCommit: Option<unsafe extern "C" fn(pArg_p: *mut c_void) -> tCopKernel>,
}

// tCopStoreDriver: pointer, three DWORDs, five function pointers.
#[cfg(target_pointer_width = "32")]
static_assertions::const_assert_eq!(core::mem::size_of::<tCopStoreDriver>(), 36);
#[cfg(target_pointer_width = "64")]
static_assertions::const_assert_eq!(core::mem::size_of::<tCopStoreDriver>(), 64);
