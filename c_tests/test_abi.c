/*
 * test_abi.c - the C view of every structure shared with the library has
 * the size and field offsets of its Rust #[repr(C)] twin (src/ffi).
 *
 * Compiled once per test configuration (c_tests/cfg and c_tests/cfg_big)
 * and linked against the library built from the same folder; the library
 * asserts its own side. Expected values follow the repr(C) rules: each
 * field at the next multiple of its alignment, the size rounded up to the
 * largest alignment. Pointer-dependent values are for x86-64 (8-byte
 * pointers, LP64); on a 32-bit target the same rules give the ARM values
 * noted in cop_types.h (tCcmInitParam 40 bytes, tObdSubEntry 16, ...).
 */
#include <stddef.h>

#include "test_util.h"
#include "cop_config.h"

/* ---- widths that do not depend on the pointer size --------------------------- */
_Static_assert(sizeof(BYTE) == 1, "BYTE");
_Static_assert(sizeof(WORD) == 2, "WORD");
_Static_assert(sizeof(DWORD) == 4, "DWORD is 32 bits on every target");
_Static_assert(sizeof(tFastByte) == 4, "tFastByte is a DWORD");
_Static_assert(sizeof(tTime) == 4, "tTime is a DWORD of 100 us ticks");
_Static_assert(sizeof(tObdUnsigned32) == 4 && sizeof(tObdInteger32) == 4, "32-bit OBD types");
_Static_assert(sizeof(tObdUnsigned24) == 4 && sizeof(tObdInteger24) == 4, "24-bit OBD types live in 32 bits");
_Static_assert(sizeof(tObdUnsigned64) == 8 && sizeof(tObdInteger64) == 8, "64-bit OBD types");
_Static_assert(sizeof(tNmtEvent) == 4 && sizeof(tProgMonEvent) == 4 && sizeof(tCcmInitCall) == 4, "tFastByte enums");
_Static_assert(sizeof(tNmtCommand) == 2, "tNmtCommand is a WORD");
_Static_assert(sizeof(tCdrvBaudIndex) == 1, "tCdrvBaudIndex is one byte");
_Static_assert(sizeof(tMsgTyp) == 1, "tMsgTyp");
_Static_assert(sizeof(tCdrvStatus) == 2, "tCdrvStatus");
_Static_assert(sizeof(tCopKernel) == 4, "tCopKernel enum (int-sized on this compiler)");

#if (OBD_SUPPORTED_OBJ_SIZE == OBD_OBJ_SIZE_BIG)
#define EXPECT_OBD_SIZE 4
#elif (OBD_SUPPORTED_OBJ_SIZE == OBD_OBJ_SIZE_MIDDLE)
#define EXPECT_OBD_SIZE 2
#else
#define EXPECT_OBD_SIZE 1
#endif
_Static_assert(sizeof(tObdSize) == EXPECT_OBD_SIZE, "tObdSize follows OBD_SUPPORTED_OBJ_SIZE");

/* LSS (SYSTEC_API_MORE.md section 3: tLssCbParam on ARM 0/4/5/6, sizeof 8). */
_Static_assert(sizeof(tLssAddress) == 16, "tLssAddress: four DWORDs");
_Static_assert(offsetof(tLssCbParam, m_bNodeId) == 4, "tLssCbParam.m_bNodeId");
_Static_assert(offsetof(tLssCbParam, m_bBtrTableSelector) == 5, "tLssCbParam.m_bBtrTableSelector");
_Static_assert(offsetof(tLssCbParam, m_bBtrIndex) == 6, "tLssCbParam.m_bBtrIndex");
_Static_assert(sizeof(tLssCbParam) == 8, "tLssCbParam");

/* tCdrvMsg: WORD id (CAN20A) at 0, type 2, DLC 3, channel 4, data 5..12;
 * with CDRV_TIMESTAMP the DWORD time at 16 (size 20), else size 14. */
#if (CDRV_CAN_SPEC == CAN20B)
_Static_assert(offsetof(tCdrvMsg, m_MsgType) == 4, "tCdrvMsg.m_MsgType (CAN20B)");
_Static_assert(offsetof(tCdrvMsg, m_bData) == 7, "tCdrvMsg.m_bData (CAN20B)");
#else
_Static_assert(offsetof(tCdrvMsg, m_CanId) == 0, "tCdrvMsg.m_CanId");
_Static_assert(offsetof(tCdrvMsg, m_MsgType) == 2, "tCdrvMsg.m_MsgType");
_Static_assert(offsetof(tCdrvMsg, m_bSize) == 3, "tCdrvMsg.m_bSize");
_Static_assert(offsetof(tCdrvMsg, m_bChannel_p) == 4, "tCdrvMsg.m_bChannel_p");
_Static_assert(offsetof(tCdrvMsg, m_bData) == 5, "tCdrvMsg.m_bData");
#if (CDRV_TIMESTAMP != FALSE)
_Static_assert(offsetof(tCdrvMsg, m_Time) == 16, "tCdrvMsg.m_Time");
_Static_assert(sizeof(tCdrvMsg) == 20, "tCdrvMsg with timestamp");
#else
_Static_assert(sizeof(tCdrvMsg) == 14, "tCdrvMsg");
#endif
#endif

/* tSrdoCommuParam {BYTE; WORD} */
_Static_assert(offsetof(tSrdoCommuParam, m_wSct) == 2 && sizeof(tSrdoCommuParam) == 4, "tSrdoCommuParam");
/* tEmcParam {WORD 0; BYTE 2; BYTE[5] 3; WORD 8} = 10 */
_Static_assert(offsetof(tEmcParam, m_bErrorRegister) == 2, "tEmcParam.m_bErrorRegister");
_Static_assert(offsetof(tEmcParam, m_abManufactErrorCode) == 3, "tEmcParam.m_abManufactErrorCode");
_Static_assert(offsetof(tEmcParam, m_wAdditionalInfo) == 8, "tEmcParam.m_wAdditionalInfo");
_Static_assert(sizeof(tEmcParam) == 10, "tEmcParam");
/* tHbcProdParam {WORD; BYTE; BYTE} = 4, tNmtmSlaveParam {WORD; BYTE} = 4,
 * tNmtmSlaveInfo {BYTE; BYTE; BYTE} = 3 (vendored SYS TEC nmtm.h);
 * tCobParam (cob.h) on ILP32 with CAN 2.0A: m_bSize 3, m_fpCallback 4,
 * m_CobHdl 12, m_pbData 16, sizeof 24 */
_Static_assert(sizeof(tHbcProdParam) == 4, "tHbcProdParam");
_Static_assert(sizeof(tNmtmSlaveParam) == 4, "tNmtmSlaveParam");
_Static_assert(offsetof(tNmtmSlaveInfo, m_bLostMsgCount) == 1 && offsetof(tNmtmSlaveInfo, m_bSlaveNodeState) == 2 && sizeof(tNmtmSlaveInfo) == 3, "tNmtmSlaveInfo");
_Static_assert(offsetof(tCobParam, m_bCobType) == sizeof(tCanId) && offsetof(tCobParam, m_bSize) == sizeof(tCanId) + 1, "tCobParam.m_bSize");
_Static_assert(offsetof(tCobParam, m_CobHdl) == offsetof(tCobParam, m_pArg) + sizeof(void*), "tCobParam.m_CobHdl");
_Static_assert(sizeof(tCobHdl) == ((COB_MORE_THAN_128_ENTRIES != FALSE) ? 2 : 1), "tCobHdl width");
/* tCopStoreDriver {void* 0; DWORD 8, 12, 16; five function pointers 24..56} = 64 (LP64) */
_Static_assert(offsetof(tCopStoreDriver, m_dwSize) == 8 && offsetof(tCopStoreDriver, m_dwConfigKey) == 16, "tCopStoreDriver");
_Static_assert(offsetof(tCopStoreDriver, m_fpOpen) == 24 && offsetof(tCopStoreDriver, m_fpCommit) == 56, "tCopStoreDriver");
_Static_assert(sizeof(tCopStoreDriver) == 64, "tCopStoreDriver size");
/* tSdocParam {BYTE 0; tTime 4; WORD 8; DWORD 12; DWORD 16; BYTE 20} = 24 */
_Static_assert(offsetof(tSdocParam, m_TimeOut) == 4 && offsetof(tSdocParam, m_bServerNodeId) == 20, "tSdocParam");
_Static_assert(sizeof(tSdocParam) == 24, "tSdocParam size");
/* tSdocCbFinishParam {WORD 0; tSdocState 4; DWORD 8} = 12 */
_Static_assert(offsetof(tSdocCbFinishParam, m_SdocState) == 4 && sizeof(tSdocCbFinishParam) == 12, "tSdocCbFinishParam");

#if defined(__x86_64__) || defined(_M_X64) || defined(__aarch64__)
_Static_assert(sizeof(void*) == 8, "64-bit host");

/* tCdrvHwParam: exactly two pointers. */
_Static_assert(sizeof(tCdrvHwParam) == 16, "tCdrvHwParam");
/* tCdrvBuffInit {ptr 0; WORD 8} = 16 */
_Static_assert(offsetof(tCdrvBuffInit, m_MaxEntries) == 8 && sizeof(tCdrvBuffInit) == 16, "tCdrvBuffInit");

/* tCcmInitParam: node-ID 0, baud index 1 (one byte), table 8, table size
 * 16, AMR 20, ACR 24, hardware 32 (16 bytes), interrupt 48, NMT callback
 * 56, ObdInitRam 64 = 72. */
_Static_assert(offsetof(tCcmInitParam, m_bInitNodeId) == 0, "tCcmInitParam.m_bInitNodeId");
_Static_assert(offsetof(tCcmInitParam, m_BaudIndex) == 1, "tCcmInitParam.m_BaudIndex");
_Static_assert(offsetof(tCcmInitParam, m_pBdiTable) == 8, "tCcmInitParam.m_pBdiTable");
_Static_assert(offsetof(tCcmInitParam, m_wSizeOfBdiTab) == 16, "tCcmInitParam.m_wSizeOfBdiTab");
_Static_assert(offsetof(tCcmInitParam, m_dwAmr) == 20, "tCcmInitParam.m_dwAmr");
_Static_assert(offsetof(tCcmInitParam, m_dwAcr) == 24, "tCcmInitParam.m_dwAcr");
_Static_assert(offsetof(tCcmInitParam, m_HwParam) == 32, "tCcmInitParam.m_HwParam");
_Static_assert(offsetof(tCcmInitParam, m_fpCanInterruptEnable) == 48, "tCcmInitParam.m_fpCanInterruptEnable");
_Static_assert(offsetof(tCcmInitParam, m_fpNmtEventCallback) == 56, "tCcmInitParam.m_fpNmtEventCallback");
_Static_assert(offsetof(tCcmInitParam, m_fpObdInitRam) == 64, "tCcmInitParam.m_fpObdInitRam");
_Static_assert(sizeof(tCcmInitParam) == 72, "tCcmInitParam");

/* tCdrvInitParam: baud 0, table 8, size 16, AMR 20, ACR 24, hardware 32,
 * four buffers at 48/64/80/96 (16 each), interrupt 112 = 120. */
_Static_assert(offsetof(tCdrvInitParam, m_BaudIndex) == 0, "tCdrvInitParam.m_BaudIndex");
_Static_assert(offsetof(tCdrvInitParam, m_pBdiTable) == 8, "tCdrvInitParam.m_pBdiTable");
_Static_assert(offsetof(tCdrvInitParam, m_wSizeOfBdiTab) == 16, "tCdrvInitParam.m_wSizeOfBdiTab");
_Static_assert(offsetof(tCdrvInitParam, m_dwAmr) == 20, "tCdrvInitParam.m_dwAmr");
_Static_assert(offsetof(tCdrvInitParam, m_dwAcr) == 24, "tCdrvInitParam.m_dwAcr");
_Static_assert(offsetof(tCdrvInitParam, m_HwParam) == 32, "tCdrvInitParam.m_HwParam");
_Static_assert(offsetof(tCdrvInitParam, m_RxBuffHigh) == 48, "tCdrvInitParam.m_RxBuffHigh");
_Static_assert(offsetof(tCdrvInitParam, m_TxBuffHigh) == 64, "tCdrvInitParam.m_TxBuffHigh");
_Static_assert(offsetof(tCdrvInitParam, m_RxBuffLow) == 80, "tCdrvInitParam.m_RxBuffLow");
_Static_assert(offsetof(tCdrvInitParam, m_TxBuffLow) == 96, "tCdrvInitParam.m_TxBuffLow");
_Static_assert(offsetof(tCdrvInitParam, m_fpEnableInterrupt) == 112, "tCdrvInitParam.m_fpEnableInterrupt");
_Static_assert(sizeof(tCdrvInitParam) == 120, "tCdrvInitParam");

/* tObdSubEntry: sub 0, type 1, access 2, kind 3, size 4 (DWORD), default
 * 8, current 16 = 24. */
_Static_assert(offsetof(tObdSubEntry, m_bSubIndex) == 0, "tObdSubEntry.m_bSubIndex");
_Static_assert(offsetof(tObdSubEntry, m_bType) == 1, "tObdSubEntry.m_bType");
_Static_assert(offsetof(tObdSubEntry, m_bAccess) == 2, "tObdSubEntry.m_bAccess");
_Static_assert(offsetof(tObdSubEntry, m_bKind) == 3, "tObdSubEntry.m_bKind");
_Static_assert(offsetof(tObdSubEntry, m_dwSize) == 4, "tObdSubEntry.m_dwSize");
_Static_assert(offsetof(tObdSubEntry, m_pDefault) == 8, "tObdSubEntry.m_pDefault");
_Static_assert(offsetof(tObdSubEntry, m_pCurrent) == 16, "tObdSubEntry.m_pCurrent");
_Static_assert(sizeof(tObdSubEntry) == 24, "tObdSubEntry");

/* tObdEntry: index 0, table 8, count 16, callback 24 = 32. */
_Static_assert(offsetof(tObdEntry, m_wIndex) == 0, "tObdEntry.m_wIndex");
_Static_assert(offsetof(tObdEntry, m_pSubIndex) == 8, "tObdEntry.m_pSubIndex");
_Static_assert(offsetof(tObdEntry, m_bCount) == 16, "tObdEntry.m_bCount");
_Static_assert(offsetof(tObdEntry, m_fpCallback) == 24, "tObdEntry.m_fpCallback");
_Static_assert(sizeof(tObdEntry) == 32, "tObdEntry");

/* tObdVarEntry: data 0, size 8 (tObdSize, at most 4 bytes), callback 16,
 * argument 24 = 32 (callback and argument always present). */
_Static_assert(offsetof(tObdVarEntry, m_pData) == 0, "tObdVarEntry.m_pData");
_Static_assert(offsetof(tObdVarEntry, m_Size) == 8, "tObdVarEntry.m_Size");
_Static_assert(offsetof(tObdVarEntry, m_fpCallback) == 16, "tObdVarEntry.m_fpCallback");
_Static_assert(offsetof(tObdVarEntry, m_pArg) == 24, "tObdVarEntry.m_pArg");
_Static_assert(sizeof(tObdVarEntry) == 32, "tObdVarEntry");

/* tObdCbParam: event 0 (BYTE), index 2, sub 4, argument 8, abort code 16
 * = 24. */
_Static_assert(offsetof(tObdCbParam, m_ObdEvent) == 0, "tObdCbParam.m_ObdEvent");
_Static_assert(offsetof(tObdCbParam, m_wIndex) == 2, "tObdCbParam.m_wIndex");
_Static_assert(offsetof(tObdCbParam, m_bSubIndex) == 4, "tObdCbParam.m_bSubIndex");
_Static_assert(offsetof(tObdCbParam, m_pArg) == 8, "tObdCbParam.m_pArg");
_Static_assert(offsetof(tObdCbParam, m_dwAbortCode) == 16, "tObdCbParam.m_dwAbortCode");
_Static_assert(sizeof(tObdCbParam) == 24, "tObdCbParam");

/* tVarParam: flags 0, index 2, sub 4, size 5 (BYTE) / 6 (WORD) / 8
 * (DWORD), data 8 or 16, callback, argument. */
_Static_assert(offsetof(tVarParam, m_bValidFlag) == 0, "tVarParam.m_bValidFlag");
_Static_assert(offsetof(tVarParam, m_wIndex) == 2, "tVarParam.m_wIndex");
_Static_assert(offsetof(tVarParam, m_bSubindex) == 4, "tVarParam.m_bSubindex");
#if (OBD_SUPPORTED_OBJ_SIZE == OBD_OBJ_SIZE_BIG)
_Static_assert(offsetof(tVarParam, m_Size) == 8, "tVarParam.m_Size (DWORD)");
_Static_assert(offsetof(tVarParam, m_pData) == 16, "tVarParam.m_pData");
_Static_assert(offsetof(tVarParam, m_fpCallback) == 24, "tVarParam.m_fpCallback");
_Static_assert(offsetof(tVarParam, m_pArg) == 32, "tVarParam.m_pArg");
_Static_assert(sizeof(tVarParam) == 40, "tVarParam");
#else
_Static_assert(offsetof(tVarParam, m_Size) == (EXPECT_OBD_SIZE == 1 ? 5 : 6), "tVarParam.m_Size");
_Static_assert(offsetof(tVarParam, m_pData) == 8, "tVarParam.m_pData");
_Static_assert(offsetof(tVarParam, m_fpCallback) == 16, "tVarParam.m_fpCallback");
_Static_assert(offsetof(tVarParam, m_pArg) == 24, "tVarParam.m_pArg");
_Static_assert(sizeof(tVarParam) == 32, "tVarParam");
#endif

/* tSrdoMappParam: count 0, pointers at 8: 8 + 8 * (128 / granularity). */
_Static_assert(offsetof(tSrdoMappParam, m_apMappedVariable) == 8, "tSrdoMappParam.m_apMappedVariable");
_Static_assert(sizeof(tSrdoMappParam) == 8 + 8 * (128 / SRDO_GRANULARITY), "tSrdoMappParam");
_Static_assert(SRDO_MAX_MAPPENTRIES == 128 / SRDO_GRANULARITY, "SRDO_MAX_MAPPENTRIES");

/* tSrdoAppCallbacks: four function pointers. */
_Static_assert(offsetof(tSrdoAppCallbacks, m_fpSrdoError) == 8, "tSrdoAppCallbacks.m_fpSrdoError");
_Static_assert(offsetof(tSrdoAppCallbacks, m_fpGfcEvent) == 16, "tSrdoAppCallbacks.m_fpGfcEvent");
_Static_assert(offsetof(tSrdoAppCallbacks, m_fpProgMonEvent) == 24, "tSrdoAppCallbacks.m_fpProgMonEvent");
_Static_assert(sizeof(tSrdoAppCallbacks) == 32, "tSrdoAppCallbacks");

/* tObdRamParam: six pointers 0..40, buffers 48/64/80/96, SRDO count 112
 * = 120. */
_Static_assert(offsetof(tObdRamParam, m_pGenericPart) == 0, "tObdRamParam.m_pGenericPart");
_Static_assert(offsetof(tObdRamParam, m_pManufacturerPart) == 8, "tObdRamParam.m_pManufacturerPart");
_Static_assert(offsetof(tObdRamParam, m_pDevicePart) == 16, "tObdRamParam.m_pDevicePart");
_Static_assert(offsetof(tObdRamParam, m_pUserPart) == 24, "tObdRamParam.m_pUserPart");
_Static_assert(offsetof(tObdRamParam, m_pbAbiSignature) == 32, "tObdRamParam.m_pbAbiSignature");
_Static_assert(offsetof(tObdRamParam, m_pSrdoCallbacks) == 40, "tObdRamParam.m_pSrdoCallbacks");
_Static_assert(offsetof(tObdRamParam, m_RxBuffHigh) == 48, "tObdRamParam.m_RxBuffHigh");
_Static_assert(offsetof(tObdRamParam, m_TxBuffHigh) == 64, "tObdRamParam.m_TxBuffHigh");
_Static_assert(offsetof(tObdRamParam, m_RxBuffLow) == 80, "tObdRamParam.m_RxBuffLow");
_Static_assert(offsetof(tObdRamParam, m_TxBuffLow) == 96, "tObdRamParam.m_TxBuffLow");
_Static_assert(offsetof(tObdRamParam, m_wSrdoCount) == 112, "tObdRamParam.m_wSrdoCount");
_Static_assert(sizeof(tObdRamParam) == 120, "tObdRamParam");

/* tSrdoInitParam {tSrdoTabParam {ptr 0; BYTE 8} 0; BYTE 16; ptr 24} = 32 */
_Static_assert(sizeof(tSrdoTabParam) == 16, "tSrdoTabParam");
_Static_assert(offsetof(tSrdoInitParam, m_bGranularity) == 16, "tSrdoInitParam.m_bGranularity");
_Static_assert(offsetof(tSrdoInitParam, m_pbSrdoConfigValid) == 24 && sizeof(tSrdoInitParam) == 32, "tSrdoInitParam");

/* tSdocTransferParam {WORD 0; WORD 2; BYTE 4; ptr 8; tObdSize 16; tTime 20;
 * tSdocType 24; callback 32} = 40 */
_Static_assert(offsetof(tSdocTransferParam, m_pData) == 8, "tSdocTransferParam.m_pData");
_Static_assert(offsetof(tSdocTransferParam, m_DataLen) == 16, "tSdocTransferParam.m_DataLen");
_Static_assert(offsetof(tSdocTransferParam, m_TimeOut) == 20, "tSdocTransferParam.m_TimeOut");
_Static_assert(offsetof(tSdocTransferParam, m_SdocType) == 24, "tSdocTransferParam.m_SdocType");
_Static_assert(offsetof(tSdocTransferParam, m_pfnCbFinished) == 32 && sizeof(tSdocTransferParam) == 40, "tSdocTransferParam");

/* tPdoParam: as asserted by src/ffi/pdo.rs; mapping at 20, callback 56 = 64 */
_Static_assert(offsetof(tPdoParam, m_bNodeID) == 5 && offsetof(tPdoParam, m_dwCanId) == 8, "tPdoParam head");
_Static_assert(offsetof(tPdoParam, m_bNrOfEntries) == 18 && offsetof(tPdoParam, m_adwMappParam) == 20, "tPdoParam mapping");
_Static_assert(offsetof(tPdoParam, m_fpCallback) == 56 && sizeof(tPdoParam) == 64, "tPdoParam");
#endif

static tNmtEvent LastNmtEvent_g;

static tCopKernel PUBLIC AbiNmtCallback (tNmtEvent NmtEvent_p)
{
    LastNmtEvent_g = NmtEvent_p;
    return kCopSuccessful;
}

int main (void)
{
    DWORD dwValue = 0;
    tObdSize Size = sizeof(dwValue);
    tTime TickAtInject;

    printf("configuration: tObdSize %u byte(s), SRDO granularity %u, timestamp %s, signature symbol linked at %p\n",
           (unsigned) sizeof(tObdSize), (unsigned) SRDO_GRANULARITY, (CDRV_TIMESTAMP != FALSE) ? "yes" : "no",
           (const void*) &COP_ABI_SIGNATURE);

    /* The program links (the dictionary references this configuration's
     * signature) and the library accepts the dictionary. */
    SimReset();
    CHECK_RET(TestInitNode(0, 5, ObdInitRamMin, AbiNmtCallback), kCopSuccessful);
    CHECK_EQ(LastNmtEvent_g, kNmtEvPostResetCommunication);
    CHECK_RET(CcmReadObject(0x1018, 0x01, &dwValue, &Size), kCopSuccessful);
    CHECK_EQ(Size, 4);
    CHECK_EQ(dwValue, 0x00000123UL);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestDrainSent();

    /* Receive timestamps reach the stack's buffer entries (CDRV_TIMESTAMP). */
    SimAdvanceTicks(1234);
    TickAtInject = TgtGetTickCount();
    {
        static CONST BYTE abNmt[2] = { 0x80, 0x00 };      /* enter pre-operational, all nodes */
        tCdrvMsg* pMsg = NULL;
        CHECK_EQ(SimInject(0x000, 0, 2, abNmt), 1);
        CHECK_RET(CdrvReadMsg(&pMsg), kCopCdrvMsgHigh);
        CHECK(pMsg != NULL);
        if (pMsg != NULL)
        {
            CHECK_EQ(pMsg->m_CanId, 0x000);
            CHECK_EQ(pMsg->m_bSize, 2);
#if (CDRV_TIMESTAMP != FALSE)
            CHECK_EQ(pMsg->m_Time, TickAtInject);
#else
            (void) TickAtInject;
#endif
            CHECK_RET(CdrvReleaseMsg(pMsg), kCopSuccessful);
        }
    }
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_abi");
}
