/*
 * capi.c - the C API benchmark: the library linked as a C application links
 * it (libcop.a, cop.h, an objdict.h dictionary, scripts/bench.sh builds it),
 * driven the way such an application drives it.
 *
 *   capi <scenario> <cycles>
 *
 * Scenarios (each measured region is a `measure_*` function, callgrind
 * counts inside it only; scripts/bench.sh takes (Ir(2N) - Ir(N)) / N):
 *   idle       CcmProcess with nothing received and nothing due
 *   rx         CcmProcess that reads the normal and the inverted frame of
 *              the last receive SRDO from the driver (CdrvReadMsg /
 *              CdrvReleaseMsg) and calls AppSrdoEvent, which does the
 *              manual's handshake (CcmGetSrdoState, CcmSetSrdoState)
 *   handshake  CcmGetSrdoState + CcmSetSrdoState of one receive SRDO
 *   send       CcmSendSrdo of the transmit SRDO (both CdrvWriteMsg); the
 *              dictionary has one after the receive SRDOs when there are
 *              fewer than 64
 *
 * The driver is a ring of received frames in memory and a counter of sent
 * ones; TgtGetTickCount advances by one tick (100 us) per CcmProcess. Each
 * scenario checks its own result (events, errors, frames, variables) and
 * exits with 1 when it does not hold.
 *
 * Built with a configuration of two instances (bench/capi/cfg_two), the
 * program starts instance 0 on another dictionary (objdict_other.c) and
 * measures instance 1: every call takes its handle, every callback gets it,
 * the driver sees the instance pointer of its controller (only instance 1's
 * receives the ring's frames).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cop.h"

tCopKernel PUBLIC ObdInitRamOther (void MEM* pInitParam_p);

#define NODE_ID 0x10
#define RING 16

/* The calls of the measured instance in both instance forms. */
#if (COP_MAX_INSTANCES > 1)
static tCopInstanceHdl hBench_g = CCM_ILLINSTANCE_HDL;
static BYTE abController_g[2];     /* the driver's instances: controllers 0 and 1 */
static unsigned uDriverInits_g;
#define H   hBench_g
#define H_  hBench_g,
#define MEASURED_CONTROLLER(p) ((p) == (void*) &abController_g[1])
#else
#define H
#define H_
#define MEASURED_CONTROLLER(p) 1
#endif

/* ---- driver --------------------------------------------------------------- */

static tCdrvMsg aRing_g[RING];
static unsigned uRingHead_g;
static unsigned uRingCount_g;
static tCdrvMsg* pLent_g;
static unsigned long ulSent_g;
static DWORD dwLastSentId_g;
static DWORD dwTicks_g;

tCopKernel PUBLIC CdrvInit (MCO_DECL_PTR_INSTANCE_PTR_ tCdrvInitParam MEM* pInitParam_p)
{
    (void) pInitParam_p;
#if (COP_MAX_INSTANCES > 1)
    *pInstancePtr = &abController_g[uDriverInits_g++ % 2];
#endif
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvAddInstance (MCO_DECL_PTR_INSTANCE_PTR_ tCdrvInitParam MEM* pInitParam_p)
{
    return CdrvInit(MCO_PTR_INSTANCE_PTR_ pInitParam_p);
}

#if (COP_MAX_INSTANCES > 1)
#define UNUSED_INSTANCE() (void) pInstance
#else
#define UNUSED_INSTANCE()
#endif

tCopKernel PUBLIC CdrvDeleteInstance (MCO_DECL_INSTANCE_PTR) { UNUSED_INSTANCE(); return kCopSuccessful; }
tCopKernel PUBLIC CdrvDefineCanId (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p) { UNUSED_INSTANCE(); (void) pCanMsg_p; return kCopSuccessful; }
tCopKernel PUBLIC CdrvUndefineCanId (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p) { UNUSED_INSTANCE(); (void) pCanMsg_p; return kCopSuccessful; }
tCopKernel PUBLIC CdrvGetStatus (MCO_DECL_INSTANCE_PTR_ tCdrvStatus MEM* pStatus_p) { UNUSED_INSTANCE(); *pStatus_p = 0; return kCopSuccessful; }
tCopKernel PUBLIC CdrvResetStatus (MCO_DECL_INSTANCE_PTR_ tCdrvStatus Status_p) { UNUSED_INSTANCE(); (void) Status_p; return kCopSuccessful; }

tCopKernel PUBLIC CdrvWriteMsg (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p)
{
    UNUSED_INSTANCE();
    ulSent_g++;
    dwLastSentId_g = (DWORD) pCanMsg_p->m_CanId;
    return kCopSuccessful;
}

tCopKernel PUBLIC CdrvReadMsg (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* MEM* ppCanMsg_p)
{
    if ((uRingCount_g == 0) || !MEASURED_CONTROLLER(MCO_INSTANCE_PTR))
    {
        return kCopCdrvNoMsg;
    }
    pLent_g = &aRing_g[uRingHead_g];
    *ppCanMsg_p = pLent_g;
    return kCopCdrvMsgHigh;
}

tCopKernel PUBLIC CdrvReleaseMsg (MCO_DECL_INSTANCE_PTR_ tCdrvMsg MEM* pCanMsg_p)
{
    UNUSED_INSTANCE();
    (void) pCanMsg_p;
    uRingHead_g = (uRingHead_g + 1) % RING;
    uRingCount_g--;
    return kCopSuccessful;
}

tTime PUBLIC TgtGetTickCount (void) { return dwTicks_g; }
void PUBLIC TgtEnableCanInterrupt (BYTE bEnable_p) { (void) bEnable_p; }

static void Inject (DWORD dwId_p, BYTE bDlc_p, const BYTE* pbData_p)
{
    tCdrvMsg* pMsg;

    if (uRingCount_g == RING)
    {
        fprintf(stderr, "capi: receive ring full\n");
        exit(1);
    }
    pMsg = &aRing_g[(uRingHead_g + uRingCount_g) % RING];
    memset(pMsg, 0, sizeof(*pMsg));
    pMsg->m_CanId = (tCanId) dwId_p;
    pMsg->m_MsgType = kMsgTypRecv;
    pMsg->m_bSize = bDlc_p;
    memcpy(pMsg->m_bData, pbData_p, bDlc_p);
    uRingCount_g++;
}

/* ---- application ---------------------------------------------------------- */

static unsigned long ulSrdoEvents_g;
static unsigned long ulSrdoErrors_g;
static unsigned long ulNotOk_g;

/* The manual's AppSrdoEvent: the state must say "ok", the data are used,
 * and the SRDO is marked processed (bits 4-5 = 11). */
tCopKernel PUBLIC AppSrdoEvent (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p)
{
    BYTE bState = 0;

    if ((CcmGetSrdoState(CCM_INSTANCE_HDL_ &bState, wSrdoCommuIndex_p) != kCopSuccessful) || ((bState & 0x30) != 0))
    {
        ulNotOk_g++;
    }
    if (CcmSetSrdoState(CCM_INSTANCE_HDL_ (BYTE) (bState | 0x30), wSrdoCommuIndex_p) != kCopSuccessful)
    {
        ulNotOk_g++;
    }
    ulSrdoEvents_g++;
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoError (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) InstanceHandle;
#endif
    fprintf(stderr, "capi: AppSrdoError 0x%04X 0x%04X\n", (unsigned) wSrdoCommuIndex_p, (unsigned) ErrorCode_p);
    ulSrdoErrors_g++;
    return kCopSuccessful;
}

tCopKernel PUBLIC AppGfcEvent (CCM_DECL_INSTANCE_HDL)
{
#if (COP_MAX_INSTANCES > 1)
    (void) InstanceHandle;
#endif
    return kCopSuccessful;
}

#if (SRDO_USE_PROGMONITOR != FALSE)
static unsigned long ulProgMon_g;
tCopKernel PUBLIC AppProgMonEvent (CCM_DECL_INSTANCE_HDL_ tProgMonEvent Event_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) InstanceHandle;
#endif
    (void) Event_p;
    ulProgMon_g++;
    return kCopSuccessful;
}
#endif

static tCopKernel PUBLIC NmtEvent (CCM_DECL_INSTANCE_HDL_ tNmtEvent NmtEvent_p)
{
#if (COP_MAX_INSTANCES > 1)
    (void) InstanceHandle;
#endif
    (void) NmtEvent_p;
    return kCopSuccessful;
}

/* ---- measured regions ----------------------------------------------------- */

__attribute__((noinline)) void measure_cycle (void)
{
    (void) CcmProcess(H);
}

__attribute__((noinline)) void measure_handshake (WORD wIndex_p)
{
    BYTE bState = 0;

    (void) CcmGetSrdoState(H_ &bState, wIndex_p);
    (void) CcmSetSrdoState(H_ (BYTE) (bState | 0x30), wIndex_p);
}

__attribute__((noinline)) tCopKernel measure_send (void)
{
    return CcmSendSrdo(H_ (WORD) (0x1301 + BENCH_SRDOS));
}

/* ---- set-up ----------------------------------------------------------------- */

static void Fail (const char* pszWhat_p)
{
    fprintf(stderr, "capi: %s\n", pszWhat_p);
    exit(1);
}

static void Tick (unsigned n_p)
{
    while (n_p-- > 0)
    {
        dwTicks_g++;
        (void) CcmProcess(H);
    }
}

static void SetUp (void)
{
    static tCcmInitParam InitParam;
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    BYTE bValid = 0xA5;
    WORD wIndex;
    tCopKernel Ret;

    memset(&InitParam, 0, sizeof(InitParam));
    InitParam.m_bInitNodeId = NODE_ID;
    InitParam.m_BaudIndex = kBdi500kBaud;
    InitParam.m_dwAmr = 0xFFFFFFFFUL;
    InitParam.m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    InitParam.m_fpNmtEventCallback = NmtEvent;
#if (COP_MAX_INSTANCES > 1)
    {
        /* instance 0: another node on another dictionary and controller */
        tCopInstanceHdl hOther = CCM_ILLINSTANCE_HDL;

        InitParam.m_fpObdInitRam = ObdInitRamOther;
        if (CcmInitCANopen(&hOther, &InitParam, kCcmFirstInstance) != kCopSuccessful) Fail("CcmInitCANopen (instance 0)");
        if (CcmConnectToNet(hOther) != kCopSuccessful) Fail("CcmConnectToNet (instance 0)");
    }
    InitParam.m_fpObdInitRam = ObdInitRam;
    Ret = CcmInitCANopen(&hBench_g, &InitParam, kCcmAdditionalInstance);
    if (hBench_g != 1) Fail("the measured instance is not instance 1");
#else
    InitParam.m_fpObdInitRam = ObdInitRam;
    Ret = CcmInitCANopen(&InitParam, kCcmFirstInstance);
#endif
    if (Ret != kCopSuccessful)
    {
        fprintf(stderr, "capi: CcmInitCANopen 0x%04X\n", (unsigned) Ret);
        exit(1);
    }
    if (CcmConnectToNet(H) != kCopSuccessful) Fail("CcmConnectToNet");
    Tick(2);
    for (wIndex = 0x1301; wIndex <= 0x1340; wIndex++)
    {
        WORD wCrc;

#if (COP_MAX_INSTANCES > 1)
        if (CcmCalcSrdoCrc(&hBench_g, wIndex, &wCrc) != kCopSuccessful)
#else
        if (CcmCalcSrdoCrc(wIndex, &wCrc) != kCopSuccessful)
#endif
        {
            continue;       /* an SRDO the dictionary does not declare */
        }
        if (CcmWriteObject(H_ 0x13FF, (BYTE) (wIndex - 0x1300), &wCrc, sizeof(wCrc)) != kCopSuccessful) Fail("0x13FF");
    }
    if (CcmWriteObject(H_ 0x13FE, 0, &bValid, sizeof(bValid)) != kCopSuccessful) Fail("0x13FE");
    Inject(0x000, 2, abStartAll);
    Tick(100);      /* OPERATIONAL; the transmit SRDO's first transmission */
    if (CcmObdGetNodeState(H) != kNodeStateOperational) Fail("not OPERATIONAL");
}

int main (int argc, char** argv)
{
    const char* pszScenario;
    unsigned long ulCycles;
    unsigned long i;
    WORD wLast = (WORD) (0x1300 + BENCH_SRDOS);
    DWORD dwNormal = 0x101 + 2 * (BENCH_SRDOS - 1);
    static CONST BYTE abNormal[2] = { 0x3C, 0x5A };
    static CONST BYTE abInverted[2] = { 0xC3, 0xA5 };

    if (argc != 3) Fail("usage: capi idle|rx|handshake|send <cycles>");
    pszScenario = argv[1];
    ulCycles = strtoul(argv[2], NULL, 10);
    SetUp();
    ulSrdoEvents_g = 0;
    ulSent_g = 0;

    if (strcmp(pszScenario, "idle") == 0)
    {
        for (i = 0; i < ulCycles; i++)
        {
            dwTicks_g++;
            measure_cycle();
        }
        if ((ulSent_g != 0) || (ulSrdoEvents_g != 0)) Fail("idle: frames sent or events");
    }
    else if (strcmp(pszScenario, "rx") == 0)
    {
        BYTE abVar[4] = { 0, 0, 0, 0 };
        tObdSize Size;
        BYTE bSub;

        for (i = 0; i < ulCycles; i++)
        {
            Inject(dwNormal, 2, abNormal);
            Inject(dwNormal + 1, 2, abInverted);
            dwTicks_g++;
            measure_cycle();
        }
        if (ulSrdoEvents_g != ulCycles) Fail("rx: not one AppSrdoEvent per pair");
        for (bSub = 1; bSub <= 4; bSub++)
        {
            Size = 1;
            if (CcmReadObject(H_ (WORD) (0x20FF + BENCH_SRDOS), bSub, &abVar[bSub - 1], &Size) != kCopSuccessful) Fail("rx: read");
        }
        if ((abVar[0] != 0x3C) || (abVar[1] != 0xC3) || (abVar[2] != 0x5A) || (abVar[3] != 0xA5)) Fail("rx: mapped variables");
    }
    else if (strcmp(pszScenario, "handshake") == 0)
    {
        BYTE bState = 0;

        for (i = 0; i < ulCycles; i++)
        {
            measure_handshake(wLast);
        }
        if ((CcmGetSrdoState(H_ &bState, wLast) != kCopSuccessful) || ((bState & 0x30) != 0x30)) Fail("handshake: state");
    }
    else if (strcmp(pszScenario, "send") == 0)
    {
#if BENCH_SRDOS < 64
        for (i = 0; i < ulCycles; i++)
        {
            if (measure_send() != kCopSuccessful) Fail("send: CcmSendSrdo");
        }
        if ((ulSent_g != 2 * ulCycles) || (dwLastSentId_g != (DWORD) (0x102 + 2 * BENCH_SRDOS))) Fail("send: not two frames per call");
#else
        Fail("send: needs fewer than 64 receive SRDOs");
#endif
    }
    else
    {
        Fail("unknown scenario");
    }
    if ((ulSrdoErrors_g != 0) || (ulNotOk_g != 0)) Fail("SRDO errors or handshake refused");
    (void) CcmShutDownCANopen(H);
    return 0;
}
