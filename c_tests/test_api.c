/*
 * test_api.c - every exported function of cop.h called from C: at least one
 * success and one refusal with its exact tCopKernel code (NULL pointers,
 * calls before CcmInitCANopen, bad node-IDs, unknown indices, wrong
 * states), including the private ObdInitRam contract (tObdRamParam) that
 * CcmInitCANopen checks: failing init function, foreign configuration
 * signature, unsorted tables.
 */
#include "test_util.h"
#include "cop_config.h"
#include "obdcfg.h"

#define NODE_ID 4

/* ---- init functions that break the tObdRamParam contract ----------------- */

static tCopKernel PUBLIC FailingObdInitRam (void MEM* pInitParam_p)
{
    (void) pInitParam_p;
    return kCopObdIllegalPart;
}

static CONST BYTE bForeignSignature_g = 0;

static tCopKernel PUBLIC ForeignSignatureObdInitRam (void MEM* pInitParam_p)
{
    tCopKernel Ret = ObdInitRam(pInitParam_p);
    ((tObdRamParam*) pInitParam_p)->m_pbAbiSignature = &bForeignSignature_g;
    return Ret;
}

/* A generic part whose indices are not ascending. */
static CONST DWORD dwZero_g = 0;
static CONST tObdSubEntry aSub_g[1] = {
    { 0, kObdTypUInt32, kObdAccCR, kObdKindRom, 4, &dwZero_g, NULL } };
static CONST tObdEntry aUnsorted_g[3] = {
    { 0x1018, aSub_g, 1, NULL },
    { 0x1000, aSub_g, 1, NULL },
    { OBD_TABLE_INDEX_END, NULL, 0, NULL } };

static tCopKernel PUBLIC UnsortedObdInitRam (void MEM* pInitParam_p)
{
    tCopKernel Ret = ObdInitRam(pInitParam_p);
    ((tObdRamParam*) pInitParam_p)->m_pGenericPart = aUnsorted_g;
    return Ret;
}

/* A subindex whose storage is missing. */
static CONST tObdSubEntry aBadSub_g[1] = {
    { 0, kObdTypUInt32, kObdAccRW, kObdKindRam, 4, NULL, NULL } };
static CONST tObdEntry aBadEntry_g[2] = {
    { 0x1000, aBadSub_g, 1, NULL },
    { OBD_TABLE_INDEX_END, NULL, 0, NULL } };

static tCopKernel PUBLIC BadEntryObdInitRam (void MEM* pInitParam_p)
{
    tCopKernel Ret = ObdInitRam(pInitParam_p);
    ((tObdRamParam*) pInitParam_p)->m_pGenericPart = aBadEntry_g;
    return Ret;
}

/* ---- callbacks ---------------------------------------------------------------- */

static unsigned   uErrorCallbacks_g;
static tCopKernel LastError_g;
static int        fNmtFails_g;

static tCopKernel PUBLIC ErrorCallback (void MEM* pArg_p, tCopKernel ErrorCode_p)
{
    (void) pArg_p;
    uErrorCallbacks_g++;
    LastError_g = ErrorCode_p;
    return kCopSuccessful;
}

static tCopKernel PUBLIC NmtCallback (tNmtEvent NmtEvent_p)
{
    (void) TestNmtRecorder(NmtEvent_p);
    return fNmtFails_g ? kCopNoResource : kCopSuccessful;
}

/* ---- before CcmInitCANopen ------------------------------------------------------ */

static void BeforeInit (void)
{
    BYTE abBuf[4];
    tObdSize Size = sizeof(abBuf);
    tEmcParam Emcy;
    tVarParam Var;
    WORD wIndex = 0;
    BYTE bState = 0;

    memset(&Emcy, 0, sizeof(Emcy));
    memset(&Var, 0, sizeof(Var));
    CHECK_EQ(CopGetStackVersion(), DEFINED_STACK_VERSION);
    CHECK_RET(CcmShutDownCANopen(), kCopIllegalInstance);
    CHECK_RET(CcmConnectToNet(), kCopIllegalInstance);
    CHECK_RET(CcmProcess(), kCopIllegalInstance);
    CHECK_RET(CcmReadObject(0x1000, 0, abBuf, &Size), kCopIllegalInstance);
    CHECK_RET(CcmWriteObject(0x1017, 0, abBuf, 2), kCopIllegalInstance);
    CHECK_EQ(CcmObdGetNodeState(), 0);
    CHECK_EQ(CcmLsssGetNodeId(), 0);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopIllegalInstance);
    CcmRegisterErrorCallback(NULL);                 /* no stack: kept for the next one */
    CHECK_RET(CcmConfigHbp(100), kCopIllegalInstance);
    CHECK_RET(CcmConfigEmcp(0x80 + NODE_ID), kCopIllegalInstance);
    CHECK_RET(CcmSendEmergency(&Emcy), kCopIllegalInstance);
    CHECK_RET(CcmDefineVarTab(&Var, 1), kCopIllegalInstance);
    /* the other stack functions */
    CHECK_RET(CcmInitNmtm(), kCopIllegalInstance);
    CHECK_RET(CcmInitNmtmEx(NULL), kCopIllegalInstance);
    CHECK_RET(CcmSendNmtCommand(0, kNmtCommStartRemoteNode), kCopIllegalInstance);
    CHECK_RET(CcmBootNetwork(), kCopIllegalInstance);
    CHECK_RET(CcmTriggerNodeGuard(3), kCopIllegalInstance);
    CHECK_RET(CcmInitHbc(), kCopIllegalInstance);
    CHECK_RET(CcmInitHbcEx(NULL), kCopIllegalInstance);
    CHECK_RET(CcmSdocAbort(0x1280, 0), kCopIllegalInstance);
    CHECK_RET(CcmSignalStaticPdo(0x1800), kCopIllegalInstance);
    CHECK_RET(CcmSignalCheckVar(), kCopIllegalInstance);
    CHECK_RET(CcmSendPdo(0x1800), kCopIllegalInstance);
    CHECK_RET(CcmInitSyncConsumer(), kCopIllegalInstance);
    CHECK_RET(CcmSendSrdo(0x1301), kCopIllegalInstance);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopIllegalInstance);
    CHECK_RET(CcmSendGfc(), kCopIllegalInstance);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopIllegalInstance);
    CHECK_RET(CcmSetSrdoState(0, 0x1301), kCopIllegalInstance);
    CHECK_RET(DynDestroyOd(), kCopIllegalInstance);
}

/* ---- CcmInitCANopen ---------------------------------------------------------------- */

static void InitRefusals (void)
{
    tCcmInitParam Init;

    CHECK_RET(CcmInitCANopen(NULL, kCcmFirstInstance), kCopInvalidParam);
    memset(&Init, 0, sizeof(Init));
    Init.m_bInitNodeId = NODE_ID;
    CHECK_RET(CcmInitCANopen(&Init, kCcmFirstInstance), kCopInvalidParam);      /* no m_fpObdInitRam */
    /* a tCcmInitCall that is none of the four (cop_types.h) */
    Init.m_fpObdInitRam = ObdInitRam;
    CHECK_RET(CcmInitCANopen(&Init, 7), kCopInvalidParam);
    CHECK_RET(CcmInitCANopen(&Init, 4), kCopInvalidParam);
    Init.m_fpObdInitRam = NULL;
    CHECK_RET(TestInitNode(0, 0, ObdInitRam, NULL), kCopInvalidNodeId);
    CHECK_RET(TestInitNode(0, 128, ObdInitRam, NULL), kCopInvalidNodeId);
    CHECK_RET(TestInitNode(0, NODE_ID, FailingObdInitRam, NULL), kCopInvalidParam);
    CHECK_RET(TestInitNode(0, NODE_ID, ForeignSignatureObdInitRam, NULL), kCopWrongSignature);
    CHECK_RET(TestInitNode(0, NODE_ID, UnsortedObdInitRam, NULL), kCopObdIllegalPart);
    CHECK_RET(TestInitNode(0, NODE_ID, BadEntryObdInitRam, NULL), kCopObdUnknownObjectType);
    CHECK_EQ(SimRxCapacity(0, 0), 0);       /* the driver was never initialised */
    CHECK_RET(CcmProcess(), kCopIllegalInstance);
}

/* ---- the core API on a running node --------------------------------------------------------- */

static void CoreApi (void)
{
    static CONST BYTE abEmcy[8] = { 0x10, 0x81, 0x11, 0x01, 0x02, 0x03, 0x04, 0x05 };
    BYTE abBuf[8];
    tObdSize Size;
    tEmcParam Emcy;
    WORD wValue;

    TestNmtClear();
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, NmtCallback), kCopSuccessful);
    CHECK_EQ(uTestNmtEventCount_g, 5);
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, NmtCallback), kCopNoFreeInstance);
    CHECK_EQ(SimRxCapacity(0, 1), CDRV_MAX_RX_BUFF_ENTRIES_HIGH);     /* objdef.h's buffers */
    CHECK_EQ(SimRxCapacity(0, 0), CDRV_MAX_RX_BUFF_ENTRIES_LOW);
    CHECK_EQ(CcmLsssGetNodeId(), NODE_ID);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateInitialisation);
    CHECK_RET(CcmProcess(), kCopSuccessful);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopNmtStateError);   /* not connected */

    /* emergency: not before connecting, then on the configured COB-ID */
    memset(&Emcy, 0, sizeof(Emcy));
    Emcy.m_wEmcyErrorCode = 0x8110;     /* CAN overrun */
    Emcy.m_bErrorRegister = 0x11;
    Emcy.m_abManufactErrorCode[0] = 1;
    Emcy.m_abManufactErrorCode[1] = 2;
    Emcy.m_abManufactErrorCode[2] = 3;
    Emcy.m_abManufactErrorCode[3] = 4;
    Emcy.m_abManufactErrorCode[4] = 5;
    CHECK_RET(CcmSendEmergency(&Emcy), kCopNmtStateError);
    CHECK_RET(CcmSendEmergency(NULL), kCopInvalidParam);

    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopNmtStateError);
    TestDrainSent();
    CHECK_RET(CcmConfigEmcp(0x80 + NODE_ID), kCopSuccessful);
    CHECK_RET(CcmSendEmergency(&Emcy), kCopSuccessful);
    TestProcess(1);
    TestExpectFrame("emergency", 0x80 + NODE_ID, 8, abEmcy);
    CHECK_RET(CcmConfigEmcp(0x80000000UL | (0x80 + NODE_ID)), kCopSuccessful);  /* producer off */
    CHECK_RET(CcmSendEmergency(&Emcy), kCopCobIllegalCanId);
    TestProcess(1);
    CHECK_EQ(SimSentPending(), 0);

    /* object access: NULL pointers, unknown objects */
    Size = sizeof(abBuf);
    CHECK_RET(CcmReadObject(0x1000, 0, NULL, &Size), kCopInvalidParam);
    CHECK_RET(CcmReadObject(0x1000, 0, abBuf, NULL), kCopInvalidParam);
    CHECK_RET(CcmReadObject(0x1000, 0, abBuf, &Size), kCopSuccessful);
    CHECK_EQ(Size, 4);
    Size = sizeof(abBuf);
    CHECK_RET(CcmReadObject(0x1FFF, 0, abBuf, &Size), kCopObdIndexNotExist);
    CHECK_RET(CcmWriteObject(0x1017, 0, NULL, 2), kCopInvalidParam);
    CHECK_RET(CcmWriteObject(0x1FFF, 0, abBuf, 2), kCopObdIndexNotExist);

    /* heartbeat producer time goes into 0x1017 */
    CHECK_RET(CcmConfigHbp(321), kCopSuccessful);
    wValue = 0;
    Size = sizeof(wValue);
    CHECK_RET(CcmReadObject(0x1017, 0, &wValue, &Size), kCopSuccessful);
    CHECK_EQ(wValue, 321);
    CHECK_RET(CcmConfigHbp(0), kCopSuccessful);

    /* local NMT commands */
    CHECK_RET(CcmNmtsExecCommand(0x00FF), kCopNmtUnknownCommand);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopSuccessful);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);

    /* the error callback hears about an NMT callback that failed */
    CcmRegisterErrorCallback(ErrorCallback);
    fNmtFails_g = 1;
    CHECK_RET(CcmNmtsExecCommand(kNmtCommEnterPreOperational), kCopSuccessful);
    TestProcess(1);
    fNmtFails_g = 0;
    CHECK(uErrorCallbacks_g >= 1);
    CHECK_EQ(LastError_g, kCopNoResource);          /* the code NmtCallback returned */
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    CcmRegisterErrorCallback(NULL);
    uErrorCallbacks_g = 0;
    fNmtFails_g = 1;
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopSuccessful);
    TestProcess(1);
    fNmtFails_g = 0;
    CHECK_EQ(uErrorCallbacks_g, 0);
    TestDrainSent();
}

/* ---- NMT master, heartbeat consumer, SDO client ----------------------------------------------- */

static void MasterApi (void)
{
    static CONST BYTE abStart3[2] = { 0x01, 0x03 };
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    static CONST BYTE abUpload[8] = { 0x40, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00 };
    static CONST BYTE abUploadResp[8] = { 0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0x02, 0x00 };
    static CONST BYTE abSlaves[1] = { 3 };
    static CONST BYTE abTwice[2] = { 5, 5 };
    tNmtmSlaveParam Guard;
    tNmtmSlaveInfo Info;
    tHbcProdParam Producer;
    tSdocParam Client;
    tSdocTransferParam Transfer;
    tSdocState State = 0xFF;
    DWORD dwAbort = 1;
    DWORD dwBytes = 0;
    DWORD dwData = 0;
    BYTE bState = 0;
    tSimFrame Frame;

    CHECK_RET(CcmInitNmtm(), kCopSuccessful);
    CHECK_RET(CcmInitNmtmEx(NULL), kCopSuccessful);
    CHECK_RET(CcmSendNmtCommand(3, kNmtCommStartRemoteNode), kCopSuccessful);
    TestExpectFrame("NMT start node 3", 0x000, 2, abStart3);
    CHECK_RET(CcmSendNmtCommand(3, 0x0077), kCopNmtUnknownCommand);
    CHECK_RET(CcmSendNmtCommand(200, kNmtCommStartRemoteNode), kCopNmtmInvalidSlaveNodeId);
    CHECK_RET(CcmBootNetwork(), kCopSuccessful);
    TestExpectFrame("NMT start all", 0x000, 2, abStartAll);
    TestProcess(1);

    CHECK_RET(CcmDefineSlaveTab(NULL, 1), kCopInvalidParam);
    CHECK_RET(CcmDefineSlaveTab(abTwice, 2), kCopNmtmSlaveNodeExist);
    CHECK_RET(CcmDefineSlaveTab(abSlaves, 1), kCopSuccessful);
    CHECK_RET(CcmTriggerNodeGuard(3), kCopSuccessful);
    CHECK(SimTakeSentFrame(&Frame));
    CHECK_EQ(Frame.m_dwId, 0x703);
    CHECK_EQ(Frame.m_bRtr, 1);
    memset(&Guard, 0, sizeof(Guard));
    CHECK_RET(CcmConfigLgm(3, NULL), kCopInvalidParam);
    CHECK_RET(CcmConfigLgm(9, &Guard), kCopNmtmSlaveEntryNotExist);
    CHECK_RET(CcmConfigLgm(3, &Guard), kCopSuccessful);
    CHECK_RET(CcmNmtmGetSlaveInfo(3, NULL), kCopInvalidParam);
    CHECK_RET(CcmNmtmGetSlaveInfo(3, &Info), kCopSuccessful);

    CHECK_RET(CcmInitHbc(), kCopSuccessful);
    CHECK_RET(CcmInitHbcEx(NULL), kCopSuccessful);
    memset(&Producer, 0, sizeof(Producer));
    Producer.wHeartbeatTime_p = 100;
    Producer.bProducerNodeId_p = 3;
    Producer.bSubindex_p = 1;
    CHECK_RET(CcmHbcDefineProducerTab(NULL, 1), kCopInvalidParam);
    CHECK_RET(CcmHbcDefineProducerTab(&Producer, 1), kCopHbcNoFreeEntry);      /* no 0x1016 here */
    CHECK_RET(CcmHbcGetNodeState(3, NULL), kCopInvalidParam);
    CHECK_RET(CcmHbcGetNodeState(3, &bState), kCopHbcEntryNotExist);

    /* SDO client: expedited upload of 0x1000 from node 3 */
    memset(&Client, 0, sizeof(Client));
    Client.m_bValidFlags = kSdocValidFlagServerNodeId;
    Client.m_wClientIndex = 0x1280;
    Client.m_bServerNodeId = 3;
    CHECK_RET(CcmSdocDefineClientTab(NULL, 1), kCopInvalidParam);
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSuccessful);
    Client.m_wClientIndex = 0x1290;
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSdocClientNotExist);
    memset(&Transfer, 0, sizeof(Transfer));
    Transfer.m_wClientIndex = 0x1280;
    Transfer.m_wObjIndex = 0x1000;
    Transfer.m_bObjSubIndex = 0;
    Transfer.m_pData = &dwData;
    Transfer.m_DataLen = sizeof(dwData);
    Transfer.m_SdocType = kSdocTypeSegUp;
    CHECK_RET(CcmSdocStartTransfer(NULL), kCopInvalidParam);
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    TestExpectFrame("SDO upload request", 0x603, 8, abUpload);
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSdocBusy);
    CHECK_RET(CcmSdocGetState(0x1280, NULL, &dwAbort), kCopInvalidParam);
    CHECK_RET(CcmSdocGetState(0x1280, &State, &dwAbort), kCopSuccessful);
    CHECK_EQ(State, kSdocTransferRunning);
    SimInject(0x583, 0, 8, abUploadResp);
    TestProcess(1);
    CHECK_RET(CcmSdocGetState(0x1280, &State, &dwAbort), kCopSuccessful);
    CHECK_EQ(State, kSdocTransferFinished);
    CHECK_EQ(dwAbort, 0);
    /* the SDO client moves the data bytes as they travel (CANopen byte
     * order, little-endian); the application converts them */
    CHECK_EQ(((BYTE*) &dwData)[0], 0x91);
    CHECK_EQ(((BYTE*) &dwData)[1], 0x01);
    CHECK_EQ(((BYTE*) &dwData)[2], 0x02);
    CHECK_EQ(((BYTE*) &dwData)[3], 0x00);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, NULL), kCopInvalidParam);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, &dwBytes), kCopSuccessful);
    CHECK_EQ(dwBytes, 4);
    CHECK_RET(CcmSdocAbort(0x1280, SDOAC_GENERAL_ERROR), kCopSdocTransferError);
    CHECK_RET(CcmSdocGetState(0x1290, &State, &dwAbort), kCopSdocClientNotExist);
}

/* ---- PDO, SRDO, dynamic OD ------------------------------------------------------------------------- */

static void PdoSrdoDynApi (void)
{
    tPdoParam Pdo;
    tPdoStaticParam StaticPdo;
    tProcessImageDscrpt Image;
    WORD wIndex = 0;
    BYTE bState = 0;
    DWORD dwVar = 0;

    CHECK_RET(CcmDefinePdoTab(NULL, 1), kCopInvalidParam);
    memset(&Pdo, 0, sizeof(Pdo));
    Pdo.m_bValidFlag = kPdoValidTxType;
    Pdo.m_wPdoCommuIndex = 0x1805;
    Pdo.m_bPdoType = kPdoTypeSend;
    CHECK_RET(CcmDefinePdoTab(&Pdo, 1), kCopPdoNotExist);
    Pdo.m_wPdoCommuIndex = 0x1800;
    Pdo.m_bTxTyp = 0xFE;
    CHECK_RET(CcmDefinePdoTab(&Pdo, 1), kCopSuccessful);
    CHECK_RET(CcmDefineStaticPdoTab(NULL, 1), kCopInvalidParam);
    memset(&StaticPdo, 0, sizeof(StaticPdo));
    StaticPdo.m_wPdoCommuIndex = 0x1805;
    CHECK_RET(CcmDefineStaticPdoTab(&StaticPdo, 1), kCopPdoNotExist);
    CHECK_RET(CcmSignalStaticPdo(0x1800), kCopSuccessful);
    CHECK_RET(CcmSignalStaticPdo(0x1801), kCopPdoNotExist);
    CHECK_RET(CcmSignalCheckVar(), kCopSuccessful);
    CHECK_RET(CcmSignalVar(NULL), kCopInvalidParam);
    CHECK_RET(CcmSignalVar(&dwVar), kCopPdoVarNotFound);
    CHECK_RET(CcmSendPdo(0x1801), kCopPdoNotExist);
    CHECK_RET(CcmSendPdo(0x1800), kCopPdoErrorSend);        /* COB-ID invalid (bit 31) */
    CHECK_RET(CcmInitSyncConsumer(), kCopSuccessful);
    CHECK_RET(CcmConfigSyncConsumer(0x80, 0), kCopSuccessful);
    CcmEnterCriticalSectionPdoProcess();
    CcmLeaveCriticalSectionPdoProcess();

    CHECK_RET(CcmSendSrdo(0x1310), kCopSrdoNotExist);
    CHECK_RET(CcmCheckSrdoConfig(NULL), kCopInvalidParam);
    CHECK(CcmCheckSrdoConfig(&wIndex) != kCopSuccessful);   /* 0x13FE is not 0xA5 */
    CHECK_RET(CcmGetSrdoState(NULL, 0x1301), kCopInvalidParam);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1310), kCopSrdoNotExist);
    CHECK_RET(CcmSetSrdoState(bState, 0x1301), kCopSuccessful);
    CHECK_RET(CcmSetSrdoState(bState, 0x1310), kCopSrdoNotExist);

    memset(&Image, 0, sizeof(Image));
    CHECK_RET(DynBuildOd(NULL, &Image), kCopInvalidParam);
    CHECK_RET(DynDestroyOd(), kCopSuccessful);
}

static void Shutdown (void)
{
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    CHECK_RET(CcmShutDownCANopen(), kCopIllegalInstance);
    CHECK_EQ(CcmObdGetNodeState(), 0);
    CHECK_RET(CopSimSelectInstance(SIM_MAX_NODES), kCopIllegalInstance);
    CHECK_RET(CopSimSelectInstance(1), kCopSuccessful);
    CHECK_RET(CcmProcess(), kCopIllegalInstance);           /* instance 1 is empty */
    CHECK_RET(CopSimSelectInstance(0), kCopSuccessful);
    /* the instance can be created again */
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, NmtCallback), kCopSuccessful);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
}

int main (void)
{
    SimReset();
    SimSetTrace(1);
    BeforeInit();
    InitRefusals();
    CoreApi();
    MasterApi();
    PdoSrdoDynApi();
    Shutdown();
    return TEST_DONE("test_api");
}
