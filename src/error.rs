//! Result codes of the SYS TEC API (`tCopKernel`, errordef.h) and CiA 301 SDO
//! abort codes (sdoac.h). The numbers are part of the C ABI and never change
//! meaning; the Rust core uses these enums directly and the ffi layer passes
//! them through as 32-bit integers.

c_enum! {
    /// `tCopKernel`: every value of the SYS TEC errordef.h.
    #[allow(missing_docs)]
    pub enum CopKernel: u32, fn from_code(u32) {
        Successful = 0x0000,
        IllegalInstance = 0x0001,
        InvalidInstanceParam = 0x0002,
        NoFreeInstance = 0x0003,
        WrongSignature = 0x0004,
        UnsupportedBtrTable = 0x0005,
        UnsupportedBtrIndex = 0x0006,
        InvalidNodeId = 0x0007,
        NoResource = 0x0008,
        InvalidParam = 0x0009,
        CdrvNoMsg = 0x0010,
        CdrvMsgHigh = 0x0011,
        CdrvMsgLow = 0x0012,
        CdrvInitError = 0x0013,
        CdrvNoFreeChannel = 0x0014,
        CdrvTxBuffHighOverrun = 0x0015,
        CdrvTxBuffLowOverrun = 0x0016,
        CdrvIllegalBdi = 0x0017,
        CdrvBusy = 0x0018,
        CdrvInvalidDriverType = 0x0019,
        CdrvDriverNotFound = 0x001A,
        CdrvInvalidBaseAddress = 0x001B,
        CdrvInvalidParam = 0x001C,
        CdrvInvalidDevNumber = 0x001D,
        CdrvDevAlreadyInUse = 0x001E,
        CdrvHostOsError = 0x001F,
        CobNoFreeEntry = 0x0020,
        CobAlreadyExist = 0x0021,
        CobIllegalHdl = 0x0022,
        CobIllegalCanId = 0x0023,
        CobInvalidCanId = 0x0024,
        CobCdrvStateSet = 0x0025,
        CobNoFreeEntryHighBuf = 0x0026,
        CobOwnId = 0x0027,
        CobWrongCobType = 0x0028,
        ObdIllegalPart = 0x0030,
        ObdIndexNotExist = 0x0031,
        ObdSubindexNotExist = 0x0032,
        ObdReadViolation = 0x0033,
        ObdWriteViolation = 0x0034,
        ObdAccessViolation = 0x0035,
        ObdUnknownObjectType = 0x0036,
        ObdVarEntryNotExist = 0x0037,
        ObdValueToLow = 0x0038,
        ObdValueToHigh = 0x0039,
        ObdValueLengthError = 0x003A,
        ObdIllegalFloat = 0x003B,
        ObdWrongOdBuilderKey = 0x003F,
        NmtUnknownCommand = 0x0040,
        NmtLifeguardVsHeartbeat = 0x0041,
        NmtBootupNotPossible = 0x0042,
        NmtHbcWrongCfg = 0x0043,
        NmtmSlaveNodeExist = 0x0044,
        NmtmNoFreeSlaveEntry = 0x0045,
        NmtmSlaveEntryNotExist = 0x0046,
        NmtStateError = 0x0047,
        NmtmInvalidSlaveNodeId = 0x0048,
        SdocInitError = 0x0050,
        SdocInvalidParam = 0x0051,
        SdocClientNotExist = 0x0052,
        SdocBusy = 0x0053,
        SdocTransferError = 0x0054,
        SdocWrongMultiplexor = 0x0055,
        SdocEntryAlreadyDefined = 0x0056,
        SdocNoFreeEntry = 0x0057,
        SdocConfigOrder = 0x0058,
        SdosInitError = 0x0060,
        SdosServerNotExist = 0x0061,
        SdosBusy = 0x0062,
        SdosSizeMismatch = 0x0063,
        SdosNoFreeEntry = 0x0064,
        SdosEntryAlreadyDefined = 0x0065,
        SdosConfigOrder = 0x0066,
        SdosWrongDlc = 0x0067,
        SdosWrongCcs = 0x0068,
        PdoNotExist = 0x0070,
        PdoLengthExceeded = 0x0071,
        PdoGranularityMismatch = 0x0072,
        PdoInitError = 0x0073,
        PdoErrorPdoEncode = 0x0074,
        PdoErrorPdoDecode = 0x0075,
        PdoErrorSend = 0x0076,
        PdoErrorSyncWin = 0x0077,
        PdoErrorMapp = 0x0078,
        PdoVarNotFound = 0x0079,
        PdoErrorEmcyPdoLen = 0x007A,
        PdoWriteConstObject = 0x007B,
        PdoErrorRxEventTimer = 0x007C,
        LsssResetNode = 0x0080,
        LsssInvalidNodeId = 0x0081,
        EmccNoFreeProducerEntry = 0x0090,
        EmccNodeIdNotExist = 0x0091,
        EmccNodeIdInvalid = 0x0092,
        EmccNodeIdExist = 0x0093,
        DynNoMemory = 0x00A0,
        DynInvalidConfig = 0x00A1,
        HbcEntryNotExist = 0x00B0,
        HbcEntryAlreadyExist = 0x00B1,
        HbcNoFreeEntry = 0x00B2,
        CfgMaConfigError = 0x00C0,
        CfgMaSdocTimeOut = 0x00C1,
        CfgMaNoErrorCb = 0x00C2,
        CfgMaNoFreeConfig = 0x00C3,
        CfgMaNoConfigData = 0x00C4,
        CfgMaInvaildSdoc = 0x00C5,
        CfgMaConfigwithErrors = 0x00C6,
        LssmIllegalMode = 0x00D0,
        LssmIllegalState = 0x00D1,
        LssmBusy = 0x00D2,
        LssmIllegalCmd = 0x00D3,
        LssmTimeout = 0x00D4,
        LssmErrorInConfirm = 0x00D5,
        CcmStoreUnvalidState = 0x00E0,
        CcmStoreHwError = 0x00E1,
        SrdoNotExist = 0x0100,
        SrdoGranularityMismatch = 0x0101,
        SrdoCfgTimingError = 0x0102,
        SrdoCfgIdError = 0x0103,
        SrdoCfgCrcError = 0x0104,
        SrdoNmtError = 0x0105,
        SrdoInvalidCfg = 0x0106,
        SrdoInvalid = 0x0107,
        SrdoRxTxConflict = 0x0108,
        SrdoIllegalCanId = 0x0109,
        SrdoCanIdAlreadyInUse = 0x010A,
        SrdoNotInOrder = 0x010B,
        SrdoSctTimeout = 0x010C,
        SrdoSrvtTimeout = 0x010D,
        SrdoCanIdNotValid = 0x010E,
        SrdoDlcNotValid = 0x010F,
        SrdoErrorMapp = 0x0110,
        SrdoDataError = 0x0111,
        SrdoLengthExceeded = 0x0112,
        SrdoNotHandledInApp = 0x0113,
        SrdoOverrun = 0x0114,
        SdomBusy = 0x0121,
        SdomInternStructFull = 0x0122,
        SdomErrorCbInternError = 0x0123,
        SdomErrorCbCopError = 0x0124,
        SrdBusy = 0x0130,
        SrdNotRegistered = 0x0131,
        SrdNoAnswerSdom = 0x0132,
        SrdNotMasterMode = 0x0133,
        SrdNotDynConnection = 0x0134,
        SrdSdomNotUndefSdoc = 0x0135,
        MgrTaskDeferred = 0x0140,
        MgrInvalidOperation = 0x0141,
        MgrInvalidParam = 0x0142,
        MgrNoFreeEntry = 0x0144,
        MgrNodeBusy = 0x0145,
        MgrSdocTypeAutoRunning = 0x0146,
        UserSdoAbort = 0x0800,
    }
}

impl CopKernel {
    /// True for `kCopSuccessful`.
    pub const fn is_ok(self) -> bool {
        matches!(self, CopKernel::Successful)
    }
}

/// Result type of the core: `Err` carries a SYS TEC code.
pub type CopResult<T = ()> = Result<T, CopKernel>;

/// Result of a dictionary access: `Err` says why it was refused.
pub type OdResult<T = ()> = Result<T, OdError>;

/// Converts a `CopResult<()>` into the code the C API returns.
pub fn to_code(r: CopResult) -> u32 {
    match r {
        Ok(()) => CopKernel::Successful.code(),
        Err(e) => e.code(),
    }
}

c_enum! {
    /// CiA 301 SDO abort codes (sdoac.h names in the comments).
    #[allow(missing_docs)]
    pub enum SdoAbort: u32, fn from_code(u32) {
        /// SDOAC_TOGGEL_BIT_ERROR
        ToggleBit = 0x0503_0000,
        /// SDOAC_TIME_OUT
        Timeout = 0x0504_0000,
        /// SDOAC_UNKNOWN_COMMAND_SPECIFIER
        UnknownCommand = 0x0504_0001,
        InvalidBlockSize = 0x0504_0002,
        InvalidSequenceNumber = 0x0504_0003,
        CrcError = 0x0504_0004,
        OutOfMemory = 0x0504_0005,
        /// SDOAC_UNSUPPORTED_ACCESS
        UnsupportedAccess = 0x0601_0000,
        /// SDOAC_READ_TO_WRITE_ONLY_OBJ
        ReadWriteOnly = 0x0601_0001,
        /// SDOAC_WRITE_TO_READ_ONLY_OBJ
        WriteReadOnly = 0x0601_0002,
        /// SDOAC_OBJECT_NOT_EXIST
        ObjectNotExist = 0x0602_0000,
        /// SDOAC_OBJECT_NOT_MAPPABLE
        NotMappable = 0x0604_0041,
        PdoLengthExceeded = 0x0604_0042,
        ParamIncompatible = 0x0604_0043,
        InternalIncompatible = 0x0604_0047,
        HardwareError = 0x0606_0000,
        /// SDOAC_DATA_TYPE_LENGTH_NOT_MATCH
        LengthMismatch = 0x0607_0010,
        /// SDOAC_DATA_TYPE_LENGTH_TOO_HIGH
        LengthTooHigh = 0x0607_0012,
        /// SDOAC_DATA_TYPE_LENGTH_TOO_LOW
        LengthTooLow = 0x0607_0013,
        /// SDOAC_SUB_INDEX_NOT_EXIST
        SubindexNotExist = 0x0609_0011,
        /// SDOAC_VALUE_RANGE_EXCEEDED
        ValueRange = 0x0609_0030,
        /// SDOAC_VALUE_RANGE_TOO_HIGH
        ValueTooHigh = 0x0609_0031,
        /// SDOAC_VALUE_RANGE_TOO_LOW
        ValueTooLow = 0x0609_0032,
        MaxLessMin = 0x0609_0036,
        ResourceNotAvailable = 0x060A_0023,
        /// SDOAC_GENERAL_ERROR
        General = 0x0800_0000,
        /// SDOAC_DATA_NOT_TRANSF_OR_STORED
        CannotStore = 0x0800_0020,
        /// SDOAC_DATA_NOT_TRANSF_DUE_LOCAL_CONTROL
        LocalControl = 0x0800_0021,
        /// SDOAC_DATA_NOT_TRANSF_DUE_DEVICE_STATE
        DeviceState = 0x0800_0022,
        NoObjectDictionary = 0x0800_0023,
    }
}

/// Why an object dictionary access was refused: the code the C API returns
/// and the abort code an SDO transfer sends, decided in one place.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OdError {
    /// Returned by `CcmReadObject` / `CcmWriteObject` and the Rust API.
    pub kernel: CopKernel,
    /// Sent by the SDO server; an application callback may override it.
    pub abort: u32,
}

impl OdError {
    /// Pairs a kernel code with an abort code.
    pub const fn new(kernel: CopKernel, abort: SdoAbort) -> Self {
        OdError {
            kernel,
            abort: abort.code(),
        }
    }
    /// Index does not exist.
    pub const INDEX: OdError = OdError::new(CopKernel::ObdIndexNotExist, SdoAbort::ObjectNotExist);
    /// Subindex does not exist.
    pub const SUBINDEX: OdError =
        OdError::new(CopKernel::ObdSubindexNotExist, SdoAbort::SubindexNotExist);
    /// Read of a write-only object.
    pub const READ: OdError = OdError::new(CopKernel::ObdReadViolation, SdoAbort::ReadWriteOnly);
    /// Write of a read-only or constant object.
    pub const WRITE: OdError = OdError::new(CopKernel::ObdWriteViolation, SdoAbort::WriteReadOnly);
    /// Length does not match the data type.
    pub const LENGTH: OdError =
        OdError::new(CopKernel::ObdValueLengthError, SdoAbort::LengthMismatch);
    /// Data longer than the object.
    pub const TOO_LONG: OdError =
        OdError::new(CopKernel::ObdValueLengthError, SdoAbort::LengthTooHigh);
    /// Data shorter than the object.
    pub const TOO_SHORT: OdError =
        OdError::new(CopKernel::ObdValueLengthError, SdoAbort::LengthTooLow);
    /// Value above the object's range.
    pub const TOO_HIGH: OdError = OdError::new(CopKernel::ObdValueToHigh, SdoAbort::ValueTooHigh);
    /// Value below the object's range.
    pub const TOO_LOW: OdError = OdError::new(CopKernel::ObdValueToLow, SdoAbort::ValueTooLow);
    /// A value a module's rules refuse for its object (an identifier it
    /// cannot use, a count other than the one allowed): kCopInvalidParam,
    /// SDO abort 0x06090030.
    pub const VALUE_RANGE: OdError = OdError::new(CopKernel::InvalidParam, SdoAbort::ValueRange);
    /// A USERDEF/DOMAIN object whose variable the application has not defined.
    pub const NO_VAR: OdError = OdError::new(
        CopKernel::ObdVarEntryNotExist,
        SdoAbort::ResourceNotAvailable,
    );
}

impl From<OdError> for CopKernel {
    fn from(e: OdError) -> Self {
        e.kernel
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_match_errordef_h() {
        // Spot checks against SYSTEC_API.md section 2 (errordef.h).
        assert_eq!(CopKernel::Successful.code(), 0x0000);
        assert_eq!(CopKernel::ObdIndexNotExist.code(), 0x0031);
        assert_eq!(CopKernel::PdoErrorMapp.code(), 0x0078);
        assert_eq!(CopKernel::DynNoMemory.code(), 0x00A0);
        assert_eq!(CopKernel::DynInvalidConfig.code(), 0x00A1);
        assert_eq!(CopKernel::SrdoNotExist.code(), 0x0100);
        assert_eq!(CopKernel::SrdoLengthExceeded.code(), 0x0112);
        assert_eq!(CopKernel::SrdoOverrun.code(), 0x0114);
        assert_eq!(CopKernel::UserSdoAbort.code(), 0x0800);
    }

    #[test]
    fn abort_codes_match_cia301() {
        assert_eq!(SdoAbort::ToggleBit.code(), 0x0503_0000);
        assert_eq!(SdoAbort::WriteReadOnly.code(), 0x0601_0002);
        assert_eq!(SdoAbort::SubindexNotExist.code(), 0x0609_0011);
        assert_eq!(SdoAbort::DeviceState.code(), 0x0800_0022);
        assert_eq!(
            SdoAbort::from_code(0x0602_0000),
            Some(SdoAbort::ObjectNotExist)
        );
        assert_eq!(SdoAbort::from_code(0x1234_5678), None);
    }
}
