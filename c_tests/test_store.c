/*
 * test_store.c - store / restore (0x1010 / 0x1011, CiA 301 7.5.2.13 and
 * 7.5.2.14) through the C API with the simulated memory of
 * examples_c/sim/store_sim.h: an SRDO configured (SCT, 0x13FF CRC, 0x13FE =
 * 0xA5), saved with "save" on 0x1010 sub 1, a simulated restart
 * (CcmShutDownCANopen, CcmInitCANopen, CcmInitStore in the NMT callback as
 * the SYS TEC slave calls it), the same configuration back and the SRDO
 * running without reconfiguration; a power cut in the middle of a save
 * leaves the previous configuration; without a driver start-up goes on.
 *
 * Dictionary objdict_store.h: SRDO 1 (0x1301) transmits 0x2040/1 and
 * 0x2041/1 on 0x101/0x102, SCT default 25 ms.
 */
#include "test_util.h"
#include "store_sim.h"

#define NODE_ID 2
#define SAVE 0x65766173UL   /* "save", CiA 301 7.5.2.13 */
#define LOAD 0x64616F6CUL   /* "load", CiA 301 7.5.2.14 */

static tCopKernel InitStoreResult_l = 0xFFFF;
static unsigned uInitStoreCalls_l;

/* The NMT callback of the SYS TEC slave: CcmInitStore at EnterInitialising,
 * whatever it returns the node goes on. */
static tCopKernel PUBLIC NmtWithStore (tNmtEvent NmtEvent_p)
{
    if (NmtEvent_p == kNmtEvEnterInitialising)
    {
        InitStoreResult_l = CcmInitStore();
        uInitStoreCalls_l++;
    }
    return TestNmtRecorder(NmtEvent_p);
}

static BYTE ReadU8 (WORD wIndex_p, BYTE bSub_p)
{
    BYTE bValue = 0;
    tObdSize Size = sizeof(bValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &bValue, &Size), kCopSuccessful);
    return bValue;
}

static WORD ReadU16 (WORD wIndex_p, BYTE bSub_p)
{
    WORD wValue = 0;
    tObdSize Size = sizeof(wValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &wValue, &Size), kCopSuccessful);
    return wValue;
}

static DWORD ReadU32 (WORD wIndex_p, BYTE bSub_p)
{
    DWORD dwValue = 0;
    tObdSize Size = sizeof(dwValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &dwValue, &Size), kCopSuccessful);
    return dwValue;
}

static tCopKernel Command (WORD wIndex_p, BYTE bSub_p, DWORD dwSignature_p)
{
    return CcmWriteObject(wIndex_p, bSub_p, &dwSignature_p, sizeof(dwSignature_p));
}

/* A power cycle: the stack goes, RAM variables come back with their
 * defaults (CcmInitCANopen), the memory keeps its contents. */
static void Restart (const tCopStoreDriver* pDriver_p)
{
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    CHECK_RET(CcmSetStoreDriver(pDriver_p), kCopSuccessful);
    uInitStoreCalls_l = 0;
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, NmtWithStore), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestProcess(1);
    CHECK(uInitStoreCalls_l >= 1);
}

/* SCT 40 ms, its CRC in 0x13FF sub 1, 0x13FE = 0xA5. */
static void ConfigureSrdo (WORD wSct_p)
{
    WORD wCrc = 0;
    WORD wIndex = 0;
    BYTE bValid = 0xA5;

    CHECK_RET(CcmWriteObject(0x1301, 2, &wSct_p, sizeof(wSct_p)), kCopSuccessful);
    CHECK_RET(CcmCalcSrdoCrc(0x1301, &wCrc), kCopSuccessful);
    CHECK_RET(CcmWriteObject(0x13FF, 1, &wCrc, sizeof(wCrc)), kCopSuccessful);
    CHECK_RET(CcmCalcSrdoCrc(0x1302, &wCrc), kCopSuccessful);
    CHECK_RET(CcmWriteObject(0x13FF, 2, &wCrc, sizeof(wCrc)), kCopSuccessful);
    CHECK_RET(CcmWriteObject(0x13FE, 0, &bValid, 1), kCopSuccessful);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSuccessful);
}

static void SrdoRuns (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    static CONST BYTE abNormal[1] = { 0x5A };
    static CONST BYTE abInverted[1] = { 0xA5 };
    static CONST BYTE abEnterPreop[2] = { 0x80, 0x00 };
    BYTE bOut = 0x5A;
    BYTE bInv = 0xA5;

    SimInject(0x000, 0, 2, abStartAll);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    CHECK_RET(CcmWriteObject(0x2040, 1, &bOut, 1), kCopSuccessful);
    CHECK_RET(CcmWriteObject(0x2041, 1, &bInv, 1), kCopSuccessful);
    TestDrainSent();
    SimAdvanceMs(2);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSuccessful);
    TestExpectFrame("SRDO normal frame", 0x101, 1, abNormal);
    TestExpectFrame("SRDO inverted frame", 0x102, 1, abInverted);
    /* CiA 304: no store while OPERATIONAL (SDO abort 0x08000022) */
    CHECK_RET(Command(0x1010, 1, SAVE), kCopCcmStoreUnvalidState);
    SimInject(0x000, 0, 2, abEnterPreop);
    TestProcess(1);
    TestDrainSent();
}

int main (void)
{
    WORD wIndex = 0;

    SimReset();
    SimStoreReset();

    /* No driver: start-up goes on, save refused (0x08000020). */
    CHECK_RET(CcmSetStoreDriver(NULL), kCopSuccessful);
    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, NmtWithStore), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestProcess(1);
    CHECK_EQ(InitStoreResult_l, kCopCcmStoreHwError);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
    CHECK_EQ(ReadU32(0x1010, 1), 0);
    CHECK_RET(Command(0x1010, 1, SAVE), kCopCcmStoreHwError);
    CHECK_RET(CcmStoreCheckArchivState(kObdPartGen), kCopCcmStoreHwError);

    /* With the simulated memory: nothing stored yet. */
    Restart(SimStoreDriver());
    CHECK_EQ(InitStoreResult_l, kCopSuccessful);
    CHECK_EQ(ReadU32(0x1010, 1), 1);           /* saves on command */
    CHECK_RET(CcmStoreCheckArchivState(kObdPartGen), kCopCcmStoreUnvalidState);
    CHECK_EQ(ReadU16(0x1301, 2), 25);
    CHECK_EQ(SimStoreBytesWritten(), 0);

    /* Configure, save, check. */
    ConfigureSrdo(40);
    CHECK_RET(Command(0x1010, 1, 0x12345678UL), kCopInvalidParam);   /* not the signature */
    CHECK_RET(Command(0x1010, 1, SAVE), kCopSuccessful);
    CHECK(SimStoreBytesWritten() > 0);
    CHECK_RET(CcmStoreCheckArchivState(kObdPartAll), kCopSuccessful);

    /* Without the driver the restart brings the defaults: nothing of the
     * configuration survives in RAM. */
    Restart(NULL);
    CHECK_EQ(ReadU16(0x1301, 2), 25);
    CHECK_EQ(ReadU8(0x13FE, 0), 0);

    /* With it the configuration is back and the SRDO runs. */
    Restart(SimStoreDriver());
    CHECK_EQ(InitStoreResult_l, kCopSuccessful);
    CHECK_EQ(ReadU16(0x1301, 2), 40);
    CHECK_EQ(ReadU8(0x13FE, 0), 0xA5);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSuccessful);
    SrdoRuns();

    /* A power cut in the middle of a save keeps the old configuration. */
    ConfigureSrdo(60);
    SimStoreCutAfterBytes(SimStoreBytesWritten() / 4);
    CHECK_RET(Command(0x1010, 1, SAVE), kCopCcmStoreHwError);
    SimStorePowerOn();
    Restart(SimStoreDriver());
    CHECK_EQ(InitStoreResult_l, kCopSuccessful);
    CHECK_EQ(ReadU16(0x1301, 2), 40);
    CHECK_EQ(ReadU8(0x13FE, 0), 0xA5);
    SrdoRuns();

    /* "load" on 0x1011 sub 1: the defaults after the next restart. */
    CHECK_RET(Command(0x1011, 1, LOAD), kCopSuccessful);
    CHECK_RET(CcmStoreCheckArchivState(kObdPartGen), kCopCcmStoreUnvalidState);
    Restart(SimStoreDriver());
    CHECK_EQ(ReadU16(0x1301, 2), 25);
    CHECK_EQ(ReadU8(0x13FE, 0), 0);

    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_store");
}
