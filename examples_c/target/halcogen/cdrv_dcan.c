/*
 * cdrv_dcan.c - sketch of the Cdrv* and TgtGetTickCount functions the
 * library calls, on a TMS570 DCAN driven through HALCoGen's CAN and RTI
 * drivers (docs/tms570.md). It compiles in the target stage against
 * halcogen_stub.h; it has not run on a board.
 *
 * HALCoGen configuration assumed:
 *   DCAN1 message box 1: transmit, standard identifier (the library's
 *                        frames, one at a time, high-priority first)
 *   DCAN1 message boxes 2..32: receive, standard identifiers, acceptance
 *                        mask 0 (all identifiers), receive interrupt on;
 *                        the filter of CdrvDefineCanId is kept in software
 *   RTI compare 0: period 100 us, notification on (the tick of the stack)
 *
 * Interrupt side: canMessageNotification copies a received frame into the
 * high- or low-priority ring; the main loop (CcmProcess) reads the rings
 * through CdrvReadMsg/CdrvReleaseMsg. The library is not re-entrant: only
 * these rings are shared with the interrupt.
 */
#include "cop.h"
#include "halcogen_stub.h"

#define TX_BOX          1U
#define RX_FIRST_BOX    2U
#define RING_SIZE       16U         /* frames per ring, a power of two */
#define ID_COUNT        2048U

typedef struct
{
    tCdrvMsg              m_aMsg[RING_SIZE];
    volatile unsigned int m_uHead;  /* written by the interrupt */
    volatile unsigned int m_uTail;  /* written by CdrvReleaseMsg */
} tRing;

static tRing RxHigh_g, RxLow_g;
static unsigned char abFilter_g[ID_COUNT / 8];     /* defined identifiers */
static unsigned char abHighPrio_g[ID_COUNT / 8];   /* ... of the high ring */
static volatile tCdrvStatus Status_g;
static volatile tTime dwTicks_g;

/* Tx queue: the library may queue more frames than one message box holds. */
static tCdrvMsg aTxQueue_g[RING_SIZE];
static unsigned int uTxHead_g, uTxTail_g;

static int IsSet (const unsigned char* pab_p, WORD wId_p)
{
    return (pab_p[wId_p >> 3] >> (wId_p & 7U)) & 1U;
}

static void Mark (unsigned char* pab_p, WORD wId_p, int fOn_p)
{
    if (fOn_p)
    {
        pab_p[wId_p >> 3] |= (unsigned char) (1U << (wId_p & 7U));
    }
    else
    {
        pab_p[wId_p >> 3] &= (unsigned char) ~(1U << (wId_p & 7U));
    }
}

static void TxKick (void)
{
    uint32 dwArb;
    tCdrvMsg* pMsg;
    if ((uTxHead_g == uTxTail_g) || canIsTxMessagePending(canREG1, TX_BOX))
    {
        return;
    }
    pMsg = &aTxQueue_g[uTxTail_g % RING_SIZE];
    /* IF1ARB: MsgVal (bit 31), Dir = transmit (bit 29), 11-bit identifier
     * in bits 28..18 (TMS570 TRM, DCAN IFx arbitration register) */
    dwArb = 0x80000000UL | 0x20000000UL | ((uint32) (pMsg->m_CanId & 0x7FFU) << 18);
    canUpdateID(canREG1, TX_BOX, dwArb);
    /* the DLC of the box is the one HALCoGen configured (8): the library's
     * frames of other lengths need the IFxMCTL DLC field set here */
    (void) canTransmit(canREG1, TX_BOX, pMsg->m_bData);
    uTxTail_g++;
}

tCopKernel PUBLIC CdrvInit (tCdrvInitParam MEM* pInitParam_p)
{
    (void) pInitParam_p;
    canInit();
    canEnableErrorNotification(canREG1);
    rtiInit();
    rtiEnableNotification(rtiNOTIFICATION_COMPARE0);
    rtiStartCounter(rtiCOUNTER_BLOCK0);
    _enable_IRQ();
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvDeleteInstance (void)
{
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvDefineCanId (tCdrvMsg MEM* pCanMsg_p)
{
    if ((pCanMsg_p == NULL) || (pCanMsg_p->m_CanId >= ID_COUNT))
    {
        return kCopCdrvInvalidParam;
    }
    Mark(abHighPrio_g, (WORD) pCanMsg_p->m_CanId, (pCanMsg_p->m_MsgType & kMtbHighPrio) != 0);
    Mark(abFilter_g, (WORD) pCanMsg_p->m_CanId, 1);
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvUndefineCanId (tCdrvMsg MEM* pCanMsg_p)
{
    if ((pCanMsg_p == NULL) || (pCanMsg_p->m_CanId >= ID_COUNT))
    {
        return kCopCdrvInvalidParam;
    }
    Mark(abFilter_g, (WORD) pCanMsg_p->m_CanId, 0);
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvWriteMsg (tCdrvMsg MEM* pCanMsg_p)
{
    if (pCanMsg_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    if ((uTxHead_g - uTxTail_g) >= RING_SIZE)
    {
        return ((pCanMsg_p->m_MsgType & kMtbHighPrio) != 0) ? kCopCdrvTxBuffHighOverrun : kCopCdrvTxBuffLowOverrun;
    }
    aTxQueue_g[uTxHead_g % RING_SIZE] = *pCanMsg_p;
    uTxHead_g++;
    TxKick();
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvReadMsg (tCdrvMsg MEM* MEM* ppCanMsg_p)
{
    if (ppCanMsg_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    TxKick();   /* the main loop also moves the transmit queue on */
    if (RxHigh_g.m_uHead != RxHigh_g.m_uTail)
    {
        *ppCanMsg_p = &RxHigh_g.m_aMsg[RxHigh_g.m_uTail % RING_SIZE];
        return kCopCdrvMsgHigh;
    }
    if (RxLow_g.m_uHead != RxLow_g.m_uTail)
    {
        *ppCanMsg_p = &RxLow_g.m_aMsg[RxLow_g.m_uTail % RING_SIZE];
        return kCopCdrvMsgLow;
    }
    return kCopCdrvNoMsg;
}

tCopKernel PUBLIC CdrvReleaseMsg (tCdrvMsg MEM* pCanMsg_p)
{
    if (pCanMsg_p == &RxHigh_g.m_aMsg[RxHigh_g.m_uTail % RING_SIZE])
    {
        RxHigh_g.m_uTail++;
        return kCopSuccessful;
    }
    if (pCanMsg_p == &RxLow_g.m_aMsg[RxLow_g.m_uTail % RING_SIZE])
    {
        RxLow_g.m_uTail++;
        return kCopSuccessful;
    }
    return kCopCdrvInvalidParam;
}

tCopKernel PUBLIC CdrvGetStatus (tCdrvStatus MEM* pStatus_p)
{
    if (pStatus_p == NULL)
    {
        return kCopCdrvInvalidParam;
    }
    *pStatus_p = Status_g;
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvResetStatus (tCdrvStatus Status_p)
{
    Status_g &= (tCdrvStatus) ~Status_p;  /* the interrupt may set bits meanwhile: keep this short */
    return kCopSuccessful;
}

/* HALCoGen calls this from the DCAN1 interrupt for every receive box. */
void canMessageNotification (canBASE_t* node, uint32 messageBox)
{
    uint8 abData[8];
    uint32 dwId;
    WORD wId;
    tRing* pRing;
    tCdrvMsg* pMsg;
    unsigned int i;

    if ((node != canREG1) || (messageBox < RX_FIRST_BOX))
    {
        TxKick();
        return;
    }
    (void) canGetData(node, messageBox, abData);
    dwId = canGetID(node, messageBox);
    wId = (WORD) ((dwId >> 18) & 0x7FFU);
    if (!IsSet(abFilter_g, wId))
    {
        return;
    }
    pRing = IsSet(abHighPrio_g, wId) ? &RxHigh_g : &RxLow_g;
    if ((pRing->m_uHead - pRing->m_uTail) >= RING_SIZE)
    {
        Status_g |= (pRing == &RxHigh_g) ? kCdrvRxBuffHighOverrun : kCdrvRxBuffLowOverrun;
        return;
    }
    pMsg = &pRing->m_aMsg[pRing->m_uHead % RING_SIZE];
    pMsg->m_CanId = wId;
    pMsg->m_MsgType = IsSet(abHighPrio_g, wId) ? kMtbHighPrio : 0;
    pMsg->m_bSize = 8;  /* IFxMCTL DLC: read it with the register view of reg_can.h */
    pMsg->m_bChannel_p = 0;
    for (i = 0; i < 8U; i++)
    {
        pMsg->m_bData[i] = abData[i];
    }
    pRing->m_uHead++;
}

/* HALCoGen calls this from the RTI interrupt: compare 0 every 100 us. */
void rtiNotification (uint32 notification)
{
    if (notification == rtiNOTIFICATION_COMPARE0)
    {
        dwTicks_g++;
    }
}

/* Ticks of 100 us; wraps modulo 2^32 (the library handles the wrap). */
tTime PUBLIC TgtGetTickCount (void)
{
    return dwTicks_g;
}
