/*
 * cdrv_sim.c - simulated CAN bus, CAN driver and target functions for
 * running CANopen nodes on a PC. See cdrv_sim.h for the model.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cdrv_sim.h"
#if defined(SIM_CAPTURE) && (SIM_CAPTURE != 0)
#include "capture_sim.h"
#endif

#define SIM_STD_IDS   2048u   /* 11-bit identifiers */
#define SIM_EXT_IDS   32u     /* 29-bit identifiers a node may define */

#define SIM_FILTER_NONE 0u
#define SIM_FILTER_LOW  1u
#define SIM_FILTER_HIGH 2u

/* A ring of received frames. The stack reads the oldest entry through a
 * pointer (CdrvReadMsg) and frees it (CdrvReleaseMsg). */
typedef struct
{
    tCdrvMsg m_aMsg[SIM_QUEUE_MAX];
    unsigned m_uCapacity;
    unsigned m_uHead;
    unsigned m_uCount;
} tSimQueue;

typedef struct
{
    DWORD m_dwId;       /* 29-bit value */
    BYTE  m_bPrio;      /* SIM_FILTER_* */
} tSimExtFilter;

typedef struct
{
    int           m_fUsed;                  /* between CdrvInit and CdrvDeleteInstance */
    BYTE          m_abStdFilter[SIM_STD_IDS];
    tSimExtFilter m_aExtFilter[SIM_EXT_IDS];
    tSimQueue     m_RxHigh;
    tSimQueue     m_RxLow;
    tCdrvStatus   m_Status;
    unsigned      m_uRefuseTx;
    BYTE          m_bBus;                   /* the bus (CAN line) of its controller */
    int           m_fSilent;                /* sends nothing (SimSilence) */
} tSimNode;

static tSimNode  aSimNode_g[SIM_MAX_NODES];
static BYTE      bSimSelected_g;
static DWORD     dwSimTicks_g;
static int       fSimTrace_g;
static tSimFrame aSimLog_g[SIM_LOG_MAX];
static unsigned  uSimLogHead_g;
static unsigned  uSimLogCount_g;
static int       fSimDropArmed_g;
static DWORD     dwSimDropId_g;
static int       fSimCorruptArmed_g;
static DWORD     dwSimCorruptId_g;
static BYTE      bSimCorruptXor_g;
static BYTE      abSimBusOfNode_g[SIM_MAX_NODES];   /* kept across CdrvInit */
static BYTE      bSimInjectBus_g;

static DWORD SimIdOfMsg (CONST tCdrvMsg* pMsg_p)
{
    DWORD dwId = (DWORD) pMsg_p->m_CanId;

    if ((pMsg_p->m_MsgType & kMtbExtend) != 0)
    {
        return (dwId & 0x1FFFFFFFUL) | (DWORD) CAN_FRAME_FORMAT_MASK;
    }
    return dwId & 0x7FFUL;
}

static int SimIsExtended (DWORD dwId_p)
{
    return (dwId_p & (DWORD) CAN_FRAME_FORMAT_MASK) != 0;
}

static BYTE SimFilterOf (CONST tSimNode* pNode_p, DWORD dwId_p)
{
    unsigned i;

    if (!SimIsExtended(dwId_p))
    {
        return pNode_p->m_abStdFilter[dwId_p & 0x7FFUL];
    }
    for (i = 0; i < SIM_EXT_IDS; i++)
    {
        if ((pNode_p->m_aExtFilter[i].m_bPrio != SIM_FILTER_NONE) &&
            (pNode_p->m_aExtFilter[i].m_dwId == (dwId_p & 0x1FFFFFFFUL)))
        {
            return pNode_p->m_aExtFilter[i].m_bPrio;
        }
    }
    return SIM_FILTER_NONE;
}

static tCopKernel SimSetFilter (tSimNode* pNode_p, DWORD dwId_p, BYTE bPrio_p)
{
    unsigned i;

    if (!SimIsExtended(dwId_p))
    {
        pNode_p->m_abStdFilter[dwId_p & 0x7FFUL] = bPrio_p;
        return kCopSuccessful;
    }
    for (i = 0; i < SIM_EXT_IDS; i++)
    {
        if ((pNode_p->m_aExtFilter[i].m_bPrio != SIM_FILTER_NONE) &&
            (pNode_p->m_aExtFilter[i].m_dwId == (dwId_p & 0x1FFFFFFFUL)))
        {
            pNode_p->m_aExtFilter[i].m_bPrio = bPrio_p;
            return kCopSuccessful;
        }
    }
    if (bPrio_p == SIM_FILTER_NONE)
    {
        return kCopSuccessful;
    }
    for (i = 0; i < SIM_EXT_IDS; i++)
    {
        if (pNode_p->m_aExtFilter[i].m_bPrio == SIM_FILTER_NONE)
        {
            pNode_p->m_aExtFilter[i].m_dwId = dwId_p & 0x1FFFFFFFUL;
            pNode_p->m_aExtFilter[i].m_bPrio = bPrio_p;
            return kCopSuccessful;
        }
    }
    return kCopCdrvNoFreeChannel;
}

int SimFormatCandump (CONST tSimFrame* pFrame_p, char* pszLine_p, unsigned uSize_p)
{
    int iLen;
    BYTE i;

    if ((pFrame_p == NULL) || (pszLine_p == NULL) || (uSize_p < 64))
    {
        return -1;
    }
    if (SimIsExtended(pFrame_p->m_dwId))
    {
        iLen = sprintf(pszLine_p, "  can%u  %08lX   [%u] ", (unsigned) pFrame_p->m_bBus, (unsigned long) (pFrame_p->m_dwId & 0x1FFFFFFFUL), (unsigned) pFrame_p->m_bDlc);
    }
    else
    {
        iLen = sprintf(pszLine_p, "  can%u  %03lX   [%u] ", (unsigned) pFrame_p->m_bBus, (unsigned long) pFrame_p->m_dwId, (unsigned) pFrame_p->m_bDlc);
    }
    if (pFrame_p->m_bRtr)
    {
        iLen += sprintf(pszLine_p + iLen, " remote request");
    }
    else
    {
        for (i = 0; (i < pFrame_p->m_bDlc) && (i < 8); i++)
        {
            iLen += sprintf(pszLine_p + iLen, " %02X", (unsigned) pFrame_p->m_abData[i]);
        }
    }
    return iLen;
}

static void SimTrace (CONST tSimFrame* pFrame_p)
{
    char szLine[64];

    if (fSimTrace_g && (SimFormatCandump(pFrame_p, szLine, sizeof(szLine)) > 0))
    {
        printf("%s\n", szLine);
        fflush(stdout);
    }
}

static void SimQueueInit (tSimQueue* pQueue_p, tCdrvBuffIndex MaxEntries_p)
{
    memset(pQueue_p, 0, sizeof(*pQueue_p));
    pQueue_p->m_uCapacity = (MaxEntries_p > SIM_QUEUE_MAX) ? SIM_QUEUE_MAX : (unsigned) MaxEntries_p;
}

static int SimQueuePush (tSimQueue* pQueue_p, CONST tSimFrame* pFrame_p)
{
    tCdrvMsg* pMsg;

    if (pQueue_p->m_uCount >= pQueue_p->m_uCapacity)
    {
        return 0;
    }
    pMsg = &pQueue_p->m_aMsg[(pQueue_p->m_uHead + pQueue_p->m_uCount) % SIM_QUEUE_MAX];
    memset(pMsg, 0, sizeof(*pMsg));
    pMsg->m_CanId   = (tCanId) (pFrame_p->m_dwId & 0x1FFFFFFFUL);
    pMsg->m_MsgType = (tMsgTyp) (kMtbRecv |
                                 (pFrame_p->m_bRtr ? kMtbRtr : 0) |
                                 (SimIsExtended(pFrame_p->m_dwId) ? kMtbExtend : 0));
    pMsg->m_bSize   = pFrame_p->m_bDlc;
    memcpy(pMsg->m_bData, pFrame_p->m_abData, sizeof(pMsg->m_bData));
#if (CDRV_TIMESTAMP != FALSE)
    pMsg->m_Time = (tTime) pFrame_p->m_dwTick;
#endif
    pQueue_p->m_uCount++;
    return 1;
}

/* Delivers a frame to every node but the sender; returns the receivers. */
static int SimDeliver (CONST tSimFrame* pFrame_p)
{
    unsigned n;
    int iReceivers = 0;

    for (n = 0; n < SIM_MAX_NODES; n++)
    {
        tSimNode* pNode = &aSimNode_g[n];
        BYTE bPrio;

        if (!pNode->m_fUsed || (n == pFrame_p->m_bSender) || (pNode->m_bBus != pFrame_p->m_bBus))
        {
            continue;
        }
        bPrio = SimFilterOf(pNode, pFrame_p->m_dwId);
        if (bPrio == SIM_FILTER_NONE)
        {
            continue;
        }
        /* A node without a high-priority buffer takes everything low. */
        if ((bPrio == SIM_FILTER_HIGH) && (pNode->m_RxHigh.m_uCapacity > 0))
        {
            if (SimQueuePush(&pNode->m_RxHigh, pFrame_p))
            {
                iReceivers++;
            }
            else
            {
                pNode->m_Status |= kCdrvRxBuffHighOverrun;
            }
        }
        else
        {
            if (SimQueuePush(&pNode->m_RxLow, pFrame_p))
            {
                iReceivers++;
            }
            else
            {
                pNode->m_Status |= kCdrvRxBuffLowOverrun;
            }
        }
    }
    return iReceivers;
}

/* Puts a frame on the bus (unless a fault hook drops it). */
static int SimBus (tSimFrame* pFrame_p)
{
    pFrame_p->m_dwTick = dwSimTicks_g;
    if (fSimDropArmed_g && (pFrame_p->m_dwId == dwSimDropId_g))
    {
        fSimDropArmed_g = 0;
        return 0;
    }
    if (fSimCorruptArmed_g && (pFrame_p->m_dwId == dwSimCorruptId_g) && (pFrame_p->m_bDlc > 0))
    {
        fSimCorruptArmed_g = 0;
        pFrame_p->m_abData[0] ^= bSimCorruptXor_g;
    }
    SimTrace(pFrame_p);
#if defined(SIM_CAPTURE) && (SIM_CAPTURE != 0)
    SimCaptureFrame(pFrame_p);
#endif
    if (pFrame_p->m_bSender != SIM_EXTERNAL_NODE)
    {
        if (uSimLogCount_g == SIM_LOG_MAX)
        {
            /* keep the newest frames */
            uSimLogHead_g = (uSimLogHead_g + 1) % SIM_LOG_MAX;
            uSimLogCount_g--;
        }
        aSimLog_g[(uSimLogHead_g + uSimLogCount_g) % SIM_LOG_MAX] = *pFrame_p;
        uSimLogCount_g++;
    }
    return SimDeliver(pFrame_p);
}

/* ========================================================================== */
/* Simulation API                                                             */
/* ========================================================================== */

void SimReset (void)
{
    memset(aSimNode_g, 0, sizeof(aSimNode_g));
    bSimSelected_g = 0;
    dwSimTicks_g = 0;
    uSimLogHead_g = 0;
    uSimLogCount_g = 0;
    fSimDropArmed_g = 0;
    dwSimDropId_g = 0;
    fSimCorruptArmed_g = 0;
    memset(abSimBusOfNode_g, 0, sizeof(abSimBusOfNode_g));
    bSimInjectBus_g = 0;
#if (COP_MAX_INSTANCES == 1)
    (void) CopSimSelectInstance(0);
#endif
#if defined(SIM_CAPTURE) && (SIM_CAPTURE != 0)
    SimCaptureAtReset();
#endif
}

tCopKernel SimSelectNode (BYTE bNode_p)
{
    tCopKernel Ret;

    if (bNode_p >= SIM_MAX_NODES)
    {
        return kCopIllegalInstance;
    }
#if (COP_MAX_INSTANCES == 1)
    Ret = (tCopKernel) CopSimSelectInstance(bNode_p);
#else
    Ret = kCopSuccessful;       /* the handles address the instances */
#endif
    if (Ret == kCopSuccessful)
    {
        bSimSelected_g = bNode_p;
    }
    return Ret;
}

BYTE SimSelectedNode (void)
{
    return bSimSelected_g;
}

void SimAdvanceTicks (DWORD dwTicks_p)
{
    dwSimTicks_g += dwTicks_p;      /* wraps modulo 2^32 like a hardware counter */
}

void SimAdvanceMs (DWORD dwMs_p)
{
    SimAdvanceTicks(dwMs_p * 10UL);
}

void SimSetTrace (int fOn_p)
{
    fSimTrace_g = fOn_p;
}

int SimInject (DWORD dwId_p, BYTE bRtr_p, BYTE bDlc_p, CONST BYTE* pbData_p)
{
    tSimFrame Frame;

    if (bDlc_p > 8)
    {
        return -1;
    }
    memset(&Frame, 0, sizeof(Frame));
    Frame.m_dwId = SimIsExtended(dwId_p) ? (dwId_p & (0x1FFFFFFFUL | (DWORD) CAN_FRAME_FORMAT_MASK)) : (dwId_p & 0x7FFUL);
    Frame.m_bRtr = (BYTE) (bRtr_p ? 1 : 0);
    Frame.m_bDlc = bDlc_p;
    if ((pbData_p != NULL) && !Frame.m_bRtr)
    {
        memcpy(Frame.m_abData, pbData_p, bDlc_p);
    }
    Frame.m_bSender = SIM_EXTERNAL_NODE;
    Frame.m_bBus = bSimInjectBus_g;
    return SimBus(&Frame);
}

int SimTakeSentFrame (tSimFrame* pFrame_p)
{
    if (uSimLogCount_g == 0)
    {
        return 0;
    }
    if (pFrame_p != NULL)
    {
        *pFrame_p = aSimLog_g[uSimLogHead_g];
    }
    uSimLogHead_g = (uSimLogHead_g + 1) % SIM_LOG_MAX;
    uSimLogCount_g--;
    return 1;
}

int SimTakeSent (DWORD* pdwId_p, BYTE* pbRtr_p, BYTE* pbDlc_p, BYTE* pbData_p)
{
    tSimFrame Frame;

    if (!SimTakeSentFrame(&Frame))
    {
        return 0;
    }
    if (pdwId_p != NULL)
    {
        *pdwId_p = Frame.m_dwId;
    }
    if (pbRtr_p != NULL)
    {
        *pbRtr_p = Frame.m_bRtr;
    }
    if (pbDlc_p != NULL)
    {
        *pbDlc_p = Frame.m_bDlc;
    }
    if (pbData_p != NULL)
    {
        memcpy(pbData_p, Frame.m_abData, sizeof(Frame.m_abData));
    }
    return 1;
}

unsigned SimSentPending (void)
{
    return uSimLogCount_g;
}

void SimRefuseTx (BYTE bNode_p, unsigned uCount_p)
{
    if (bNode_p < SIM_MAX_NODES)
    {
        aSimNode_g[bNode_p].m_uRefuseTx = uCount_p;
    }
}

void SimRaiseStatus (BYTE bNode_p, WORD wBits_p)
{
    if (bNode_p < SIM_MAX_NODES)
    {
        aSimNode_g[bNode_p].m_Status = (tCdrvStatus) (aSimNode_g[bNode_p].m_Status | wBits_p);
    }
}

void SimSetBus (BYTE bNode_p, BYTE bBus_p)
{
    if (bNode_p < SIM_MAX_NODES)
    {
        abSimBusOfNode_g[bNode_p] = bBus_p;
        aSimNode_g[bNode_p].m_bBus = bBus_p;
    }
}

void SimSetInjectBus (BYTE bBus_p)
{
    bSimInjectBus_g = bBus_p;
}

void SimSilence (BYTE bNode_p, int fSilent_p)
{
    if (bNode_p < SIM_MAX_NODES)
    {
        aSimNode_g[bNode_p].m_fSilent = fSilent_p;
    }
}

void SimCorruptNextId (DWORD dwId_p, BYTE bXor_p)
{
    fSimCorruptArmed_g = 1;
    dwSimCorruptId_g = SimIsExtended(dwId_p) ? dwId_p : (dwId_p & 0x7FFUL);
    bSimCorruptXor_g = bXor_p;
}

void SimDropNextId (DWORD dwId_p)
{
    fSimDropArmed_g = 1;
    dwSimDropId_g = SimIsExtended(dwId_p) ? dwId_p : (dwId_p & 0x7FFUL);
}

int SimIsIdDefined (BYTE bNode_p, DWORD dwId_p)
{
    if (bNode_p >= SIM_MAX_NODES)
    {
        return 0;
    }
    return (int) SimFilterOf(&aSimNode_g[bNode_p], dwId_p);
}

unsigned SimRxPending (BYTE bNode_p)
{
    if (bNode_p >= SIM_MAX_NODES)
    {
        return 0;
    }
    return aSimNode_g[bNode_p].m_RxHigh.m_uCount + aSimNode_g[bNode_p].m_RxLow.m_uCount;
}

WORD SimGetStatus (BYTE bNode_p)
{
    if (bNode_p >= SIM_MAX_NODES)
    {
        return 0;
    }
    return aSimNode_g[bNode_p].m_Status;
}

unsigned SimRxCapacity (BYTE bNode_p, int fHigh_p)
{
    if (bNode_p >= SIM_MAX_NODES)
    {
        return 0;
    }
    return fHigh_p ? aSimNode_g[bNode_p].m_RxHigh.m_uCapacity : aSimNode_g[bNode_p].m_RxLow.m_uCapacity;
}

/* ========================================================================== */
/* CAN driver (Cdrv*) of the selected node                                    */
/* ========================================================================== */

static tSimNode* SimCurrent (void)
{
    return &aSimNode_g[bSimSelected_g];
}

/* The controller a driver call acts on: in a multi-instance build the one
 * its instance pointer names (CdrvInit returned it), else the selected
 * node's. */
#if (COP_MAX_INSTANCES > 1)
#define SIM_THIS_NODE() ((tSimNode*) pInstance)
#else
#define SIM_THIS_NODE() SimCurrent()
#endif

/* Starts the selected node's controller (CdrvInit and CdrvAddInstance). */
static tCopKernel SimInitNode (tCdrvInitParam MEM* pInitParam_p, tSimNode** ppNode_p)
{
    tSimNode* pNode = SimCurrent();

    if (pInitParam_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    if (pNode->m_fUsed)
    {
        return kCopCdrvDevAlreadyInUse;
    }
    memset(pNode, 0, sizeof(*pNode));
    SimQueueInit(&pNode->m_RxHigh, pInitParam_p->m_RxBuffHigh.m_MaxEntries);
    SimQueueInit(&pNode->m_RxLow, pInitParam_p->m_RxBuffLow.m_MaxEntries);
    pNode->m_bBus = abSimBusOfNode_g[bSimSelected_g];
    pNode->m_fUsed = 1;
    *ppNode_p = pNode;
    return kCopSuccessful;
}

/* In a multi-instance build the node is the one selected (SimSelectNode)
 * when the library calls CdrvInit / CdrvAddInstance; its address is the
 * driver's instance pointer. */
tCopKernel PUBLIC CdrvInit (MCO_DECL_PTR_INSTANCE_PTR_ tCdrvInitParam MEM* pInitParam_p)
{
    tSimNode* pNode = NULL;
    tCopKernel Ret = SimInitNode(pInitParam_p, &pNode);

#if (COP_MAX_INSTANCES > 1)
    if (pInstancePtr == NULL)
    {
        return kCopInvalidInstanceParam;
    }
    *pInstancePtr = pNode;
#endif
    (void) pNode;
    return Ret;
}

tCopKernel PUBLIC CdrvAddInstance (MCO_DECL_PTR_INSTANCE_PTR_ tCdrvInitParam MEM* pInitParam_p)
{
    return CdrvInit(MCO_PTR_INSTANCE_PTR_ pInitParam_p);
}

tCopKernel PUBLIC CdrvDeleteInstance (MCO_DECL_INSTANCE_PTR)
{
    tSimNode* pNode = SIM_THIS_NODE();
    BYTE bBus = pNode->m_bBus;

    if (!pNode->m_fUsed)
    {
        return kCopIllegalInstance;
    }
    memset(pNode, 0, sizeof(*pNode));
    pNode->m_bBus = bBus;
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvSetBaudrate (MCO_DECL_INSTANCE_PTR_ CONST void ROM* pBdiTable_p, WORD wSizeOfBdiTab_p, BYTE bBdiIndex_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) pInstance;
#endif
    (void) pBdiTable_p;
    (void) wSizeOfBdiTab_p;
    return (bBdiIndex_p <= kBdi10kBaud) ? kCopSuccessful : kCopCdrvIllegalBdi;
}

tCopKernel PUBLIC CdrvReset (MCO_DECL_INSTANCE_PTR_ tCdrvResetCode ResetCode_p)
{
    tSimNode* pNode = SIM_THIS_NODE();

    if ((ResetCode_p & kResetRxBuffHigh) != 0)
    {
        pNode->m_RxHigh.m_uHead = 0;
        pNode->m_RxHigh.m_uCount = 0;
    }
    if ((ResetCode_p & kResetRxBuffLow) != 0)
    {
        pNode->m_RxLow.m_uHead = 0;
        pNode->m_RxLow.m_uCount = 0;
    }
    if ((ResetCode_p & kResetCanCtrl) != 0)
    {
        pNode->m_Status = kCdrvNoError;
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvClearRtr (MCO_DECL_INSTANCE_PTR_ BYTE bChannel_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) pInstance;
#endif
    (void) bChannel_p;
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvDefineCanId (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p)
{
    if (pCanMsg_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    return SimSetFilter(SIM_THIS_NODE(), SimIdOfMsg(pCanMsg_p),
                        (BYTE) (((pCanMsg_p->m_MsgType & kMtbHighPrio) != 0) ? SIM_FILTER_HIGH : SIM_FILTER_LOW));
}

tCopKernel PUBLIC CdrvUndefineCanId (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p)
{
    if (pCanMsg_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    return SimSetFilter(SIM_THIS_NODE(), SimIdOfMsg(pCanMsg_p), SIM_FILTER_NONE);
}

tCopKernel PUBLIC CdrvWriteMsg (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p)
{
    tSimNode* pNode = SIM_THIS_NODE();
    tSimFrame Frame;

    if (pCanMsg_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    if (!pNode->m_fUsed)
    {
        return kCopCdrvInitError;
    }
    if (pNode->m_uRefuseTx > 0)
    {
        pNode->m_uRefuseTx--;
        return ((pCanMsg_p->m_MsgType & kMtbHighPrio) != 0) ? kCopCdrvTxBuffHighOverrun : kCopCdrvTxBuffLowOverrun;
    }
    if (pNode->m_fSilent)
    {
        return kCopSuccessful;      /* taken, never on the bus */
    }
    memset(&Frame, 0, sizeof(Frame));
    Frame.m_dwId = SimIdOfMsg(pCanMsg_p);
    Frame.m_bRtr = (BYTE) (((pCanMsg_p->m_MsgType & kMtbRtr) != 0) ? 1 : 0);
    Frame.m_bDlc = (BYTE) ((pCanMsg_p->m_bSize > 8) ? 8 : pCanMsg_p->m_bSize);
    memcpy(Frame.m_abData, pCanMsg_p->m_bData, sizeof(Frame.m_abData));
    Frame.m_bSender = (BYTE) (pNode - aSimNode_g);
    Frame.m_bBus = pNode->m_bBus;
    (void) SimBus(&Frame);
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvReadMsg (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* MEM* ppCanMsg_p)
{
    tSimNode* pNode = SIM_THIS_NODE();

    if (ppCanMsg_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    if (pNode->m_RxHigh.m_uCount > 0)
    {
        *ppCanMsg_p = &pNode->m_RxHigh.m_aMsg[pNode->m_RxHigh.m_uHead];
        return kCopCdrvMsgHigh;
    }
    if (pNode->m_RxLow.m_uCount > 0)
    {
        *ppCanMsg_p = &pNode->m_RxLow.m_aMsg[pNode->m_RxLow.m_uHead];
        return kCopCdrvMsgLow;
    }
    return kCopCdrvNoMsg;
}

static int SimQueueRelease (tSimQueue* pQueue_p, CONST tCdrvMsg* pMsg_p)
{
    if ((pQueue_p->m_uCount == 0) || (pMsg_p != &pQueue_p->m_aMsg[pQueue_p->m_uHead]))
    {
        return 0;
    }
    pQueue_p->m_uHead = (pQueue_p->m_uHead + 1) % SIM_QUEUE_MAX;
    pQueue_p->m_uCount--;
    return 1;
}

tCopKernel PUBLIC CdrvReleaseMsg (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p)
{
    tSimNode* pNode = SIM_THIS_NODE();

    if (SimQueueRelease(&pNode->m_RxHigh, pCanMsg_p) || SimQueueRelease(&pNode->m_RxLow, pCanMsg_p))
    {
        return kCopSuccessful;
    }
    return kCopCdrvInvalidParam;
}

tCopKernel PUBLIC CdrvUpdateMsg (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) pInstance;
#endif
    return (pCanMsg_p == NULL) ? kCopCdrvInvalidParam : kCopSuccessful;
}

tCopKernel PUBLIC CdrvInterruptHandler (MCO_DECL_INSTANCE_PTR_ tCdrvIsrType IsrType_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) pInstance;
#endif
    (void) IsrType_p;
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvGetStatus (MCO_DECL_INSTANCE_PTR_ tCdrvStatus MEM* pStatus_p)
{
    if (pStatus_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    *pStatus_p = SIM_THIS_NODE()->m_Status;
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvResetStatus (MCO_DECL_INSTANCE_PTR_ tCdrvStatus Status_p)
{
    tSimNode* pNode = SIM_THIS_NODE();

    pNode->m_Status = (tCdrvStatus) (pNode->m_Status & (tCdrvStatus) ~Status_p);
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvGetDiagnostic (MCO_DECL_INSTANCE_PTR_ tCdrvDiagnostic MEM* pDiagnostic_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) pInstance;
#endif
    (void) pDiagnostic_p;
    return kCopSuccessful;
}

/* ========================================================================== */
/* Target functions                                                           */
/* ========================================================================== */

tTime PUBLIC TgtGetTickCount (void)
{
    return (tTime) dwSimTicks_g;
}

void PUBLIC TgtInit (void) {}
void PUBLIC TgtEnableGlobalInterrupt (BYTE bEnable_p) { (void) bEnable_p; }
void PUBLIC TgtInitSerial (void) {}
void PUBLIC TgtInitCanIsr (void) {}
void PUBLIC TgtFreeCanIsr (void) {}
void HWACC* PUBLIC TgtGetCanBase (BYTE bCanContr_p) { (void) bCanContr_p; return NULL; }
void PUBLIC TgtRegisterInstance (tCopInstanceHdl InstanceHdl_p, tCopPtrInstance InstancePtr_p)
{
    (void) InstanceHdl_p;
    (void) InstancePtr_p;
}
void PUBLIC TgtEnableCanInterrupt0 (BYTE bEnable_p) { (void) bEnable_p; }
void PUBLIC TgtEnableCanInterrupt1 (BYTE bEnable_p) { (void) bEnable_p; }
void PUBLIC TgtEnableCanInterrupt2 (BYTE bEnable_p) { (void) bEnable_p; }
void PUBLIC TgtEnableCanInterrupt3 (BYTE bEnable_p) { (void) bEnable_p; }
void PUBLIC TgtEnableCanInterrupt4 (BYTE bEnable_p) { (void) bEnable_p; }
void PUBLIC TgtEnableCanInterrupt (BYTE bEnable_p) { (void) bEnable_p; }
void PUBLIC TgtInitTimer (void) {}
void PUBLIC TgtStopTimer (void) {}

void PUBLIC TgtMemCpy (void GENERIC* dst, void GENERIC* src, WORD siz)
{
    memcpy(dst, src, siz);
}

void PUBLIC TgtMemSet (void GENERIC* dst, BYTE val, WORD siz)
{
    memset(dst, val, siz);
}

WORD PUBLIC TgtGetAlignOffset (BYTE MEM* pbData_p, WORD wDataSize_p)
{
    (void) pbData_p;
    (void) wDataSize_p;
    return 0;
}

/* Bit timing words per kBdi* index; the simulated bus ignores them. */
static CONST WORD ROM awSimBitrateTab_g[9] = { 0x0014, 0x0016, 0x001C, 0x011C, 0x031C, 0x041C, 0x091C, 0x181C, 0x311C };

CONST WORD ROM* PUBLIC TgtGetBitrateTabPtr (BYTE bParameter_p)
{
    (void) bParameter_p;
    return awSimBitrateTab_g;
}

void FAR* LzsEnvMemAlloc (DWORD dwMemSize_p)
{
    return malloc(dwMemSize_p);
}

void LzsEnvMemFree (void FAR* pMem_p)
{
    free(pMem_p);
}

void MEM* PUBLIC TgtMemAlloc (DWORD dwSiz_p)
{
    return malloc(dwSiz_p);
}

void PUBLIC TgtMemFree (void MEM* pData_p)
{
    free(pData_p);
}

tCopKernel PUBLIC TgtAllocHwRessource (BYTE bDevNumber_p, BYTE HWACC** ppHwBaseAddr_p)
{
    (void) bDevNumber_p;
    if (ppHwBaseAddr_p != NULL)
    {
        *ppHwBaseAddr_p = NULL;
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC TgtReleaseHwRessource (BYTE bDevNumber_p)
{
    (void) bDevNumber_p;
    return kCopSuccessful;
}

tCopKernel PUBLIC TgtGetBitrateTable (BYTE bDevNumber_p, CONST void ROM** ppBdiTable_p, WORD* wSizeOfBdiTab_p)
{
    (void) bDevNumber_p;
    if ((ppBdiTable_p == NULL) || (wSizeOfBdiTab_p == NULL))
    {
        return kCopInvalidParam;
    }
    *ppBdiTable_p = awSimBitrateTab_g;
    *wSizeOfBdiTab_p = (WORD) sizeof(awSimBitrateTab_g);
    return kCopSuccessful;
}

void PUBLIC TgtSignalEvent (BYTE bDevNumber_p, DWORD dwEventMask_p)
{
    (void) bDevNumber_p;
    (void) dwEventMask_p;
}
