/*
 * test_util.c - checks and helpers shared by the C tests, the application
 * callbacks and variables the test dictionaries name.
 */
#include "test_util.h"

/* ---- NMT ------------------------------------------------------------------ */

tNmtEvent aTestNmtEvents_g[TEST_MAX_EVENTS];
unsigned  uTestNmtEventCount_g;

const char* TestNmtEventName (tNmtEvent NmtEvent_p)
{
    switch (NmtEvent_p)
    {
        case kNmtEvEnterInitialising:      return "kNmtEvEnterInitialising";
        case kNmtEvResetNode:              return "kNmtEvResetNode";
        case kNmtEvPreResetCommunication:  return "kNmtEvPreResetCommunication";
        case kNmtEvResetCommunication:     return "kNmtEvResetCommunication";
        case kNmtEvPostResetCommunication: return "kNmtEvPostResetCommunication";
        case kNmtEvEnterPreOperational:    return "kNmtEvEnterPreOperational";
        case kNmtEvEnterOperational:       return "kNmtEvEnterOperational";
        case kNmtEvEnterStopped:           return "kNmtEvEnterStopped";
        default:                           return "?";
    }
}

tCopKernel PUBLIC TestNmtRecorder (tNmtEvent NmtEvent_p)
{
    if (uTestNmtEventCount_g < TEST_MAX_EVENTS)
    {
        aTestNmtEvents_g[uTestNmtEventCount_g++] = NmtEvent_p;
    }
    return kCopSuccessful;
}

void TestNmtClear (void)
{
    uTestNmtEventCount_g = 0;
}

tCopKernel TestInitNode (BYTE bSimNode_p, BYTE bNodeId_p, tObdInitRam fpObdInitRam_p, tCcmNmtEventCallback fpNmt_p)
{
    static tCcmInitParam aInitParam[SIM_MAX_NODES];
    tCcmInitParam* pInit;
    tCopKernel Ret;

    Ret = SimSelectNode(bSimNode_p);
    if (Ret != kCopSuccessful)
    {
        return Ret;
    }
    pInit = &aInitParam[bSimNode_p];
    memset(pInit, 0, sizeof(*pInit));
    pInit->m_bInitNodeId = bNodeId_p;
    pInit->m_BaudIndex = kBdi500kBaud;
    pInit->m_dwAmr = 0xFFFFFFFFUL;
    pInit->m_dwAcr = 0;
    pInit->m_HwParam.m_ZeroBasedCanNo.m_bCanNo = 0;
    pInit->m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    pInit->m_fpNmtEventCallback = fpNmt_p;
    pInit->m_fpObdInitRam = fpObdInitRam_p;
    return CcmInitCANopen(pInit, kCcmFirstInstance);
}

/* ---- frames ---------------------------------------------------------------- */

int TestExpectFrame (const char* pszWhat_p, DWORD dwId_p, BYTE bDlc_p, const BYTE* pbData_p)
{
    tSimFrame Frame;

    if (!SimTakeSentFrame(&Frame))
    {
        printf("%s: expected frame %03lX [%u], bus is empty\n", pszWhat_p, (unsigned long) dwId_p, (unsigned) bDlc_p);
        iTestFailures_g++;
        return 0;
    }
    if ((Frame.m_dwId != dwId_p) || (Frame.m_bDlc != bDlc_p) || Frame.m_bRtr ||
        ((bDlc_p > 0) && (pbData_p != NULL) && (memcmp(Frame.m_abData, pbData_p, bDlc_p) != 0)))
    {
        unsigned i;
        printf("%s: got %03lX [%u]", pszWhat_p, (unsigned long) Frame.m_dwId, (unsigned) Frame.m_bDlc);
        for (i = 0; i < Frame.m_bDlc; i++)
        {
            printf(" %02X", (unsigned) Frame.m_abData[i]);
        }
        printf(", expected %03lX [%u]", (unsigned long) dwId_p, (unsigned) bDlc_p);
        for (i = 0; (pbData_p != NULL) && (i < bDlc_p); i++)
        {
            printf(" %02X", (unsigned) pbData_p[i]);
        }
        printf("\n");
        iTestFailures_g++;
        return 0;
    }
    return 1;
}

unsigned TestDrainSent (void)
{
    unsigned n = 0;

    while (SimTakeSentFrame(NULL))
    {
        n++;
    }
    return n;
}

void TestProcess (unsigned n_p)
{
    unsigned i;

    for (i = 0; i < n_p; i++)
    {
        (void) CcmProcess();
    }
}

/* ---- OBD callbacks ---------------------------------------------------------------- */

BYTE     abTestObdEvents_g[TEST_MAX_OBD_EVENTS];
unsigned uTestObdEventCount_g;
tObdSize TestInitWriteSize_g;

void TestObdClear (void)
{
    uTestObdEventCount_g = 0;
    TestInitWriteSize_g = 0;
}

tCopKernel PUBLIC TestCbVeto (tObdCbParam MEM* pParam_p)
{
    if ((pParam_p->m_ObdEvent == kObdEvPreWrite) && (pParam_p->m_pArg != NULL))
    {
        WORD wValue;
        memcpy(&wValue, pParam_p->m_pArg, sizeof(wValue));
        if (wValue == 0x0BAD)
        {
            pParam_p->m_dwAbortCode = SDOAC_VALUE_RANGE_EXCEEDED;
            return kCopObdValueToHigh;
        }
    }
    return kCopSuccessful;
}

BYTE bTestCbRefuseEvent_g = 0xFF;

tCopKernel PUBLIC TestCbRecord (tObdCbParam MEM* pParam_p)
{
    if (pParam_p->m_ObdEvent == bTestCbRefuseEvent_g)
    {
        pParam_p->m_dwAbortCode = SDOAC_DATA_NOT_TRANSF_DUE_LOCAL_CONTROL;
        return kCopObdAccessViolation;
    }
    if (uTestObdEventCount_g < TEST_MAX_OBD_EVENTS)
    {
        abTestObdEvents_g[uTestObdEventCount_g++] = pParam_p->m_ObdEvent;
    }
    if ((pParam_p->m_ObdEvent == kObdEvInitWrite) && (pParam_p->m_pArg != NULL))
    {
        TestInitWriteSize_g = *(tObdSize*) pParam_p->m_pArg;
    }
    return kCopSuccessful;
}

/* ---- SRDO callbacks ------------------------------------------------------------------ */

unsigned   uTestSrdoEvents_g;
unsigned   uTestSrdoErrors_g;
WORD       wTestLastSrdoIndex_g;
tCopKernel TestLastSrdoError_g;
tCopKernel aTestSrdoErrors_g[TEST_MAX_SRDO_ERRORS];
unsigned   uTestGfcEvents_g;
unsigned   uTestProgMonEvents_g;
BYTE       bTestLastSrdoNode_g = 0xFF;
BYTE       bTestLastGfcNode_g = 0xFF;
void (*pfnTestSrdoEventHook_g) (WORD wSrdoCommuIndex_p);
void (*pfnTestSrdoErrorHook_g) (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p);

void TestSrdoClear (void)
{
    uTestSrdoEvents_g = 0;
    uTestSrdoErrors_g = 0;
    wTestLastSrdoIndex_g = 0;
    TestLastSrdoError_g = kCopSuccessful;
    memset(aTestSrdoErrors_g, 0, sizeof(aTestSrdoErrors_g));
    uTestGfcEvents_g = 0;
    uTestProgMonEvents_g = 0;
    bTestLastSrdoNode_g = 0xFF;
    bTestLastGfcNode_g = 0xFF;
    pfnTestSrdoEventHook_g = NULL;
    pfnTestSrdoErrorHook_g = NULL;
}

void TestSrdoEventHandshake (WORD wSrdoCommuIndex_p)
{
    BYTE bState = 0;

    if (CcmGetSrdoState(&bState, wSrdoCommuIndex_p) == kCopSuccessful)
    {
        (void) CcmSetSrdoState((BYTE) (bState | 0x30), wSrdoCommuIndex_p);
    }
}

void TestSrdoErrorHandshake (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    BYTE bState = 0;

    if ((ErrorCode_p != kCopSrdoNotHandledInApp) &&
        (CcmGetSrdoState(&bState, wSrdoCommuIndex_p) == kCopSuccessful) && ((bState & 0x30) == 0x10))
    {
        bState |= 0x30;
        bState ^= 0xC0;
        (void) CcmSetSrdoState(bState, wSrdoCommuIndex_p);
    }
}

tCopKernel TestSrdoMakeValid (void)
{
    BYTE bValid = 0xA5;
    WORD wIndex;
    WORD wCrc;
    tCopKernel Ret;

    for (wIndex = 0x1301; wIndex <= 0x1340; wIndex++)
    {
        if (CcmCalcSrdoCrc(wIndex, &wCrc) != kCopSuccessful)
        {
            continue;
        }
        Ret = CcmWriteObject(0x13FF, (BYTE) (wIndex - 0x1300), &wCrc, sizeof(wCrc));
        if (Ret != kCopSuccessful)
        {
            return Ret;
        }
    }
    return CcmWriteObject(0x13FE, 0, &bValid, sizeof(bValid));
}

tCopKernel TestWriteU8 (WORD wIndex_p, BYTE bSub_p, BYTE bValue_p)
{
    return CcmWriteObject(wIndex_p, bSub_p, &bValue_p, sizeof(bValue_p));
}

tCopKernel TestWriteU16 (WORD wIndex_p, BYTE bSub_p, WORD wValue_p)
{
    return CcmWriteObject(wIndex_p, bSub_p, &wValue_p, sizeof(wValue_p));
}

tCopKernel TestWriteU32 (WORD wIndex_p, BYTE bSub_p, DWORD dwValue_p)
{
    return CcmWriteObject(wIndex_p, bSub_p, &dwValue_p, sizeof(dwValue_p));
}

BYTE TestReadU8 (WORD wIndex_p, BYTE bSub_p)
{
    BYTE bValue = 0;
    tObdSize Size = sizeof(bValue);

    (void) CcmReadObject(wIndex_p, bSub_p, &bValue, &Size);
    return bValue;
}

#if !defined(TEST_OWN_APP_CALLBACKS)   /* a test with its own App* callbacks */

tCopKernel PUBLIC AppSrdoEvent (WORD wSrdoCommuIndex_p)
{
    uTestSrdoEvents_g++;
    wTestLastSrdoIndex_g = wSrdoCommuIndex_p;
    bTestLastSrdoNode_g = SimSelectedNode();
    if (pfnTestSrdoEventHook_g != NULL)
    {
        pfnTestSrdoEventHook_g(wSrdoCommuIndex_p);
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    if (uTestSrdoErrors_g < TEST_MAX_SRDO_ERRORS)
    {
        aTestSrdoErrors_g[uTestSrdoErrors_g] = ErrorCode_p;
    }
    uTestSrdoErrors_g++;
    wTestLastSrdoIndex_g = wSrdoCommuIndex_p;
    TestLastSrdoError_g = ErrorCode_p;
    bTestLastSrdoNode_g = SimSelectedNode();
    if (pfnTestSrdoErrorHook_g != NULL)
    {
        pfnTestSrdoErrorHook_g(wSrdoCommuIndex_p, ErrorCode_p);
    }
    return kCopSuccessful;
}

#if (SRDO_USE_GFC != FALSE)
tCopKernel PUBLIC AppGfcEvent (void)
{
    uTestGfcEvents_g++;
    bTestLastGfcNode_g = SimSelectedNode();
    return kCopSuccessful;
}
#endif

#if (SRDO_USE_PROGMONITOR != FALSE)
tCopKernel PUBLIC AppProgMonEvent (tProgMonEvent Event_p)
{
    (void) Event_p;
    uTestProgMonEvents_g++;
    return kCopSuccessful;
}
#endif

#endif /* !TEST_OWN_APP_CALLBACKS */

/* ---- application variables of objdict_all.h ------------------------------------------- */

tObdUnsigned32 dwTestExtVar_g;
tObdUnsigned8  bTestExtVarRg_g;
tObdUnsigned16 wTestExtNoInit_g;
tObdUnsigned16 awTestExtArray_g[3];

/* ---- application arrays of objdict_min.h ------------------------------------------------ */

tObdUnsigned8 abTestDigitalIn_g[1];
tObdInteger16 aiTestAnalogIn_g[2];
