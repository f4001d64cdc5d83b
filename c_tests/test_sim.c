/*
 * test_sim.c - the simulated CAN bus (examples_c/sim): receive filters,
 * queue order and priorities, overrun status bits, transmission between
 * nodes, fault hooks, timestamps, the clock, the candump format - first by
 * calling the Cdrv* functions directly, then through the stack, which must
 * subscribe (CdrvDefineCanId) every identifier it receives.
 */
#include "test_util.h"

static void InitDriver (BYTE bNode_p, tCdrvBuffIndex High_p, tCdrvBuffIndex Low_p)
{
    tCdrvInitParam Param;

    memset(&Param, 0, sizeof(Param));
    Param.m_RxBuffHigh.m_MaxEntries = High_p;
    Param.m_RxBuffLow.m_MaxEntries = Low_p;
    CHECK_RET(SimSelectNode(bNode_p), kCopSuccessful);
    CHECK_RET(CdrvInit(&Param), kCopSuccessful);
}

static void Define (WORD wId_p, int fHigh_p)
{
    tCdrvMsg Msg;

    memset(&Msg, 0, sizeof(Msg));
    Msg.m_CanId = wId_p;
    Msg.m_MsgType = (tMsgTyp) (kMtbRecv | (fHigh_p ? kMtbHighPrio : 0));
    CHECK_RET(CdrvDefineCanId(&Msg), kCopSuccessful);
}

static void Send (WORD wId_p, BYTE bDlc_p, BYTE bFirst_p, int fHigh_p, tCopKernel Expected_p)
{
    tCdrvMsg Msg;

    memset(&Msg, 0, sizeof(Msg));
    Msg.m_CanId = wId_p;
    Msg.m_MsgType = (tMsgTyp) (fHigh_p ? kMtbHighPrio : 0);
    Msg.m_bSize = bDlc_p;
    Msg.m_bData[0] = bFirst_p;
    CHECK_RET(CdrvWriteMsg(&Msg), Expected_p);
}

/* Reads one frame of the selected node and checks identifier and first byte. */
static void Receive (tCopKernel Expected_p, WORD wId_p, BYTE bFirst_p)
{
    tCdrvMsg* pMsg = NULL;
    tCopKernel Ret = CdrvReadMsg(&pMsg);

    CHECK_RET(Ret, Expected_p);
    if ((Ret == kCopCdrvMsgHigh) || (Ret == kCopCdrvMsgLow))
    {
        CHECK(pMsg != NULL);
        if (pMsg != NULL)
        {
            CHECK_EQ(pMsg->m_CanId, wId_p);
            CHECK_EQ(pMsg->m_bData[0], bFirst_p);
            CHECK((pMsg->m_MsgType & kMtbRecv) != 0);
            CHECK_RET(CdrvReleaseMsg(pMsg), kCopSuccessful);
        }
    }
}

static void DirectDriver (void)
{
    static CONST BYTE abOne[1] = { 0x01 };
    BYTE abData[8] = { 0 };
    tCdrvStatus Status = 0;
    tCdrvInitParam Param;
    tSimFrame Frame;
    DWORD dwId = 0;
    BYTE bRtr = 0;
    BYTE bDlc = 0;
    char szLine[64];
    tCdrvMsg* pMsg = NULL;
    int i;

    SimReset();

    /* A node whose driver was never initialised cannot send. */
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    Send(0x123, 1, 0x00, 0, kCopCdrvInitError);
    CHECK_RET(CdrvReadMsg(&pMsg), kCopCdrvNoMsg);
    CHECK_RET(SimSelectNode(SIM_MAX_NODES), kCopIllegalInstance);
    CHECK_RET(CdrvInit(NULL), kCopCdrvInvalidParam);

    InitDriver(1, 2, 3);
    memset(&Param, 0, sizeof(Param));
    CHECK_RET(CdrvInit(&Param), kCopCdrvDevAlreadyInUse);
    CHECK_EQ(SimRxCapacity(1, 1), 2);
    CHECK_EQ(SimRxCapacity(1, 0), 3);

    /* Only defined identifiers are received, into the queue asked for. */
    Define(0x123, 0);
    Define(0x080, 1);
    CHECK_EQ(SimIsIdDefined(1, 0x123), 1);
    CHECK_EQ(SimIsIdDefined(1, 0x080), 2);
    CHECK_EQ(SimIsIdDefined(1, 0x124), 0);
    CHECK_EQ(SimInject(0x124, 0, 1, abOne), 0);
    CHECK_EQ(SimInject(0x123, 0, 1, abOne), 1);
    abData[0] = 0x02;
    CHECK_EQ(SimInject(0x080, 0, 1, abData), 1);
    CHECK_EQ(SimRxPending(1), 2);
    Receive(kCopCdrvMsgHigh, 0x080, 0x02);          /* high priority first */
    Receive(kCopCdrvMsgLow, 0x123, 0x01);
    Receive(kCopCdrvNoMsg, 0, 0);
    CHECK_EQ(SimInject(0x123, 0, 9, abOne), -1);     /* DLC above 8 */

    /* A pointer that is not the oldest entry is refused. */
    {
        tCdrvMsg Foreign;
        memset(&Foreign, 0, sizeof(Foreign));
        CHECK_RET(CdrvReleaseMsg(&Foreign), kCopCdrvInvalidParam);
    }

    /* Overrun: the fourth frame for a queue of three is lost. */
    for (i = 0; i < 4; i++)
    {
        abData[0] = (BYTE) (0x10 + i);
        CHECK_EQ(SimInject(0x123, 0, 1, abData), (i < 3) ? 1 : 0);
    }
    CHECK_RET(CdrvGetStatus(&Status), kCopSuccessful);
    CHECK_EQ(Status & kCdrvRxBuffLowOverrun, kCdrvRxBuffLowOverrun);
    CHECK_EQ(Status & kCdrvRxBuffHighOverrun, 0);
    CHECK_RET(CdrvResetStatus(kCdrvRxBuffLowOverrun), kCopSuccessful);
    CHECK_RET(CdrvGetStatus(&Status), kCopSuccessful);
    CHECK_EQ(Status, 0);
    Receive(kCopCdrvMsgLow, 0x123, 0x10);
    Receive(kCopCdrvMsgLow, 0x123, 0x11);
    Receive(kCopCdrvMsgLow, 0x123, 0x12);
    Receive(kCopCdrvNoMsg, 0, 0);
    for (i = 0; i < 3; i++)
    {
        CHECK_EQ(SimInject(0x080, 0, 1, abOne), (i < 2) ? 1 : 0);
    }
    CHECK_EQ(SimGetStatus(1) & kCdrvRxBuffHighOverrun, kCdrvRxBuffHighOverrun);
    CHECK_RET(CdrvReset(kResetRxBuffer | kResetCanCtrl), kCopSuccessful);
    CHECK_EQ(SimRxPending(1), 0);
    CHECK_EQ(SimGetStatus(1), 0);
    CHECK_RET(CdrvGetStatus(NULL), kCopCdrvInvalidParam);

    /* Between nodes: a controller does not receive its own frames. */
    InitDriver(2, 4, 4);
    Define(0x123, 0);
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    Send(0x123, 2, 0x42, 0, kCopSuccessful);
    CHECK_EQ(SimRxPending(1), 0);
    CHECK_EQ(SimRxPending(2), 1);
    CHECK_EQ(SimSentPending(), 1);
    CHECK(SimTakeSentFrame(&Frame));
    CHECK_EQ(Frame.m_dwId, 0x123);
    CHECK_EQ(Frame.m_bDlc, 2);
    CHECK_EQ(Frame.m_abData[0], 0x42);
    CHECK_EQ(Frame.m_bSender, 1);
    CHECK(!SimTakeSent(&dwId, &bRtr, &bDlc, abData));
    CHECK_RET(SimSelectNode(2), kCopSuccessful);
    Receive(kCopCdrvMsgLow, 0x123, 0x42);

    /* Frames from outside are not in the sent log. */
    CHECK_EQ(SimInject(0x123, 0, 1, abOne), 2);
    CHECK_EQ(SimSentPending(), 0);
    CHECK_RET(CdrvReset(kResetRxBuffer), kCopSuccessful);

    /* Remote requests. */
    CHECK_EQ(SimInject(0x123, 1, 0, NULL), 2);
    CHECK_RET(CdrvReadMsg(&pMsg), kCopCdrvMsgLow);
    CHECK((pMsg->m_MsgType & kMtbRtr) != 0);
    CHECK_RET(CdrvReleaseMsg(pMsg), kCopSuccessful);

    /* Fault hook: refused transmissions report the buffer of the frame. */
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    SimRefuseTx(1, 2);
    Send(0x123, 1, 0x01, 0, kCopCdrvTxBuffLowOverrun);
    Send(0x123, 1, 0x01, 1, kCopCdrvTxBuffHighOverrun);
    CHECK_EQ(SimSentPending(), 0);
    Send(0x123, 1, 0x03, 0, kCopSuccessful);
    CHECK(SimTakeSent(&dwId, &bRtr, &bDlc, abData));
    CHECK_EQ(dwId, 0x123);
    CHECK_EQ(abData[0], 0x03);

    /* Fault hook: the next frame with an identifier is lost, once. */
    CHECK_RET(SimSelectNode(2), kCopSuccessful);
    CHECK_RET(CdrvReset(kResetRxBuffer), kCopSuccessful);
    SimDropNextId(0x123);
    CHECK_EQ(SimInject(0x123, 0, 1, abOne), 0);
    CHECK_EQ(SimInject(0x123, 0, 1, abOne), 2);

    /* Undefine. */
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    CHECK_RET(CdrvReset(kResetRxBuffer | kResetCanCtrl), kCopSuccessful);
    CHECK_RET(SimSelectNode(2), kCopSuccessful);
    {
        tCdrvMsg Msg;
        memset(&Msg, 0, sizeof(Msg));
        Msg.m_CanId = 0x123;
        CHECK_RET(CdrvUndefineCanId(&Msg), kCopSuccessful);
        CHECK_EQ(SimIsIdDefined(2, 0x123), 0);
        CHECK_EQ(SimInject(0x123, 0, 1, abOne), 1);     /* node 1 only */
    }

    /* The clock: 100 us ticks, wrapping modulo 2^32. */
    {
        tTime Start = TgtGetTickCount();
        SimAdvanceMs(5);
        CHECK_EQ(TgtGetTickCount() - Start, 50);
        SimAdvanceTicks(0xFFFFFFFFUL);
        CHECK_EQ((tTime) (TgtGetTickCount() - Start), 49);
    }

    /* candump lines. */
    memset(&Frame, 0, sizeof(Frame));
    Frame.m_dwId = 0x702;
    Frame.m_bDlc = 1;
    CHECK(SimFormatCandump(&Frame, szLine, sizeof(szLine)) > 0);
    CHECK(strcmp(szLine, "  can0  702   [1]  00") == 0);
    Frame.m_dwId = 0x602;
    Frame.m_bDlc = 8;
    Frame.m_abData[0] = 0x40;
    Frame.m_abData[2] = 0x60;
    Frame.m_abData[3] = 0x01;
    CHECK(SimFormatCandump(&Frame, szLine, sizeof(szLine)) > 0);
    CHECK(strcmp(szLine, "  can0  602   [8]  40 00 60 01 00 00 00 00") == 0);
    Frame.m_dwId = 0x702;
    Frame.m_bDlc = 0;
    Frame.m_bRtr = 1;
    CHECK(SimFormatCandump(&Frame, szLine, sizeof(szLine)) > 0);
    CHECK(strcmp(szLine, "  can0  702   [0]  remote request") == 0);
    CHECK_EQ(SimFormatCandump(&Frame, szLine, 8), -1);

    /* Delete. */
    CHECK_RET(SimSelectNode(2), kCopSuccessful);
    CHECK_RET(CdrvDeleteInstance(), kCopSuccessful);
    CHECK_RET(CdrvDeleteInstance(), kCopIllegalInstance);
    CHECK_EQ(SimInject(0x080, 0, 1, abOne), 1);         /* node 1 only */
}

/* The stack subscribes what it needs, and nothing arrives otherwise. */
static void ThroughTheStack (void)
{
    static CONST BYTE abStart[2] = { 0x01, 0x00 };

    SimReset();
    CHECK_RET(TestInitNode(0, 3, ObdInitRamMin, TestNmtRecorder), kCopSuccessful);
    CHECK(SimIsIdDefined(0, 0x000) != 0);   /* NMT */
    CHECK_EQ(SimIsIdDefined(0, 0x000), 2);  /* ... in the high-priority buffer */
    CHECK(SimIsIdDefined(0, 0x603) != 0);   /* SDO requests for node 3 */
    CHECK(SimIsIdDefined(0, 0x703) != 0);   /* node guarding (RTR) */
    CHECK_EQ(SimIsIdDefined(0, 0x604), 0);
    CHECK_EQ(SimIsIdDefined(0, 0x583), 0);  /* its own responses */
    CHECK_EQ(SimInject(0x604, 0, 8, NULL), 0);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_EQ(SimInject(0x000, 0, 2, abStart), 1);
    TestProcess(2);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    CHECK_EQ(SimRxPending(0), 0);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    CHECK_EQ(SimIsIdDefined(0, 0x000), 0);  /* CdrvDeleteInstance */
}

int main (void)
{
    DirectDriver();
    ThroughTheStack();
    return TEST_DONE("test_sim");
}
