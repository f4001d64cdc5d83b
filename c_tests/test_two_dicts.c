/*
 * test_two_dicts.c - two dictionaries in one program (objdict_all.c with
 * ObdInitRam, objdict_min.c with ObdInitRamMin: all generated data is
 * static, so they do not collide), each driving its own node on the
 * simulated bus. SimSelectNode decides which node the Ccm* calls address.
 */
#include "test_util.h"

static DWORD ReadU32 (WORD wIndex_p, BYTE bSub_p)
{
    DWORD dwValue = 0;
    tObdSize Size = sizeof(dwValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &dwValue, &Size), kCopSuccessful);
    return dwValue;
}

int main (void)
{
    static CONST BYTE abBootUp[1] = { 0x00 };
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    WORD wValue = 0;
    tObdSize Size = sizeof(wValue);

    SimReset();
    SimSetTrace(1);
    CHECK_RET(TestInitNode(0, 4, ObdInitRam, TestNmtRecorder), kCopSuccessful);
    CHECK_RET(TestInitNode(1, 5, ObdInitRamMin, TestNmtRecorder), kCopSuccessful);

    CHECK_RET(SimSelectNode(0), kCopSuccessful);
    CHECK_EQ(CcmLsssGetNodeId(), 4);
    CHECK_EQ(ReadU32(0x1018, 2), 0x4711);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestExpectFrame("boot-up node 4", 0x704, 1, abBootUp);

    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    CHECK_EQ(CcmLsssGetNodeId(), 5);
    CHECK_EQ(ReadU32(0x1018, 2), 0x0002);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateInitialisation);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestExpectFrame("boot-up node 5", 0x705, 1, abBootUp);

    /* objects of one dictionary are not in the other */
    {
        BYTE abBuf[4];
        tObdSize n = sizeof(abBuf);
        CHECK_RET(CcmReadObject(0x2000, 1, abBuf, &n), kCopObdIndexNotExist);
    }

    /* a write reaches only the selected node's dictionary */
    wValue = 250;
    CHECK_RET(SimSelectNode(0), kCopSuccessful);
    CHECK_RET(CcmWriteObject(0x1017, 0, &wValue, sizeof(wValue)), kCopSuccessful);
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    wValue = 0xFFFF;
    CHECK_RET(CcmReadObject(0x1017, 0, &wValue, &Size), kCopSuccessful);
    CHECK_EQ(wValue, 0);

    /* one NMT broadcast reaches both nodes */
    CHECK_EQ(SimInject(0x000, 0, 2, abStartAll), 2);
    CHECK_RET(SimSelectNode(0), kCopSuccessful);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);    /* not processed yet */
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);

    /* the heartbeat of node 4 only */
    TestDrainSent();
    SimAdvanceMs(250);
    CHECK_RET(SimSelectNode(0), kCopSuccessful);
    TestProcess(1);
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    TestProcess(1);
    {
        static CONST BYTE abOperational[1] = { 0x05 };
        TestExpectFrame("heartbeat node 4", 0x704, 1, abOperational);
        CHECK_EQ(SimSentPending(), 0);
    }

    CHECK_RET(SimSelectNode(0), kCopSuccessful);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    CHECK_RET(SimSelectNode(1), kCopSuccessful);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_two_dicts");
}
