/*
 * test_lss.c - the LSS slave (CiA 305) as a SYS TEC application uses it:
 * CcmInitCANopen with node-ID 0xFF (LSS_INVALID_NODEID; the test library
 * has CCM_MODULE_LSSS in CCM_MODULE_INTEGRATION), CcmProcessLssInitState
 * until an LSS master has given the node a node-ID, then CcmConnectToNet.
 * The master's requests are injected on 0x7E5; the answers come on 0x7E4,
 * 8 bytes each (CiA 305). objdict_min.h gives the LSS address (0x1018 sub
 * 1..4: 0x123, 0x2, DEFINED_OBJ1018_VERSION, 0x1).
 */
#include "test_util.h"

/* An LSS frame: the specifier, a number in bytes 1..4 (little-endian), the
 * rest 0. */
static void LssFrame (BYTE* pbData_p, BYTE bCs_p, DWORD dwValue_p)
{
    memset(pbData_p, 0, 8);
    pbData_p[0] = bCs_p;
    pbData_p[1] = (BYTE) dwValue_p;
    pbData_p[2] = (BYTE) (dwValue_p >> 8);
    pbData_p[3] = (BYTE) (dwValue_p >> 16);
    pbData_p[4] = (BYTE) (dwValue_p >> 24);
}

static void Request (BYTE bCs_p, DWORD dwValue_p)
{
    BYTE abData[8];

    LssFrame(abData, bCs_p, dwValue_p);
    CHECK_EQ(SimInject(0x7E5, 0, 8, abData), 1);
}

static void ExpectAnswer (const char* pszWhat_p, BYTE bCs_p, DWORD dwValue_p)
{
    BYTE abData[8];

    LssFrame(abData, bCs_p, dwValue_p);
    TestExpectFrame(pszWhat_p, 0x7E4, 8, abData);
}

int main (void)
{
    static CONST DWORD adwAddress[4] = { 0x123, 0x2, DEFINED_OBJ1018_VERSION, 0x1 };
    static CONST BYTE abBootUp[1] = { 0x00 };
    static CONST tNmtEvent aTakeNodeId[] = {
        kNmtEvPreResetCommunication, kNmtEvResetCommunication, kNmtEvPostResetCommunication };
    BYTE i;

    SimReset();
    TestNmtClear();
    CHECK_RET(TestInitNode(0, LSS_INVALID_NODEID, ObdInitRamMin, TestNmtRecorder), kCopSuccessful);
    CHECK_EQ(CcmLsssGetNodeId(), LSS_INVALID_NODEID);
    CHECK_RET(CcmProcessLssInitState(), kCopLsssInvalidNodeId);
    CHECK_RET(CcmConnectToNet(), kCopLsssInvalidNodeId);
    TestDrainSent();
    TestNmtClear();

    /* identify non-configured remote slave: 0x50 */
    Request(0x4C, 0);
    CHECK_RET(CcmProcessLssInitState(), kCopLsssInvalidNodeId);
    ExpectAnswer("identify non-configured", 0x50, 0);

    /* switch state selective with the LSS address: 0x44 */
    for (i = 0; i < 4; i++)
    {
        Request((BYTE) (0x40 + i), adwAddress[i]);
    }
    CHECK_RET(CcmProcessLssInitState(), kCopLsssInvalidNodeId);
    ExpectAnswer("switch state selective", 0x44, 0);

    /* inquire the serial number and the node-ID (none: 0xFF) */
    Request(0x5D, 0);
    Request(0x5E, 0);
    CHECK_RET(CcmProcessLssInitState(), kCopLsssInvalidNodeId);
    ExpectAnswer("inquire serial number", 0x5D, adwAddress[3]);
    ExpectAnswer("inquire node-ID", 0x5E, 0xFF);

    /* configure node-ID 0x22: error code 0; 0x80: error code 1 */
    Request(0x11, 0x80);
    Request(0x11, 0x22);
    CHECK_RET(CcmProcessLssInitState(), kCopLsssInvalidNodeId);
    ExpectAnswer("configure node-ID 0x80", 0x11, 1);
    ExpectAnswer("configure node-ID 0x22", 0x11, 0);
    CHECK_EQ(uTestNmtEventCount_g, 0);

    /* store configuration: error code 1, not supported */
    Request(0x17, 0);
    CHECK_RET(CcmProcessLssInitState(), kCopLsssInvalidNodeId);
    ExpectAnswer("store configuration", 0x17, 1);

    /* switch state global to waiting: the node takes 0x22 with a reset
     * communication */
    Request(0x04, 0);
    CHECK_RET(CcmProcessLssInitState(), kCopSuccessful);
    CHECK_EQ(CcmLsssGetNodeId(), 0x22);
    CHECK_EQ(uTestNmtEventCount_g, 3);
    for (i = 0; (i < 3) && (i < uTestNmtEventCount_g); i++)
    {
        CHECK_EQ(aTestNmtEvents_g[i], aTakeNodeId[i]);
    }
    CHECK_EQ(SimSentPending(), 0);

    /* CcmConnectToNet: boot-up on 0x700 + 0x22 (CiA 301 7.2.8.3.2.1) */
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestProcess(1);
    TestExpectFrame("boot-up", 0x722, 1, abBootUp);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    CHECK_RET(CcmProcessLssInitState(), kCopSuccessful);

    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    CHECK_RET(CcmProcessLssInitState(), kCopIllegalInstance);
    return TEST_DONE("test_lss");
}
