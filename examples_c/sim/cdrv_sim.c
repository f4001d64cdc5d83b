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

#define SIM_NS_PER_TICK       100000ULL  /* one tick of TgtGetTickCount: 100 us */
#define SIM_INTERMISSION_BITS 3u         /* ISO 11898-1:2015 10.4.5 */
#define SIM_TAIL_BITS         10u        /* CRC delimiter, ACK slot and delimiter, EOF: never stuffed */
#define SIM_CRC15_POLY        0x4599u    /* x^15 + x^14 + x^10 + x^8 + x^7 + x^4 + x^3 + 1 */
#define SIM_BIT_RATE_MIN      10000UL
#define SIM_BIT_RATE_MAX      1000000UL

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

/* A transmit buffer of the physical model: frames with the bus time they
 * were queued at, oldest first. */
typedef struct
{
    tSimFrame          m_aFrame[SIM_QUEUE_MAX];
    unsigned long long m_aullQueuedNs[SIM_QUEUE_MAX];
    unsigned           m_uCapacity;
    unsigned           m_uHead;
    unsigned           m_uCount;
} tSimTxQueue;

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
    tSimTxQueue   m_TxHigh;                 /* physical bus only */
    tSimTxQueue   m_TxLow;
} tSimNode;

/* The physical model of one bus. */
typedef struct
{
    DWORD              m_dwBitRate;         /* 0: the ideal bus */
    unsigned long long m_ullIdleFromNs;     /* no SOF before (end of the last frame + intermission) */
    int                m_fInFlight;
    tSimFrame          m_InFlight;
    unsigned long long m_ullEndNs;          /* end of frame of m_InFlight */
    unsigned           m_uInFlightBits;     /* with the intermission */
    tSimTxQueue        m_Outside;           /* frames of SimInject */
    tSimBusStats       m_Stats;
} tSimPhysBus;

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
static tSimPhysBus aSimPhys_g[SIM_MAX_BUSES];
static unsigned long long ullSimNs_g;                /* bus time since SimReset */

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
                if (pFrame_p->m_bBus < SIM_MAX_BUSES)
                {
                    aSimPhys_g[pFrame_p->m_bBus].m_Stats.m_ullRxLostHigh++;
                }
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
                if (pFrame_p->m_bBus < SIM_MAX_BUSES)
                {
                    aSimPhys_g[pFrame_p->m_bBus].m_Stats.m_ullRxLostLow++;
                }
            }
        }
    }
    return iReceivers;
}

/* Puts a frame on the bus (unless a fault hook drops it), at the time its
 * m_dwTick / m_wSubTickUs say. */
static int SimBus (tSimFrame* pFrame_p)
{
    if (pFrame_p->m_bBus < SIM_MAX_BUSES)
    {
        aSimPhys_g[pFrame_p->m_bBus].m_Stats.m_ullFrames++;
    }
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
/* Physical model (SimSetBitRate)                                             */
/* ========================================================================== */

static unsigned SimPushBits (BYTE* pbBits_p, unsigned uAt_p, DWORD dwValue_p, unsigned uCount_p)
{
    while (uCount_p > 0)
    {
        uCount_p--;
        pbBits_p[uAt_p++] = (BYTE) ((dwValue_p >> uCount_p) & 1UL);
    }
    return uAt_p;
}

/* The CRC-15 of ISO 11898-1:2015 10.4.2.6 over uCount_p bits. */
static WORD SimCrc15 (CONST BYTE* pbBits_p, unsigned uCount_p)
{
    WORD wReg = 0;
    unsigned i;

    for (i = 0; i < uCount_p; i++)
    {
        BYTE bTop = (BYTE) ((wReg >> 14) & 1u);

        wReg = (WORD) ((wReg << 1) & 0x7FFFu);
        if (pbBits_p[i] != bTop)
        {
            wReg ^= SIM_CRC15_POLY;
        }
    }
    return wReg;
}

unsigned SimFrameBits (CONST tSimFrame* pFrame_p)
{
    /* SOF .. CRC sequence of the longest frame: 1 + 32 + 6 + 64 + 15 bits. */
    BYTE abBits[128];
    unsigned n = 0;
    unsigned i;
    unsigned uStuffed = 0;
    unsigned uRun = 0;
    BYTE bLast = 2;
    DWORD dwId;
    BYTE bDlc;

    if (pFrame_p == NULL)
    {
        return 0;
    }
    bDlc = (BYTE) (pFrame_p->m_bDlc & 0x0Fu);
    dwId = pFrame_p->m_dwId & 0x1FFFFFFFUL;
    abBits[n++] = 0;                                            /* SOF */
    if (SimIsExtended(pFrame_p->m_dwId))
    {
        n = SimPushBits(abBits, n, dwId >> 18, 11);
        abBits[n++] = 1;                                        /* SRR */
        abBits[n++] = 1;                                        /* IDE: extended */
        n = SimPushBits(abBits, n, dwId & 0x3FFFFUL, 18);
        abBits[n++] = (BYTE) (pFrame_p->m_bRtr ? 1 : 0);
        abBits[n++] = 0;                                        /* r1 */
        abBits[n++] = 0;                                        /* r0 */
    }
    else
    {
        n = SimPushBits(abBits, n, dwId & 0x7FFUL, 11);
        abBits[n++] = (BYTE) (pFrame_p->m_bRtr ? 1 : 0);
        abBits[n++] = 0;                                        /* IDE: base */
        abBits[n++] = 0;                                        /* r0 */
    }
    n = SimPushBits(abBits, n, bDlc, 4);
    if (!pFrame_p->m_bRtr)
    {
        for (i = 0; (i < bDlc) && (i < 8); i++)
        {
            n = SimPushBits(abBits, n, pFrame_p->m_abData[i], 8);
        }
    }
    n = SimPushBits(abBits, n, SimCrc15(abBits, n), 15);
    /* ISO 11898-1:2015 10.5: after five equal bits one of the opposite
     * value, which starts the next run. */
    for (i = 0; i < n; i++)
    {
        if (abBits[i] == bLast)
        {
            uRun++;
        }
        else
        {
            bLast = abBits[i];
            uRun = 1;
        }
        if (uRun == 5)
        {
            uStuffed++;
            bLast = (BYTE) !bLast;
            uRun = 1;
        }
    }
    return n + uStuffed + SIM_TAIL_BITS;
}

/* The arbitration field as a number in which a lower value wins (a
 * dominant bit is 0): base identifier, SRR/RTR, IDE, extension, RTR. */
static DWORD SimArbitrationKey (CONST tSimFrame* pFrame_p)
{
    DWORD dwId = pFrame_p->m_dwId & 0x1FFFFFFFUL;
    DWORD dwRtr = pFrame_p->m_bRtr ? 1UL : 0UL;

    if (SimIsExtended(pFrame_p->m_dwId))
    {
        return ((dwId >> 18) << 21) | (3UL << 19) | ((dwId & 0x3FFFFUL) << 1) | dwRtr;
    }
    return ((dwId & 0x7FFUL) << 21) | (dwRtr << 20);
}

static unsigned long long SimBitsNs (CONST tSimPhysBus* pBus_p, unsigned uBits_p)
{
    unsigned long long ullRate = pBus_p->m_dwBitRate;

    return ((unsigned long long) uBits_p * 1000000000ULL + ullRate - 1ULL) / ullRate;
}

static void SimTxInit (tSimTxQueue* pQueue_p, tCdrvBuffIndex MaxEntries_p)
{
    memset(pQueue_p, 0, sizeof(*pQueue_p));
    pQueue_p->m_uCapacity = (MaxEntries_p > SIM_QUEUE_MAX) ? SIM_QUEUE_MAX :
                            ((MaxEntries_p == 0) ? 1u : (unsigned) MaxEntries_p);
}

static int SimTxPush (tSimTxQueue* pQueue_p, CONST tSimFrame* pFrame_p)
{
    unsigned uAt;

    if (pQueue_p->m_uCount >= pQueue_p->m_uCapacity)
    {
        return 0;
    }
    uAt = (pQueue_p->m_uHead + pQueue_p->m_uCount) % SIM_QUEUE_MAX;
    pQueue_p->m_aFrame[uAt] = *pFrame_p;
    pQueue_p->m_aullQueuedNs[uAt] = ullSimNs_g;
    pQueue_p->m_uCount++;
    return 1;
}

/* The queue whose oldest frame the node offers: high before low. */
static tSimTxQueue* SimTxHead (tSimNode* pNode_p)
{
    if (pNode_p->m_TxHigh.m_uCount > 0)
    {
        return &pNode_p->m_TxHigh;
    }
    return (pNode_p->m_TxLow.m_uCount > 0) ? &pNode_p->m_TxLow : NULL;
}

/* Starts the frame that wins arbitration at the first moment the bus is
 * idle and a frame waits, if that is not after ullUntil_p. */
static int SimPhysStart (BYTE bBus_p, unsigned long long ullUntil_p)
{
    tSimPhysBus* pBus = &aSimPhys_g[bBus_p];
    tSimTxQueue* apQueue[SIM_MAX_NODES + 1];
    BYTE abSender[SIM_MAX_NODES + 1];
    unsigned uOffers = 0;
    unsigned long long ullFirst = 0;
    unsigned long long ullStart;
    tSimTxQueue* pWinner = NULL;
    BYTE bWinner = SIM_EXTERNAL_NODE;
    DWORD dwBest = 0;
    unsigned n;
    unsigned uBits;

    for (n = 0; n < SIM_MAX_NODES; n++)
    {
        if (aSimNode_g[n].m_fUsed && (aSimNode_g[n].m_bBus == bBus_p) &&
            (SimTxHead(&aSimNode_g[n]) != NULL))
        {
            apQueue[uOffers] = SimTxHead(&aSimNode_g[n]);
            abSender[uOffers++] = (BYTE) n;
        }
    }
    if (pBus->m_Outside.m_uCount > 0)
    {
        apQueue[uOffers] = &pBus->m_Outside;
        abSender[uOffers++] = SIM_EXTERNAL_NODE;
    }
    for (n = 0; n < uOffers; n++)
    {
        unsigned long long ullQueued = apQueue[n]->m_aullQueuedNs[apQueue[n]->m_uHead];

        if ((n == 0) || (ullQueued < ullFirst))
        {
            ullFirst = ullQueued;
        }
    }
    if (uOffers == 0)
    {
        return 0;
    }
    ullStart = (ullFirst > pBus->m_ullIdleFromNs) ? ullFirst : pBus->m_ullIdleFromNs;
    if (ullStart > ullUntil_p)
    {
        return 0;
    }
    /* Offers in node order, the outside last: the first of equal keys wins. */
    for (n = 0; n < uOffers; n++)
    {
        tSimTxQueue* pQueue = apQueue[n];
        DWORD dwKey = SimArbitrationKey(&pQueue->m_aFrame[pQueue->m_uHead]);

        if ((pQueue->m_aullQueuedNs[pQueue->m_uHead] <= ullStart) && ((pWinner == NULL) || (dwKey < dwBest)))
        {
            pWinner = pQueue;
            bWinner = abSender[n];
            dwBest = dwKey;
        }
    }
    pBus->m_InFlight = pWinner->m_aFrame[pWinner->m_uHead];
    pBus->m_InFlight.m_bSender = bWinner;
    pWinner->m_uHead = (pWinner->m_uHead + 1) % SIM_QUEUE_MAX;
    pWinner->m_uCount--;
    uBits = SimFrameBits(&pBus->m_InFlight);
    pBus->m_uInFlightBits = uBits + SIM_INTERMISSION_BITS;
    pBus->m_ullEndNs = ullStart + SimBitsNs(pBus, uBits);
    pBus->m_fInFlight = 1;
    return 1;
}

/* Runs bus bBus_p up to ullUntil_p: frames start and arrive. */
static void SimPhysRun (BYTE bBus_p, unsigned long long ullUntil_p)
{
    tSimPhysBus* pBus = &aSimPhys_g[bBus_p];

    for (;;)
    {
        if (pBus->m_fInFlight)
        {
            if (pBus->m_ullEndNs > ullUntil_p)
            {
                break;
            }
            pBus->m_fInFlight = 0;
            pBus->m_ullIdleFromNs = pBus->m_ullEndNs + SimBitsNs(pBus, SIM_INTERMISSION_BITS);
            pBus->m_Stats.m_ullBits += pBus->m_uInFlightBits;
            pBus->m_Stats.m_ullBusyNs += SimBitsNs(pBus, pBus->m_uInFlightBits);
            pBus->m_InFlight.m_dwTick = (DWORD) (pBus->m_ullEndNs / SIM_NS_PER_TICK);
            pBus->m_InFlight.m_wSubTickUs = (WORD) ((pBus->m_ullEndNs % SIM_NS_PER_TICK) / 1000ULL);
            (void) SimBus(&pBus->m_InFlight);
            continue;
        }
        if (!SimPhysStart(bBus_p, ullUntil_p))
        {
            break;
        }
    }
}

static int SimIsPhysical (BYTE bBus_p)
{
    return (bBus_p < SIM_MAX_BUSES) && (aSimPhys_g[bBus_p].m_dwBitRate != 0);
}

tCopKernel SimSetBitRate (BYTE bBus_p, DWORD dwBitRate_p)
{
    tSimPhysBus* pBus;
    unsigned n;

    if ((bBus_p >= SIM_MAX_BUSES) ||
        ((dwBitRate_p != 0) && ((dwBitRate_p < SIM_BIT_RATE_MIN) || (dwBitRate_p > SIM_BIT_RATE_MAX))))
    {
        return kCopInvalidParam;
    }
    pBus = &aSimPhys_g[bBus_p];
    pBus->m_dwBitRate = dwBitRate_p;
    pBus->m_fInFlight = 0;
    pBus->m_ullIdleFromNs = ullSimNs_g;
    SimTxInit(&pBus->m_Outside, SIM_QUEUE_MAX);
    for (n = 0; n < SIM_MAX_NODES; n++)
    {
        if (aSimNode_g[n].m_bBus == bBus_p)
        {
            aSimNode_g[n].m_TxHigh.m_uCount = 0;
            aSimNode_g[n].m_TxLow.m_uCount = 0;
        }
    }
    return kCopSuccessful;
}

void SimGetBusStats (BYTE bBus_p, tSimBusStats* pStats_p)
{
    if (pStats_p == NULL)
    {
        return;
    }
    memset(pStats_p, 0, sizeof(*pStats_p));
    if (bBus_p < SIM_MAX_BUSES)
    {
        *pStats_p = aSimPhys_g[bBus_p].m_Stats;
        pStats_p->m_ullElapsedNs = ullSimNs_g;
    }
}

unsigned SimTxPending (BYTE bNode_p)
{
    if (bNode_p >= SIM_MAX_NODES)
    {
        return 0;
    }
    return aSimNode_g[bNode_p].m_TxHigh.m_uCount + aSimNode_g[bNode_p].m_TxLow.m_uCount;
}

/* ========================================================================== */
/* Simulation API                                                             */
/* ========================================================================== */

#if defined(SIM_CAPTURE) && (SIM_CAPTURE != 0)
/* Host builds: COP_SIM_BIT_RATE (bit/s) puts every bus of every scenario
 * on the physical model, so an unchanged program runs with bit times. */
static void SimBitRateFromEnv (void)
{
    const char* pszRate = getenv("COP_SIM_BIT_RATE");
    char* pszEnd = NULL;
    unsigned long ulRate;
    BYTE b;

    if ((pszRate == NULL) || (pszRate[0] == '\0'))
    {
        return;
    }
    ulRate = strtoul(pszRate, &pszEnd, 10);
    for (b = 0; b < SIM_MAX_BUSES; b++)
    {
        if ((*pszEnd != '\0') || (SimSetBitRate(b, (DWORD) ulRate) != kCopSuccessful))
        {
            fprintf(stderr, "sim: COP_SIM_BIT_RATE=%s is not a bit rate of 10000 .. 1000000; the bus stays ideal\n", pszRate);
            return;
        }
    }
}
#endif

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
    memset(aSimPhys_g, 0, sizeof(aSimPhys_g));
    ullSimNs_g = 0;
#if (COP_MAX_INSTANCES == 1)
    (void) CopSimSelectInstance(0);
#endif
#if defined(SIM_CAPTURE) && (SIM_CAPTURE != 0)
    SimCaptureAtReset();
    SimBitRateFromEnv();
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
    BYTE b;

    ullSimNs_g += (unsigned long long) dwTicks_p * SIM_NS_PER_TICK;
    for (b = 0; b < SIM_MAX_BUSES; b++)
    {
        if (SimIsPhysical(b))
        {
            SimPhysRun(b, ullSimNs_g);
        }
    }
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
    if (SimIsPhysical(Frame.m_bBus))
    {
        return SimTxPush(&aSimPhys_g[Frame.m_bBus].m_Outside, &Frame) ? 0 : -1;
    }
    Frame.m_dwTick = dwSimTicks_g;
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
    SimTxInit(&pNode->m_TxHigh, pInitParam_p->m_TxBuffHigh.m_MaxEntries);
    SimTxInit(&pNode->m_TxLow, pInitParam_p->m_TxBuffLow.m_MaxEntries);
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
    if ((ResetCode_p & kResetTxBuffHigh) != 0)
    {
        pNode->m_TxHigh.m_uCount = 0;
    }
    if ((ResetCode_p & kResetTxBuffLow) != 0)
    {
        pNode->m_TxLow.m_uCount = 0;
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
    if (SimIsPhysical(Frame.m_bBus))
    {
        int fHigh = (pCanMsg_p->m_MsgType & kMtbHighPrio) != 0;

        if (!SimTxPush(fHigh ? &pNode->m_TxHigh : &pNode->m_TxLow, &Frame))
        {
            aSimPhys_g[Frame.m_bBus].m_Stats.m_ullTxRefused++;
            return fHigh ? kCopCdrvTxBuffHighOverrun : kCopCdrvTxBuffLowOverrun;
        }
        return kCopSuccessful;
    }
    Frame.m_dwTick = dwSimTicks_g;
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
