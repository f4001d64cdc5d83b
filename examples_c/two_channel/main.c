/*
 * main.c - the two-channel safety example: the SIL 3 structure of the
 * safety manual (section 1.6, figure 3) with one CPU per board and two CAN
 * controllers, each controller run by its own stack instance
 * (COP_MAX_INSTANCES 4, copcfg.h).
 *
 *   bus 0 (can0): sensor channel A (node 1) -> actuator channel A (node 2)
 *   bus 1 (can1): sensor channel B (node 1) -> actuator channel B (node 2)
 *
 * The sensor sends its safety value (a speed limit) in SRDO 1 over both
 * channels every 20 ms. The actuator's two instances each receive it, and
 * the application cross-checks the channels every millisecond: the safe
 * output is ON only while both channels delivered the same value within the
 * last 60 ms; it goes to the safe state (OFF, latched until RESET) when the
 * channels disagree, when either channel reports an SRDO error or a GFC,
 * or when one channel falls silent.
 *
 * The script injects three faults: channel B's controller on the sensor
 * falls silent, a corrupted frame on channel A, and a sensor channel that
 * sends another value than the other one. Each is detected and the output
 * goes OFF; RESET brings it back once both channels agree again.
 *
 * Every callback takes the instance handle first (CCM_DECL_INSTANCE_HDL_);
 * the application finds the channel by the handle. The exit code is 0 when
 * the actuator behaved as a two-channel safety actuator must.
 */
#include <stdio.h>

#include "cdrv_sim.h"

#if (COP_MAX_INSTANCES < 4)
#error "the two-channel example runs four instances (copcfg.h)"
#endif

tCopKernel PUBLIC ObdInitRamSensorA (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamSensorB (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamActuatorA (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamActuatorB (void MEM* pInitParam_p);

#define SILENCE_MS  60      /* a channel without a valid SRDO this long is silent */
#define REFRESH_MS  20      /* the sensor's refresh time (0x1301/2) */

typedef struct
{
    const char*     m_pszName;
    BYTE            m_bController;      /* simulated CAN controller */
    BYTE            m_bBus;             /* its CAN line */
    BYTE            m_bNodeId;
    tObdInitRam     m_fpObdInitRam;
    int             m_fActuator;
    tCopInstanceHdl m_Handle;           /* from CcmInitCANopen */
    WORD            m_wValue;           /* actuator: last value received */
    unsigned        m_uLastMs;          /* actuator: when */
    int             m_fSeen;
} tChannel;

static tChannel aChannel_g[4] = {
    { "sensor   A", 0, 0, 1, ObdInitRamSensorA, 0, CCM_ILLINSTANCE_HDL, 0, 0, 0 },
    { "sensor   B", 1, 1, 1, ObdInitRamSensorB, 0, CCM_ILLINSTANCE_HDL, 0, 0, 0 },
    { "actuator A", 2, 0, 2, ObdInitRamActuatorA, 1, CCM_ILLINSTANCE_HDL, 0, 0, 0 },
    { "actuator B", 3, 1, 2, ObdInitRamActuatorB, 1, CCM_ILLINSTANCE_HDL, 0, 0, 0 },
};

static unsigned uNowMs_g;
static int      fOutputOn_g;
static int      fLatched_g;
static WORD     wSensorValue_g = 300;
static WORD     wSensorOffsetB_g;       /* a faulty sensor channel B adds this */
static unsigned uSafeStates_g;

static const char* KernelName (tCopKernel Code_p)
{
    switch (Code_p)
    {
        case kCopSrdoSctTimeout:  return "kCopSrdoSctTimeout";
        case kCopSrdoSrvtTimeout: return "kCopSrdoSrvtTimeout";
        case kCopSrdoDataError:   return "kCopSrdoDataError";
        case kCopSrdoNotInOrder:  return "kCopSrdoNotInOrder";
        case kCopSrdoDlcNotValid: return "kCopSrdoDlcNotValid";
        default:                  return "another SRDO error";
    }
}

/* The channel an instance handle belongs to. */
static tChannel* ChannelOf (tCopInstanceHdl Handle_p)
{
    unsigned i;

    for (i = 0; i < 4; i++)
    {
        if (aChannel_g[i].m_Handle == Handle_p)
        {
            return &aChannel_g[i];
        }
    }
    return NULL;
}

static void SafeState (const char* pszWhy_p)
{
    if (fOutputOn_g || !fLatched_g)
    {
        printf("[%4u ms] actuator   >>> SAFE STATE, output OFF (%s)\n", uNowMs_g, pszWhy_p);
    }
    fOutputOn_g = 0;
    fLatched_g = 1;
    uSafeStates_g++;
}

/* ---- the application's callbacks (one set for all four instances) ----------------- */

tCopKernel PUBLIC AppSrdoEvent (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p)
{
    tChannel* pCh = ChannelOf(InstanceHandle);
    BYTE bState = 0;
    WORD wNormal = 0;
    WORD wInverted = 0;
    tObdSize Size = sizeof(WORD);

    if ((pCh == NULL) || (CcmGetSrdoState(InstanceHandle, &bState, wSrdoCommuIndex_p) != kCopSuccessful))
    {
        SafeState("SRDO event of an unknown instance");
        return kCopSuccessful;
    }
    if (pCh->m_fActuator)
    {
        /* the mapped objects of this instance's dictionary */
        (void) CcmReadObject(InstanceHandle, 0x2200, 1, &wNormal, &Size);
        Size = sizeof(WORD);
        (void) CcmReadObject(InstanceHandle, 0x2201, 1, &wInverted, &Size);
        if ((WORD) ~wInverted != wNormal)
        {
            SafeState("inverted copy does not match");
        }
        pCh->m_wValue = wNormal;
        pCh->m_uLastMs = uNowMs_g;
        pCh->m_fSeen = 1;
    }
    /* manual 2.9.1: mark the SRDO processed */
    (void) CcmSetSrdoState(InstanceHandle, (BYTE) (bState | 0x30), wSrdoCommuIndex_p);
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoError (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    tChannel* pCh = ChannelOf(InstanceHandle);
    BYTE bState = 0;
    char szWhy[96];

    printf("[%4u ms] %s AppSrdoError(handle %u, 0x%04X, %s)\n", uNowMs_g,
           (pCh != NULL) ? pCh->m_pszName : "?", (unsigned) InstanceHandle, (unsigned) wSrdoCommuIndex_p,
           KernelName(ErrorCode_p));
    if ((pCh != NULL) && pCh->m_fActuator)
    {
        sprintf(szWhy, "channel %c: %s", pCh->m_pszName[9], KernelName(ErrorCode_p));
        SafeState(szWhy);
    }
    /* manual 2.9.2: bits 6-7 = 10, the error was handled */
    if (CcmGetSrdoState(InstanceHandle, &bState, wSrdoCommuIndex_p) == kCopSuccessful)
    {
        (void) CcmSetSrdoState(InstanceHandle, (BYTE) ((bState & 0x0F) | 0xB0), wSrdoCommuIndex_p);
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppGfcEvent (CCM_DECL_INSTANCE_HDL)
{
    tChannel* pCh = ChannelOf(InstanceHandle);

    if ((pCh != NULL) && pCh->m_fActuator)
    {
        SafeState("GFC");
    }
    return kCopSuccessful;
}

/* ---- start-up ----------------------------------------------------------------------- */

/* CcmInitCANopen for one channel on its controller and bus; the handle is
 * what the application keeps. */
static tCopKernel StartChannel (tChannel* pCh_p, tCcmInitCall InitCall_p)
{
    tCcmInitParam Init;
    tCopKernel Ret;
    WORD wCrc = 0;
    BYTE bValid = 0xA5;

    memset(&Init, 0, sizeof(Init));
    Init.m_bInitNodeId = pCh_p->m_bNodeId;
    Init.m_BaudIndex = kBdi500kBaud;
    Init.m_dwAmr = 0xFFFFFFFFUL;
    Init.m_HwParam.m_ZeroBasedCanNo.m_bCanNo = pCh_p->m_bController;
    Init.m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    Init.m_fpObdInitRam = pCh_p->m_fpObdInitRam;
    SimSetBus(pCh_p->m_bController, pCh_p->m_bBus);
    SimSelectNode(pCh_p->m_bController);
    Ret = CcmInitCANopen(&pCh_p->m_Handle, &Init, InitCall_p);
    if (Ret != kCopSuccessful)
    {
        return Ret;
    }
    /* the configuration of the dictionary made valid (manual 2.8.8) */
    Ret = CcmCalcSrdoCrc(&pCh_p->m_Handle, 0x1301, &wCrc);
    if (Ret == kCopSuccessful)
    {
        Ret = CcmWriteObject(pCh_p->m_Handle, 0x13FF, 1, &wCrc, sizeof(wCrc));
    }
    if (Ret == kCopSuccessful)
    {
        Ret = CcmWriteObject(pCh_p->m_Handle, 0x13FE, 0, &bValid, sizeof(bValid));
    }
    printf("%s: handle %u, controller %u on can%u, node-ID %u, SRDO 1 CRC 0x%04X\n", pCh_p->m_pszName,
           (unsigned) pCh_p->m_Handle, (unsigned) pCh_p->m_bController, (unsigned) pCh_p->m_bBus,
           (unsigned) pCh_p->m_bNodeId, (unsigned) wCrc);
    return (Ret == kCopSuccessful) ? CcmConnectToNet(pCh_p->m_Handle) : Ret;
}

/* ---- the two boards' cycles ---------------------------------------------------------------- */

static void SensorCycle (void)
{
    unsigned i;

    for (i = 0; i < 2; i++)
    {
        tChannel* pCh = &aChannel_g[i];
        WORD wValue = (WORD) (wSensorValue_g + ((i == 1) ? wSensorOffsetB_g : 0));
        WORD wInverted = (WORD) ~wValue;

        (void) CcmProcess(pCh->m_Handle);
        if ((uNowMs_g % REFRESH_MS) == 10)
        {
            (void) CcmWriteObject(pCh->m_Handle, 0x2100, 1, &wValue, sizeof(wValue));
            (void) CcmWriteObject(pCh->m_Handle, 0x2101, 1, &wInverted, sizeof(wInverted));
            (void) CcmSendSrdo(pCh->m_Handle, 0x1301);
        }
    }
}

/* The cross-check of the two actuator channels. */
static void ActuatorCycle (void)
{
    tChannel* pA = &aChannel_g[2];
    tChannel* pB = &aChannel_g[3];
    int fFreshA;
    int fFreshB;

    (void) CcmProcess(pA->m_Handle);
    (void) CcmProcess(pB->m_Handle);
    fFreshA = pA->m_fSeen && ((uNowMs_g - pA->m_uLastMs) <= SILENCE_MS);
    fFreshB = pB->m_fSeen && ((uNowMs_g - pB->m_uLastMs) <= SILENCE_MS);
    if (pA->m_fSeen && !fFreshA)
    {
        SafeState("channel A silent");
    }
    else if (pB->m_fSeen && !fFreshB)
    {
        SafeState("channel B silent");
    }
    else if (fFreshA && fFreshB && (pA->m_wValue != pB->m_wValue))
    {
        char szWhy[64];

        sprintf(szWhy, "channels disagree: A %u, B %u mm/s", (unsigned) pA->m_wValue, (unsigned) pB->m_wValue);
        SafeState(szWhy);
    }
    else if (fFreshA && fFreshB && !fLatched_g && !fOutputOn_g)
    {
        fOutputOn_g = 1;
        printf("[%4u ms] actuator   >>> output ON (both channels %u mm/s)\n", uNowMs_g, (unsigned) pA->m_wValue);
    }
}

static void OperatorReset (void)
{
    fLatched_g = 0;
    aChannel_g[2].m_fSeen = 0;      /* both channels must deliver again */
    aChannel_g[3].m_fSeen = 0;
}

/* ---- the script ------------------------------------------------------------------------------- */

#define T_NMT_START    5
#define T_VALUE        100
#define T_SILENT_B     150
#define T_BACK_B       250
#define T_RESET_1      280
#define T_CORRUPT_A    330
#define T_RESET_2      380
#define T_DISAGREE     430
#define T_END          520

static void Say (const char* pszWhat_p)
{
    printf("\n[%4u ms] ======== %s\n", uNowMs_g, pszWhat_p);
}

int main (void)
{
    static CONST BYTE abNmtStartAll[2] = { 0x01, 0x00 };
    int fOnAtStart = 0, fOffSilent = 0, fOnAfterReset = 0, fOffCorrupt = 0, fOnAgain = 0, fOffDisagree = 0;
    unsigned i;
    int fOk;

    printf("cop two-channel safety example: sensor and actuator, two stack instances each\n");
    printf("frames are shown as candump lines (  can<bus>  <id>   [<dlc>]  <data>)\n");
    SimReset();
    SimSetTrace(1);
    for (i = 0; i < 4; i++)
    {
        if (StartChannel(&aChannel_g[i], (i == 0) ? kCcmFirstInstance : kCcmAdditionalInstance) != kCopSuccessful)
        {
            printf("%s: start-up failed\n", aChannel_g[i].m_pszName);
            return 1;
        }
    }

    for (uNowMs_g = 0; uNowMs_g < T_END; uNowMs_g++)
    {
        switch (uNowMs_g)
        {
            case T_NMT_START:
                Say("NMT master: start all nodes, on both buses");
                SimSetInjectBus(0);
                (void) SimInject(0x000, 0, 2, abNmtStartAll);
                SimSetInjectBus(1);
                (void) SimInject(0x000, 0, 2, abNmtStartAll);
                break;
            case T_VALUE:
                Say("sensor: the speed limit changes to 250 mm/s (both channels)");
                wSensorValue_g = 250;
                break;
            case T_SILENT_B:
                Say("FAULT INJECTION: the sensor's CAN controller of channel B falls silent");
                SimSilence(aChannel_g[1].m_bController, 1);
                break;
            case T_BACK_B:
                Say("channel B's controller sends again");
                SimSilence(aChannel_g[1].m_bController, 0);
                break;
            case T_RESET_1:
            case T_RESET_2:
                Say("operator presses RESET on the actuator");
                OperatorReset();
                break;
            case T_CORRUPT_A:
                Say("FAULT INJECTION: the next normal frame 0x101 on channel A is corrupted (bit 0 of byte 0)");
                SimCorruptNextId(0x101, 0x01);
                break;
            case T_DISAGREE:
                Say("FAULT INJECTION: sensor channel B measures 5 mm/s more than channel A");
                wSensorOffsetB_g = 5;
                break;
            default:
                break;
        }
        SensorCycle();
        ActuatorCycle();
        while (SimTakeSentFrame(NULL))
        {
            /* the trace has shown them */
        }
        if (uNowMs_g == T_VALUE - 1)              fOnAtStart = fOutputOn_g;
        if (uNowMs_g == T_BACK_B - 1)             fOffSilent = !fOutputOn_g;
        if (uNowMs_g == T_CORRUPT_A - 1)          fOnAfterReset = fOutputOn_g;
        if (uNowMs_g == T_RESET_2 - 1)            fOffCorrupt = !fOutputOn_g;
        if (uNowMs_g == T_DISAGREE - 1)           fOnAgain = fOutputOn_g;
        if (uNowMs_g == T_END - 1)                fOffDisagree = !fOutputOn_g;
        SimAdvanceMs(1);
    }

    Say("end of the script");
    for (i = 0; i < 4; i++)
    {
        (void) CcmShutDownCANopen(aChannel_g[i].m_Handle);
    }
    fOk = fOnAtStart && fOffSilent && fOnAfterReset && fOffCorrupt && fOnAgain && fOffDisagree;
    printf("result: ON after start-up: %s, OFF on a silent channel: %s, ON after RESET: %s, "
           "OFF on a corrupted frame: %s, ON after RESET: %s, OFF when the channels disagree: %s\n",
           fOnAtStart ? "yes" : "NO", fOffSilent ? "yes" : "NO", fOnAfterReset ? "yes" : "NO",
           fOffCorrupt ? "yes" : "NO", fOnAgain ? "yes" : "NO", fOffDisagree ? "yes" : "NO");
    printf("two_channel: %s\n", fOk ? "PASSED" : "FAILED");
    return fOk ? 0 : 1;
}
