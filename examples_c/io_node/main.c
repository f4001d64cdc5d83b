/*
 * main.c - a CANopen I/O node (node-ID 2) written the way a SYS TEC
 * application is: fill tCcmInitParam, CcmInitCANopen, CcmConnectToNet, then
 * call CcmProcess in the main loop; the NMT callback AppCbNmtEvent reports
 * the state machine. The node reads its inputs into abDigitalInputs_g /
 * aiAnalogInputs_g and drives its outputs from abDigitalOutputs_g; the
 * dictionary (objdict.h) points at these arrays.
 *
 * Here it runs on the simulated CAN bus (examples_c/sim): the same program
 * plays a CANopen master on the bus (the simulation's external node API)
 * and sends, one step per millisecond of simulated time,
 *
 *   NMT "start remote node" to all nodes         000 [2] 01 00
 *   SDO write 0x6200/1 = 0xFF (8 outputs)         602 [8] 2F 00 62 01 FF 00 00 00
 *   SDO read 0x6000/1 (8 digital inputs)          602 [8] 40 00 60 01 00 00 00 00
 *   SDO read 0x6401/1 (analog input 1)            602 [8] 40 01 64 01 00 00 00 00
 *
 * (the three SDO examples of seed 004) and checks the node's answers
 * 60 00 62 01 ..., 4F 00 60 01 01 ..., 4B 01 64 01 34 12 .... Every frame on
 * the bus is printed in candump format. Exit code 0 when all answers match.
 *
 * On the real target only the driver changes: the Cdrv* functions and
 * TgtGetTickCount of the board instead of cdrv_sim.c, and no master part.
 */
#include <stdio.h>
#include <string.h>

#include "cop.h"
#include "cdrv_sim.h"

#define NODE_ID 2

/* I/O image the dictionary points at (objdict.h, EXTARRAY). */
tObdUnsigned8 abDigitalInputs_g[1];
tObdUnsigned8 abDigitalOutputs_g[1];
tObdInteger16 aiAnalogInputs_g[2];

static tCcmInitParam CcmInitParam_g;
static BYTE bOutputsApplied_g;

static const char* NmtEventName (tNmtEvent NmtEvent_p)
{
    switch (NmtEvent_p)
    {
        case kNmtEvEnterInitialising:      return "kNmtEvEnterInitialising";
        case kNmtEvResetNode:              return "kNmtEvResetNode";
        case kNmtEvPreResetCommunication:  return "kNmtEvPreResetCommunication";
        case kNmtEvResetCommunication:     return "kNmtEvResetCommunication";
        case kNmtEvPostResetCommunication: return "kNmtEvPostResetCommunication";
        case kNmtEvEnterPreOperational:    return "kNmtEvEnterPreOperational";
        case kNmtEvEnterOperational:       return "kNmtEvEnterOperational";
        case kNmtEvEnterStopped:           return "kNmtEvEnterStopped";
        default:                           return "unknown event";
    }
}

/* NMT state machine of the node (tCcmInitParam.m_fpNmtEventCallback). */
static tCopKernel PUBLIC AppCbNmtEvent (tNmtEvent NmtEvent_p)
{
    printf("node %u: AppCbNmtEvent (%s)\n", (unsigned) NODE_ID, NmtEventName(NmtEvent_p));
    switch (NmtEvent_p)
    {
        case kNmtEvResetCommunication:
            /* communication objects were reset: emergency COB-ID */
            return CcmConfigEmcp(0x80 + NODE_ID);

        case kNmtEvEnterPreOperational:
        case kNmtEvEnterStopped:
            /* no process data outside OPERATIONAL: outputs off */
            abDigitalOutputs_g[0] = 0;
            break;

        default:
            break;
    }
    return kCopSuccessful;
}

/* The board's I/O: read inputs, apply outputs. */
static void ProcessIo (void)
{
    abDigitalInputs_g[0] = 0x01;        /* input 1 high */
    aiAnalogInputs_g[0] = 0x1234;       /* analog input 1 */
    aiAnalogInputs_g[1] = -1;
    if (abDigitalOutputs_g[0] != bOutputsApplied_g)
    {
        bOutputsApplied_g = abDigitalOutputs_g[0];
        printf("node %u: digital outputs now 0x%02X\n", (unsigned) NODE_ID, (unsigned) bOutputsApplied_g);
    }
}

/* ---- the scripted master ------------------------------------------------ */

typedef struct
{
    const char* m_pszWhat;
    DWORD       m_dwId;
    BYTE        m_bDlc;
    BYTE        m_abData[8];
    DWORD       m_dwReplyId;        /* 0: no reply expected */
    BYTE        m_abReply[8];
} tMasterStep;

static CONST tMasterStep aMasterScript_g[] = {
    { "NMT start remote node (all)", 0x000, 2, { 0x01, 0x00 }, 0, { 0 } },
    { "SDO write 0x6200/1 = 0xFF", 0x600 + NODE_ID, 8, { 0x2F, 0x00, 0x62, 0x01, 0xFF, 0x00, 0x00, 0x00 },
      0x580 + NODE_ID, { 0x60, 0x00, 0x62, 0x01, 0x00, 0x00, 0x00, 0x00 } },
    { "SDO read 0x6000/1", 0x600 + NODE_ID, 8, { 0x40, 0x00, 0x60, 0x01, 0x00, 0x00, 0x00, 0x00 },
      0x580 + NODE_ID, { 0x4F, 0x00, 0x60, 0x01, 0x01, 0x00, 0x00, 0x00 } },
    { "SDO read 0x6401/1", 0x600 + NODE_ID, 8, { 0x40, 0x01, 0x64, 0x01, 0x00, 0x00, 0x00, 0x00 },
      0x580 + NODE_ID, { 0x4B, 0x01, 0x64, 0x01, 0x34, 0x12, 0x00, 0x00 } },
};

#define MASTER_STEPS (sizeof(aMasterScript_g) / sizeof(aMasterScript_g[0]))

/* Looks at what the node sent; returns 1 when the expected reply came. */
static int MasterCheckReply (CONST tMasterStep* pStep_p, int* pfMismatch_p)
{
    tSimFrame Frame;
    int fGot = 0;

    while (SimTakeSentFrame(&Frame))
    {
        if ((pStep_p->m_dwReplyId != 0) && (Frame.m_dwId == pStep_p->m_dwReplyId))
        {
            fGot = 1;
            if ((Frame.m_bDlc != 8) || (memcmp(Frame.m_abData, pStep_p->m_abReply, 8) != 0))
            {
                printf("master: unexpected answer to \"%s\"\n", pStep_p->m_pszWhat);
                *pfMismatch_p = 1;
            }
            else if ((Frame.m_abData[0] & 0xE0) == 0x60)
            {
                printf("master: \"%s\" confirmed\n", pStep_p->m_pszWhat);
            }
            else
            {
                printf("master: \"%s\" -> value 0x%02X%02X%02X%02X\n", pStep_p->m_pszWhat,
                       (unsigned) Frame.m_abData[7], (unsigned) Frame.m_abData[6],
                       (unsigned) Frame.m_abData[5], (unsigned) Frame.m_abData[4]);
            }
        }
    }
    return fGot || (pStep_p->m_dwReplyId == 0);
}

int main (void)
{
    tCopKernel Ret;
    DWORD dwVersion = CopGetStackVersion();
    unsigned uStep = 0;
    unsigned uMs;
    int fMismatch = 0;
    int fAnswered = 1;

    printf("cop I/O node example, stack V%u.%u r%u, node-ID %u\n",
           (unsigned) COP_GET_MAJOR_VERSION(dwVersion), (unsigned) COP_GET_MINOR_VERSION(dwVersion),
           (unsigned) COP_GET_RELEASE_VERSION(dwVersion), (unsigned) NODE_ID);

    /* the PC stands in for the board: simulated bus, node 0 of it */
    SimReset();
    SimSetTrace(1);
    SimSelectNode(0);

    /* SYS TEC start-up sequence */
    memset(&CcmInitParam_g, 0, sizeof(CcmInitParam_g));
    CcmInitParam_g.m_bInitNodeId = NODE_ID;
    CcmInitParam_g.m_BaudIndex = kBdi500kBaud;
    (void) TgtGetBitrateTable(0, &CcmInitParam_g.m_pBdiTable, &CcmInitParam_g.m_wSizeOfBdiTab);
    CcmInitParam_g.m_dwAmr = 0xFFFFFFFFUL;
    CcmInitParam_g.m_dwAcr = 0x00000000UL;
    CcmInitParam_g.m_HwParam.m_ZeroBasedCanNo.m_bCanNo = 0;
    CcmInitParam_g.m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    CcmInitParam_g.m_fpNmtEventCallback = AppCbNmtEvent;
    CcmInitParam_g.m_fpObdInitRam = ObdInitRam;

    Ret = CcmInitCANopen(&CcmInitParam_g, kCcmFirstInstance);
    if (Ret != kCopSuccessful)
    {
        printf("CcmInitCANopen failed: 0x%04X\n", (unsigned) Ret);
        return 1;
    }
    Ret = CcmConnectToNet();
    if (Ret != kCopSuccessful)
    {
        printf("CcmConnectToNet failed: 0x%04X\n", (unsigned) Ret);
        return 1;
    }

    /* main loop: 1 ms per pass; the master acts every 10 ms */
    for (uMs = 0; uMs < 100; uMs++)
    {
        ProcessIo();
        Ret = CcmProcess();
        if (Ret != kCopSuccessful)
        {
            printf("CcmProcess: 0x%04X\n", (unsigned) Ret);
        }

        if ((uMs % 10) == 9)
        {
            if (uStep == 0)
            {
                (void) SimTakeSentFrame(NULL);      /* the boot-up message */
            }
            else if (uStep <= MASTER_STEPS)
            {
                fAnswered = MasterCheckReply(&aMasterScript_g[uStep - 1], &fMismatch) && fAnswered;
            }
            if (uStep < MASTER_STEPS)
            {
                CONST tMasterStep* pStep = &aMasterScript_g[uStep];
                printf("master: %s\n", pStep->m_pszWhat);
                (void) SimInject(pStep->m_dwId, 0, pStep->m_bDlc, pStep->m_abData);
            }
            uStep++;
        }
        SimAdvanceMs(1);
    }

    CcmShutDownCANopen();
    if (!fAnswered || fMismatch || (uStep <= MASTER_STEPS))
    {
        printf("io_node: the node did not answer as in seed 004\n");
        return 1;
    }
    printf("io_node: all answers as in seed 004\n");
    return 0;
}
