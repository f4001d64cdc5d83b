/*
 * test_nmt.c - NMT slave behaviour seen from C: the callback sequence of
 * CcmInitCANopen and CcmConnectToNet with the boot-up frame, NMT commands
 * from the bus (start, stop, pre-operational, reset communication, reset
 * node; broadcast and addressed), local commands (CcmNmtsExecCommand), node
 * guarding and the heartbeat producer (CiA 301 7.2.8).
 */
#include "test_util.h"

#define NODE_ID 2

static void ExpectEvents (const char* pszWhat_p, const tNmtEvent* pExpected_p, unsigned uCount_p)
{
    unsigned i;
    int fOk = (uTestNmtEventCount_g == uCount_p);

    for (i = 0; fOk && (i < uCount_p); i++)
    {
        fOk = (aTestNmtEvents_g[i] == pExpected_p[i]);
    }
    if (!fOk)
    {
        printf("%s: NMT events", pszWhat_p);
        for (i = 0; i < uTestNmtEventCount_g; i++)
        {
            printf(" %s", TestNmtEventName(aTestNmtEvents_g[i]));
        }
        printf(", expected");
        for (i = 0; i < uCount_p; i++)
        {
            printf(" %s", TestNmtEventName(pExpected_p[i]));
        }
        printf("\n");
        iTestFailures_g++;
    }
    TestNmtClear();
}

static void NmtFrame (BYTE bCs_p, BYTE bNode_p)
{
    BYTE abData[2];

    abData[0] = bCs_p;
    abData[1] = bNode_p;
    CHECK_EQ(SimInject(0x000, 0, 2, abData), 1);
    TestProcess(1);
}

static CONST BYTE abBootUp_g[1] = { 0x00 };

static void StartUp (void)
{
    static CONST tNmtEvent aInit[] = {
        kNmtEvEnterInitialising, kNmtEvResetNode, kNmtEvPreResetCommunication,
        kNmtEvResetCommunication, kNmtEvPostResetCommunication };
    static CONST tNmtEvent aConnect[] = { kNmtEvEnterPreOperational };

    TestNmtClear();
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRamMin, TestNmtRecorder), kCopSuccessful);
    ExpectEvents("CcmInitCANopen", aInit, 5);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateInitialisation);
    CHECK_EQ(SimSentPending(), 0);                  /* silent until connected */
    TestProcess(2);
    CHECK_EQ(uTestNmtEventCount_g, 0);
    CHECK_EQ(SimSentPending(), 0);

    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    ExpectEvents("CcmConnectToNet", aConnect, 1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    TestExpectFrame("boot-up", 0x700 + NODE_ID, 1, abBootUp_g);
    CHECK_EQ(SimSentPending(), 0);
    CHECK_RET(CcmConnectToNet(), kCopNmtStateError);
}

static void CommandsFromTheBus (void)
{
    static CONST tNmtEvent aOp[] = { kNmtEvEnterOperational };
    static CONST tNmtEvent aStop[] = { kNmtEvEnterStopped };
    static CONST tNmtEvent aPreOp[] = { kNmtEvEnterPreOperational };
    static CONST tNmtEvent aResetComm[] = {
        kNmtEvPreResetCommunication, kNmtEvResetCommunication, kNmtEvPostResetCommunication,
        kNmtEvEnterPreOperational };
    static CONST tNmtEvent aResetNode[] = {
        kNmtEvResetNode, kNmtEvPreResetCommunication, kNmtEvResetCommunication,
        kNmtEvPostResetCommunication, kNmtEvEnterPreOperational };

    NmtFrame(0x01, 0x00);                           /* start all */
    ExpectEvents("start all", aOp, 1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    NmtFrame(0x01, 0x00);                           /* already operational: no event */
    ExpectEvents("start again", NULL, 0);
    NmtFrame(0x02, NODE_ID);                        /* stop this node */
    ExpectEvents("stop node 2", aStop, 1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateStopped);
    NmtFrame(0x01, NODE_ID + 1);                    /* another node */
    ExpectEvents("start node 3", NULL, 0);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateStopped);
    NmtFrame(0x80, 0x00);                           /* pre-operational, all */
    ExpectEvents("pre-operational all", aPreOp, 1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    NmtFrame(0x01, NODE_ID);
    ExpectEvents("start node 2", aOp, 1);
    CHECK_EQ(SimSentPending(), 0);

    NmtFrame(0x82, NODE_ID);                        /* reset communication */
    ExpectEvents("reset communication", aResetComm, 4);
    TestExpectFrame("boot-up after reset communication", 0x700 + NODE_ID, 1, abBootUp_g);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);

    NmtFrame(0x81, 0x00);                           /* reset node, all */
    ExpectEvents("reset node", aResetNode, 5);
    TestExpectFrame("boot-up after reset node", 0x700 + NODE_ID, 1, abBootUp_g);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    CHECK_EQ(SimSentPending(), 0);
}

static void LocalCommands (void)
{
    static CONST tNmtEvent aOp[] = { kNmtEvEnterOperational };
    static CONST tNmtEvent aStop[] = { kNmtEvEnterStopped };
    static CONST tNmtEvent aPreOp[] = { kNmtEvEnterPreOperational };
    static CONST tNmtEvent aResetComm[] = {
        kNmtEvPreResetCommunication, kNmtEvResetCommunication, kNmtEvPostResetCommunication,
        kNmtEvEnterPreOperational };

    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopSuccessful);
    TestProcess(1);
    ExpectEvents("local start", aOp, 1);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStopRemoteNode), kCopSuccessful);
    TestProcess(1);
    ExpectEvents("local stop", aStop, 1);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommEnterPreOperational), kCopSuccessful);
    TestProcess(1);
    ExpectEvents("local pre-operational", aPreOp, 1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommResetCommunication), kCopSuccessful);
    TestProcess(1);
    ExpectEvents("local reset communication", aResetComm, 4);
    TestExpectFrame("boot-up after local reset", 0x700 + NODE_ID, 1, abBootUp_g);
    CHECK_RET(CcmNmtsExecCommand(0x1234), kCopNmtUnknownCommand);
    CHECK_EQ(uTestNmtEventCount_g, 0);
}

static void ErrorControl (void)
{
    static CONST BYTE abPreOp[1] = { 0x7F };
    static CONST BYTE abPreOpToggled[1] = { 0xFF };
    static CONST BYTE abOperational[1] = { 0x05 };

    /* node guarding: the state with a toggling bit 7 */
    CHECK_EQ(SimInject(0x700 + NODE_ID, 1, 1, NULL), 1);
    TestProcess(1);
    TestExpectFrame("guard reply 1", 0x700 + NODE_ID, 1, abPreOp);
    CHECK_EQ(SimInject(0x700 + NODE_ID, 1, 1, NULL), 1);
    TestProcess(1);
    TestExpectFrame("guard reply 2", 0x700 + NODE_ID, 1, abPreOpToggled);

    /* heartbeat producer every 100 ms */
    CHECK_RET(CcmConfigHbp(100), kCopSuccessful);
    TestProcess(1);
    TestDrainSent();
    SimAdvanceMs(100);
    TestProcess(1);
    TestExpectFrame("heartbeat", 0x700 + NODE_ID, 1, abPreOp);
    CHECK_RET(CcmNmtsExecCommand(kNmtCommStartRemoteNode), kCopSuccessful);
    TestProcess(1);
    TestNmtClear();
    SimAdvanceMs(100);
    TestProcess(1);
    TestExpectFrame("heartbeat operational", 0x700 + NODE_ID, 1, abOperational);
    SimAdvanceMs(50);
    TestProcess(1);
    CHECK_EQ(SimSentPending(), 0);
    CHECK_RET(CcmConfigHbp(0), kCopSuccessful);
    SimAdvanceMs(500);
    TestProcess(1);
    CHECK_EQ(SimSentPending(), 0);
}

int main (void)
{
    SimReset();
    SimSetTrace(1);
    StartUp();
    CommandsFromTheBus();
    LocalCommands();
    ErrorControl();
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    CHECK_EQ(CcmObdGetNodeState(), 0);
    return TEST_DONE("test_nmt");
}
