/*
 * safety_node.c - the safety node (node-ID 3): a guard-door switch and the
 * tool position, sent in SRDO 1 once the node has a valid SRDO
 * configuration. The node does not configure its SRDO itself: it leaves
 * the factory with SRDO 1 off and a configuration tool (configurator.c)
 * writes the parameters over SDO. At kNmtEvEnterOperational the
 * application reads what it got (CcmGetSrdoParam, manual 2.9.5) and only
 * transmits when that is a valid transmit SRDO.
 */
#include "configurator.h"

#define SRDO 0x1301

/* SRDO data (objdict_safety.h) */
tObdUnsigned8  bDoorClosed_g;
tObdUnsigned8  bDoorClosedInv_g;
tObdUnsigned16 wPosition_g;
tObdUnsigned16 wPositionInv_g;

static int   fTransmit_g;           /* OPERATIONAL with a valid transmit SRDO */
static WORD  wRefreshMs_g;
static DWORD dwOperationalSince_g;
static DWORD dwLastSend_g;
static int   fFirstSent_g;
static int   fDoorOpen_g;
static WORD  wTool_g = 1000;        /* 100.0 mm */

void SafetyNodeOpenDoor (void)
{
    fDoorOpen_g = 1;
}

tCopKernel PUBLIC SafetyNodeNmtEvent (tNmtEvent NmtEvent_p)
{
    tSrdoCommuParam Commu;
    tSrdoMappParam Mapp;
    BYTE bValid = 0;
    tObdSize Size = sizeof(bValid);

    switch (NmtEvent_p)
    {
        case kNmtEvEnterOperational:
            (void) CcmReadObject(0x13FE, 0, &bValid, &Size);
            if ((CcmGetSrdoParam(SRDO, &Commu, &Mapp) == kCopSuccessful) && (Commu.m_bDirection == 1) &&
                (bValid == 0xA5))
            {
                fTransmit_g = 1;
                fFirstSent_g = 0;
                wRefreshMs_g = Commu.m_wSct;
                dwOperationalSince_g = (DWORD) TgtGetTickCount();
                Log("node 3", "OPERATIONAL: SRDO 0x%04X transmits, refresh time %u ms, %u mapped objects",
                    (unsigned) SRDO, (unsigned) Commu.m_wSct, (unsigned) Mapp.m_bNoOfMappedObjects);
            }
            else
            {
                fTransmit_g = 0;
                Log("node 3", "OPERATIONAL without a valid SRDO configuration (direction %u, 0x13FE = 0x%02X): "
                    "no safety data", (unsigned) Commu.m_bDirection, (unsigned) bValid);
            }
            break;

        case kNmtEvEnterPreOperational:
        case kNmtEvEnterStopped:
            fTransmit_g = 0;
            break;

        default:
            break;
    }
    return kCopSuccessful;
}

void SafetyNodeCycle (void)
{
    DWORD dwNow = (DWORD) TgtGetTickCount();
    tCopKernel Ret;

    if (!fTransmit_g)
    {
        return;
    }
    /* first transmission 0.5 ms x node-ID after OPERATIONAL, then every refresh time */
    if (!fFirstSent_g)
    {
        if ((dwNow - dwOperationalSince_g) < 5u * ID_SAFETY_NODE)
        {
            return;
        }
    }
    else if ((dwNow - dwLastSend_g) < (DWORD) wRefreshMs_g * 10)
    {
        return;
    }

    bDoorClosed_g = (tObdUnsigned8) (fDoorOpen_g ? 0 : 1);
    wPosition_g = wTool_g;
    bDoorClosedInv_g = (tObdUnsigned8) ~bDoorClosed_g;
    wPositionInv_g = (tObdUnsigned16) ~wPosition_g;
    Ret = CcmSendSrdo(SRDO);
    if (Ret != kCopSuccessful)
    {
        Log("node 3", "CcmSendSrdo -> 0x%04X", (unsigned) Ret);
    }
    fFirstSent_g = 1;
    dwLastSend_g = dwNow;
    if (!fDoorOpen_g)
    {
        wTool_g = (WORD) (wTool_g + 5);     /* the tool moves 0.5 mm per cycle */
    }
}

/* Status handshake of manual 2.9.1 / 2.9.2 */
void SafetyNodeSrdoEvent (WORD wSrdoCommuIndex_p)
{
    BYTE bState = 0;

    if (CcmGetSrdoState(&bState, wSrdoCommuIndex_p) == kCopSuccessful)
    {
        (void) CcmSetSrdoState((BYTE) (bState | 0x30), wSrdoCommuIndex_p);
    }
}

void SafetyNodeSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    BYTE bState = 0;

    Log("node 3", "AppSrdoError(0x%04X, 0x%04X)", (unsigned) wSrdoCommuIndex_p, (unsigned) ErrorCode_p);
    if ((CcmGetSrdoState(&bState, wSrdoCommuIndex_p) == kCopSuccessful) && ((bState & 0x30) == 0x10))
    {
        (void) CcmSetSrdoState((BYTE) ((bState | 0x30) ^ 0xC0), wSrdoCommuIndex_p);
    }
}
