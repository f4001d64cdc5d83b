/*
 * main.c - a slave that uses the API as a firmware with a dynamic object
 * dictionary does: the static dictionary has only 0x1000..0x1018
 * (objdict.h), obdcfg.h counts 0 RPDOs and 0 TPDOs, and everything else -
 * 2 RPDOs, 2 TPDOs of transmission type 254, manufacturer objects and
 * network variables, 127 entries with 0x1003 sub 0 = 4 - comes from a
 * container dcf2bin made from slave.dcf.
 * The order is CcmInitCANopen, DynBuildOd, CcmConnectToNet; the
 * application exchanges process data only through the process image
 * (no CcmSignalCheckVar, no CcmSendPdo). An external master on the
 * simulated bus checks the frame trace:
 *
 *   boot-up          0x702 [00]                    (CiA 301 7.2.8.3.2.1)
 *   SDO answers      0x582, expedited upload 0x43 / 0x4B / 0x4F
 *                    (CiA 301 7.2.4.3.3) with the firmware's 0x1000 and
 *                    0x1018/4, the container's 0x1017 and 0x2320/2, and
 *                    0x1003/0 unchanged although the container carries 4
 *                    (it describes the device's error field, not a write)
 *   OPERATIONAL      NMT start [01 02]; heartbeat 0x702 [05]
 *   RPDO 0x202       into the input area of the process image
 *   TPDO 0x182       once per change of the output area
 *
 * Exit code 0 when every check passes.
 */
#include <stdio.h>
#include <string.h>

#include "cop.h"
#include "cdrv_sim.h"
#include "slave_container.h"

#define NODE_ID 2

static int iFailures_l;

#define CHECK(cond, what)                                                  \
    do {                                                                   \
        if (!(cond)) {                                                     \
            printf("FAILED: %s (%s:%d)\n", what, __FILE__, __LINE__);      \
            iFailures_l++;                                                 \
        }                                                                  \
    } while (0)

static BYTE abProcessImage_l[0xC0];
static tProcessImageDscrpt PIDscrpt_l;
static tCcmInitParam InitParam_l;

tCopKernel PUBLIC ObdInitRam (void MEM* pInitParam_p);

static tCopKernel PUBLIC AppCbNmtEvent (tNmtEvent NmtEvent_p)
{
    (void) NmtEvent_p;
    return kCopSuccessful;
}

static void Process (unsigned uMs_p)
{
    unsigned u;
    for (u = 0; u < uMs_p; u++)
    {
        (void) CcmProcess();
        SimAdvanceMs(1);
    }
}

/* Takes the frames sent so far; returns how many had identifier dwId_p and
 * copies the last of them to pLast_p. */
static unsigned TakeSent (DWORD dwId_p, tSimFrame* pLast_p)
{
    tSimFrame Frame;
    unsigned uCount = 0;
    char szLine[64];

    while (SimTakeSentFrame(&Frame))
    {
        (void) SimFormatCandump(&Frame, szLine, sizeof(szLine));
        printf("  %s\n", szLine);
        if (Frame.m_dwId == dwId_p)
        {
            uCount++;
            if (pLast_p != NULL)
            {
                *pLast_p = Frame;
            }
        }
    }
    return uCount;
}

/* Expedited SDO upload by an external client: returns the answer's data
 * bytes 4..7 as a number and its command byte. */
static DWORD Upload (WORD wIndex_p, BYTE bSub_p, BYTE* pbCommand_p)
{
    BYTE abReq[8] = { 0x40, 0, 0, 0, 0, 0, 0, 0 };
    tSimFrame Answer;
    DWORD dwValue;

    abReq[1] = (BYTE) (wIndex_p & 0xFF);
    abReq[2] = (BYTE) (wIndex_p >> 8);
    abReq[3] = bSub_p;
    memset(&Answer, 0, sizeof(Answer));
    (void) SimInject(0x600 + NODE_ID, 0, 8, abReq);
    Process(2);
    if (TakeSent(0x580 + NODE_ID, &Answer) != 1)
    {
        *pbCommand_p = 0;
        return 0;
    }
    *pbCommand_p = Answer.m_abData[0];
    CHECK(Answer.m_abData[1] == abReq[1] && Answer.m_abData[2] == abReq[2]
              && Answer.m_abData[3] == bSub_p, "SDO answer names the object");
    dwValue = (DWORD) Answer.m_abData[4] | ((DWORD) Answer.m_abData[5] << 8)
              | ((DWORD) Answer.m_abData[6] << 16) | ((DWORD) Answer.m_abData[7] << 24);
    return dwValue;
}

int main (void)
{
    static CONST BYTE abStart[2] = { 0x01, NODE_ID };
    static CONST BYTE abRpdo1[8] = { 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88 };
    tSimFrame Frame;
    tCopKernel Ret;
    BYTE bCommand = 0;
    BYTE bValue = 0;
    tObdSize Size;
    WORD wIndex = 0;
    BYTE bSub = 0;
    DWORD dwOffset = 0;
    tCopKernel Code = kCopSuccessful;
    BYTE* pbOut;
    BYTE* pbIn;

    SimReset();
    InitParam_l.m_bInitNodeId = NODE_ID;
    InitParam_l.m_BaudIndex = kBdi500kBaud;
    (void) TgtGetBitrateTable(0, &InitParam_l.m_pBdiTable, &InitParam_l.m_wSizeOfBdiTab);
    InitParam_l.m_dwAmr = 0xFFFFFFFFUL;
    InitParam_l.m_dwAcr = 0x00000000UL;
    InitParam_l.m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    InitParam_l.m_fpNmtEventCallback = AppCbNmtEvent;
    InitParam_l.m_fpObdInitRam = ObdInitRam;
    CHECK(CcmInitCANopen(&InitParam_l, kCcmFirstInstance) == kCopSuccessful, "CcmInitCANopen");

    /* the dynamic OD before the node connects to the network */
    PIDscrpt_l.m_pbProcessImage = abProcessImage_l;
    PIDscrpt_l.m_dwProcessImageSize = sizeof(abProcessImage_l);
    Ret = DynBuildOd((BYTE FAR*) abSlaveContainer_l, &PIDscrpt_l);
    if (Ret != kCopSuccessful)
    {
        (void) DynGetLastError(&wIndex, &bSub, &dwOffset, &Code);
        printf("DynBuildOd refused entry 0x%04X/%u at container offset %lu: 0x%04lX\n",
               (unsigned) wIndex, (unsigned) bSub, (unsigned long) dwOffset, (unsigned long) Code);
        CHECK(0, "DynBuildOd");
        return 1;
    }
    (void) DynGetLastError(NULL, NULL, NULL, &Code);
    CHECK(Code == kCopSuccessful, "DynGetLastError after a build that succeeded");
    printf("DynBuildOd: inputs at %lu (%lu), outputs at %lu (%lu)\n",
           (unsigned long) PIDscrpt_l.m_dwDynPIOffsetIn, (unsigned long) PIDscrpt_l.m_dwDynPISizeIn,
           (unsigned long) PIDscrpt_l.m_dwDynPIOffsetOut, (unsigned long) PIDscrpt_l.m_dwDynPISizeOut);
    /* four UNSIGNED8 inputs 0xA040/1..4 from 0, outputs 0xA4C0/1..4 from
     * the next multiple of 8 (seed chapter 6, the rule dcf2bin applies) */
    CHECK(PIDscrpt_l.m_dwDynPIOffsetIn == 0 && PIDscrpt_l.m_dwDynPISizeIn == 4, "input area");
    CHECK(PIDscrpt_l.m_dwDynPIOffsetOut == 8 && PIDscrpt_l.m_dwDynPISizeOut == 4, "output area");
    pbIn = abProcessImage_l + PIDscrpt_l.m_dwDynPIOffsetIn;
    pbOut = abProcessImage_l + PIDscrpt_l.m_dwDynPIOffsetOut;

    /* boot-up */
    CHECK(CcmConnectToNet() == kCopSuccessful, "CcmConnectToNet");
    Process(1);
    printf("boot-up:\n");
    memset(&Frame, 0, sizeof(Frame));
    CHECK(TakeSent(0x700 + NODE_ID, &Frame) == 1 && Frame.m_bDlc == 1 && Frame.m_abData[0] == 0x00,
          "boot-up 0x702 [00]");

    /* SDO: the firmware keeps 0x1000 and 0x1018/4 (read-only); the
     * container's values of writable objects apply */
    printf("SDO:\n");
    CHECK(Upload(0x1000, 0, &bCommand) == 0x00020191UL && bCommand == 0x43, "0x1000 firmware value");
    CHECK(Upload(0x1018, 4, &bCommand) == 0x00000007UL && bCommand == 0x43, "0x1018/4 firmware value");
    CHECK(Upload(0x1017, 0, &bCommand) == 100 && bCommand == 0x4B, "0x1017 from the container");
    CHECK(Upload(0x2320, 2, &bCommand) == 0x1000 && bCommand == 0x43, "0x2320/2 created by the container");
    CHECK(Upload(0x1003, 0, &bCommand) == 0 && bCommand == 0x4F, "0x1003/0 no error");
    CHECK(Upload(0x1600, 0, &bCommand) == 8 && bCommand == 0x4F, "RPDO 1 mapping count");

    /* NMT start: OPERATIONAL, heartbeat state 5 */
    printf("OPERATIONAL:\n");
    (void) SimInject(0x000, 0, 2, abStart);
    Process(120);
    memset(&Frame, 0, sizeof(Frame));
    CHECK(TakeSent(0x700 + NODE_ID, &Frame) >= 1 && Frame.m_abData[0] == 0x05, "heartbeat [05]");
    CHECK(TakeSent(0x180 + NODE_ID, NULL) == 0, "no TPDO before anything changed");

    /* RPDO 1 into the process image (network variables) and the pool
     * (0x2300/1..4) */
    printf("RPDO:\n");
    (void) SimInject(0x200 + NODE_ID, 0, 8, abRpdo1);
    Process(2);
    CHECK(pbIn[0] == 0x11 && pbIn[1] == 0x22 && pbIn[2] == 0x33 && pbIn[3] == 0x44,
          "RPDO 1 in the input area");
    Size = sizeof(bValue);
    CHECK(CcmReadObject(0x2300, 4, &bValue, &Size) == kCopSuccessful && bValue == 0x88, "0x2300/4");
    (void) TakeSent(0, NULL);

    /* TPDO 1 on change of the output area, once per change */
    printf("TPDO:\n");
    pbOut[0] = 0xA1;
    pbOut[3] = 0xA4;
    Process(5);
    memset(&Frame, 0, sizeof(Frame));
    CHECK(TakeSent(0x180 + NODE_ID, &Frame) == 1, "one TPDO 1 after the change");
    CHECK(Frame.m_bDlc == 8 && Frame.m_abData[0] == 0xA1 && Frame.m_abData[3] == 0xA4
              && Frame.m_abData[1] == 0 && Frame.m_abData[4] == 0, "TPDO 1 data");
    Process(20);
    CHECK(TakeSent(0x180 + NODE_ID, NULL) == 0, "no TPDO while nothing changes");
    pbOut[1] = 0x5A;
    Process(5);
    memset(&Frame, 0, sizeof(Frame));
    CHECK(TakeSent(0x180 + NODE_ID, &Frame) == 1 && Frame.m_abData[1] == 0x5A, "TPDO 1 on the next change");

    /* DynDestroyOd gives the PDO channels back to the pool; the PDOs are
     * gone (a TPDO no longer follows the image) until the next build */
    CHECK(DynDestroyOd() == kCopSuccessful, "DynDestroyOd");
    pbOut[2] = 0x77;
    Process(5);
    CHECK(TakeSent(0x180 + NODE_ID, NULL) == 0, "no TPDO without the dynamic OD");
    memset(abProcessImage_l, 0, sizeof(abProcessImage_l));
    PIDscrpt_l.m_dwProcessImageSize = sizeof(abProcessImage_l);
    CHECK(DynBuildOd((BYTE FAR*) abSlaveContainer_l, &PIDscrpt_l) == kCopSuccessful, "build again");
    (void) SimInject(0x000, 0, 2, abStart);
    Process(5);
    (void) TakeSent(0, NULL);
    pbOut[2] = 0x77;
    Process(5);
    memset(&Frame, 0, sizeof(Frame));
    CHECK(TakeSent(0x180 + NODE_ID, &Frame) == 1 && Frame.m_abData[2] == 0x77,
          "TPDO 1 again after the second build");
    CHECK(DynDestroyOd() == kCopSuccessful, "DynDestroyOd again");
    (void) CcmShutDownCANopen();
    if (iFailures_l == 0)
    {
        printf("slave with dynamic OD: all checks passed\n");
        return 0;
    }
    printf("%d checks failed\n", iFailures_l);
    return 1;
}
