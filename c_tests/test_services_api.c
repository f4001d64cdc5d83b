/*
 * test_services_api.c - the smaller CCM services with success and refusal
 * codes, on two simulated nodes:
 *
 *   node P (simulated node 0): objdict_services.h, node-ID 2 - a slave whose
 *          NMT callback does what the AWorks adapter does (CcmInitLgs and
 *          CcmInitStore at kNmtEvEnterInitialising, CcmStoreCheckArchivState
 *          and CcmConfigEmcp (0x80 + node-ID; the dictionary's 0x1014 is
 *          0x80000000) at kNmtEvResetCommunication);
 *   node M (simulated node 1): objdict_master.h, node-ID 1 - NMT master
 *          guarding P and emergency consumer of P.
 *
 * CcmInitEmcc, CcmInitEmccEx, CcmEmccDefineProducerTab,
 * CcmClearPreDefinedErrorField, CcmInitLgs, CcmConfigLgs (and the
 * CcmConfigHbp conflict), CcmConfigSyncProducer, CcmTspSend, CcmInitStore,
 * CcmStoreCheckArchivState, CcmStoreRestoreDefault, the error behaviour
 * 0x1029 on a bus-off; frames per CiA 301
 * (EMCY 7.2.7.3.1, SYNC 7.2.5, TIME 7.2.6, SDO 7.2.4.3).
 */
#include "test_util.h"
/* EMCC_MAX_CONSUMER as the library was built (c_tests/cfg, copdef.h). */
#include "obdcfg.h"
#include "copdef.h"

#define SIM_P 0
#define SIM_M 1
#define ID_P  2
#define ID_M  1

tCopKernel PUBLIC ObdInitRamServices (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamMaster (void MEM* pInitParam_p);

extern tObdUnsigned8 bServicesOut_g;

/* ---- callbacks ---------------------------------------------------------------- */

/* What P's NMT callback got back from the calls the AWorks adapter makes. */
static tCopKernel RetInitLgs_g = 0xFFFF;
static tCopKernel RetInitStore_g = 0xFFFF;
static tCopKernel RetArchive_g = 0xFFFF;
static tCopKernel RetConfigEmcp_g = 0xFFFF;
static unsigned uResetComm_g;
static unsigned uEnterPreOp_g;

static tCopKernel PUBLIC AppCbNmtEvent (tNmtEvent NmtEvent_p)
{
    switch (NmtEvent_p)
    {
        case kNmtEvEnterInitialising:
            RetInitLgs_g = CcmInitLgs();
            /* No storage: the adapter logs this; the node runs on from the
             * dictionary's defaults. */
            RetInitStore_g = CcmInitStore();
            return RetInitLgs_g;

        case kNmtEvResetCommunication:
            /* "no valid archive": the application configures its defaults */
            RetArchive_g = CcmStoreCheckArchivState(kObdPartGen);
            uResetComm_g++;
            RetConfigEmcp_g = CcmConfigEmcp(0x80 + ID_P);
            return RetConfigEmcp_g;

        case kNmtEvEnterPreOperational:
            uEnterPreOp_g++;
            return kCopSuccessful;

        default:
            return kCopSuccessful;
    }
}

#define MAX_EMCY 16
static BYTE      abEmccNode_g[MAX_EMCY];
static tEmcParam aEmcc_g[MAX_EMCY];
static unsigned  uEmcc_g;

static tCopKernel PUBLIC EmccCb (BYTE bNodeId_p, tEmcParam MEM* pEmcParam_p)
{
    if (uEmcc_g < MAX_EMCY)
    {
        abEmccNode_g[uEmcc_g] = bNodeId_p;
        aEmcc_g[uEmcc_g++] = *pEmcParam_p;
    }
    return kCopSuccessful;
}

/* ---- helpers -------------------------------------------------------------------- */

/* n ms of bus time, both nodes processing every ms; P stays selected. */
static void Run (unsigned uMs_p)
{
    unsigned i;

    for (i = 0; i < uMs_p; i++)
    {
        SimAdvanceMs(1);
        SimSelectNode(SIM_P);
        (void) CcmProcess();
        SimSelectNode(SIM_M);
        (void) CcmProcess();
    }
    SimSelectNode(SIM_P);
}

static DWORD ReadU32 (WORD wIndex_p, BYTE bSub_p)
{
    DWORD dwValue = 0;
    tObdSize Size = sizeof(dwValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &dwValue, &Size), kCopSuccessful);
    return dwValue;
}

static WORD ReadU16 (WORD wIndex_p, BYTE bSub_p)
{
    WORD wValue = 0;
    tObdSize Size = sizeof(wValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &wValue, &Size), kCopSuccessful);
    return wValue;
}

/* An SDO client's expedited download of 4 bytes (1 byte when bOne_p) to P;
 * checks P's answer: confirmation, or the abort code dwAbort_p. */
static void SdoDownload (WORD wIndex_p, BYTE bSub_p, DWORD dwValue_p, int fOne_p, DWORD dwAbort_p)
{
    BYTE abReq[8];
    BYTE abAnswer[8];

    abReq[0] = fOne_p ? 0x2F : 0x23;
    abReq[1] = (BYTE) wIndex_p;
    abReq[2] = (BYTE) (wIndex_p >> 8);
    abReq[3] = bSub_p;
    abReq[4] = (BYTE) dwValue_p;
    abReq[5] = (BYTE) (dwValue_p >> 8);
    abReq[6] = (BYTE) (dwValue_p >> 16);
    abReq[7] = (BYTE) (dwValue_p >> 24);
    memset(abAnswer, 0, sizeof(abAnswer));
    abAnswer[0] = (dwAbort_p == 0) ? 0x60 : 0x80;
    abAnswer[1] = abReq[1];
    abAnswer[2] = abReq[2];
    abAnswer[3] = bSub_p;
    abAnswer[4] = (BYTE) dwAbort_p;
    abAnswer[5] = (BYTE) (dwAbort_p >> 8);
    abAnswer[6] = (BYTE) (dwAbort_p >> 16);
    abAnswer[7] = (BYTE) (dwAbort_p >> 24);
    TestDrainSent();
    CHECK(SimInject(0x600 + ID_P, 0, 8, abReq) >= 1);
    SimSelectNode(SIM_P);
    (void) CcmProcess();
    TestExpectFrame("SDO answer", 0x580 + ID_P, 8, abAnswer);
}

static unsigned CountSent (DWORD dwId_p)
{
    tSimFrame Frame;
    unsigned n = 0;

    while (SimTakeSentFrame(&Frame))
    {
        if ((Frame.m_dwId == dwId_p) && !Frame.m_bRtr)
        {
            n++;
        }
    }
    return n;
}

/* ---- the tests -------------------------------------------------------------------- */

static void BeforeInit (void)
{
    static CONST BYTE abProducers[1] = { ID_P };
    tTimeOfDay Time = { 0, 0 };

    SimSelectNode(SIM_P);
    CHECK_RET(CcmInitEmcc(), kCopIllegalInstance);
    CHECK_RET(CcmInitEmccEx(EmccCb), kCopIllegalInstance);
    CHECK_RET(CcmEmccDefineProducerTab(abProducers, 1), kCopIllegalInstance);
    CHECK_RET(CcmClearPreDefinedErrorField(), kCopIllegalInstance);
    CHECK_RET(CcmInitLgs(), kCopIllegalInstance);
    CHECK_RET(CcmConfigLgs(100, 3), kCopIllegalInstance);
    CHECK_RET(CcmConfigSyncProducer(0x40000080UL, 1000), kCopIllegalInstance);
    CHECK_RET(CcmTspSend(0x100, &Time), kCopIllegalInstance);
    CHECK_RET(CcmInitStore(), kCopIllegalInstance);
    CHECK_RET(CcmStoreCheckArchivState(kObdPartGen), kCopIllegalInstance);
    CHECK_RET(CcmStoreRestoreDefault(), kCopIllegalInstance);
}

static void StartUp (void)
{
    CHECK_RET(TestInitNode(SIM_P, ID_P, ObdInitRamServices, AppCbNmtEvent), kCopSuccessful);
    /* the calls the AWorks adapter makes from its NMT callback */
    CHECK_RET(RetInitLgs_g, kCopSuccessful);
    CHECK_RET(RetInitStore_g, kCopCcmStoreHwError);
    CHECK_RET(RetArchive_g, kCopCcmStoreHwError);
    CHECK_RET(RetConfigEmcp_g, kCopSuccessful);
    /* the object shows the COB-ID the callback configured (CiA 301 7.5.2.21) */
    CHECK_EQ(ReadU32(0x1014, 0), 0x80 + ID_P);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(TestInitNode(SIM_M, ID_M, ObdInitRamMaster, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    Run(1);
    TestDrainSent();
}

static void EmergencyConsumer (void)
{
    static CONST BYTE abP[1] = { ID_P };
    static CONST BYTE abTwice[2] = { ID_P, ID_P };
    static CONST BYTE abZero[1] = { 0 };
    static CONST BYTE abOwn[1] = { ID_M };
    static CONST BYTE abResetCommP[2] = { 0x82, ID_P };
    BYTE abTooMany[EMCC_MAX_CONSUMER + 1];
    tEmcParam Emcy;
    unsigned i;

    for (i = 0; i < sizeof(abTooMany); i++)
    {
        abTooMany[i] = (BYTE) (10 + i);
    }
    SimSelectNode(SIM_M);
    CHECK_RET(CcmInitEmcc(), kCopSuccessful);
    CHECK_RET(CcmInitEmccEx(EmccCb), kCopSuccessful);
    CHECK_RET(CcmEmccDefineProducerTab(NULL, 1), kCopInvalidParam);
    CHECK_RET(CcmEmccDefineProducerTab(abZero, 1), kCopSuccessful);         /* 0 = unused entry */
    CHECK_RET(CcmEmccDefineProducerTab(abOwn, 1), kCopEmccNodeIdInvalid);
    CHECK_RET(CcmEmccDefineProducerTab(abTwice, 2), kCopEmccNodeIdExist);
    CHECK_RET(CcmEmccDefineProducerTab(abTooMany, (BYTE) sizeof(abTooMany)), kCopEmccNoFreeProducerEntry);
    CHECK_RET(CcmEmccDefineProducerTab(abP, 1), kCopSuccessful);
    /* the consumer's controller receives 0x80 + node-ID now */
    CHECK(SimIsIdDefined(SIM_M, 0x80 + ID_P) != 0);

    SimSelectNode(SIM_P);
    memset(&Emcy, 0, sizeof(Emcy));
    Emcy.m_wEmcyErrorCode = 0x5000;
    Emcy.m_bErrorRegister = 0x01;
    Emcy.m_abManufactErrorCode[0] = 0xA1;
    Emcy.m_abManufactErrorCode[4] = 0xA5;
    Emcy.m_wAdditionalInfo = 0x1234;            /* not part of the frame */
    CHECK_RET(CcmSendEmergency(&Emcy), kCopSuccessful);
    Run(1);
    CHECK_EQ(uEmcc_g, 1);
    CHECK_EQ(abEmccNode_g[0], ID_P);
    CHECK_EQ(aEmcc_g[0].m_wEmcyErrorCode, 0x5000);
    CHECK_EQ(aEmcc_g[0].m_bErrorRegister, 0x01);
    CHECK_EQ(aEmcc_g[0].m_abManufactErrorCode[0], 0xA1);
    CHECK_EQ(aEmcc_g[0].m_abManufactErrorCode[4], 0xA5);
    CHECK_EQ(aEmcc_g[0].m_wAdditionalInfo, 0);
    TestDrainSent();

    /* NMT reset communication of P [82 02]: 0x1014 goes back to 0x80000000,
     * the callback configures it again, and P's emergencies still arrive */
    CHECK(SimInject(0x000, 0, 2, abResetCommP) >= 1);
    Run(5);
    CHECK_EQ(uResetComm_g, 2);
    SimSelectNode(SIM_P);
    CHECK_RET(RetConfigEmcp_g, kCopSuccessful);
    CHECK_EQ(ReadU32(0x1014, 0), 0x80 + ID_P);
    CHECK_RET(CcmSendEmergency(&Emcy), kCopSuccessful);
    Run(1);
    CHECK_EQ(uEmcc_g, 2);
    CHECK_EQ(abEmccNode_g[1], ID_P);
    CHECK_EQ(aEmcc_g[1].m_wEmcyErrorCode, 0x5000);
    TestDrainSent();
}

static void ErrorField (void)
{
    BYTE bOne = 1;

    SimSelectNode(SIM_P);
    CHECK_EQ(TestReadU8(0x1003, 0), 1);                 /* the emergency above */
    CHECK_EQ(ReadU32(0x1003, 1), 0x00A15000UL);        /* code, manufacturer bytes 0-1 */
    CHECK_EQ(TestReadU8(0x1001, 0), 0x01);
    CHECK_RET(CcmClearPreDefinedErrorField(), kCopSuccessful);
    CHECK_EQ(TestReadU8(0x1003, 0), 0);
    CHECK_EQ(ReadU32(0x1003, 1), 0);
    CHECK_EQ(TestReadU8(0x1001, 0), 0);

    /* writing: only 0 (CiA 301), over SDO and through the API */
    CHECK_RET(CcmWriteObject(0x1003, 0, &bOne, 1), kCopInvalidParam);
    SdoDownload(0x1003, 0, 1, 1, 0x06090030UL);
    SdoDownload(0x1003, 0, 0, 1, 0);

    /* the master's dictionary has no 0x1003 */
    SimSelectNode(SIM_M);
    CHECK_RET(CcmClearPreDefinedErrorField(), kCopObdIndexNotExist);
    SimSelectNode(SIM_P);
}

static void LifeGuarding (void)
{
    static CONST BYTE abP[1] = { ID_P };
    tNmtmSlaveParam Guard;

    SimSelectNode(SIM_P);
    CHECK_RET(CcmConfigLgs(10, 2), kCopSuccessful);
    CHECK_EQ(ReadU16(0x100C, 0), 10);
    CHECK_EQ(TestReadU8(0x100D, 0), 2);

    /* M guards P every 10 ms */
    SimSelectNode(SIM_M);
    CHECK_RET(CcmInitNmtm(), kCopSuccessful);
    CHECK_RET(CcmDefineSlaveTab(abP, 1), kCopSuccessful);
    Guard.m_wLifeguardTime = 10;
    Guard.m_bLifeguardFactor = 2;
    CHECK_RET(CcmConfigLgm(ID_P, &Guard), kCopSuccessful);
    uEmcc_g = 0;
    Run(100);
    CHECK_EQ(uEmcc_g, 0);
    /* M stops guarding: after 20 ms P reports the life guarding event */
    SimSelectNode(SIM_M);
    Guard.m_wLifeguardTime = 0;
    CHECK_RET(CcmConfigLgm(ID_P, &Guard), kCopSuccessful);
    Run(30);
    CHECK_EQ(uEmcc_g, 1);
    CHECK_EQ(abEmccNode_g[0], ID_P);
    CHECK_EQ(aEmcc_g[0].m_wEmcyErrorCode, 0x8130);
    CHECK_EQ(aEmcc_g[0].m_bErrorRegister, 0x11);
    Run(100);
    CHECK_EQ(uEmcc_g, 1);                               /* once per loss */
    TestDrainSent();

    /* life guarding and heartbeat exclude each other */
    SimSelectNode(SIM_P);
    CHECK_RET(CcmConfigHbp(100), kCopNmtLifeguardVsHeartbeat);
    CHECK_RET(CcmConfigLgs(0, 0), kCopSuccessful);
    CHECK_RET(CcmConfigHbp(100), kCopSuccessful);
    CHECK_RET(CcmConfigLgs(10, 2), kCopNmtLifeguardVsHeartbeat);
    CHECK_EQ(ReadU16(0x100C, 0), 0);
    CHECK_RET(CcmConfigHbp(0), kCopSuccessful);
}

static void SyncProducer (void)
{
    tSimFrame Frame;
    BYTE bValue;
    BYTE bCount;
    BYTE abCounter[1];

    SimSelectNode(SIM_P);
    CHECK_RET(CcmConfigSyncProducer(0x40000701UL, 1000), kCopInvalidParam);   /* restricted */
    CHECK_EQ(ReadU32(0x1005, 0), 0x80);
    CHECK_RET(CcmConfigSyncProducer(0x40000080UL, 10000), kCopSuccessful);
    CHECK_EQ(ReadU32(0x1005, 0), 0x40000080UL);
    CHECK_EQ(ReadU32(0x1006, 0), 10000);
    TestDrainSent();
    Run(9);
    CHECK_EQ(SimSentPending(), 0);
    Run(1);
    TestExpectFrame("SYNC", 0x080, 0, NULL);

    /* OPERATIONAL: P's synchronous TPDO follows its own SYNC */
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopSuccessful);
    bServicesOut_g = 0x5A;
    TestDrainSent();
    Run(10);
    TestExpectFrame("SYNC", 0x080, 0, NULL);
    CHECK(SimTakeSentFrame(&Frame));
    CHECK_EQ(Frame.m_dwId, 0x180 + ID_P);
    CHECK_EQ(Frame.m_bDlc, 1);
    CHECK_EQ(Frame.m_abData[0], 0x5A);

    /* 0x1019 (CiA 301 7.5.2.22): written only while the cycle period is 0
     * (0x08000022), 1 and 241..255 reserved (0x06090030); with 3 the SYNC
     * carries a counter 1, 2, 3, 1 (CiA 301 7.2.5.2.1) */
    bValue = 3;
    CHECK_RET(CcmWriteObject(0x1019, 0, &bValue, 1), kCopInvalidParam);
    SdoDownload(0x1019, 0, 3, 1, 0x08000022UL);
    CHECK_RET(CcmConfigSyncProducer(0x40000080UL, 0), kCopSuccessful);
    SdoDownload(0x1019, 0, 1, 1, 0x06090030UL);
    SdoDownload(0x1019, 0, 241, 1, 0x06090030UL);
    CHECK_EQ(TestReadU8(0x1019, 0), 0);
    CHECK_RET(CcmWriteObject(0x1019, 0, &bValue, 1), kCopSuccessful);
    CHECK_RET(CcmConfigSyncProducer(0x40000080UL, 10000), kCopSuccessful);
    TestDrainSent();
    for (bCount = 1; bCount <= 4; bCount++)
    {
        abCounter[0] = (BYTE) (((bCount - 1) % 3) + 1);
        Run(10);
        TestExpectFrame("SYNC with counter", 0x080, 1, abCounter);
        TestDrainSent();
    }
    CHECK_RET(CcmConfigSyncProducer(0x40000080UL, 0), kCopSuccessful);
    bValue = 0;
    CHECK_RET(CcmWriteObject(0x1019, 0, &bValue, 1), kCopSuccessful);

    /* without bit 30 this node sends no SYNC */
    CHECK_RET(CcmConfigSyncProducer(0x80, 10000), kCopSuccessful);
    TestDrainSent();
    Run(30);
    CHECK_EQ(CountSent(0x080), 0);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommEnterPreOperational), kCopSuccessful);
}

static void TimeStamp (void)
{
    static CONST BYTE abNoon2024[6] = { 0x00, 0x2E, 0x93, 0x02, 0x12, 0x39 };
    tTimeOfDay Time;

    SimSelectNode(SIM_P);
    TestDrainSent();
    Time.m_dwMs = 43200000UL;                           /* 12:00:00.000 */
    Time.m_wDays = 14610;                               /* 1 January 2024 */
    CHECK_RET(CcmTspSend(0x100, &Time), kCopSuccessful);
    TestExpectFrame("TIME", 0x100, 6, abNoon2024);
    CHECK_RET(CcmTspSend(0x100, NULL), kCopInvalidParam);
    CHECK_RET(CcmTspSend(0x701, &Time), kCopInvalidParam);
    Time.m_dwMs = 86400000UL;                           /* not a time of day */
    CHECK_RET(CcmTspSend(0x100, &Time), kCopInvalidParam);
    CHECK_EQ(SimSentPending(), 0);
}

static void Store (void)
{
    SimSelectNode(SIM_P);
    CHECK_RET(CcmInitStore(), kCopCcmStoreHwError);
    CHECK_RET(CcmStoreCheckArchivState(kObdPartAll), kCopCcmStoreHwError);
    CHECK_RET(CcmStoreCheckArchivState(0x10), kCopObdIllegalPart);
    CHECK_RET(CcmStoreRestoreDefault(), kCopSuccessful);
    /* 0x1010 reads "does not save"; "save" is refused, "load" accepted */
    CHECK_EQ(ReadU32(0x1010, 1), 0);
    SdoDownload(0x1010, 1, 0x65766173UL, 0, 0x08000020UL);
    SdoDownload(0x1011, 1, 0x65766173UL, 0, 0x08000020UL);
    SdoDownload(0x1011, 1, 0x64616F6CUL, 0, 0);
    CHECK_EQ(ReadU32(0x1011, 1), 1);
}

/* 0x1029 (CiA 301 7.5.2.32): the state after a communication error; here
 * the driver's kCdrvBusOff. */
static void ErrorBehaviour (void)
{
    SimSelectNode(SIM_P);
    /* only 0 (pre-operational), 1 (no change) and 2 (stopped) are written */
    SdoDownload(0x1029, 1, 0x03, 1, 0x06090030UL);
    SdoDownload(0x1029, 1, 0x80, 1, 0x06090030UL);
    CHECK_EQ(TestReadU8(0x1029, 1), 1);

    /* 1: a bus-off changes nothing */
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopSuccessful);
    SimRaiseStatus(SIM_P, kCdrvBusOff);
    uEnterPreOp_g = 0;
    Run(5);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    CHECK_EQ(uEnterPreOp_g, 0);
    /* the stack reads the flag and leaves it to the application */
    CHECK_EQ(SimGetStatus(SIM_P) & kCdrvBusOff, kCdrvBusOff);
    CHECK_RET(CdrvResetStatus(kCdrvBusOff), kCopSuccessful);
    Run(1);

    /* 0: the next bus-off leads OPERATIONAL to PRE-OPERATIONAL, once */
    SdoDownload(0x1029, 1, 0x00, 1, 0);
    SimRaiseStatus(SIM_P, kCdrvBusOff);
    Run(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    CHECK_EQ(uEnterPreOp_g, 1);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopSuccessful);
    Run(5);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);

    /* 2: cleared and raised again, the node stops */
    SdoDownload(0x1029, 1, 0x02, 1, 0);
    CHECK_RET(CdrvResetStatus(kCdrvBusOff), kCopSuccessful);
    Run(1);
    SimRaiseStatus(SIM_P, kCdrvBusOff);
    Run(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateStopped);

    CHECK_RET(CdrvResetStatus(kCdrvBusOff), kCopSuccessful);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommEnterPreOperational), kCopSuccessful);
    Run(1);
    SdoDownload(0x1029, 1, 0x01, 1, 0);
    TestDrainSent();
}

int main (void)
{
    SimReset();
    SimSetTrace(1);

    BeforeInit();
    StartUp();
    EmergencyConsumer();
    ErrorField();
    LifeGuarding();
    SyncProducer();
    TimeStamp();
    Store();
    ErrorBehaviour();

    SimSelectNode(SIM_M);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    SimSelectNode(SIM_P);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_services_api");
}
