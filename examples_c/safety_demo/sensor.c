/*
 * sensor.c - the safety sensor (node-ID 1): reads its E-stop button and
 * the permitted speed, and transmits both in SRDO 1 every refresh time
 * (manual 2.5.1: the application sends, the library checks the inverted
 * copy bit by bit before anything goes on the bus).
 *
 * When the E-stop is pressed (a dangerous condition) the sensor sends the
 * global fail-safe command at once and, right after it, the SRDO with the
 * new values (manual 2.8.3).
 */
#include "cdrv_sim.h"
#include "safety_node.h"

#define SPEED_LIMIT_MMS  300u   /* permitted speed while the E-stop is released */

/* SRDO data (objdict_sensor.h maps them: normal, inverted, normal, inverted) */
tObdUnsigned8  bSensorEStop_g;
tObdUnsigned8  bSensorEStopInv_g;
tObdUnsigned16 wSensorSpeedLimit_g;
tObdUnsigned16 wSensorSpeedLimitInv_g;

static int   fEStopPressed_g;       /* the button, as the input stage reads it */
static int   fDangerReported_g;     /* GFC already sent for this press */
static DWORD dwLastSend_g;

/* The board's input stage (scripted by main.c). */
void SensorSetEStop (int fPressed_p)
{
    fEStopPressed_g = fPressed_p;
    if (!fPressed_p)
    {
        fDangerReported_g = 0;
    }
}

static tCopKernel SendSrdo (tSafetyNode* pNode_p)
{
    tCopKernel Ret;

    /* both copies are written together; the library refuses to send a
     * pair that is not bit-exact inverted (kCopSrdoDataError) */
    bSensorEStop_g = (tObdUnsigned8) (fEStopPressed_g ? 0 : 1);
    wSensorSpeedLimit_g = (tObdUnsigned16) (fEStopPressed_g ? 0 : SPEED_LIMIT_MMS);
    bSensorEStopInv_g = (tObdUnsigned8) ~bSensorEStop_g;
    wSensorSpeedLimitInv_g = (tObdUnsigned16) ~wSensorSpeedLimit_g;

    SafetyLog(pNode_p, "CcmSendSrdo(0x%04X): E-stop %s, speed limit %u mm/s", (unsigned) SAFETY_SRDO,
              bSensorEStop_g ? "released" : "PRESSED", (unsigned) wSensorSpeedLimit_g);
    Ret = CcmSendSrdo(SAFETY_SRDO);
    if (Ret != kCopSuccessful)
    {
        SafetyLog(pNode_p, "CcmSendSrdo -> 0x%04X %s", (unsigned) Ret, SafetyKernelName(Ret));
    }
    dwLastSend_g = (DWORD) TgtGetTickCount();
    return Ret;
}

void SensorCycle (tSafetyNode* pNode_p)
{
    DWORD dwNow = (DWORD) TgtGetTickCount();
    int fSendNow = 0;

    if ((pNode_p->m_SrdoRun == kSrdoRunNotOperational) || pNode_p->m_fSafetyFault)
    {
        /* a faulty sensor stays silent: its receivers run into their SCT */
        return;
    }
    if (pNode_p->m_SrdoRun == kSrdoRunEnterOperational)
    {
        /* manual 2.5.1: first transmission 0.5 ms x node-ID after entering
         * OPERATIONAL (ticks of 100 us) */
        if ((dwNow - pNode_p->m_dwOperationalSince) < (DWORD) pNode_p->m_bNodeId * 5)
        {
            return;
        }
        pNode_p->m_SrdoRun = kSrdoRunOperational;
        fSendNow = 1;
    }

    if (fEStopPressed_g && !fDangerReported_g)
    {
        tCopKernel Ret = CcmSendGfc();
        SafetyLog(pNode_p, "E-stop pressed: CcmSendGfc -> %s, then the SRDO at once", SafetyKernelName(Ret));
        fDangerReported_g = 1;
        fSendNow = 1;
    }

    /* refresh time: the application is responsible for sending in time */
    if (fSendNow || ((dwNow - dwLastSend_g) >= (DWORD) pNode_p->m_SrdoCommu.m_wSct * 10))
    {
        (void) SendSrdo(pNode_p);
    }
}
