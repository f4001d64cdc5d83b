/*
 * test_obd_callbacks.c - OBD callbacks named in objdict.h index entries
 * (tObdCallback): one that vetoes a write (the value stays as it was, the
 * caller gets the callback's code), one that records every event it sees:
 * kObdEvCheckExist, kObdEvPreRead, kObdEvPostRead for reads;
 * kObdEvCheckExist, kObdEvInitWrite (with the object size),
 * kObdEvPreWrite, kObdEvPostWrite for writes; refusals at each stage; and,
 * over SDO, kObdEvWrStringDomain (string download) and kObdEvAbortSdo
 * (download aborted by the client).
 */
#include "test_util.h"

#define NODE_ID 2

static int SawEvent (BYTE bEvent_p)
{
    unsigned i;

    for (i = 0; i < uTestObdEventCount_g; i++)
    {
        if (abTestObdEvents_g[i] == bEvent_p)
        {
            return 1;
        }
    }
    return 0;
}

static void ExpectEvents (const char* pszWhat_p, const BYTE* pExpected_p, unsigned uCount_p)
{
    unsigned i;
    int fOk = (uTestObdEventCount_g == uCount_p);

    for (i = 0; fOk && (i < uCount_p); i++)
    {
        fOk = (abTestObdEvents_g[i] == pExpected_p[i]);
    }
    if (!fOk)
    {
        printf("%s: events", pszWhat_p);
        for (i = 0; i < uTestObdEventCount_g; i++)
        {
            printf(" %u", (unsigned) abTestObdEvents_g[i]);
        }
        printf(", expected");
        for (i = 0; i < uCount_p; i++)
        {
            printf(" %u", (unsigned) pExpected_p[i]);
        }
        printf("\n");
        iTestFailures_g++;
    }
    TestObdClear();
}

static void Veto (void)
{
    WORD wValue = 0;
    tObdSize Size = sizeof(wValue);

    CHECK_RET(CcmReadObject(0x2020, 0, &wValue, &Size), kCopSuccessful);
    CHECK_EQ(wValue, 1);
    wValue = 0x0BAD;
    CHECK_RET(CcmWriteObject(0x2020, 0, &wValue, sizeof(wValue)), kCopObdValueToHigh);
    wValue = 0;
    CHECK_RET(CcmReadObject(0x2020, 0, &wValue, &Size), kCopSuccessful);
    CHECK_EQ(wValue, 1);
    wValue = 0x0002;
    CHECK_RET(CcmWriteObject(0x2020, 0, &wValue, sizeof(wValue)), kCopSuccessful);
    wValue = 0;
    CHECK_RET(CcmReadObject(0x2020, 0, &wValue, &Size), kCopSuccessful);
    CHECK_EQ(wValue, 2);
}

static void EveryEventOfTheApi (void)
{
    static CONST BYTE aRead[] = { kObdEvCheckExist, kObdEvPreRead, kObdEvPostRead };
    static CONST BYTE aWrite[] = { kObdEvCheckExist, kObdEvInitWrite, kObdEvPreWrite, kObdEvPostWrite };
    static CONST BYTE aRefusedAtPreWrite[] = { kObdEvCheckExist, kObdEvInitWrite };
    DWORD dwValue = 0;
    tObdSize Size = sizeof(dwValue);

    TestObdClear();
    CHECK_RET(CcmReadObject(0x2021, 1, &dwValue, &Size), kCopSuccessful);
    CHECK_EQ(dwValue, 0x10);
    ExpectEvents("read", aRead, 3);

    dwValue = 0x12345678UL;
    CHECK_RET(CcmWriteObject(0x2021, 1, &dwValue, sizeof(dwValue)), kCopSuccessful);
    ExpectEvents("write", aWrite, 4);

    /* kObdEvInitWrite carries the object's size */
    dwValue = 0x1UL;
    CHECK_RET(CcmWriteObject(0x2021, 1, &dwValue, sizeof(dwValue)), kCopSuccessful);
    CHECK_EQ(TestInitWriteSize_g, 4);
    TestObdClear();

    /* a refusal at each stage stops the access, the value stays */
    bTestCbRefuseEvent_g = kObdEvPreRead;
    CHECK_RET(CcmReadObject(0x2021, 1, &dwValue, &Size), kCopObdAccessViolation);
    bTestCbRefuseEvent_g = kObdEvPostRead;
    CHECK_RET(CcmReadObject(0x2021, 1, &dwValue, &Size), kCopObdAccessViolation);
    bTestCbRefuseEvent_g = kObdEvCheckExist;
    CHECK_RET(CcmReadObject(0x2021, 1, &dwValue, &Size), kCopObdSubindexNotExist);
    dwValue = 0x99UL;
    CHECK_RET(CcmWriteObject(0x2021, 1, &dwValue, sizeof(dwValue)), kCopObdSubindexNotExist);
    bTestCbRefuseEvent_g = kObdEvInitWrite;
    CHECK_RET(CcmWriteObject(0x2021, 1, &dwValue, sizeof(dwValue)), kCopObdAccessViolation);
    TestObdClear();
    bTestCbRefuseEvent_g = kObdEvPreWrite;
    CHECK_RET(CcmWriteObject(0x2021, 1, &dwValue, sizeof(dwValue)), kCopObdAccessViolation);
    ExpectEvents("write refused at kObdEvPreWrite", aRefusedAtPreWrite, 2);
    bTestCbRefuseEvent_g = 0xFF;
    dwValue = 0;
    CHECK_RET(CcmReadObject(0x2021, 1, &dwValue, &Size), kCopSuccessful);
    CHECK_EQ(dwValue, 0x1UL);
    TestObdClear();
}

/* SDO download of a string into 0x2021/2 (segmented), then one aborted by
 * the client. Returns how many of kObdEvWrStringDomain / kObdEvAbortSdo
 * were not raised. */
static int EventsOverSdo (void)
{
    static CONST BYTE abInit[8]     = { 0x21, 0x21, 0x20, 0x02, 10, 0, 0, 0 };
    static CONST BYTE abInitResp[8] = { 0x60, 0x21, 0x20, 0x02, 0, 0, 0, 0 };
    static CONST BYTE abSeg1[8]     = { 0x00, '0', '1', '2', '3', '4', '5', '6' };
    static CONST BYTE abSeg1Resp[8] = { 0x20, 0, 0, 0, 0, 0, 0, 0 };
    static CONST BYTE abSeg2[8]     = { 0x19, '7', '8', '9', 0, 0, 0, 0 };
    static CONST BYTE abSeg2Resp[8] = { 0x30, 0, 0, 0, 0, 0, 0, 0 };
    static CONST BYTE abAbort[8]    = { 0x80, 0x21, 0x20, 0x02, 0x00, 0x00, 0x04, 0x05 };
    char szValue[20];
    tObdSize Size = sizeof(szValue);
    int iMissing = 0;

    TestDrainSent();
    TestObdClear();
    SimInject(0x600 + NODE_ID, 0, 8, abInit);
    TestProcess(1);
    TestExpectFrame("initiate download response", 0x580 + NODE_ID, 8, abInitResp);
    SimInject(0x600 + NODE_ID, 0, 8, abSeg1);
    TestProcess(1);
    TestExpectFrame("segment 1 response", 0x580 + NODE_ID, 8, abSeg1Resp);
    SimInject(0x600 + NODE_ID, 0, 8, abSeg2);
    TestProcess(1);
    TestExpectFrame("segment 2 response", 0x580 + NODE_ID, 8, abSeg2Resp);
    memset(szValue, 0, sizeof(szValue));
    CHECK_RET(CcmReadObject(0x2021, 2, szValue, &Size), kCopSuccessful);
    CHECK(strcmp(szValue, "0123456789") == 0);
    CHECK(SawEvent(kObdEvPreWrite));
    CHECK(SawEvent(kObdEvPostWrite));
    if (!SawEvent(kObdEvWrStringDomain))
    {
        printf("NOT YET IN THE LIBRARY: kObdEvWrStringDomain is not raised for a string download over SDO\n");
        iMissing++;
    }

    TestObdClear();
    SimInject(0x600 + NODE_ID, 0, 8, abInit);
    TestProcess(1);
    TestExpectFrame("initiate download response (2)", 0x580 + NODE_ID, 8, abInitResp);
    SimInject(0x600 + NODE_ID, 0, 8, abAbort);
    TestProcess(1);
    CHECK_EQ(SimSentPending(), 0);                  /* an abort is not answered */
    if (!SawEvent(kObdEvAbortSdo))
    {
        printf("NOT YET IN THE LIBRARY: kObdEvAbortSdo is not raised when the client aborts a download\n");
        iMissing++;
    }
    Size = sizeof(szValue);
    memset(szValue, 0, sizeof(szValue));
    CHECK_RET(CcmReadObject(0x2021, 2, szValue, &Size), kCopSuccessful);
    CHECK(strcmp(szValue, "0123456789") == 0);
    return iMissing;
}

int main (void)
{
    int iMissing;

    SimReset();
    SimSetTrace(1);
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, TestNmtRecorder), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestProcess(1);
    Veto();
    EveryEventOfTheApi();
    iMissing = EventsOverSdo();
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    if ((iTestFailures_g == 0) && (iMissing > 0))
    {
        printf("test_obd_callbacks: every check passed except %d event(s) the library does not raise yet\n", iMissing);
        return TEST_SKIP;
    }
    return TEST_DONE("test_obd_callbacks");
}
