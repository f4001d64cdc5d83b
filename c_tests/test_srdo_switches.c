/*
 * test_srdo_switches.c - the same two-node SRDO scenario (objdict_all.h on
 * node A, objdict_srdo_peer.h on node P: configuration, a transmitted and
 * received SRDO, an SCT timeout, a GFC) with the library built three ways:
 *
 *   c_tests/cfg           GFC and program monitor on: AppGfcEvent runs,
 *                         AppProgMonEvent runs;
 *   c_tests/cfg_nogfc     SRDO_USE_GFC FALSE: no CcmSendGfc (see also the
 *                         must-not-compile / must-not-link tests), the node
 *                         does not even receive id 0x001, no AppGfcEvent;
 *   c_tests/cfg_noprogmon SRDO_USE_PROGMONITOR FALSE: AppProgMonEvent is
 *                         never called. Built once with a counting
 *                         AppProgMonEvent (TEST_COUNT_PROGMON, the count
 *                         stays 0) and once without any (the program links:
 *                         nothing refers to it).
 */
#include "test_util.h"

#define SIM_A 0
#define SIM_P 1

extern tObdUnsigned8 bPeerIn_g;
tCopKernel PUBLIC ObdInitRamSrdoPeer (void MEM* pInitParam_p);

#if defined(TEST_COUNT_PROGMON)
/* cop_app.h declares no AppProgMonEvent in this configuration */
tCopKernel PUBLIC AppProgMonEvent (tProgMonEvent Event_p);
tCopKernel PUBLIC AppProgMonEvent (tProgMonEvent Event_p)
{
    (void) Event_p;
    uTestProgMonEvents_g++;
    return kCopSuccessful;
}
#endif

int main (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    BYTE bValue = 0x5A;

    SimReset();
    SimSetTrace(1);
    TestSrdoClear();

    CHECK_RET(TestInitNode(SIM_A, 2, ObdInitRam, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1300, 0, 1), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2040, 1, bValue), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2041, 1, (BYTE) ~bValue), kCopSuccessful);
    CHECK_RET(TestSrdoMakeValid(), kCopSuccessful);
    CHECK_RET(TestInitNode(SIM_P, 5, ObdInitRamSrdoPeer, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1300, 0, 1), kCopSuccessful);
    CHECK_RET(TestSrdoMakeValid(), kCopSuccessful);

    SimInject(0x000, 0, 2, abStartAll);
    SimSelectNode(SIM_A);
    TestProcess(1);
    SimSelectNode(SIM_P);
    TestProcess(1);
    SimAdvanceMs(2);

    /* A -> P */
    SimSelectNode(SIM_A);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSuccessful);
    SimSelectNode(SIM_P);
    TestProcess(1);
    CHECK_EQ(uTestSrdoEvents_g, 2);                 /* sent on A, received on P */
    CHECK_EQ(bPeerIn_g, 0x5A);
    /* no valid pair within P's SCT (100 ms) */
    SimAdvanceMs(120);
    TestProcess(1);
    CHECK_EQ(TestLastSrdoError_g, kCopSrdoNotHandledInApp);
    CHECK_EQ(aTestSrdoErrors_g[0], kCopSrdoSctTimeout);

    /* the global fail-safe command */
#if defined(COP_CFG_SRDO_USE_GFC)
    CHECK_EQ(SimIsIdDefined(SIM_P, 0x001), 2);      /* high-priority buffer */
    SimSelectNode(SIM_A);
    CHECK_RET(CcmSendGfc(), kCopSuccessful);
    SimSelectNode(SIM_P);
    TestProcess(1);
    CHECK_EQ(uTestGfcEvents_g, 1);
#else
    CHECK_EQ(SimIsIdDefined(SIM_P, 0x001), 0);      /* not received at all */
    SimInject(0x001, 0, 0, NULL);
    TestProcess(1);
    CHECK_EQ(uTestGfcEvents_g, 0);
#endif

    /* the program monitor */
#if defined(COP_CFG_SRDO_USE_PROGMONITOR)
    CHECK(uTestProgMonEvents_g > 0);
#else
    CHECK_EQ(uTestProgMonEvents_g, 0);
#endif
    printf("AppProgMonEvent calls: %u, AppGfcEvent calls: %u\n", uTestProgMonEvents_g, uTestGfcEvents_g);

    SimSelectNode(SIM_A);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    SimSelectNode(SIM_P);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_srdo_switches");
}
