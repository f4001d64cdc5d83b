/*
 * test_srdo.c - SRDO and GFC (CiA 304) through the C API with the objects
 * objdict_all.h declares with the SRDO macros: configuration (CRC in
 * 0x13FF, 0xA5 in 0x13FE), transmission (CcmSendSrdo: normal and inverted
 * frame), reception of a valid pair into the mapped variables, a data
 * error and an SCT timeout reported through AppSrdoError, the GFC in both
 * directions, the program monitor, and the application callbacks objdef.h
 * collected into tObdRamParam.m_pSrdoCallbacks.
 *
 * SRDO 1 (0x1301): transmit, SCT 25 ms, COB-IDs 0x101/0x102, maps
 * 0x2040/1 (normal) and 0x2041/1 (inverted). SRDO 2 (0x1302): receive, SCT
 * 100 ms, SRVT 20 ms, COB-IDs 0x103/0x104, maps 0x2042/1 and 0x2043/1.
 */
#include "test_util.h"

#define NODE_ID 2

static BYTE ReadU8 (WORD wIndex_p, BYTE bSub_p)
{
    BYTE bValue = 0;
    tObdSize Size = sizeof(bValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &bValue, &Size), kCopSuccessful);
    return bValue;
}

static void WriteU8 (WORD wIndex_p, BYTE bSub_p, BYTE bValue_p, tCopKernel Expected_p)
{
    CHECK_RET(CcmWriteObject(wIndex_p, bSub_p, &bValue_p, sizeof(bValue_p)), Expected_p);
}

static int SawError (tCopKernel Code_p)
{
    unsigned i;

    for (i = 0; (i < uTestSrdoErrors_g) && (i < TEST_MAX_SRDO_ERRORS); i++)
    {
        if (aTestSrdoErrors_g[i] == Code_p)
        {
            return 1;
        }
    }
    return 0;
}

static void Configure (void)
{
    WORD wCrc1 = 0;
    WORD wCrc2 = 0;
    WORD wBad;
    WORD wIndex = 0;
    DWORD dwCob = 0x100;

    CHECK_RET(CcmCalcSrdoCrc(0x1301, &wCrc1), kCopSuccessful);
    CHECK_RET(CcmCalcSrdoCrc(0x1302, &wCrc2), kCopSuccessful);
    CHECK_RET(CcmCalcSrdoCrc(0x1303, &wCrc2), kCopSrdoNotExist);
    CHECK_RET(CcmCalcSrdoCrc(0x1302, &wCrc2), kCopSuccessful);
    CHECK_RET(CcmCalcSrdoCrc(0x1302, NULL), kCopInvalidParam);

    /* a wrong checksum: 0xA5 is refused and 0x13FE stays 0 */
    wBad = (WORD) (wCrc1 ^ 0x0001);
    CHECK_RET(CcmWriteObject(0x13FF, 1, &wBad, sizeof(wBad)), kCopSuccessful);
    CHECK_RET(CcmWriteObject(0x13FF, 2, &wCrc2, sizeof(wCrc2)), kCopSuccessful);
    WriteU8(0x13FE, 0, 0xA5, kCopSrdoCfgCrcError);
    CHECK_EQ(ReadU8(0x13FE, 0), 0);
    CHECK(CcmCheckSrdoConfig(&wIndex) != kCopSuccessful);

    /* parameters that the SRDO rules refuse */
    CHECK_RET(CcmWriteObject(0x1301, 5, &dwCob, sizeof(dwCob)), kCopSrdoInvalidCfg);
    WriteU8(0x1301, 1, 3, kCopObdValueToHigh);
    WriteU8(0x1300, 0, 2, kCopObdValueToHigh);

    /* the right checksum */
    CHECK_RET(CcmWriteObject(0x13FF, 1, &wCrc1, sizeof(wCrc1)), kCopSuccessful);
    WriteU8(0x13FE, 0, 0xA5, kCopSuccessful);
    CHECK_EQ(ReadU8(0x13FE, 0), 0xA5);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSuccessful);
    CHECK_RET(CcmCheckSrdoConfig(NULL), kCopInvalidParam);
    WriteU8(0x1300, 0, 1, kCopSuccessful);      /* GFC on */
}

static void Parameters (void)
{
    tSrdoCommuParam Commu;
    tSrdoMappParam Mapp;

    memset(&Commu, 0, sizeof(Commu));
    memset(&Mapp, 0, sizeof(Mapp));
    CHECK_RET(CcmGetSrdoParam(0x1301, &Commu, &Mapp), kCopSuccessful);
    CHECK_EQ(Commu.m_bDirection, 1);
    CHECK_EQ(Commu.m_wSct, 25);
    CHECK_EQ(Mapp.m_bNoOfMappedObjects, 2);
    CHECK(Mapp.m_apMappedVariable[0] != NULL);
    CHECK(Mapp.m_apMappedVariable[1] != NULL);
    CHECK_RET(CcmGetSrdoParam(0x1302, &Commu, NULL), kCopSuccessful);
    CHECK_EQ(Commu.m_bDirection, 2);
    CHECK_EQ(Commu.m_wSct, 100);
    CHECK_RET(CcmGetSrdoParam(0x1310, &Commu, NULL), kCopSrdoNotExist);
}

static void Transmit (void)
{
    static CONST BYTE abNormal[1] = { 0x5A };
    static CONST BYTE abInverted[1] = { 0xA5 };
    unsigned uEvents;

    WriteU8(0x2040, 1, 0x5A, kCopSuccessful);
    WriteU8(0x2041, 1, 0xA5, kCopSuccessful);
    TestDrainSent();
    SimAdvanceMs(2);            /* first transmission 0.5 ms x node-ID after OPERATIONAL */
    uEvents = uTestSrdoEvents_g;
    CHECK_RET(CcmSendSrdo(0x1301), kCopSuccessful);
    TestExpectFrame("SRDO normal frame", 0x101, 1, abNormal);
    TestExpectFrame("SRDO inverted frame", 0x102, 1, abInverted);
    CHECK_EQ(uTestSrdoEvents_g, uEvents + 1);
    CHECK_EQ(wTestLastSrdoIndex_g, 0x1301);
    CHECK_RET(CcmSendSrdo(0x1302), kCopSrdoRxTxConflict); /* a receive SRDO */
    CHECK_RET(CcmSendSrdo(0x1310), kCopSrdoNotExist);
    CHECK_RET(CcmSendSrdo(0), kCopSuccessful);             /* every transmit SRDO */
    TestExpectFrame("SRDO normal frame (all)", 0x101, 1, abNormal);
    TestExpectFrame("SRDO inverted frame (all)", 0x102, 1, abInverted);
}

/* CcmSendSrdo from inside AppSrdoEvent (an application answering a
 * received SRDO with its own): the transmit SRDO's AppSrdoEvent comes after
 * the running callback has returned, never inside it (the library's rule
 * for every Ccm* call from a callback, test_callback_order.c). */
static unsigned   uHookDepth_g;
static unsigned   uHookMaxDepth_g;
static tCopKernel HookSendRet_g = kCopSuccessful;

static void SendInHook (WORD wSrdoCommuIndex_p)
{
    uHookDepth_g++;
    if (uHookDepth_g > uHookMaxDepth_g)
    {
        uHookMaxDepth_g = uHookDepth_g;
    }
    if (wSrdoCommuIndex_p == 0x1302)
    {
        HookSendRet_g = CcmSendSrdo(0x1301);
    }
    uHookDepth_g--;
}

static void SendFromCallback (void)
{
    static CONST BYTE abRxNormal[1] = { 0x3C };
    static CONST BYTE abRxInverted[1] = { 0xC3 };
    static CONST BYTE abNormal[1] = { 0x5A };
    static CONST BYTE abInverted[1] = { 0xA5 };
    unsigned uEvents = uTestSrdoEvents_g;

    TestDrainSent();
    pfnTestSrdoEventHook_g = SendInHook;
    SimInject(0x103, 0, 1, abRxNormal);
    SimAdvanceMs(1);
    SimInject(0x104, 0, 1, abRxInverted);
    TestProcess(1);
    pfnTestSrdoEventHook_g = NULL;
    CHECK_RET(HookSendRet_g, kCopSuccessful);
    TestExpectFrame("SRDO normal frame (from the callback)", 0x101, 1, abNormal);
    TestExpectFrame("SRDO inverted frame (from the callback)", 0x102, 1, abInverted);
    CHECK_EQ(uTestSrdoEvents_g, uEvents + 2);   /* 0x1302 received, then 0x1301 sent */
    CHECK_EQ(wTestLastSrdoIndex_g, 0x1301);
    CHECK_EQ(uHookMaxDepth_g, 1);
}

static void Receive (void)
{
    static CONST BYTE abNormal[1] = { 0x3C };
    static CONST BYTE abInverted[1] = { 0xC3 };
    static CONST BYTE abBad[1] = { 0x11 };
    BYTE bState = 0xFF;
    unsigned uEvents = uTestSrdoEvents_g;

    SimInject(0x103, 0, 1, abNormal);
    SimAdvanceMs(1);
    SimInject(0x104, 0, 1, abInverted);
    TestProcess(1);
    CHECK_EQ(uTestSrdoEvents_g, uEvents + 1);
    CHECK_EQ(wTestLastSrdoIndex_g, 0x1302);
    CHECK_EQ(ReadU8(0x2042, 1), 0x3C);
    CHECK_EQ(ReadU8(0x2043, 1), 0xC3);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1302), kCopSuccessful);
    CHECK_EQ(bState & 0x30, 0x00);
    CHECK_RET(CcmGetSrdoState(NULL, 0x1302), kCopInvalidParam);
    CHECK_RET(CcmSetSrdoState((BYTE) (bState | 0x30), 0x1302), kCopSuccessful);

    /* not inverted: data error, nothing written */
    SimInject(0x103, 0, 1, abBad);
    SimInject(0x104, 0, 1, abBad);
    TestProcess(1);
    CHECK(SawError(kCopSrdoDataError));
    CHECK_EQ(ReadU8(0x2042, 1), 0x3C);

    /* no valid pair within the SCT */
    SimAdvanceMs(150);
    TestProcess(1);
    CHECK(SawError(kCopSrdoSctTimeout));
    CHECK_EQ(wTestLastSrdoIndex_g, 0x1302);
}

static void Gfc (void)
{
    CHECK_EQ(SimIsIdDefined(0, 0x001), 2);       /* GFC in the high-priority buffer */
    SimInject(0x001, 0, 0, NULL);
    TestProcess(1);
    CHECK_EQ(uTestGfcEvents_g, 1);
    TestDrainSent();
    CHECK_RET(CcmSendGfc(), kCopSuccessful);
    TestExpectFrame("GFC", 0x001, 0, NULL);
}

int main (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };

    SimReset();
    SimSetTrace(1);
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, TestNmtRecorder), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestProcess(1);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSrdoNmtError);      /* not OPERATIONAL */

    Configure();
    Parameters();

    CHECK(SimIsIdDefined(0, 0x103) != 0);       /* the stack subscribed the receive SRDO */
    CHECK(SimIsIdDefined(0, 0x104) != 0);
    SimInject(0x000, 0, 2, abStartAll);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    WriteU8(0x1301, 3, 30, kCopSrdoNmtError);      /* no SRDO parameter changes while OPERATIONAL */

    Transmit();
    SendFromCallback();
    Receive();
    Gfc();
#if defined(COP_CFG_SRDO_USE_PROGMONITOR)
    CHECK(uTestProgMonEvents_g > 0);
#endif

    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_srdo");
}
