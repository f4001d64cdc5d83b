/*
 * test_check.c - the result of a test program and the names of the
 * tCopKernel codes for its messages (test_check.h).
 */
#include "test_check.h"

int iTestFailures_g;

int TestDone (const char* pszName_p)
{
    if (iTestFailures_g != 0)
    {
        printf("%s: %d check(s) FAILED\n", pszName_p, iTestFailures_g);
        return 1;
    }
    printf("%s: all checks passed\n", pszName_p);
    return 0;
}

const char* TestKernelName (tCopKernel Ret_p)
{
    switch (Ret_p)
    {
        case kCopSuccessful: return "kCopSuccessful";
        case kCopIllegalInstance: return "kCopIllegalInstance";
        case kCopInvalidInstanceParam: return "kCopInvalidInstanceParam";
        case kCopNoFreeInstance: return "kCopNoFreeInstance";
        case kCopWrongSignature: return "kCopWrongSignature";
        case kCopUnsupportedBtrTable: return "kCopUnsupportedBtrTable";
        case kCopUnsupportedBtrIndex: return "kCopUnsupportedBtrIndex";
        case kCopInvalidNodeId: return "kCopInvalidNodeId";
        case kCopNoResource: return "kCopNoResource";
        case kCopInvalidParam: return "kCopInvalidParam";
        case kCopCdrvNoMsg: return "kCopCdrvNoMsg";
        case kCopCdrvMsgHigh: return "kCopCdrvMsgHigh";
        case kCopCdrvMsgLow: return "kCopCdrvMsgLow";
        case kCopCdrvInitError: return "kCopCdrvInitError";
        case kCopCdrvNoFreeChannel: return "kCopCdrvNoFreeChannel";
        case kCopCdrvTxBuffHighOverrun: return "kCopCdrvTxBuffHighOverrun";
        case kCopCdrvTxBuffLowOverrun: return "kCopCdrvTxBuffLowOverrun";
        case kCopCdrvIllegalBdi: return "kCopCdrvIllegalBdi";
        case kCopCdrvBusy: return "kCopCdrvBusy";
        case kCopCdrvInvalidDriverType: return "kCopCdrvInvalidDriverType";
        case kCopCdrvDriverNotFound: return "kCopCdrvDriverNotFound";
        case kCopCdrvInvalidBaseAddress: return "kCopCdrvInvalidBaseAddress";
        case kCopCdrvInvalidParam: return "kCopCdrvInvalidParam";
        case kCopCdrvInvalidDevNumber: return "kCopCdrvInvalidDevNumber";
        case kCopCdrvDevAlreadyInUse: return "kCopCdrvDevAlreadyInUse";
        case kCopCdrvHostOsError: return "kCopCdrvHostOsError";
        case kCopCobNoFreeEntry: return "kCopCobNoFreeEntry";
        case kCopCobAlreadyExist: return "kCopCobAlreadyExist";
        case kCopCobIllegalHdl: return "kCopCobIllegalHdl";
        case kCopCobIllegalCanId: return "kCopCobIllegalCanId";
        case kCopCobInvalidCanId: return "kCopCobInvalidCanId";
        case kCopCobCdrvStateSet: return "kCopCobCdrvStateSet";
        case kCopCobNoFreeEntryHighBuf: return "kCopCobNoFreeEntryHighBuf";
        case kCopCobOwnId: return "kCopCobOwnId";
        case kCopCobWrongCobType: return "kCopCobWrongCobType";
        case kCopObdIllegalPart: return "kCopObdIllegalPart";
        case kCopObdIndexNotExist: return "kCopObdIndexNotExist";
        case kCopObdSubindexNotExist: return "kCopObdSubindexNotExist";
        case kCopObdReadViolation: return "kCopObdReadViolation";
        case kCopObdWriteViolation: return "kCopObdWriteViolation";
        case kCopObdAccessViolation: return "kCopObdAccessViolation";
        case kCopObdUnknownObjectType: return "kCopObdUnknownObjectType";
        case kCopObdVarEntryNotExist: return "kCopObdVarEntryNotExist";
        case kCopObdValueToLow: return "kCopObdValueToLow";
        case kCopObdValueToHigh: return "kCopObdValueToHigh";
        case kCopObdValueLengthError: return "kCopObdValueLengthError";
        case kCopObdIllegalFloat: return "kCopObdIllegalFloat";
        case kCopObdWrongOdBuilderKey: return "kCopObdWrongOdBuilderKey";
        case kCopNmtUnknownCommand: return "kCopNmtUnknownCommand";
        case kCopNmtLifeguardVsHeartbeat: return "kCopNmtLifeguardVsHeartbeat";
        case kCopNmtBootupNotPossible: return "kCopNmtBootupNotPossible";
        case kCopNmtHbcWrongCfg: return "kCopNmtHbcWrongCfg";
        case kCopNmtmSlaveNodeExist: return "kCopNmtmSlaveNodeExist";
        case kCopNmtmNoFreeSlaveEntry: return "kCopNmtmNoFreeSlaveEntry";
        case kCopNmtmSlaveEntryNotExist: return "kCopNmtmSlaveEntryNotExist";
        case kCopNmtStateError: return "kCopNmtStateError";
        case kCopNmtmInvalidSlaveNodeId: return "kCopNmtmInvalidSlaveNodeId";
        case kCopSdocInitError: return "kCopSdocInitError";
        case kCopSdocInvalidParam: return "kCopSdocInvalidParam";
        case kCopSdocClientNotExist: return "kCopSdocClientNotExist";
        case kCopSdocBusy: return "kCopSdocBusy";
        case kCopSdocTransferError: return "kCopSdocTransferError";
        case kCopSdocWrongMultiplexor: return "kCopSdocWrongMultiplexor";
        case kCopSdocEntryAlreadyDefined: return "kCopSdocEntryAlreadyDefined";
        case kCopSdocNoFreeEntry: return "kCopSdocNoFreeEntry";
        case kCopSdocConfigOrder: return "kCopSdocConfigOrder";
        case kCopSdosInitError: return "kCopSdosInitError";
        case kCopSdosServerNotExist: return "kCopSdosServerNotExist";
        case kCopSdosBusy: return "kCopSdosBusy";
        case kCopSdosSizeMismatch: return "kCopSdosSizeMismatch";
        case kCopSdosNoFreeEntry: return "kCopSdosNoFreeEntry";
        case kCopSdosEntryAlreadyDefined: return "kCopSdosEntryAlreadyDefined";
        case kCopSdosConfigOrder: return "kCopSdosConfigOrder";
        case kCopSdosWrongDlc: return "kCopSdosWrongDlc";
        case kCopSdosWrongCcs: return "kCopSdosWrongCcs";
        case kCopPdoNotExist: return "kCopPdoNotExist";
        case kCopPdoLengthExceeded: return "kCopPdoLengthExceeded";
        case kCopPdoGranularityMismatch: return "kCopPdoGranularityMismatch";
        case kCopPdoInitError: return "kCopPdoInitError";
        case kCopPdoErrorPdoEncode: return "kCopPdoErrorPdoEncode";
        case kCopPdoErrorPdoDecode: return "kCopPdoErrorPdoDecode";
        case kCopPdoErrorSend: return "kCopPdoErrorSend";
        case kCopPdoErrorSyncWin: return "kCopPdoErrorSyncWin";
        case kCopPdoErrorMapp: return "kCopPdoErrorMapp";
        case kCopPdoVarNotFound: return "kCopPdoVarNotFound";
        case kCopPdoErrorEmcyPdoLen: return "kCopPdoErrorEmcyPdoLen";
        case kCopPdoWriteConstObject: return "kCopPdoWriteConstObject";
        case kCopPdoErrorRxEventTimer: return "kCopPdoErrorRxEventTimer";
        case kCopLsssResetNode: return "kCopLsssResetNode";
        case kCopLsssInvalidNodeId: return "kCopLsssInvalidNodeId";
        case kCopEmccNoFreeProducerEntry: return "kCopEmccNoFreeProducerEntry";
        case kCopEmccNodeIdNotExist: return "kCopEmccNodeIdNotExist";
        case kCopEmccNodeIdInvalid: return "kCopEmccNodeIdInvalid";
        case kCopEmccNodeIdExist: return "kCopEmccNodeIdExist";
        case kCopDynNoMemory: return "kCopDynNoMemory";
        case kCopDynInvalidConfig: return "kCopDynInvalidConfig";
        case kCopHbcEntryNotExist: return "kCopHbcEntryNotExist";
        case kCopHbcEntryAlreadyExist: return "kCopHbcEntryAlreadyExist";
        case kCopHbcNoFreeEntry: return "kCopHbcNoFreeEntry";
        case kCopCfgMaConfigError: return "kCopCfgMaConfigError";
        case kCopCfgMaSdocTimeOut: return "kCopCfgMaSdocTimeOut";
        case kCopCfgMaNoErrorCb: return "kCopCfgMaNoErrorCb";
        case kCopCfgMaNoFreeConfig: return "kCopCfgMaNoFreeConfig";
        case kCopCfgMaNoConfigData: return "kCopCfgMaNoConfigData";
        case kCopCfgMaInvaildSdoc: return "kCopCfgMaInvaildSdoc";
        case kCopCfgMaConfigwithErrors: return "kCopCfgMaConfigwithErrors";
        case kCopLssmIllegalMode: return "kCopLssmIllegalMode";
        case kCopLssmIllegalState: return "kCopLssmIllegalState";
        case kCopLssmBusy: return "kCopLssmBusy";
        case kCopLssmIllegalCmd: return "kCopLssmIllegalCmd";
        case kCopLssmTimeout: return "kCopLssmTimeout";
        case kCopLssmErrorInConfirm: return "kCopLssmErrorInConfirm";
        case kCopCcmStoreUnvalidState: return "kCopCcmStoreUnvalidState";
        case kCopCcmStoreHwError: return "kCopCcmStoreHwError";
        case kCopSrdoNotExist: return "kCopSrdoNotExist";
        case kCopSrdoGranularityMismatch: return "kCopSrdoGranularityMismatch";
        case kCopSrdoCfgTimingError: return "kCopSrdoCfgTimingError";
        case kCopSrdoCfgIdError: return "kCopSrdoCfgIdError";
        case kCopSrdoCfgCrcError: return "kCopSrdoCfgCrcError";
        case kCopSrdoNmtError: return "kCopSrdoNmtError";
        case kCopSrdoInvalidCfg: return "kCopSrdoInvalidCfg";
        case kCopSrdoInvalid: return "kCopSrdoInvalid";
        case kCopSrdoRxTxConflict: return "kCopSrdoRxTxConflict";
        case kCopSrdoIllegalCanId: return "kCopSrdoIllegalCanId";
        case kCopSrdoCanIdAlreadyInUse: return "kCopSrdoCanIdAlreadyInUse";
        case kCopSrdoNotInOrder: return "kCopSrdoNotInOrder";
        case kCopSrdoSctTimeout: return "kCopSrdoSctTimeout";
        case kCopSrdoSrvtTimeout: return "kCopSrdoSrvtTimeout";
        case kCopSrdoCanIdNotValid: return "kCopSrdoCanIdNotValid";
        case kCopSrdoDlcNotValid: return "kCopSrdoDlcNotValid";
        case kCopSrdoErrorMapp: return "kCopSrdoErrorMapp";
        case kCopSrdoDataError: return "kCopSrdoDataError";
        case kCopSrdoLengthExceeded: return "kCopSrdoLengthExceeded";
        case kCopSrdoNotHandledInApp: return "kCopSrdoNotHandledInApp";
        case kCopSrdoOverrun: return "kCopSrdoOverrun";
        case kCopSdomBusy: return "kCopSdomBusy";
        case kCopSdomInternStructFull: return "kCopSdomInternStructFull";
        case kCopSdomErrorCbInternError: return "kCopSdomErrorCbInternError";
        case kCopSdomErrorCbCopError: return "kCopSdomErrorCbCopError";
        case kCopSrdBusy: return "kCopSrdBusy";
        case kCopSrdNotRegistered: return "kCopSrdNotRegistered";
        case kCopSrdNoAnswerSdom: return "kCopSrdNoAnswerSdom";
        case kCopSrdNotMasterMode: return "kCopSrdNotMasterMode";
        case kCopSrdNotDynConnection: return "kCopSrdNotDynConnection";
        case kCopSrdSdomNotUndefSdoc: return "kCopSrdSdomNotUndefSdoc";
        case kCopMgrTaskDeferred: return "kCopMgrTaskDeferred";
        case kCopMgrInvalidOperation: return "kCopMgrInvalidOperation";
        case kCopMgrInvalidParam: return "kCopMgrInvalidParam";
        case kCopMgrNoFreeEntry: return "kCopMgrNoFreeEntry";
        case kCopMgrNodeBusy: return "kCopMgrNodeBusy";
        case kCopMgrSdocTypeAutoRunning: return "kCopMgrSdocTypeAutoRunning";
        case kCopUserSDOAbort: return "kCopUserSDOAbort";
        default:                        return "?";
    }
}
