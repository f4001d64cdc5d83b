/*
 * actuator.c - the safety actuator (node-ID 2) and its safe output (think
 * of the contactor that lets a drive move).
 *
 * The output is ON only while all of this holds:
 *  - the node is OPERATIONAL with a valid, checked SRDO configuration;
 *  - the last SRDO was a valid pair (normal data and inverted copy agree)
 *    and no SRDO error has been reported since (AppSrdoError covers SCT,
 *    SRVT, order, data errors);
 *  - the received E-stop state says "released";
 *  - no fault is latched.
 * Any AppSrdoError, a GFC, leaving OPERATIONAL or a failed check switches
 * it OFF at once (the safe state). A communication fault or a GFC is
 * latched: a later valid SRDO alone does not switch the output on again,
 * the operator has to press RESET (restart interlock). The manual's rule
 * "safe state -> operation only with a successfully received SRDO" (2.5.3)
 * holds in both cases.
 */
#include "cdrv_sim.h"
#include "safety_node.h"

/* SRDO data (objdict_actuator.h maps them) */
tObdUnsigned8  bActEStop_g;
tObdUnsigned8  bActEStopInv_g;
tObdUnsigned16 wActSpeedLimit_g;
tObdUnsigned16 wActSpeedLimitInv_g;

static int fOutputOn_g;         /* the safe output as driven */
static int fSrdoValid_g;        /* last SRDO valid, nothing reported since */
static int fLatched_g;          /* a fault switched off: wait for RESET */
static int fResetRequest_g;     /* the RESET button */

static void SetOutput (tSafetyNode* pNode_p, int fOn_p, const char* pszReason_p)
{
    static const char* pszLastReason = "";

    if (fOn_p == fOutputOn_g)
    {
        if (!fOn_p && (pszReason_p != pszLastReason) && (pNode_p->m_SrdoRun != kSrdoRunNotOperational))
        {
            /* still off, for another reason now */
            SafetyLog(pNode_p, "    safe output stays OFF: %s", pszReason_p);
            pszLastReason = pszReason_p;
        }
        return;
    }
    fOutputOn_g = fOn_p;
    pszLastReason = pszReason_p;
    if (fOn_p)
    {
        SafetyLog(pNode_p, ">>> SAFE OUTPUT ON  (speed limit %u mm/s)", (unsigned) wActSpeedLimit_g);
    }
    else
    {
        SafetyLog(pNode_p, ">>> SAFE OUTPUT OFF (safe state: %s)", pszReason_p);
    }
}

void ActuatorSafeState (tSafetyNode* pNode_p, const char* pszReason_p)
{
    fSrdoValid_g = 0;
    if (pNode_p->m_SrdoRun != kSrdoRunNotOperational)
    {
        fLatched_g = 1;
    }
    SetOutput(pNode_p, 0, pszReason_p);
}

/* Called from AppSrdoEvent with a valid pair in the variables. */
void ActuatorSrdoReceived (tSafetyNode* pNode_p)
{
    /* the library has compared the frames bit by bit; the copies in RAM
     * are compared once more before they are used */
    if (((bActEStop_g ^ bActEStopInv_g) != 0xFFu) || ((wActSpeedLimit_g ^ wActSpeedLimitInv_g) != 0xFFFFu))
    {
        ActuatorSafeState(pNode_p, "normal and inverted data differ");
        return;
    }
    fSrdoValid_g = 1;
    SafetyLog(pNode_p, "    E-stop %s, speed limit %u mm/s", bActEStop_g ? "released" : "PRESSED",
              (unsigned) wActSpeedLimit_g);
}

void ActuatorOperatorReset (void)
{
    fResetRequest_g = 1;
}

void ActuatorCycle (tSafetyNode* pNode_p)
{
    const char* pszWhy = "waiting for a valid SRDO";
    int fOn;

    if (pNode_p->m_SrdoRun == kSrdoRunEnterOperational)
    {
        /* the SCT runs from here; the output waits for the first SRDO */
        pNode_p->m_SrdoRun = kSrdoRunOperational;
    }
    if (fResetRequest_g)
    {
        fResetRequest_g = 0;
        if (pNode_p->m_fSafetyFault)
        {
            SafetyLog(pNode_p, "RESET pressed: refused, a node fault is latched");
        }
        else
        {
            SafetyLog(pNode_p, "RESET pressed: restart interlock released");
            fLatched_g = 0;
        }
    }

    fOn = (pNode_p->m_SrdoRun == kSrdoRunOperational) && !pNode_p->m_fSafetyFault && !fLatched_g &&
          fSrdoValid_g && (bActEStop_g == 1);
    if (!fOn)
    {
        if (fLatched_g)
        {
            pszWhy = "latched, waiting for RESET";
        }
        else if (fSrdoValid_g && (bActEStop_g != 1))
        {
            pszWhy = "E-stop pressed";
        }
    }
    SetOutput(pNode_p, fOn, pszWhy);
}

/* For the end of the demo. */
int ActuatorOutputOn (void)
{
    return fOutputOn_g;
}
