/*
 * test_master_app.c - a CANopen master application written the way existing
 * SYS TEC master applications use the API, on the simulated bus, with its
 * frame trace checked:
 *
 *   node M (simulated node 0): objdict_master.h, node-ID 1 - NMT master,
 *          SDO client, heartbeat and EMCY consumer, one RPDO;
 *   node S (simulated node 3): objdict_min.h, node-ID 3 - a slave.
 *
 * Built against c_tests/cfg_master (copcfg.h) and c_tests/cfg_master_od
 * (obdcfg.h, another folder: COP_OBDCFG_DIR), with COB_MORE_THAN_128_ENTRIES
 * (tCobHdl is a WORD) and 32-bit object sizes. What it uses as such an
 * application does:
 *
 *  - copinc.h / ccmmain.h / ami.h / cob.h / nmtm.h includes, PRINTF0..PRINTF3,
 *    COP_MEMSET / COP_MEMCPY;
 *  - SDO download data built with AmiSetWord / AmiSetByte;
 *  - the RPDO callback finds the PDO length by walking the receive COB
 *    handles 0 .. COB_MAX_RX_COB_ENTRIES-1 with CcmCobGetParam until m_CobId
 *    is the PDO's identifier;
 *  - the slave's state from tNmtmSlaveInfo: with kNmtmStateLgActive,
 *    kNmtmStateNgActive or kNmtmUpdate set, m_bSlaveNodeState counts when
 *    kNmtmLgReceived or kNmtmUpdate is set; otherwise the heartbeat
 *    consumer's CcmHbcGetNodeState.
 */
#include "copinc.h"
#include "ccmmain.h"
#include "ami.h"
#include "cob.h"
#include "nmtm.h"
#include "obdcfg.h"              /* COB_MAX_RX_COB_ENTRIES, as such applications include it */
#include "cop_config.h"
#include "test_util.h"

#define SIM_M 0
#define SIM_S 3
#define ID_M  1
#define ID_S  3

tCopKernel PUBLIC ObdInitRamMaster (void MEM* pInitParam_p);

/* The link-time signature names the COB handle width (ch16 with
 * COB_MORE_THAN_128_ENTRIES): the member access compiles only when
 * COP_ABI_SIGNATURE expands to exactly this name. */
struct tSignatureName { int COP_ABI_SIGNATURE; };
static int SignatureName (const struct tSignatureName* p)
{
    return p->CopLibAbi_os4_gr8_sm0_pm0_ts0_id11_pe8_ch16;
}

/* ---- the application's callbacks ------------------------------------------- */

static unsigned  uBootups_g;
static unsigned  uLgNoAnswer_g;
static unsigned  uHbcLost_g;
static unsigned  uHbcConnected_g;
static unsigned  uEmcy_g;
static BYTE      bEmcyNode_g;
static tEmcParam LastEmcy_g;
static unsigned  uRxPdo_g;
static BYTE      bRxPdoSize_g;
static tCanId    RxPdoCobId_g;

static tCopKernel PUBLIC AppCbNmtmEvent (BYTE bNodeId_p, tNmtErrCtrlEvent Event_p)
{
    PRINTF2("NMTM event node %u: 0x%02X\n", (unsigned) bNodeId_p, (unsigned) Event_p);
    if (Event_p == kNmtErrCtrlEvBootupReceived)
    {
        uBootups_g++;
    }
    if (Event_p == kNmtErrCtrlEvLgNoAnswer)
    {
        uLgNoAnswer_g++;
    }
    return kCopSuccessful;
}

static tCopKernel PUBLIC AppCbHbcEvent (BYTE bNodeId_p, tNmtErrCtrlEvent Event_p)
{
    PRINTF2("HBC event node %u: 0x%02X\n", (unsigned) bNodeId_p, (unsigned) Event_p);
    if (Event_p == kNmtErrCtrlEvHbcConnectionLost)
    {
        uHbcLost_g++;
    }
    if (Event_p == kNmtErrCtrlEvHbcConnected)
    {
        uHbcConnected_g++;
    }
    return kCopSuccessful;
}

static tCopKernel PUBLIC AppCbEmccEvent (BYTE bNodeId_p, tEmcParam MEM* pEmcParam_p)
{
    PRINTF3("EMCY node %u: code 0x%04X register 0x%02X\n", (unsigned) bNodeId_p,
            (unsigned) pEmcParam_p->m_wEmcyErrorCode, (unsigned) pEmcParam_p->m_bErrorRegister);
    uEmcy_g++;
    bEmcyNode_g = bNodeId_p;
    COP_MEMCPY(&LastEmcy_g, pEmcParam_p, sizeof(LastEmcy_g));
    return kCopSuccessful;
}

/* The RPDO callback: the PDO's length from the receive COB table. */
static tCopKernel PUBLIC AppCbRxPdo (WORD wPdoCommuIndex_p)
{
    tCobParam CobParam;

    PRINTF1("RX-PDO %u event\n", (unsigned) (wPdoCommuIndex_p & 0x1FF));
    COP_MEMSET(&CobParam, 0, sizeof(CobParam));
    for (CobParam.m_CobHdl = 0; CobParam.m_CobHdl < COB_MAX_RX_COB_ENTRIES; CobParam.m_CobHdl++)
    {
        (void) CcmCobGetParam((tCobParam MEM*) &CobParam);
        if (CobParam.m_CobId == 0x180 + ID_S)
        {
            break;
        }
    }
    uRxPdo_g++;
    RxPdoCobId_g = CobParam.m_CobId;
    bRxPdoSize_g = CobParam.m_bSize;
    return kCopSuccessful;
}

/* The slave's NMT state as the master reports it (0xFF: disconnected). */
static BYTE SlaveNodeState (BYTE bNodeId_p)
{
    static BYTE bLastToggle_l;
    tNmtmSlaveInfo Info;
    BYTE bState = 0xFF;

    COP_MEMSET(&Info, 0, sizeof(Info));
    if (CcmNmtmGetSlaveInfo(bNodeId_p, &Info) != kCopSuccessful)
    {
        return 0xFF;
    }
    if ((Info.m_bSlaveState & (kNmtmStateLgActive | kNmtmStateNgActive | kNmtmUpdate)) != 0)
    {
        if (((Info.m_bSlaveState & (kNmtmLgReceived | kNmtmUpdate)) != 0) ||
            ((Info.m_bSlaveState & kNmtmStateToggleBit) != bLastToggle_l))
        {
            bState = Info.m_bSlaveNodeState;
        }
        bLastToggle_l = (BYTE) (Info.m_bSlaveState & kNmtmStateToggleBit);
    }
    else if (CcmHbcGetNodeState(bNodeId_p, &bState) != kCopSuccessful)
    {
        bState = 0xFF;
    }
    return bState;
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

static void ExpectRemote (const char* pszWhat_p, DWORD dwId_p)
{
    tSimFrame Frame;

    if (!SimTakeSentFrame(&Frame) || (Frame.m_dwId != dwId_p) || (Frame.m_bRtr != 1) || (Frame.m_bDlc != 1))
    {
        printf("%s: no remote request %03lX [1]\n", pszWhat_p, (unsigned long) dwId_p);
        CHECK(0);
    }
}

/* One SDO transfer of the client 0x1280, run to its end. */
static tSdocState Sdo (WORD wIndex_p, BYTE bSub_p, void* pData_p, tObdSize Size_p, tSdocType Type_p, DWORD* pdwAbort_p)
{
    tSdocTransferParam Transfer;
    tSdocState State = 0xFF;
    unsigned i;

    COP_MEMSET(&Transfer, 0, sizeof(Transfer));
    Transfer.m_wClientIndex = 0x1280;
    Transfer.m_wObjIndex = wIndex_p;
    Transfer.m_bObjSubIndex = bSub_p;
    Transfer.m_pData = pData_p;
    Transfer.m_DataLen = Size_p;
    Transfer.m_SdocType = Type_p;
    CHECK_RET(CcmSdocStartTransfer(&Transfer), kCopSuccessful);
    for (i = 0; i < 10; i++)
    {
        Run(1, 1);
        CHECK_RET(CcmSdocGetState(0x1280, &State, pdwAbort_p), kCopSuccessful);
        if (State != kSdocTransferRunning)
        {
            break;
        }
    }
    return State;
}

/* ---- the scenario ------------------------------------------------------------------ */

static void Boot (void)
{
    /* the application's node table, in RAM, defined before the slaves are
     * known and filled later (entries 0 are free) as master applications
     * of the SYS TEC API do: the library reads it again when it changes */
    static BYTE abSlaves[4];
    static CONST BYTE abBootup[1] = { 0x00 };   /* CiA 301 7.2.8.3.3 */
    static CONST BYTE abStart[2] = { 0x01, ID_S };
    tSdocParam Client;
    tPdoParam Rpdo;
    tNmtmSlaveInfo Info;

    CHECK_RET(TestInitNode(SIM_M, ID_M, ObdInitRamMaster, NULL), kCopSuccessful);
    PRINTF0("master initialised\n");
    CHECK_RET(CcmInitNmtm(), kCopSuccessful);
    CHECK_RET(CcmInitNmtmEx(AppCbNmtmEvent), kCopSuccessful);
    CHECK_RET(CcmInitHbcEx(AppCbHbcEvent), kCopSuccessful);
    CHECK_RET(CcmInitEmccEx(AppCbEmccEvent), kCopSuccessful);
    COP_MEMSET(abSlaves, 0, sizeof(abSlaves));
    CHECK_RET(CcmEmccDefineProducerTab(abSlaves, sizeof(abSlaves)), kCopSuccessful);
    CHECK_RET(CcmDefineSlaveTab(abSlaves, sizeof(abSlaves)), kCopSuccessful);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopNmtmSlaveEntryNotExist);
    abSlaves[0] = ID_S;                         /* the slave is added */

    /* the RPDO that receives the slave's TPDO1 (predefined set 0x180 + 3) */
    COP_MEMSET(&Rpdo, 0, sizeof(Rpdo));
    Rpdo.m_bValidFlag = kPdoValidAll;
    Rpdo.m_wPdoCommuIndex = 0x1400;
    Rpdo.m_bPdoType = kPdoTypeRecv;
    Rpdo.m_bNodeID = ID_S;
    Rpdo.m_dwCanId = 0x180 + ID_S;              /* the full identifier: kept as it is */
    Rpdo.m_bTxTyp = 0xFE;
    Rpdo.m_bNrOfEntries = 1;
    Rpdo.m_adwMappParam[0] = 0x20600108;
    Rpdo.m_fpCallback = AppCbRxPdo;
    CHECK_RET(CcmDefinePdoTab(&Rpdo, 1), kCopSuccessful);

    COP_MEMSET(&Client, 0, sizeof(Client));
    Client.m_bValidFlags = kSdocValidFlagServerNodeId;
    Client.m_wClientIndex = 0x1280;
    Client.m_bServerNodeId = ID_S;
    CHECK_RET(CcmSdocDefineClientTab(&Client, 1), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    Run(1, 0);
    TestDrainSent();                            /* the master's own boot-up */

    /* before the slave has said anything: in the table, nothing else */
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState, kNmtmStateUsed);
    CHECK_EQ(Info.m_bLostMsgCount, 0);

    CHECK_RET(TestInitNode(SIM_S, ID_S, ObdInitRamMin, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    SimSelectNode(SIM_M);
    Run(1, 1);
    TestExpectFrame("slave boot-up", 0x700 + ID_S, 1, abBootup);
    CHECK_EQ(uBootups_g, 1);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState, kNmtmStateUsed | kNmtmBootupReceived);

    CHECK_RET(CcmSendNmtCommand(ID_S, kNmtCommStartRemoteNode), kCopSuccessful);
    TestExpectFrame("NMT start node 3", 0x000, 2, abStart);
    Run(1, 1);
    CHECK_EQ(TestDrainSent(), 0);
}

static void ReadSlave (void)
{
    /* CiA 301 7.2.4.3.3 (expedited download, 2 bytes: 0x2B) and 7.2.4.3.5
     * (upload request 0x40; expedited answer 0x43 with 4 bytes). */
    static CONST BYTE abDown1017[8] = { 0x2B, 0x17, 0x10, 0x00, 0x64, 0x00, 0x00, 0x00 };
    static CONST BYTE abDownAck[8] = { 0x60, 0x17, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00 };
    static CONST BYTE abUp1018[8] = { 0x40, 0x18, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00 };
    static CONST BYTE abUpAnswer[8] = { 0x43, 0x18, 0x10, 0x01, 0x23, 0x01, 0x00, 0x00 };
    BYTE abData[4];
    DWORD dwAbort = 0xFFFFFFFFUL;
    DWORD dwBytes = 0;
    WORD wTime = 0;
    tObdSize Size = sizeof(wTime);

    /* the producer heartbeat time 100 ms, built with AmiSetWord */
    COP_MEMSET(abData, 0, sizeof(abData));
    AmiSetWord(abData, 100);
    CHECK_EQ(Sdo(0x1017, 0, abData, 2, kSdocTypeSegDown, &dwAbort), kSdocTransferFinished);
    CHECK_EQ(dwAbort, 0);
    TestExpectFrame("SDO download 0x1017", 0x600 + ID_S, 8, abDown1017);
    TestExpectFrame("SDO download answer", 0x580 + ID_S, 8, abDownAck);
    SimSelectNode(SIM_S);
    wTime = 0;
    CHECK_RET(CcmReadObject(0x1017, 0, &wTime, &Size), kCopSuccessful);
    CHECK_EQ(wTime, 100);
    SimSelectNode(SIM_M);

    /* the vendor-ID, read back in bus byte order */
    COP_MEMSET(abData, 0, sizeof(abData));
    CHECK_EQ(Sdo(0x1018, 1, abData, sizeof(abData), kSdocTypeSegUp, &dwAbort), kSdocTransferFinished);
    TestExpectFrame("SDO upload 0x1018/1", 0x600 + ID_S, 8, abUp1018);
    TestExpectFrame("SDO upload answer", 0x580 + ID_S, 8, abUpAnswer);
    CHECK_EQ(AmiGetDword(abData), 0x123);
    CHECK_RET(SdocGetTransmittedBytes(0x1280, &dwBytes), kCopSuccessful);
    CHECK_EQ(dwBytes, 4);

    /* heartbeat time back to 0 with AmiSetByte (one byte per call) */
    AmiSetByte(&abData[0], 0);
    AmiSetByte(&abData[1], 0);
    CHECK_EQ(Sdo(0x1017, 0, abData, 2, kSdocTypeSegDown, &dwAbort), kSdocTransferFinished);
    Run(2, 1);
    TestDrainSent();
}

static void Guarding (void)
{
    /* CiA 301 7.2.8.3.2.1: the answer is the state (5 = operational) with
     * the toggle bit in bit 7, starting at 0. */
    static CONST BYTE abAnswer0[1] = { 0x05 };
    static CONST BYTE abAnswer1[1] = { 0x85 };
    tNmtmSlaveParam Guard;
    tNmtmSlaveInfo Info;

    Guard.m_wLifeguardTime = 20;
    Guard.m_bLifeguardFactor = 3;
    CHECK_RET(CcmConfigLgm(ID_S, &Guard), kCopSuccessful);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState & (kNmtmStateLgActive | kNmtmStateNgActive | kNmtmLgReceived | kNmtmUpdate),
             kNmtmStateLgActive | kNmtmStateNgActive);
    Run(2, 1);                                  /* request, then the answer */
    ExpectRemote("guard request 1", 0x700 + ID_S);
    TestExpectFrame("guard answer 1", 0x700 + ID_S, 1, abAnswer0);
    CHECK_EQ(SlaveNodeState(ID_S), kNodeStateOperational);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState & (kNmtmLgReceived | kNmtmUpdate | kNmtmStateToggleBit), kNmtmLgReceived);
    Run(20, 1);                                 /* the next request after 20 ms */
    ExpectRemote("guard request 2", 0x700 + ID_S);
    TestExpectFrame("guard answer 2", 0x700 + ID_S, 1, abAnswer1);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState & (kNmtmUpdate | kNmtmStateToggleBit), kNmtmUpdate | kNmtmStateToggleBit);
    CHECK_EQ(Info.m_bSlaveNodeState, kNodeStateOperational);
    CHECK_EQ(Info.m_bLostMsgCount, 0);

    /* the slave stops answering: three requests in vain, one event */
    Run(80, 0);
    CHECK_EQ(uLgNoAnswer_g, 1);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK(Info.m_bLostMsgCount >= 3);

    Guard.m_wLifeguardTime = 0;
    CHECK_RET(CcmConfigLgm(ID_S, &Guard), kCopSuccessful);
    CHECK_RET(CcmNmtmGetSlaveInfo(ID_S, &Info), kCopSuccessful);
    CHECK_EQ(Info.m_bSlaveState & (kNmtmStateLgActive | kNmtmStateNgActive), 0);
    /* the slave answers what it had queued */
    SimSelectNode(SIM_S);
    TestProcess(2);
    SimSelectNode(SIM_M);
    Run(2, 1);
    TestDrainSent();
}

static void Heartbeat (void)
{
    static CONST BYTE abHeartbeat[1] = { 0x05 };
    tHbcProdParam Producer;

    SimSelectNode(SIM_S);
    CHECK_RET(CcmConfigHbp(20), kCopSuccessful);
    SimSelectNode(SIM_M);
    Producer.wHeartbeatTime_p = 50;
    Producer.bProducerNodeId_p = ID_S;
    Producer.bSubindex_p = 1;
    CHECK_RET(CcmHbcDefineProducerTab(&Producer, 1), kCopSuccessful);
    TestDrainSent();
    Run(21, 1);                                 /* the first heartbeat after 20 ms */
    TestExpectFrame("heartbeat", 0x700 + ID_S, 1, abHeartbeat);
    CHECK_EQ(TestDrainSent(), 0);
    Run(30, 1);
    CHECK_EQ(uHbcConnected_g, 1);
    /* no guarding any more: the state comes from the heartbeat consumer */
    CHECK_EQ(SlaveNodeState(ID_S), kNodeStateOperational);
    TestDrainSent();
    Run(80, 0);
    CHECK_EQ(uHbcLost_g, 1);
    SimSelectNode(SIM_S);
    CHECK_RET(CcmConfigHbp(0), kCopSuccessful);
    SimSelectNode(SIM_M);
    Producer.wHeartbeatTime_p = 0;
    CHECK_RET(CcmHbcDefineProducerTab(&Producer, 1), kCopSuccessful);
    Run(2, 1);
    TestDrainSent();
}

static void Emergency (void)
{
    /* CiA 301 7.2.7.3.1: error code 0x8130 (life guard error), error
     * register 0x11, manufacturer bytes 01 02 03 04 05. */
    static CONST BYTE abEmcy[8] = { 0x30, 0x81, 0x11, 0x01, 0x02, 0x03, 0x04, 0x05 };

    CHECK(SimInject(0x080 + ID_S, 0, 8, abEmcy));
    Run(1, 0);
    CHECK_EQ(uEmcy_g, 1);
    CHECK_EQ(bEmcyNode_g, ID_S);
    CHECK_EQ(LastEmcy_g.m_wEmcyErrorCode, 0x8130);
    CHECK_EQ(LastEmcy_g.m_bErrorRegister, 0x11);
    CHECK_EQ(LastEmcy_g.m_abManufactErrorCode[4], 0x05);
    TestDrainSent();
}

static void ProcessData (void)
{
    static CONST BYTE abPdo[1] = { 0x5A };
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    tCobParam CobParam;
    tCobParam Before;

    /* NMT start of all nodes (CiA 301 7.2.8.3.1.1: 01 00): the master's
     * own PDOs run from now on */
    CHECK_RET(CcmSendNmtCommand(0, kNmtCommStartRemoteNode), kCopSuccessful);
    TestExpectFrame("NMT start all", 0x000, 2, abStartAll);
    Run(1, 1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    TestDrainSent();

    /* a TPDO of node 3 (CiA 301 predefined set 0x180 + node-ID) */
    CHECK(SimInject(0x180 + ID_S, 0, 1, abPdo) == 1);
    Run(1, 0);
    CHECK_EQ(uRxPdo_g, 1);
    CHECK_EQ(RxPdoCobId_g, 0x180 + ID_S);
    CHECK_EQ(bRxPdoSize_g, 1);
    CHECK_EQ(TestReadU8(0x2060, 1), 0x5A);

    /* the entries themselves: receive handle 0 is the RPDO at 0x1400 */
    COP_MEMSET(&CobParam, 0xA5, sizeof(CobParam));
    CobParam.m_CobHdl = kCobHdlRxTable | 0;
    CHECK_RET(CcmCobGetParam(&CobParam), kCopSuccessful);
    CHECK_EQ(CobParam.m_CobId, 0x180 + ID_S);
    CHECK_EQ(CobParam.m_bCobType, kCobTypRecv);
    CHECK_EQ(CobParam.m_bSize, 1);
    CHECK(CobParam.m_fpCallback == NULL);
    CHECK(CobParam.m_pbData == NULL);
    CHECK_EQ(CobParam.m_CobHdl, kCobHdlRxTable | 0);
    /* handle 1 is no PDO; transmit handle 0 is the TPDO at 0x1800, which
     * is not valid (objdict_master.h): refused, nothing written */
    COP_MEMSET(&CobParam, 0xA5, sizeof(CobParam));
    CobParam.m_CobHdl = kCobHdlRxTable | 1;
    COP_MEMCPY(&Before, &CobParam, sizeof(Before));
    CHECK_RET(CcmCobGetParam(&CobParam), kCopCobIllegalHdl);
    CHECK(memcmp(&Before, &CobParam, sizeof(Before)) == 0);
    CobParam.m_CobHdl = kCobHdlTxTable | 0;
    COP_MEMCPY(&Before, &CobParam, sizeof(Before));
    CHECK_RET(CcmCobGetParam(&CobParam), kCopCobIllegalHdl);
    CHECK(memcmp(&Before, &CobParam, sizeof(Before)) == 0);
    CHECK_RET(CcmCobGetParam(NULL), kCopInvalidParam);
    CHECK_EQ(sizeof(tCobHdl), 2);                       /* COB_MORE_THAN_128_ENTRIES TRUE */
    TestDrainSent();
}

int main (void)
{
    struct tSignatureName Name;

    Name.COP_ABI_SIGNATURE = 1;
    CHECK_EQ(SignatureName(&Name), 1);
    SimReset();
    Boot();
    ReadSlave();
    Guarding();
    Heartbeat();
    Emergency();
    ProcessData();
    return TEST_DONE("test_master_app");
}
