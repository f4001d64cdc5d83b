/*
 * test_master_api.c - every exported master-side function with success and
 * refusal codes, with a real partner on the simulated bus:
 *
 *   node M (simulated node 0): objdict_master.h, node-ID 1 - NMT master,
 *          heartbeat consumer, SDO client;
 *   node S (simulated node 1): objdict_min.h, node-ID 3 - a slave (boot-up,
 *          node guarding answers, heartbeat producer, SDO server).
 *
 * CcmInitNmtm, CcmInitNmtmEx (boot-up and life-guarding events),
 * CcmDefineSlaveTab, CcmSendNmtCommand, CcmBootNetwork, CcmTriggerNodeGuard,
 * CcmConfigLgm, CcmNmtmGetSlaveInfo, CcmInitHbc, CcmInitHbcEx (connected,
 * lost), CcmHbcDefineProducerTab, CcmHbcGetNodeState,
 * CcmSdocDefineClientTab, CcmSdocStartTransfer (download, upload, block
 * download, block upload, the server's abort, timeout, finish callback),
 * CcmSdocAbort, CcmSdocGetState, SdocGetTransmittedBytes.
 */
#include "test_util.h"

#define SIM_M 0
#define SIM_S 1
#define ID_M  1
#define ID_S  3

tCopKernel PUBLIC ObdInitRamMaster (void MEM* pInitParam_p);

/* ---- callbacks of the master ------------------------------------------------- */

#define MAX_EV 32
static BYTE             abNmtmNode_g[MAX_EV];
static tNmtErrCtrlEvent aNmtmEv_g[MAX_EV];
static unsigned         uNmtm_g;
static BYTE             abHbcNode_g[MAX_EV];
static tNmtErrCtrlEvent aHbcEv_g[MAX_EV];
static unsigned         uHbc_g;

static tCopKernel PUBLIC NmtmCb (BYTE bNodeId_p, tNmtErrCtrlEvent Event_p)
{
    if (uNmtm_g < MAX_EV)
    {
        abNmtmNode_g[uNmtm_g] = bNodeId_p;
        aNmtmEv_g[uNmtm_g++] = Event_p;
    }
    return kCopSuccessful;
}

static tCopKernel PUBLIC HbcCb (BYTE bNodeId_p, tNmtErrCtrlEvent Event_p)
{
    if (uHbc_g < MAX_EV)
    {
        abHbcNode_g[uHbc_g] = bNodeId_p;
        aHbcEv_g[uHbc_g++] = Event_p;
    }
    return kCopSuccessful;
}

static int SawNmtm (BYTE bNode_p, tNmtErrCtrlEvent Event_p)
{
    unsigned i;

    for (i = 0; i < uNmtm_g; i++)
    {
        if ((abNmtmNode_g[i] == bNode_p) && (aNmtmEv_g[i] == Event_p))
        {
            return 1;
        }
    }
    return 0;
}

static int SawHbc (BYTE bNode_p, tNmtErrCtrlEvent Event_p)
{
    unsigned i;

    for (i = 0; i < uHbc_g; i++)
    {
        if ((abHbcNode_g[i] == bNode_p) && (aHbcEv_g[i] == Event_p))
        {
            return 1;
        }
    }
    return 0;
}

static unsigned           uFinished_g;
static tSdocCbFinishParam LastFinish_g;

static void PUBLIC SdocFinished (tSdocCbFinishParam MEM* pParam_p)
{
    uFinished_g++;
    LastFinish_g = *pParam_p;
}

/* ---- helpers -------------------------------------------------------------------- */

/* n ms of bus time, both nodes processing every ms (fSlave_p: S runs). */
static void Run (unsigned uMs_p, int fSlave_p)
{
    unsigned i;

    for (i = 0; i < uMs_p; i++)
    {
        if (fSlave_p)
        {
            SimSelectNode(SIM_S);
            (void) CcmProcess();
        }
        SimSelectNode(SIM_M);
        (void) CcmProcess();
        SimAdvanceMs(1);
    }
    SimSelectNode(SIM_M);
}

static tSdocState SdocState (DWORD* pdwAbort_p)
{
    tSdocState State = 0xFF;

    CHECK_RET(CcmSdocGetState(0x1280, &State, pdwAbort_p), kCopSuccessful);
    return State;
}

/* ---- the tests -------------------------------------------------------------------- */

static void BeforeInit (void)
{
    static CONST BYTE abSlaves[1] = { ID_S };
    tNmtmSlaveParam Guard = { 10, 2 };
    tNmtmSlaveInfo Info;
    tHbcProdParam Producer = { 50, ID_S, 1 };
    tSdocParam Client;
    tSdocTransferParam Transfer;
    tSdocState State;
    DWORD dwValue = 0;
    BYTE bState = 0;

    memset(&Client, 0, sizeof(Client));
    memset(&Transfer, 0, sizeof(Transfer));
    Transfer.m_pData = &dwValue;
    Transfer.m_DataLen = 4;
    SimSelectNode(SIM_M);
    CHECK_RET(CcmInitNmtm(), kCopIllegalInstance);
    CHECK_RET(CcmInitNmtmEx(NmtmCb), kCopIllegalInstance);
    CHECK_RET(CcmDefineSlaveTab(abSlaves, 1), kCopIllegalInstance);
    CHECK_RET(CcmSendNmtCommand(0, kNmtCommStartRemoteNode), kCopIllegalInstance);
    CHECK_RET(CcmBootNetwork(), kCopIllegalInstance);
    CHECK_RET(CcmTriggerNodeGuard(ID_S), kCopIllegalInstance);
    CHECK_RET(CcmConfigLgm(ID_S, &Guard), kCopIllegalInstance);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopIllegalInstance);
    CHECK_RET(CcmInitHbc(), kCopIllegalInstance);
    CHECK_RET(CcmInitHbcEx(HbcCb), kCopIllegalInstance);
    CHECK_RET(CcmHbcDefineProducerTab(&Producer, 1), kCopIllegalInstance);
    CHECK_RET(CcmHbcGetNodeState(ID_S, &bState), kCopIllegalInstance);
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopIllegalInstance);
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopIllegalInstance);
    CHECK_RET(CcmSdocAbort(0x1280, 0), kCopIllegalInstance);
    CHECK_RET(CcmSdocGetState(0x1280, &State, &dwValue), kCopIllegalInstance);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, &dwValue), kCopIllegalInstance);
}

static void StartUp (void)
{
    static CONST BYTE abSlaves[1] = { ID_S };
    static CONST BYTE abTwice[2] = { ID_S, ID_S };
    static CONST BYTE abZero[1] = { 0 };
    static CONST BYTE ab128[1] = { 128 };
    static CONST BYTE abFive[5] = { 3, 4, 5, 6, 7 };
    static CONST BYTE abStart3[2] = { 0x01, ID_S };
    tNmtmSlaveInfo Info;

    CHECK_RET(TestInitNode(SIM_M, ID_M, ObdInitRamMaster, NULL), kCopSuccessful);
    CHECK_RET(CcmInitNmtm(), kCopSuccessful);
    CHECK_RET(CcmInitNmtmEx(NmtmCb), kCopSuccessful);
    CHECK_RET(CcmInitHbc(), kCopSuccessful);
    CHECK_RET(CcmInitHbcEx(HbcCb), kCopSuccessful);
    /* not connected yet: no NMT command leaves the node */
    CHECK_RET(CcmSendNmtCommand(ID_S, kNmtCommStartRemoteNode), kCopNmtStateError);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);

    /* the slave table */
    CHECK_RET(CcmDefineSlaveTab(NULL, 1), kCopInvalidParam);
    CHECK_RET(CcmDefineSlaveTab(abTwice, 2), kCopNmtmSlaveNodeExist);
    CHECK_RET(CcmDefineSlaveTab(abZero, 1), kCopSuccessful);                 /* 0 = unused entry */
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopNmtmSlaveEntryNotExist);
    CHECK_RET(CcmDefineSlaveTab(ab128, 1), kCopNmtmInvalidSlaveNodeId);
    CHECK_RET(CcmDefineSlaveTab(abFive, 5), kCopNmtmNoFreeSlaveEntry);      /* NMTM_MAX_SLAVE_ENTRIES 4 */
    CHECK_RET(CcmDefineSlaveTab(abSlaves, 1), kCopSuccessful);

    /* the slave boots: the master's callback hears it */
    CHECK_RET(TestInitNode(SIM_S, ID_S, ObdInitRamMin, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    Run(1, 1);
    CHECK(SawNmtm(ID_S, kNmtErrCtrlEvBootupReceived));
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveNodeState, 0);                /* boot-up */
    CHECK(Info.m_bSlaveState & kNmtmBootupReceived);
    TestDrainSent();

    /* NMT commands */
    CHECK_RET(CcmSendNmtCommand(ID_S, kNmtCommStartRemoteNode), kCopSuccessful);
    TestExpectFrame("NMT start node 3", 0x000, 2, abStart3);
    CHECK_RET(CcmSendNmtCommand(ID_S, 0x0077), kCopNmtUnknownCommand);
    CHECK_RET(CcmSendNmtCommand(128, kNmtCommStartRemoteNode), kCopNmtmInvalidSlaveNodeId);
    Run(1, 1);
    SimSelectNode(SIM_S);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    SimSelectNode(SIM_M);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);   /* addressed node 3 only */
    CHECK_RET(CcmSendNmtCommand(0, kNmtCommEnterPreOperational), kCopSuccessful);
    Run(1, 1);
    SimSelectNode(SIM_S);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    SimSelectNode(SIM_M);
    CHECK_RET(CcmBootNetwork(), kCopSuccessful);        /* start all: also this node */
    Run(1, 1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    SimSelectNode(SIM_S);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    SimSelectNode(SIM_M);
    TestDrainSent();
}

static void Guarding (void)
{
    static CONST BYTE abAnswer[1] = { 0x05 };
    tNmtmSlaveParam Guard;
    tNmtmSlaveInfo Info;
    tSimFrame Frame;

    /* one guard request, the slave answers "operational" (toggle 0) */
    CHECK_RET(CcmTriggerNodeGuard(ID_S), kCopSuccessful);
    CHECK(SimTakeSentFrame(&Frame));
    CHECK_EQ(Frame.m_dwId, 0x700 + ID_S);
    CHECK_EQ(Frame.m_bRtr, 1);
    CHECK_RET(CcmTriggerNodeGuard(9), kCopNmtmSlaveEntryNotExist);
    CHECK_RET(CcmTriggerNodeGuard(200), kCopNmtmInvalidSlaveNodeId);
    Run(1, 1);
    TestExpectFrame("guard answer", 0x700 + ID_S, 1, abAnswer);
    memset(&Info, 0xEE, sizeof(Info));
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveNodeState, kNodeStateOperational);
    CHECK_EQ(Info.m_bLostMsgCount, 0);
    /* nmtm.h bits: used, answer received, fresh; toggle 0 */
    CHECK_EQ(Info.m_bSlaveState & (kNmtmStateUsed | kNmtmLgReceived | kNmtmUpdate | kNmtmStateToggleBit),
             kNmtmStateUsed | kNmtmLgReceived | kNmtmUpdate);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState & kNmtmUpdate, 0);      /* the read cleared it */
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, NULL), kCopInvalidParam);
    CHECK_RET(CcmNmtmGetSlaveInfo(9, &Info), kCopNmtmSlaveEntryNotExist);
    CHECK_RET(CcmNmtmGetSlaveInfo(0, &Info), kCopNmtmInvalidSlaveNodeId);

    /* life guarding: 10 ms, factor 2; answered while the slave runs */
    Guard.m_wLifeguardTime = 10;
    Guard.m_bLifeguardFactor = 2;
    CHECK_RET(CcmConfigLgm(ID_S, NULL), kCopInvalidParam);
    CHECK_RET(CcmConfigLgm(9, &Guard), kCopNmtmSlaveEntryNotExist);
    CHECK_RET(CcmConfigLgm(ID_S, &Guard), kCopSuccessful);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState & (kNmtmStateLgActive | kNmtmStateNgActive | kNmtmLgReceived),
             kNmtmStateLgActive | kNmtmStateNgActive);
    CHECK_EQ(Info.m_bLostMsgCount, 0);
    Run(50, 1);
    CHECK(!SawNmtm(ID_S, kNmtErrCtrlEvLgNoAnswer));
    CHECK(!SawNmtm(ID_S, kNmtErrCtrlEvLgToggleError));
    /* the slave goes silent: after two unanswered requests */
    Run(40, 0);
    CHECK(SawNmtm(ID_S, kNmtErrCtrlEvLgNoAnswer));
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK(Info.m_bLostMsgCount >= 2);
    /* guarding off */
    Guard.m_wLifeguardTime = 0;
    CHECK_RET(CcmConfigLgm(ID_S, &Guard), kCopSuccessful);
    SimSelectNode(SIM_S);
    TestDrainSent();
    TestProcess(2);                                     /* the slave answers what is queued */
    SimSelectNode(SIM_M);
    Run(5, 1);
    TestDrainSent();
}

static void Heartbeat (void)
{
    tHbcProdParam aProducer[2];
    BYTE bState = 0;
    DWORD dwEntry = 0;
    tObdSize Size = sizeof(dwEntry);

    /* the slave produces every 20 ms */
    SimSelectNode(SIM_S);
    CHECK_RET(CcmConfigHbp(20), kCopSuccessful);
    SimSelectNode(SIM_M);

    aProducer[0].wHeartbeatTime_p = 50;
    aProducer[0].bProducerNodeId_p = ID_S;
    aProducer[0].bSubindex_p = 1;
    aProducer[1] = aProducer[0];
    aProducer[1].bSubindex_p = 2;
    CHECK_RET(CcmHbcDefineProducerTab(NULL, 1), kCopInvalidParam);
    CHECK_RET(CcmHbcDefineProducerTab(aProducer, 2), kCopHbcEntryAlreadyExist);   /* node 3 twice */
    aProducer[1].bSubindex_p = 0;
    aProducer[1].bProducerNodeId_p = 4;
    CHECK_RET(CcmHbcDefineProducerTab(&aProducer[1], 1), kCopHbcNoFreeEntry);     /* subindex 0 */
    aProducer[1].bSubindex_p = 3;
    CHECK_RET(CcmHbcDefineProducerTab(&aProducer[1], 1), kCopHbcNoFreeEntry);     /* 0x1016 has 2 */
    CHECK_RET(CcmHbcGetNodeState(ID_S, &bState), kCopHbcEntryNotExist);           /* not supervised */
    CHECK_RET(CcmHbcDefineProducerTab(aProducer, 1), kCopSuccessful);
    CHECK_RET(CcmReadObject(0x1016, 1, &dwEntry, &Size), kCopSuccessful);
    CHECK_EQ(dwEntry, ((DWORD) ID_S << 16) | 50);

    Run(30, 1);
    CHECK(SawHbc(ID_S, kNmtErrCtrlEvHbcConnected));
    CHECK_RET(CcmHbcGetNodeState(ID_S, &bState), kCopSuccessful);
    CHECK_EQ(bState, kNodeStateOperational);
    CHECK_RET(CcmHbcGetNodeState(ID_S, NULL), kCopInvalidParam);
    CHECK_RET(CcmHbcGetNodeState(9, &bState), kCopHbcEntryNotExist);

    /* the slave goes silent for more than 50 ms */
    Run(80, 0);
    CHECK(SawHbc(ID_S, kNmtErrCtrlEvHbcConnectionLost));
    /* from the loss on the node is "disconnected" (0x01, the node state of
       DS 301 v3 node guarding; README, behaviour decisions), not the last
       state it reported; a master that only polls sees it stopped */
    bState = 0;
    CHECK_RET(CcmHbcGetNodeState(ID_S, &bState), kCopSuccessful);
    CHECK_EQ(bState, 0x01);
    Run(30, 0);
    CHECK_RET(CcmHbcGetNodeState(ID_S, &bState), kCopSuccessful);
    CHECK_EQ(bState, 0x01);
    /* until its next heartbeat */
    uHbc_g = 0;
    Run(30, 1);
    CHECK(SawHbc(ID_S, kNmtErrCtrlEvHbcConnected));
    CHECK_RET(CcmHbcGetNodeState(ID_S, &bState), kCopSuccessful);
    CHECK_EQ(bState, kNodeStateOperational);

    SimSelectNode(SIM_S);
    CHECK_RET(CcmConfigHbp(0), kCopSuccessful);
    TestProcess(1);
    SimSelectNode(SIM_M);
    aProducer[0].wHeartbeatTime_p = 0;                  /* supervision off */
    CHECK_RET(CcmHbcDefineProducerTab(aProducer, 1), kCopSuccessful);
    Run(2, 1);
    TestDrainSent();
}

static void SdoClient (void)
{
    static CONST BYTE abDownload[8] = { 0x2F, 0x00, 0x62, 0x01, 0xFF, 0x00, 0x00, 0x00 };
    static CONST BYTE abUpload[8] = { 0x40, 0x18, 0x10, 0x02, 0x00, 0x00, 0x00, 0x00 };
    tSdocParam Client;
    tSdocTransferParam Transfer;
    tSdocState State;
    BYTE abData[4];
    BYTE bOut = 0xFF;
    DWORD dwAbort = 0;
    DWORD dwBytes = 0;

    /* the client channel: predefined connection set of node 3 */
    memset(&Client, 0, sizeof(Client));
    Client.m_bValidFlags = kSdocValidFlagServerNodeId;
    Client.m_wClientIndex = 0x1280;
    Client.m_bServerNodeId = ID_S;
    CHECK_RET(CcmSdocDefineClientTab(NULL, 1), kCopInvalidParam);
    /* 29-bit identifiers need a CAN 2.0B build (CDRV_CAN_SPEC; this one is
     * CAN20A, so tCanId is a WORD): refused, not cut to 16 bits */
    Client.m_bValidFlags = kSdocValidFlagRxCanId | kSdocValidFlagTxCanId;
    Client.m_dwTxCanId = 0x21234603UL;
    Client.m_dwRxCanId = 0x21234583UL;
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSdocInvalidParam);
    Client.m_bValidFlags = kSdocValidFlagServerNodeId;
    Client.m_wClientIndex = 0x1281;
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSdocClientNotExist);     /* SDO_MAX_CLIENT_IN_OBD 1 */
    Client.m_wClientIndex = 0x1280;
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSuccessful);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferNotActive);

    /* expedited download 0x6200/1 = 0xFF (seed 004, example 1) */
    memset(&Transfer, 0, sizeof(Transfer));
    Transfer.m_wClientIndex = 0x1280;
    Transfer.m_wObjIndex = 0x6200;
    Transfer.m_bObjSubIndex = 1;
    Transfer.m_pData = &bOut;
    Transfer.m_DataLen = 1;
    Transfer.m_SdocType = kSdocTypeSegDown;
    Transfer.m_pfnCbFinished = SdocFinished;
    CHECK_RET(CcmSdocStartTransfer(NULL), kCopInvalidParam);
    Transfer.m_SdocType = kSdocTypeBlockUp + 1;        /* no tSdocType */
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSdocInvalidParam);
    Transfer.m_SdocType = kSdocTypeSegDown;
    Transfer.m_wClientIndex = 0x1281;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSdocClientNotExist);
    Transfer.m_wClientIndex = 0x1280;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestExpectFrame("SDO download 0x6200/1", 0x600 + ID_S, 8, abDownload);
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSdocBusy);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferRunning);
    Run(2, 1);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferFinished);
    CHECK_EQ(dwAbort, 0);
    CHECK_EQ(uFinished_g, 1);
    CHECK_EQ(LastFinish_g.m_wClientIndex, 0x1280);
    CHECK_EQ(LastFinish_g.m_SdocState, kSdocTransferFinished);
    SimSelectNode(SIM_S);
    CHECK_EQ(TestReadU8(0x6200, 1), 0xFF);
    SimSelectNode(SIM_M);
    TestDrainSent();

    /* expedited upload 0x1018/2: the product code, as the bytes travel */
    memset(abData, 0, sizeof(abData));
    Transfer.m_wObjIndex = 0x1018;
    Transfer.m_bObjSubIndex = 2;
    Transfer.m_pData = abData;
    Transfer.m_DataLen = sizeof(abData);
    Transfer.m_SdocType = kSdocTypeSegUp;
    Transfer.m_pfnCbFinished = NULL;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestExpectFrame("SDO upload 0x1018/2", 0x600 + ID_S, 8, abUpload);
    Run(2, 1);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferFinished);
    CHECK_EQ(abData[0], 0x02);
    CHECK_EQ(abData[1], 0x00);
    CHECK_EQ(abData[2], 0x00);
    CHECK_EQ(abData[3], 0x00);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, &dwBytes), kCopSuccessful);
    CHECK_EQ(dwBytes, 4);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, NULL), kCopInvalidParam);
    CHECK_RET(SdocGetTransmittedBytes(0x1281, &dwBytes), kCopSdocClientNotExist);
    CHECK_EQ(uFinished_g, 1);                           /* no callback given this time */
    TestDrainSent();

    /* the server refuses: object does not exist */
    Transfer.m_wObjIndex = 0x1FFF;
    Transfer.m_bObjSubIndex = 0;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    Run(2, 1);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferRxAborted);
    CHECK_EQ(dwAbort, SDOAC_OBJECT_NOT_EXIST);
    TestDrainSent();

    /* the client aborts a running transfer */
    Transfer.m_wObjIndex = 0x1018;
    Transfer.m_bObjSubIndex = 1;
    CHECK_RET(CcmSdocAbort(0x1280, SDOAC_GENERAL_ERROR), kCopSdocTransferError);   /* nothing running */
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestDrainSent();
    CHECK_RET(CcmSdocAbort(0x1281, SDOAC_GENERAL_ERROR), kCopSdocClientNotExist);
    CHECK_RET(CcmSdocAbort(0x1280, SDOAC_GENERAL_ERROR), kCopSuccessful);
    {
        static CONST BYTE abAbort[8] = { 0x80, 0x18, 0x10, 0x01, 0x00, 0x00, 0x00, 0x08 };
        TestExpectFrame("SDO abort from the client", 0x600 + ID_S, 8, abAbort);
    }
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferTxAborted);
    CHECK_EQ(dwAbort, SDOAC_GENERAL_ERROR);
    Run(2, 1);
    TestDrainSent();

    /* no answer: the client's timeout (100 ms) */
    Transfer.m_TimeOut = 1000;                          /* ticks of 100 us */
    Transfer.m_pfnCbFinished = SdocFinished;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    Run(150, 0);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferTxAborted);
    CHECK_EQ(dwAbort, SDOAC_TIME_OUT);
    CHECK_EQ(uFinished_g, 2);
    CHECK_EQ(LastFinish_g.m_dwAbortCode, SDOAC_TIME_OUT);
    CHECK_RET(CcmSdocGetState(0x1280, NULL, &dwAbort), kCopInvalidParam);
    CHECK_RET(CcmSdocGetState(0x1280, &State, NULL), kCopInvalidParam);
    CHECK_RET(CcmSdocGetState(0x1281, &State, &dwAbort), kCopSdocClientNotExist);
    TestDrainSent();
}

/* A master that gives up on an absent server before the client's own
 * timeout and defines the client again (as a master adapter does at start
 * with slaves missing): the running transfer ends as CcmSdocAbort ends it
 * (abort frame to the server with SDOAC_GENERAL_ERROR, the finish callback
 * told before CcmSdocDefineClientTab returns) and the new definition is
 * taken, so the next transfer starts. */
static void SdoClientRedefined (void)
{
    /* CiA 301 7.2.4.3.2: ccs 2 initiate upload, 0x1018 sub 1 */
    static CONST BYTE abUpload[8] = { 0x40, 0x18, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00 };
    /* CiA 301 7.2.4.3.17: cs 4 abort, the same multiplexer, code LE */
    static CONST BYTE abAbort[8] = { 0x80, 0x18, 0x10, 0x01, 0x00, 0x00, 0x00, 0x08 };
    tSdocParam Client;
    tSdocTransferParam Transfer;
    BYTE abData[4];
    DWORD dwAbort = 0;
    unsigned uBefore;

    TestDrainSent();
    memset(&Client, 0, sizeof(Client));
    Client.m_bValidFlags = kSdocValidFlagServerNodeId;
    Client.m_wClientIndex = 0x1280;
    Client.m_bServerNodeId = 5;                         /* no such node */
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSuccessful);

    memset(&Transfer, 0, sizeof(Transfer));
    Transfer.m_wClientIndex = 0x1280;
    Transfer.m_wObjIndex = 0x1018;
    Transfer.m_bObjSubIndex = 1;
    Transfer.m_pData = abData;
    Transfer.m_DataLen = sizeof(abData);
    Transfer.m_SdocType = kSdocTypeSegUp;
    Transfer.m_pfnCbFinished = SdocFinished;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestExpectFrame("SDO upload to the absent node 5", 0x605, 8, abUpload);
    Run(50, 0);                                         /* no answer, not timed out */
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferRunning);

    /* defined again, for node ID_S */
    uBefore = uFinished_g;
    Client.m_bServerNodeId = ID_S;
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSuccessful);
    TestExpectFrame("SDO abort to node 5", 0x605, 8, abAbort);
    CHECK_EQ(uFinished_g, uBefore + 1);
    CHECK_EQ(LastFinish_g.m_wClientIndex, 0x1280);
    CHECK_EQ(LastFinish_g.m_SdocState, kSdocTransferTxAborted);
    CHECK_EQ(LastFinish_g.m_dwAbortCode, SDOAC_GENERAL_ERROR);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferTxAborted);
    CHECK_EQ(dwAbort, SDOAC_GENERAL_ERROR);

    /* the new definition is in force: the next transfer goes to node ID_S */
    memset(abData, 0, sizeof(abData));
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestExpectFrame("SDO upload to node 3", 0x600 + ID_S, 8, abUpload);
    Run(2, 1);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferFinished);
    CHECK_EQ(uFinished_g, uBefore + 2);
    CHECK_EQ(LastFinish_g.m_SdocState, kSdocTransferFinished);
    /* no frame left over for node 5: the old transfer is over */
    Run(1200, 0);
    CHECK_EQ(uFinished_g, uBefore + 2);
    TestDrainSent();
}

/* kSdocTypeBlockDown / kSdocTypeBlockUp (CiA 301 SDO block download and
 * block upload protocols) against the slave's server. */
static void SdoBlock (void)
{
    /* C6: ccs 6, CRC supported, size indicated; size 2 */
    static CONST BYTE abInitDown[8] = { 0xC6, 0x17, 0x10, 0x00, 0x02, 0x00, 0x00, 0x00 };
    /* A4: ccs 5, CRC supported; blksize, pst 0 */
    static CONST BYTE abInitUp[8] = { 0xA4, 0x18, 0x10, 0x02, SDO_BLOCKSIZE_UPLOAD, 0x00, 0x00, 0x00 };
    /* C6: scs 6, CRC supported, size indicated; 4 bytes */
    static CONST BYTE abInitUpResp[8] = { 0xC6, 0x18, 0x10, 0x02, 0x04, 0x00, 0x00, 0x00 };
    tSdocTransferParam Transfer;
    BYTE abHeartbeat[2] = { 0xE8, 0x03 };               /* 1000 ms */
    BYTE abData[8];
    WORD wHeartbeat = 0;
    tObdSize Size = sizeof(wHeartbeat);
    DWORD dwAbort = 0;
    DWORD dwBytes = 0;

    Run(5, 1);
    TestDrainSent();
    uFinished_g = 0;

    memset(&Transfer, 0, sizeof(Transfer));
    Transfer.m_wClientIndex = 0x1280;
    Transfer.m_wObjIndex = 0x1017;
    Transfer.m_bObjSubIndex = 0;
    Transfer.m_pData = abHeartbeat;
    Transfer.m_DataLen = sizeof(abHeartbeat);
    Transfer.m_SdocType = kSdocTypeBlockDown;
    Transfer.m_pfnCbFinished = SdocFinished;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestExpectFrame("SDO block download initiate 0x1017", 0x600 + ID_S, 8, abInitDown);
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSdocBusy);
    Run(6, 1);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferFinished);
    CHECK_EQ(dwAbort, 0);
    CHECK_EQ(uFinished_g, 1);
    CHECK_EQ(LastFinish_g.m_SdocState, kSdocTransferFinished);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, &dwBytes), kCopSuccessful);
    CHECK_EQ(dwBytes, 2);
    SimSelectNode(SIM_S);
    CHECK_RET(CcmReadObject(0x1017, 0, &wHeartbeat, &Size), kCopSuccessful);
    CHECK_EQ(wHeartbeat, 1000);
    SimSelectNode(SIM_M);
    TestDrainSent();

    memset(abData, 0xEE, sizeof(abData));
    Transfer.m_wObjIndex = 0x1018;
    Transfer.m_bObjSubIndex = 2;
    Transfer.m_pData = abData;
    Transfer.m_DataLen = sizeof(abData);
    Transfer.m_SdocType = kSdocTypeBlockUp;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestExpectFrame("SDO block upload initiate 0x1018/2", 0x600 + ID_S, 8, abInitUp);
    SimSelectNode(SIM_S);
    (void) CcmProcess();
    TestExpectFrame("SDO block upload initiate response", 0x580 + ID_S, 8, abInitUpResp);
    Run(6, 1);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferFinished);
    CHECK_EQ(dwAbort, 0);
    CHECK_EQ(uFinished_g, 2);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, &dwBytes), kCopSuccessful);
    CHECK_EQ(dwBytes, 4);
    CHECK_EQ(abData[0], 0x02);                          /* product code 0x00000002 */
    CHECK_EQ(abData[1], 0x00);
    CHECK_EQ(abData[3], 0x00);
    CHECK_EQ(abData[4], 0xEE);                          /* nothing past the value */
    CHECK_EQ(abData[7], 0xEE);

    /* the server's refusal: 0x1000 is read-only */
    Transfer.m_wObjIndex = 0x1000;
    Transfer.m_bObjSubIndex = 0;
    Transfer.m_DataLen = 4;
    Transfer.m_SdocType = kSdocTypeBlockDown;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    Run(3, 1);
    CHECK_EQ(SdocState(&dwAbort), kSdocTransferRxAborted);
    CHECK_EQ(dwAbort, SDOAC_WRITE_TO_READ_ONLY_OBJ);
    TestDrainSent();
}

int main (void)
{
    SimReset();
    SimSetTrace(1);

    BeforeInit();
    StartUp();
    Guarding();
    Heartbeat();
    SdoClient();
    SdoClientRedefined();
    SdoBlock();

    SimSelectNode(SIM_S);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    SimSelectNode(SIM_M);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_master_api");
}
