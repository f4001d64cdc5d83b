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

static void InitDriverTx (BYTE bNode_p, tCdrvBuffIndex RxLow_p, tCdrvBuffIndex TxLow_p)
{
    tCdrvInitParam Param;

    memset(&Param, 0, sizeof(Param));
    Param.m_RxBuffHigh.m_MaxEntries = 16;
    Param.m_RxBuffLow.m_MaxEntries = RxLow_p;
    Param.m_TxBuffHigh.m_MaxEntries = 16;
    Param.m_TxBuffLow.m_MaxEntries = TxLow_p;
    CHECK_RET(SimSelectNode(bNode_p), kCopSuccessful);
    CHECK_RET(CdrvInit(&Param), kCopSuccessful);
}

static void SendData (BYTE bNode_p, WORD wId_p, BYTE bDlc_p, CONST BYTE* pbData_p, int fHigh_p, tCopKernel Expected_p)
{
    tCdrvMsg Msg;

    memset(&Msg, 0, sizeof(Msg));
    Msg.m_CanId = wId_p;
    Msg.m_MsgType = (tMsgTyp) (fHigh_p ? kMtbHighPrio : 0);
    Msg.m_bSize = bDlc_p;
    memcpy(Msg.m_bData, pbData_p, bDlc_p);
    CHECK_RET(SimSelectNode(bNode_p), kCopSuccessful);
    CHECK_RET(CdrvWriteMsg(&Msg), Expected_p);
}

static unsigned FrameBits (DWORD dwId_p, BYTE bDlc_p, CONST BYTE* pbData_p)
{
    tSimFrame Frame;

    memset(&Frame, 0, sizeof(Frame));
    Frame.m_dwId = dwId_p;
    Frame.m_bDlc = bDlc_p;
    memcpy(Frame.m_abData, pbData_p, bDlc_p);
    return SimFrameBits(&Frame);
}

/* The physical model (SimSetBitRate): frame lengths, arbitration, bit
 * time, end-of-frame timestamps, bounded transmit and receive buffers. The
 * lengths are the ones worked out by hand from ISO 11898-1:2015 10.4.2 and
 * 10.5 in src/sim/physical.rs (known_frames_have_their_length); the times
 * are the ones src/sim.rs asserts for the same frames on the Rust model
 * (physical_bus_sends_the_lowest_identifier_first,
 * physical_capture_has_the_end_of_frame_times), so both models agree. */
static void PhysicalBus (void)
{
    static CONST BYTE abPdo[8] = { 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88 };
    static CONST BYTE abHb[1] = { 0x05 };
    static CONST BYTE abNmt[2] = { 0x01, 0x00 };
    static CONST BYTE abZero[8] = { 0 };
    tSimFrame Frame;
    tSimBusStats Stats;
    char szLine[64];
    unsigned i;

    /* 0x705 [05]: 56 bits, 4 stuff bits; NMT [01 00]: 65; 0x181 with eight
     * bytes: 112; identifier 0, no data: 34 dominant bits, 6 stuff: 50. */
    CHECK_EQ(FrameBits(0x705, 1, abHb), 56);
    CHECK_EQ(FrameBits(0x000, 2, abNmt), 65);
    CHECK_EQ(FrameBits(0x181, 8, abPdo), 112);
    CHECK_EQ(FrameBits(0x000, 0, abZero), 50);
    /* Worst-case bound of stuffing (Davis, Burns, Bril, Lukkien 2007): 8
     * bytes of zeros, base and extended format, within 44 + 64 + 24 and
     * 64 + 64 + 29 bits. */
    CHECK(FrameBits(0x000, 8, abZero) <= 44 + 64 + 24);
    CHECK(FrameBits(0x000 | CAN_FRAME_FORMAT_MASK, 8, abZero) <= 64 + 64 + 29);
    CHECK(FrameBits(0x000 | CAN_FRAME_FORMAT_MASK, 8, abZero) > FrameBits(0x000, 8, abZero));
    CHECK_EQ(SimFrameBits(NULL), 0);

    SimReset();
    CHECK_RET(SimSetBitRate(0, 9999), kCopInvalidParam);
    CHECK_RET(SimSetBitRate(0, 1000001), kCopInvalidParam);
    CHECK_RET(SimSetBitRate(SIM_MAX_BUSES, 125000), kCopInvalidParam);
    CHECK_RET(SimSetBitRate(0, 1000000), kCopSuccessful);
    for (i = 0; i < 4; i++)
    {
        InitDriverTx((BYTE) i, 10, 10);
    }
    Define(0x000, 0);
    Define(0x181, 0);
    Define(0x705, 0);
    /* Queued in node order; the lowest identifier goes first. */
    SendData(0, 0x181, 8, abPdo, 0, kCopSuccessful);
    SendData(1, 0x705, 1, abHb, 0, kCopSuccessful);
    SendData(2, 0x000, 2, abNmt, 1, kCopSuccessful);
    CHECK_EQ(SimTxPending(0), 1);
    CHECK_EQ(SimRxPending(3), 0);
    SimAdvanceMs(1);
    CHECK_EQ(SimTxPending(0), 0);
    CHECK_EQ(SimRxPending(3), 3);
    /* Ends at 65, 180 and 239 us: ticks 0, 1, 2 and the microseconds. */
    CHECK(SimTakeSentFrame(&Frame));
    CHECK_EQ(Frame.m_dwId, 0x000);
    CHECK_EQ(Frame.m_dwTick, 0);
    CHECK_EQ(Frame.m_wSubTickUs, 65);
    CHECK(SimTakeSentFrame(&Frame));
    CHECK_EQ(Frame.m_dwId, 0x181);
    CHECK_EQ(Frame.m_bSender, 0);
    CHECK_EQ(Frame.m_dwTick, 1);
    CHECK_EQ(Frame.m_wSubTickUs, 80);
    CHECK(SimTakeSentFrame(&Frame));
    CHECK_EQ(Frame.m_dwId, 0x705);
    CHECK_EQ(Frame.m_dwTick, 2);
    CHECK_EQ(Frame.m_wSubTickUs, 39);
    CHECK(SimFormatCandump(&Frame, szLine, sizeof(szLine)) > 0);
    CHECK(strcmp(szLine, "  can0  705   [1]  05") == 0);
    CHECK_EQ(SimTakeSentFrame(&Frame), 0);
    CHECK_RET(SimSelectNode(3), kCopSuccessful);
    Receive(kCopCdrvMsgLow, 0x000, 0x01);
    Receive(kCopCdrvMsgLow, 0x181, 0x11);
    Receive(kCopCdrvMsgLow, 0x705, 0x05);
    SimGetBusStats(0, &Stats);
    CHECK_EQ(Stats.m_ullFrames, 3);
    CHECK_EQ(Stats.m_ullBits, 65 + 112 + 56 + 3 * 3);
    CHECK_EQ(Stats.m_ullBusyNs, (65 + 112 + 56 + 3 * 3) * 1000ULL);
    CHECK_EQ(Stats.m_ullElapsedNs, 1000000ULL);

    /* The transmit buffer of its capacity; a full one refuses. The high
     * buffer goes first, whatever the identifiers. */
    SimReset();
    CHECK_RET(SimSetBitRate(0, 125000), kCopSuccessful);
    InitDriverTx(0, 10, 2);
    InitDriverTx(1, 10, 10);
    Define(0x080, 0);
    Define(0x102, 0);
    Define(0x705, 0);
    SendData(0, 0x080, 1, abHb, 0, kCopSuccessful);
    SendData(0, 0x080, 1, abHb, 0, kCopSuccessful);
    SendData(0, 0x080, 1, abHb, 0, kCopCdrvTxBuffLowOverrun);
    SendData(0, 0x102, 1, abHb, 1, kCopSuccessful);
    SimGetBusStats(0, &Stats);
    CHECK_EQ(Stats.m_ullTxRefused, 1);
    SimAdvanceMs(5);
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    Receive(kCopCdrvMsgLow, 0x102, 0x05);
    Receive(kCopCdrvMsgLow, 0x080, 0x05);
    Receive(kCopCdrvMsgLow, 0x080, 0x05);
    Receive(kCopCdrvNoMsg, 0, 0);
    /* At 125 kbit/s the 56 bits of a heartbeat take 448 us: still on the
     * bus after 4 ticks, there after 5. Injected frames arrive the same way. */
    CHECK_EQ(SimInject(0x705, 0, 1, abHb), 0);
    SimAdvanceTicks(4);
    CHECK_EQ(SimRxPending(1), 0);
    SimAdvanceTicks(1);
    CHECK_EQ(SimRxPending(1), 1);
    Receive(kCopCdrvMsgLow, 0x705, 0x05);

    /* Eleven frames for a low receive buffer of ten: one lost, the low
     * overrun bit. */
    SimReset();
    CHECK_RET(SimSetBitRate(0, 1000000), kCopSuccessful);
    InitDriverTx(0, 10, 16);
    InitDriverTx(1, 10, 16);
    Define(0x581, 0);
    for (i = 0; i < 11; i++)
    {
        SendData(0, 0x581, 1, abHb, 1, kCopSuccessful);
    }
    SimAdvanceMs(2);
    SimGetBusStats(0, &Stats);
    CHECK_EQ(Stats.m_ullRxLostLow, 1);
    CHECK_EQ(Stats.m_ullRxLostHigh, 0);
    CHECK_EQ(SimGetStatus(1), kCdrvRxBuffLowOverrun);
    /* Back to the ideal bus: at once again. */
    CHECK_RET(SimSetBitRate(0, 0), kCopSuccessful);
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    CHECK_RET(CdrvReset(kResetRxBuffer | kResetCanCtrl), kCopSuccessful);
    SendData(0, 0x581, 1, abHb, 0, kCopSuccessful);
    CHECK_EQ(SimRxPending(1), 1);
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
    PhysicalBus();
    ThroughTheStack();
    return TEST_DONE("test_sim");
}
