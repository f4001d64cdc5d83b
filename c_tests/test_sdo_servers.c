/*
 * test_sdo_servers.c - an additional SDO server (object 0x1201, CiA 301
 * 7.5.2.33) beside the default one, as an external SDO client sees it on the
 * simulated bus.
 *
 * objdict_all.h declares OBD_CREATE_SDOS(0x1201, 1, 0x80000000, 0x80000000,
 * 0x05): the server exists as an object, delivered without COB-IDs (bit 31
 * set: "SDO does not exist / is not valid"); c_tests/cfg/obdcfg.h sets
 * SDO_MAX_SERVER_IN_OBD 2. The test gives it the identifiers 0x641 (client
 * to server) and 0x5C1 (server to client) over the default server, then
 * runs a segmented upload on it while the default server answers an
 * expedited request in between (each server keeps its own transfer, CiA 301
 * 7.2.4.1), disables it again with bit 31, and checks that reset
 * communication brings back the dictionary's default (no server).
 *
 * Frames as CiA 301 7.2.4.3 defines them: initiate upload request 0x40,
 * expedited response 0x43 (4 bytes, size indicated), segmented initiate
 * response 0x41 with the size in bytes 4..7, upload segment request 0x60 /
 * 0x70 (toggle), segment response with toggle (bit 4), unused bytes n (bits
 * 3..1) and c (bit 0, last segment); initiate download 0x23 -> 0x60.
 * While the server exists (bit 31 clear), its COB-IDs keep bits 0..29: a
 * download of another identifier is aborted with 0x06090030 (value range;
 * CiA 301 7.5.2.33, the same rule as for PDOs in 7.5.2.35), the way to a new
 * identifier is bit 31 first.
 */
#include "test_util.h"

#define NODE_ID 3
#define DEFAULT_RX (0x600 + NODE_ID)
#define DEFAULT_TX (0x580 + NODE_ID)
#define SECOND_RX 0x641
#define SECOND_TX 0x5C1

static void Request (DWORD dwId_p, const BYTE* pbData_p)
{
    SimInject(dwId_p, 0, 8, pbData_p);
    TestProcess(1);
}

/* A request on dwRx_p and the response expected on dwTx_p. */
static void Exchange (const char* pszWhat_p, DWORD dwRx_p, const BYTE* pbReq_p, DWORD dwTx_p, const BYTE* pbResp_p)
{
    Request(dwRx_p, pbReq_p);
    TestExpectFrame(pszWhat_p, dwTx_p, 8, pbResp_p);
}

int main (void)
{
    static CONST BYTE abBootUp[1] = { 0x00 };
    /* upload 0x1018/1 (vendor-ID 0x00000123) and 0x1018/2 (product code 0x00004711) */
    static CONST BYTE abReadVendor[8]  = { 0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0 };
    static CONST BYTE abVendor[8]      = { 0x43, 0x18, 0x10, 0x01, 0x23, 0x01, 0x00, 0x00 };
    static CONST BYTE abReadProduct[8] = { 0x40, 0x18, 0x10, 0x02, 0, 0, 0, 0 };
    static CONST BYTE abProduct[8]     = { 0x43, 0x18, 0x10, 0x02, 0x11, 0x47, 0x00, 0x00 };
    /* download 0x1201/1 = 0x00000641, 0x1201/2 = 0x000005C1, 0x1201/1 = 0x80000641 */
    static CONST BYTE abSetRx[8]   = { 0x23, 0x01, 0x12, 0x01, 0x41, 0x06, 0x00, 0x00 };
    static CONST BYTE abSetRxOk[8] = { 0x60, 0x01, 0x12, 0x01, 0x00, 0x00, 0x00, 0x00 };
    static CONST BYTE abSetTx[8]   = { 0x23, 0x01, 0x12, 0x02, 0xC1, 0x05, 0x00, 0x00 };
    static CONST BYTE abSetTxOk[8] = { 0x60, 0x01, 0x12, 0x02, 0x00, 0x00, 0x00, 0x00 };
    static CONST BYTE abOff[8]     = { 0x23, 0x01, 0x12, 0x01, 0x41, 0x06, 0x00, 0x80 };
    /* download 0x1201/1 = 0x00000642 while valid: abort 0x06090030 */
    static CONST BYTE abMove[8]    = { 0x23, 0x01, 0x12, 0x01, 0x42, 0x06, 0x00, 0x00 };
    static CONST BYTE abMoveAbort[8] = { 0x80, 0x01, 0x12, 0x01, 0x30, 0x00, 0x09, 0x06 };
    /* segmented upload of 0x1008 "cop test node" (13 bytes) */
    static CONST BYTE abReadName[8] = { 0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0 };
    static CONST BYTE abNameInit[8] = { 0x41, 0x08, 0x10, 0x00, 0x0D, 0x00, 0x00, 0x00 };
    static CONST BYTE abSeg0[8]     = { 0x60, 0, 0, 0, 0, 0, 0, 0 };
    static CONST BYTE abSeg0Resp[8] = { 0x00, 'c', 'o', 'p', ' ', 't', 'e', 's' };
    static CONST BYTE abSeg1[8]     = { 0x70, 0, 0, 0, 0, 0, 0, 0 };
    /* toggle 1, one unused byte, last segment: 0x10 | 1 << 1 | 1 */
    static CONST BYTE abSeg1Resp[8] = { 0x13, 't', ' ', 'n', 'o', 'd', 'e', 0x00 };
    static CONST BYTE abResetComm[2] = { 0x82, NODE_ID };
    DWORD dwCobId = 0;
    tObdSize Size = sizeof(dwCobId);

    SimReset();
    SimSetTrace(1);
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, TestNmtRecorder), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestExpectFrame("boot-up", 0x700 + NODE_ID, 1, abBootUp);
    TestDrainSent();

    /* delivered without COB-IDs: nobody answers on 0x641 */
    Request(SECOND_RX, abReadVendor);
    CHECK_EQ(SimSentPending(), 0);

    /* the default server configures the second one */
    Exchange("0x1201/1 written", DEFAULT_RX, abSetRx, DEFAULT_TX, abSetRxOk);
    Exchange("0x1201/2 written", DEFAULT_RX, abSetTx, DEFAULT_TX, abSetTxOk);
    CHECK_RET(CcmReadObject(0x1201, 2, &dwCobId, &Size), kCopSuccessful);
    CHECK_EQ(dwCobId, SECOND_TX);

    Request(SECOND_RX, abReadProduct);
    if (SimSentPending() == 0)
    {
        printf("0x1201 configured, but the additional SDO server does not answer\n");
        iTestFailures_g++;
        return TEST_DONE("test_sdo_servers");
    }
    TestExpectFrame("second server: expedited upload", SECOND_TX, 8, abProduct);

    /* a segmented upload on the second server, the default server in between */
    Exchange("second server: initiate segmented upload", SECOND_RX, abReadName, SECOND_TX, abNameInit);
    Exchange("default server meanwhile", DEFAULT_RX, abReadVendor, DEFAULT_TX, abVendor);
    Exchange("second server: segment 0", SECOND_RX, abSeg0, SECOND_TX, abSeg0Resp);
    Exchange("second server: last segment", SECOND_RX, abSeg1, SECOND_TX, abSeg1Resp);
    CHECK_EQ(SimSentPending(), 0);

    /* bit 31: the server does not exist any more */
    Exchange("0x1201/1 = 0x80000641", DEFAULT_RX, abOff, DEFAULT_TX, abSetRxOk);
    Request(SECOND_RX, abReadProduct);
    CHECK_EQ(SimSentPending(), 0);

    /* on again, then reset communication restores the dictionary's defaults */
    Exchange("0x1201/1 written again", DEFAULT_RX, abSetRx, DEFAULT_TX, abSetRxOk);
    Exchange("second server on again", SECOND_RX, abReadProduct, SECOND_TX, abProduct);

    /* another identifier while it exists: refused, over SDO and the API */
    Exchange("0x1201/1 moved while valid", DEFAULT_RX, abMove, DEFAULT_TX, abMoveAbort);
    dwCobId = SECOND_TX + 1;
    CHECK_RET(CcmWriteObject(0x1201, 2, &dwCobId, sizeof(dwCobId)), kCopInvalidParam);
    dwCobId = SECOND_TX;
    CHECK_RET(CcmWriteObject(0x1201, 2, &dwCobId, sizeof(dwCobId)), kCopSuccessful);
    Size = sizeof(dwCobId);
    CHECK_RET(CcmReadObject(0x1201, 1, &dwCobId, &Size), kCopSuccessful);
    CHECK_EQ(dwCobId, SECOND_RX);
    Exchange("second server still on its identifiers", SECOND_RX, abReadProduct, SECOND_TX, abProduct);
    SimInject(0x000, 0, 2, abResetComm);
    TestProcess(2);
    TestExpectFrame("boot-up after reset communication", 0x700 + NODE_ID, 1, abBootUp);
    TestDrainSent();
    Size = sizeof(dwCobId);
    CHECK_RET(CcmReadObject(0x1201, 1, &dwCobId, &Size), kCopSuccessful);
    CHECK_EQ(dwCobId, 0x80000000UL);
    Request(SECOND_RX, abReadProduct);
    CHECK_EQ(SimSentPending(), 0);
    Exchange("default server after the reset", DEFAULT_RX, abReadVendor, DEFAULT_TX, abVendor);

    CHECK_EQ(SimSentPending(), 0);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_sdo_servers");
}
