/*
 * test_error_callback.c - the code an application callback returns reaches
 * the error callback (CcmRegisterErrorCallback) unchanged, whenever the
 * callback runs:
 *
 *  - an error callback registered before CcmInitCANopen is the one of the
 *    instance that CcmInitCANopen starts (CcmRegisterErrorCallback cannot
 *    report a refusal: it returns void);
 *  - the NMT callback refusing kNmtEvResetCommunication inside
 *    CcmInitCANopen: the node starts (kCopSuccessful, as the AWorks slave,
 *    which prints the code and goes on, needs) and the error callback gets
 *    the application's code;
 *  - at a later reset communication the same, not kCopNmtStateError.
 */
#include "test_util.h"

#define NODE_ID 2
#define APP_CODE kCopObdValueToHigh     /* a code of the application's own choice */

static unsigned   uErrors_g;
static tCopKernel LastError_g;
static int        fRefuseReset_g;

static tCopKernel PUBLIC ErrorCallback (void MEM* pArg_p, tCopKernel ErrorCode_p)
{
    (void) pArg_p;
    uErrors_g++;
    LastError_g = ErrorCode_p;
    return kCopSuccessful;
}

static tCopKernel PUBLIC RefusingNmt (tNmtEvent NmtEvent_p)
{
    (void) TestNmtRecorder(NmtEvent_p);
    return (fRefuseReset_g && (NmtEvent_p == kNmtEvResetCommunication)) ? APP_CODE : kCopSuccessful;
}

int main (void)
{
    static CONST BYTE abResetComm[2] = { 0x82, NODE_ID };

    SimReset();
    SimSetTrace(1);
    TestNmtClear();

    /* registered before the stack exists */
    CcmRegisterErrorCallback(ErrorCallback);
    fRefuseReset_g = 1;
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRamMin, RefusingNmt), kCopSuccessful);
    CHECK_EQ(uTestNmtEventCount_g, 5);          /* the start-up went on */
    CHECK_EQ(uErrors_g, 1);
    CHECK_EQ(LastError_g, APP_CODE);

    /* a later reset communication */
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestProcess(1);
    uErrors_g = 0;
    SimInject(0x000, 0, 2, abResetComm);
    TestProcess(2);
    CHECK_EQ(uErrors_g, 1);
    CHECK_EQ(LastError_g, APP_CODE);

    /* unregistered: nothing more */
    CcmRegisterErrorCallback(NULL);
    uErrors_g = 0;
    SimInject(0x000, 0, 2, abResetComm);
    TestProcess(2);
    CHECK_EQ(uErrors_g, 0);

    /* a callback registered for a stack that was shut down is not the
     * next one's */
    CcmRegisterErrorCallback(ErrorCallback);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    fRefuseReset_g = 1;
    uErrors_g = 0;
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRamMin, RefusingNmt), kCopSuccessful);
    CHECK_EQ(uErrors_g, 0);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_error_callback");
}
