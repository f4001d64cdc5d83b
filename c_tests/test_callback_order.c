/*
 * test_callback_order.c - the application's callbacks run one after the
 * other, never inside each other, even when a callback calls Ccm*
 * functions that let the stack work off its events (CcmWriteObject,
 * CcmSendSrdo, ...):
 *
 *  - manual 2.9.5 writes SRDO parameters with CcmWriteObject inside the NMT
 *    callback at kNmtEvResetCommunication: the next start-up event
 *    (kNmtEvPostResetCommunication) must come after that callback has
 *    returned, not from inside its first CcmWriteObject;
 *  - an AppSrdoError that calls CcmWriteObject before it sets the status
 *    bits 6-7 to 10 (manual 2.9.2) has still handled the error: the library
 *    must not check the handshake before AppSrdoError has returned (no
 *    kCopSrdoNotHandledInApp);
 *  - an SRDO sent from inside AppSrdoEvent: its own AppSrdoEvent, which
 *    comes after the outer one has returned, still finds the status "ok"
 *    (bits 4-5 = 00) that the manual's AppSrdoEvent (2.9.1) requires,
 *    although the outer callback has marked the SRDO processed meanwhile.
 */
#include "test_util.h"

#define NODE_ID 2

static unsigned  uDepth_g;
static unsigned  uMaxDepth_g;
static tNmtEvent aSeq_g[16];
static unsigned  uSeq_g;

static tCopKernel PUBLIC NestingNmt (tNmtEvent NmtEvent_p)
{
    uDepth_g++;
    if (uDepth_g > uMaxDepth_g)
    {
        uMaxDepth_g = uDepth_g;
    }
    if (uSeq_g < 16)
    {
        aSeq_g[uSeq_g++] = NmtEvent_p;
    }
    if (NmtEvent_p == kNmtEvResetCommunication)
    {
        /* an application-owned parameter, as in manual 2.9.5 */
        CHECK_RET(TestWriteU16(0x1017, 0, 0), kCopSuccessful);
    }
    uDepth_g--;
    return kCopSuccessful;
}

static unsigned uErrorDepth_g;
static unsigned uErrorMaxDepth_g;

static void ErrorHookWithWrite (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    uErrorDepth_g++;
    if (uErrorDepth_g > uErrorMaxDepth_g)
    {
        uErrorMaxDepth_g = uErrorDepth_g;
    }
    /* some bookkeeping of the application in its dictionary first ... */
    CHECK_RET(TestWriteU8(0x2000, 0x05, 0x42), kCopSuccessful);
    /* ... then the handshake of manual 2.9.2 */
    TestSrdoErrorHandshake(wSrdoCommuIndex_p, ErrorCode_p);
    uErrorDepth_g--;
}

/* Manual 2.9.1, as manual_app.c writes it out: the status must say "ok"
 * (bits 4-5 = 00) when AppSrdoEvent runs, else the application reports a
 * safety-critical error; then the SRDO is marked processed. Before the
 * handshake, the first event sends the SRDO once more from inside the
 * callback. */
static unsigned uSafetyCritical_g;
static unsigned uSendsInside_g;
static unsigned uEventDepth_g;
static unsigned uEventMaxDepth_g;

static void EventHookSendingAgain (WORD wSrdoCommuIndex_p)
{
    BYTE bSrdoState_l = 0;

    uEventDepth_g++;
    if (uEventDepth_g > uEventMaxDepth_g)
    {
        uEventMaxDepth_g = uEventDepth_g;
    }
    if ((CcmGetSrdoState(&bSrdoState_l, wSrdoCommuIndex_p) != kCopSuccessful) ||
        ((bSrdoState_l & 0x30) != 0x00))
    {
        uSafetyCritical_g++;
    }
    if (uSendsInside_g == 0)
    {
        uSendsInside_g++;
        CHECK_RET(CcmSendSrdo(wSrdoCommuIndex_p), kCopSuccessful);
    }
    CHECK_RET(CcmSetSrdoState((BYTE) (bSrdoState_l | 0x30), wSrdoCommuIndex_p), kCopSuccessful);
    uEventDepth_g--;
}

int main (void)
{
    static CONST tNmtEvent aExpected[5] = {
        kNmtEvEnterInitialising, kNmtEvResetNode, kNmtEvPreResetCommunication,
        kNmtEvResetCommunication, kNmtEvPostResetCommunication };
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    static CONST BYTE abBad[1] = { 0x11 };
    unsigned i;
    tCopKernel Ret;

    SimReset();
    SimSetTrace(1);
    TestSrdoClear();

    /* 1. NMT callback: the start-up events in order, none nested */
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, NestingNmt), kCopSuccessful);
    CHECK_EQ(uSeq_g, 5);
    for (i = 0; (i < 5) && (i < uSeq_g); i++)
    {
        if (aSeq_g[i] != aExpected[i])
        {
            printf("NMT event %u: %s, expected %s\n", i, TestNmtEventName(aSeq_g[i]), TestNmtEventName(aExpected[i]));
            iTestFailures_g++;
        }
    }
    CHECK_EQ(uMaxDepth_g, 1);

    /* 2. AppSrdoError with a CcmWriteObject before the handshake */
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(TestSrdoMakeValid(), kCopSuccessful);
    SimInject(0x000, 0, 2, abStartAll);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    pfnTestSrdoErrorHook_g = ErrorHookWithWrite;
    SimInject(0x103, 0, 1, abBad);
    SimInject(0x104, 0, 1, abBad);          /* not inverted: kCopSrdoDataError */
    Ret = CcmProcess();
    CHECK_RET(Ret, kCopSuccessful);
    CHECK_EQ(uTestSrdoErrors_g, 1);
    CHECK_EQ(aTestSrdoErrors_g[0], kCopSrdoDataError);
    CHECK_EQ(aTestSrdoErrors_g[1], 0);      /* no kCopSrdoNotHandledInApp */
    CHECK_EQ(uErrorMaxDepth_g, 1);
    pfnTestSrdoErrorHook_g = NULL;

    /* 3. an SRDO sent from inside AppSrdoEvent */
    SimAdvanceMs(5);                        /* the first-send delay */
    TestProcess(1);
    TestDrainSent();
    TestSrdoClear();
    pfnTestSrdoEventHook_g = EventHookSendingAgain;
    CHECK_RET(CcmSendSrdo(0x1301), kCopSuccessful);
    TestProcess(1);
    pfnTestSrdoEventHook_g = NULL;
    CHECK_EQ(uSendsInside_g, 1);
    CHECK_EQ(uTestSrdoEvents_g, 2);         /* one per transmission */
    CHECK_EQ(uSafetyCritical_g, 0);         /* each saw "ok" */
    CHECK_EQ(uEventMaxDepth_g, 1);          /* one after the other */
    CHECK_EQ(TestDrainSent(), 4);           /* two pairs */

    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_callback_order");
}
