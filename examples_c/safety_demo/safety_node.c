/*
 * safety_node.c - the parts of the safety application both boards share:
 * the SYS TEC callbacks of the SRDO module (called by name from inside
 * CcmProcess / CcmSendSrdo), the NMT callback that configures the SRDO,
 * the program-flow monitor and the checks of the main loop.
 *
 * The reaction to an error is role specific: the actuator switches its
 * safe output off (actuator.c), the sensor stops transmitting, so that
 * every receiver runs into its SCT and switches off too.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "cdrv_sim.h"
#include "safety_node.h"

/* ---- helpers --------------------------------------------------------------- */

tSafetyNode* SafetyCurrentNode (void)
{
    BYTE bSim = SimSelectedNode();
    unsigned i;

    for (i = 0; i < 2; i++)
    {
        if (aSafetyNode_g[i].m_bSimNode == bSim)
        {
            return &aSafetyNode_g[i];
        }
    }
    return &aSafetyNode_g[0];
}

void SafetyLog (const tSafetyNode* pNode_p, const char* pszFormat_p, ...)
{
    va_list Args;
    DWORD dwTicks = (DWORD) TgtGetTickCount();

    printf("[%4lu.%lu ms] %-8s ", (unsigned long) (dwTicks / 10), (unsigned long) (dwTicks % 10),
           pNode_p->m_pszName);
    va_start(Args, pszFormat_p);
    vprintf(pszFormat_p, Args);
    va_end(Args);
    printf("\n");
}

const char* SafetyKernelName (tCopKernel Ret_p)
{
    switch (Ret_p)
    {
        case kCopSuccessful:          return "kCopSuccessful";
        case kCopSrdoNotExist:        return "kCopSrdoNotExist";
        case kCopSrdoCfgTimingError:  return "kCopSrdoCfgTimingError";
        case kCopSrdoCfgIdError:      return "kCopSrdoCfgIdError";
        case kCopSrdoCfgCrcError:     return "kCopSrdoCfgCrcError";
        case kCopSrdoNmtError:        return "kCopSrdoNmtError";
        case kCopSrdoInvalidCfg:      return "kCopSrdoInvalidCfg";
        case kCopSrdoInvalid:         return "kCopSrdoInvalid";
        case kCopSrdoRxTxConflict:    return "kCopSrdoRxTxConflict";
        case kCopSrdoNotInOrder:      return "kCopSrdoNotInOrder";
        case kCopSrdoSctTimeout:      return "kCopSrdoSctTimeout";
        case kCopSrdoSrvtTimeout:     return "kCopSrdoSrvtTimeout";
        case kCopSrdoDlcNotValid:     return "kCopSrdoDlcNotValid";
        case kCopSrdoErrorMapp:       return "kCopSrdoErrorMapp";
        case kCopSrdoDataError:       return "kCopSrdoDataError";
        case kCopSrdoLengthExceeded:  return "kCopSrdoLengthExceeded";
        case kCopSrdoNotHandledInApp: return "kCopSrdoNotHandledInApp";
        case kCopSrdoOverrun:         return "kCopSrdoOverrun";
        default:                      return "(other code)";
    }
}

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
        default:                           return "unknown NMT event";
    }
}

/* A fault the node found itself (program flow, status byte, configuration):
 * latched, only a restart of the board clears it. */
static void SafetyFault (tSafetyNode* pNode_p, const char* pszReason_p)
{
    if (!pNode_p->m_fSafetyFault)
    {
        SafetyLog(pNode_p, "SAFETY FAULT: %s", pszReason_p);
    }
    pNode_p->m_fSafetyFault = 1;
    if (pNode_p->m_Role == kRoleActuator)
    {
        ActuatorSafeState(pNode_p, pszReason_p);
    }
}

/* ---- SRDO callbacks of the library (manual 2.9) ------------------------------ */

/* A transfer without error (manual 2.9.1): the status must say "ok"; then
 * the data are used and the status becomes "processed". */
tCopKernel PUBLIC AppSrdoEvent (WORD wSrdoCommuIndex_p)
{
    tSafetyNode* pNode = SafetyCurrentNode();
    BYTE bSrdoState = 0;
    tCopKernel Ret;

    pNode->m_uCycleSrdoEvents++;
    pNode->m_fSrdoSeen = 1;
    Ret = CcmGetSrdoState(&bSrdoState, wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        SafetyFault(pNode, "CcmGetSrdoState failed in AppSrdoEvent");
        return kCopSuccessful;
    }
    if ((bSrdoState & SRDO_TRANSFER_MASK) != SRDO_TRANSFER_OK)
    {
        SafetyFault(pNode, "AppSrdoEvent with a status that does not say ok");
        return kCopSuccessful;
    }

    SafetyLog(pNode, "AppSrdoEvent(0x%04X): %s, status 0x%02X -> 0x%02X", (unsigned) wSrdoCommuIndex_p,
              (pNode->m_Role == kRoleActuator) ? "received" : "sent",
              (unsigned) bSrdoState, (unsigned) (bSrdoState | SRDO_PROCESSED));
    if (pNode->m_Role == kRoleActuator)
    {
        ActuatorSrdoReceived(pNode);
    }

    Ret = CcmSetSrdoState((BYTE) (bSrdoState | SRDO_PROCESSED), wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        SafetyFault(pNode, "CcmSetSrdoState failed in AppSrdoEvent");
    }
    return kCopSuccessful;
}

/* A faulty transfer (manual 2.9.2): the library has set bits 4-5 to
 * "failed" and bits 6-7 to 01; the application reacts, marks the SRDO
 * processed and toggles bits 6-7 to 10 so the library sees it handled. */
tCopKernel PUBLIC AppSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    tSafetyNode* pNode = SafetyCurrentNode();
    BYTE bSrdoState = 0;
    BYTE bBefore;
    tCopKernel Ret;

    pNode->m_fSrdoSeen = 1;
    if (ErrorCode_p == kCopSrdoNotHandledInApp)
    {
        /* the library's verdict on an earlier AppSrdoError of ours */
        SafetyFault(pNode, "the library reports an SRDO error as not handled");
        return kCopSuccessful;
    }
    pNode->m_uCycleSrdoErrors++;

    Ret = CcmGetSrdoState(&bSrdoState, wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        SafetyFault(pNode, "CcmGetSrdoState failed in AppSrdoError");
        return kCopSuccessful;
    }
    bBefore = bSrdoState;
    if ((bSrdoState & SRDO_TRANSFER_MASK) == SRDO_TRANSFER_FAILED)
    {
        SafetyLog(pNode, "AppSrdoError(0x%04X, %s)", (unsigned) wSrdoCommuIndex_p, SafetyKernelName(ErrorCode_p));
        if (pNode->m_Role == kRoleActuator)
        {
            ActuatorSafeState(pNode, SafetyKernelName(ErrorCode_p));
        }
        bSrdoState |= SRDO_PROCESSED;
        bSrdoState ^= SRDO_ERROR_TOGGLE;
    }
    else
    {
        SafetyFault(pNode, "AppSrdoError with a status that does not say failed");
    }

    Ret = CcmSetSrdoState(bSrdoState, wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        SafetyFault(pNode, "CcmSetSrdoState failed in AppSrdoError");
    }
    SafetyLog(pNode, "status handshake: 0x%02X -> 0x%02X (bits 6-7: 01 -> 10, handled)",
              (unsigned) bBefore, (unsigned) bSrdoState);
    return kCopSuccessful;
}

/* A global fail-safe command (manual 2.9.3). */
tCopKernel PUBLIC AppGfcEvent (void)
{
    tSafetyNode* pNode = SafetyCurrentNode();

    SafetyLog(pNode, "AppGfcEvent: global fail-safe command");
    if (pNode->m_Role == kRoleActuator)
    {
        ActuatorSafeState(pNode, "GFC");
    }
    return kCopSuccessful;
}

/* Program-flow monitor (manual 2.9.4): every event adds its weight; the
 * main loop compares the sum of one cycle with what that cycle must have
 * done (SafetyProgMonCheck). */
enum
{
    kPMonSctChecked                  = 0x0001,
    kPMonSctNotCheckedItIsTx         = 0x0002,
    kPMonSctNotCheckedItIsInvalid    = 0x0004,
    kPMonSctNotCheckedNotOperational = 0x0008,
    kPMonSrdoError                   = 0x0010,
    kPMonSrdoReceived                = 0x0020,
    kPMonSrdoTransmitted             = 0x0040
};

tCopKernel PUBLIC AppProgMonEvent (tProgMonEvent Event_p)
{
    tSafetyNode* pNode = SafetyCurrentNode();

    switch (Event_p)
    {
        case kSrdoPMEvSctChecked:                  pNode->m_wPMonValue += kPMonSctChecked; break;
        case kSrdoPMEvSctNotCheckedItIsTx:         pNode->m_wPMonValue += kPMonSctNotCheckedItIsTx; break;
        case kSrdoPMEvSctNotCheckedItIsInvalid:    pNode->m_wPMonValue += kPMonSctNotCheckedItIsInvalid; break;
        case kSrdoPMEvSctNotCheckedNotOperational: pNode->m_wPMonValue += kPMonSctNotCheckedNotOperational; break;
        case kSrdoPMEvSrdoError:                   pNode->m_wPMonValue += kPMonSrdoError; break;
        case kSrdoPMEvSrdoReceived:                pNode->m_wPMonValue += kPMonSrdoReceived; break;
        case kSrdoPMEvSrdoTransmitted:             pNode->m_wPMonValue += kPMonSrdoTransmitted; break;
        default:                                   pNode->m_wPMonValue += 0x8000; break;   /* never expected */
    }
    return kCopSuccessful;
}

/* ---- NMT callback (manual 2.9.5) -------------------------------------------- */

static tCopKernel WriteObject (tSafetyNode* pNode_p, WORD wIndex_p, BYTE bSub_p, const void* pData_p, tObdSize Size_p)
{
    tCopKernel Ret = CcmWriteObject(wIndex_p, bSub_p, pData_p, Size_p);

    if (Ret != kCopSuccessful)
    {
        SafetyLog(pNode_p, "CcmWriteObject(0x%04X/%u) refused: 0x%04X %s", (unsigned) wIndex_p, (unsigned) bSub_p,
                  (unsigned) Ret, SafetyKernelName(Ret));
    }
    return Ret;
}

/* Reset communication reloaded the factory SRDO parameters: write the ones
 * this application owns, the CRC over them, and declare the configuration
 * valid (the library runs its configuration check on that write). */
static tCopKernel ConfigureSrdo (tSafetyNode* pNode_p)
{
    const tSafetySrdoParam* pParam = &pNode_p->m_Srdo;
    BYTE bGfcOn = 1;
    BYTE bValid = 0xA5;
    WORD wCrc = 0;
    tCopKernel Ret;

    pNode_p->m_fConfigured = 0;
    Ret = WriteObject(pNode_p, 0x1300, 0, &bGfcOn, sizeof(bGfcOn));
    /* COB-IDs first: they may only change while the direction is 0 */
    if (Ret == kCopSuccessful) Ret = WriteObject(pNode_p, SAFETY_SRDO, 5, &pParam->m_dwCobId1, sizeof(DWORD));
    if (Ret == kCopSuccessful) Ret = WriteObject(pNode_p, SAFETY_SRDO, 6, &pParam->m_dwCobId2, sizeof(DWORD));
    if (Ret == kCopSuccessful) Ret = WriteObject(pNode_p, SAFETY_SRDO, 2, &pParam->m_wSctMs, sizeof(WORD));
    if (Ret == kCopSuccessful) Ret = WriteObject(pNode_p, SAFETY_SRDO, 3, &pParam->m_bSrvtMs, sizeof(BYTE));
    if (Ret == kCopSuccessful) Ret = WriteObject(pNode_p, SAFETY_SRDO, 1, &pParam->m_bDirection, sizeof(BYTE));
    if (Ret == kCopSuccessful)
    {
        Ret = CcmCalcSrdoCrc(SAFETY_SRDO, &wCrc);
    }
    if (Ret == kCopSuccessful) Ret = WriteObject(pNode_p, 0x13FF, 1, &wCrc, sizeof(wCrc));
    if (Ret == kCopSuccessful) Ret = WriteObject(pNode_p, 0x13FE, 0, &bValid, sizeof(bValid));
    if (Ret == kCopSuccessful)
    {
        pNode_p->m_wConfiguredCrc = wCrc;
        pNode_p->m_fConfigured = 1;
        SafetyLog(pNode_p, "SRDO 0x%04X: direction %u, %s %u ms, SRVT %u ms, COB-IDs 0x%03lX/0x%03lX",
                  (unsigned) SAFETY_SRDO, (unsigned) pParam->m_bDirection,
                  (pParam->m_bDirection == 1) ? "refresh time" : "SCT", (unsigned) pParam->m_wSctMs,
                  (unsigned) pParam->m_bSrvtMs, (unsigned long) pParam->m_dwCobId1, (unsigned long) pParam->m_dwCobId2);
        SafetyLog(pNode_p, "CRC 0x%04X -> 0x13FF/1, 0xA5 -> 0x13FE: configuration valid", (unsigned) wCrc);
    }
    return Ret;
}

static tCopKernel PUBLIC AppCbNmtEvent (tNmtEvent NmtEvent_p)
{
    tSafetyNode* pNode = SafetyCurrentNode();
    tSrdoMappParam Mapp;
    tCopKernel Ret;

    SafetyLog(pNode, "AppCbNmtEvent(%s)", NmtEventName(NmtEvent_p));
    switch (NmtEvent_p)
    {
        case kNmtEvResetCommunication:
            Ret = ConfigureSrdo(pNode);
            if (Ret != kCopSuccessful)
            {
                /* no valid configuration: the SRDO will not run, the
                 * actuator keeps its output off */
                SafetyLog(pNode, "SRDO configuration failed: 0x%04X %s", (unsigned) Ret, SafetyKernelName(Ret));
            }
            break;

        case kNmtEvEnterPreOperational:
        case kNmtEvEnterStopped:
            /* SRDOs must not be processed any more */
            pNode->m_SrdoRun = kSrdoRunNotOperational;
            if (pNode->m_Role == kRoleActuator)
            {
                ActuatorSafeState(pNode, "not OPERATIONAL");
            }
            break;

        case kNmtEvEnterOperational:
            /* read what the SRDO runs with now (parameters may have come
             * over SDO as well) */
            Ret = CcmGetSrdoParam(SAFETY_SRDO, &pNode->m_SrdoCommu, &Mapp);
            if ((Ret != kCopSuccessful) || !pNode->m_fConfigured ||
                (pNode->m_SrdoCommu.m_bDirection != pNode->m_Srdo.m_bDirection) || (Mapp.m_bNoOfMappedObjects != 4))
            {
                SafetyFault(pNode, "SRDO not configured");
                break;
            }
            SafetyLog(pNode, "CcmGetSrdoParam: direction %u, %s %u ms, %u mapped objects",
                      (unsigned) pNode->m_SrdoCommu.m_bDirection,
                      (pNode->m_SrdoCommu.m_bDirection == 1) ? "refresh time" : "SCT",
                      (unsigned) pNode->m_SrdoCommu.m_wSct, (unsigned) Mapp.m_bNoOfMappedObjects);
            pNode->m_dwOperationalSince = (DWORD) TgtGetTickCount();
            pNode->m_fSrdoSeen = 0;
            pNode->m_SrdoRun = kSrdoRunEnterOperational;
            break;

        default:
            break;
    }
    return kCopSuccessful;
}

/* ---- start-up and main loop ------------------------------------------------------ */

tCopKernel SafetyNodeStart (tSafetyNode* pNode_p)
{
    tCcmInitParam* pInit = &pNode_p->m_InitParam;
    tCopKernel Ret;

    SimSelectNode(pNode_p->m_bSimNode);
    memset(pInit, 0, sizeof(*pInit));
    pInit->m_bInitNodeId = pNode_p->m_bNodeId;
    pInit->m_BaudIndex = kBdi500kBaud;
    (void) TgtGetBitrateTable(0, &pInit->m_pBdiTable, &pInit->m_wSizeOfBdiTab);
    pInit->m_dwAmr = 0xFFFFFFFFUL;
    pInit->m_dwAcr = 0;
    pInit->m_HwParam.m_ZeroBasedCanNo.m_bCanNo = 0;
    pInit->m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    pInit->m_fpNmtEventCallback = AppCbNmtEvent;
    pInit->m_fpObdInitRam = pNode_p->m_fpObdInitRam;

    Ret = CcmInitCANopen(pInit, kCcmFirstInstance);
    if (Ret == kCopSuccessful)
    {
        Ret = CcmConnectToNet();
    }
    if (Ret != kCopSuccessful)
    {
        SafetyLog(pNode_p, "start-up failed: 0x%04X", (unsigned) Ret);
    }
    return Ret;
}

/* What this cycle's events must add up to (manual 2.9.4): the SCT step of
 * the library's cycle once, plus one weight per SRDO the application saw
 * succeed or fail. */
static void SafetyProgMonCheck (tSafetyNode* pNode_p)
{
    WORD wExpected;

    if (CcmObdGetNodeState() != kNodeStateOperational)
    {
        wExpected = kPMonSctNotCheckedNotOperational;
    }
    else if ((pNode_p->m_SrdoRun == kSrdoRunNotOperational) || !pNode_p->m_fConfigured)
    {
        wExpected = kPMonSctNotCheckedItIsInvalid;
    }
    else if (pNode_p->m_Role == kRoleActuator)
    {
        wExpected = kPMonSctChecked;
    }
    else
    {
        wExpected = kPMonSctNotCheckedItIsTx;
    }
    wExpected = (WORD) (wExpected + pNode_p->m_uCycleSrdoErrors * kPMonSrdoError +
                        pNode_p->m_uCycleSrdoEvents *
                        ((pNode_p->m_Role == kRoleActuator) ? kPMonSrdoReceived : kPMonSrdoTransmitted));
    if (pNode_p->m_wPMonValue != wExpected)
    {
        char szWhy[80];
        snprintf(szWhy, sizeof(szWhy), "program flow: checksum 0x%04X, expected 0x%04X",
                 (unsigned) pNode_p->m_wPMonValue, (unsigned) wExpected);
        SafetyFault(pNode_p, szWhy);
    }
}

/* Outside the callbacks the status must always read "processed" once an
 * SRDO has been reported (manual 2.5.3); anything else means an event was
 * not handled. */
static void SafetyStatusCheck (tSafetyNode* pNode_p)
{
    BYTE bSrdoState = 0;

    if (!pNode_p->m_fSrdoSeen || (pNode_p->m_SrdoRun == kSrdoRunNotOperational))
    {
        return;
    }
    if ((CcmGetSrdoState(&bSrdoState, SAFETY_SRDO) != kCopSuccessful) ||
        ((bSrdoState & SRDO_TRANSFER_MASK) != SRDO_PROCESSED))
    {
        SafetyFault(pNode_p, "SRDO status not processed in the main loop");
    }
}

/* Diagnostic test interval (manual 2.8.2): the configuration is checked
 * again; an error while 0x13FE says valid means the safe state. */
static void SafetyDiagnostics (tSafetyNode* pNode_p)
{
    DWORD dwNow = (DWORD) TgtGetTickCount();
    WORD wBadIndex = 0;
    BYTE bValid = 0;
    tObdSize Size = sizeof(bValid);
    tCopKernel Ret;

    if ((dwNow - pNode_p->m_dwLastDiag) < (DWORD) SAFETY_DIAG_MS * 10)
    {
        return;
    }
    pNode_p->m_dwLastDiag = dwNow;
    Ret = CcmCheckSrdoConfig(&wBadIndex);
    (void) CcmReadObject(0x13FE, 0, &bValid, &Size);
    if (Ret == kCopSuccessful)
    {
        SafetyLog(pNode_p, "diagnostics: CcmCheckSrdoConfig ok, 0x13FE = 0x%02X", (unsigned) bValid);
    }
    else
    {
        SafetyLog(pNode_p, "diagnostics: CcmCheckSrdoConfig -> %s at 0x%04X, 0x13FE = 0x%02X",
                  SafetyKernelName(Ret), (unsigned) wBadIndex, (unsigned) bValid);
        SafetyFault(pNode_p, (bValid == 0xA5) ? "configuration check failed" : "no valid SRDO configuration");
    }
}

void SafetyNodeCycle (tSafetyNode* pNode_p, void (*pfnApp_p) (tSafetyNode* pNode_p))
{
    tCopKernel Ret;

    SimSelectNode(pNode_p->m_bSimNode);
    pNode_p->m_wPMonValue = 0;
    pNode_p->m_uCycleSrdoEvents = 0;
    pNode_p->m_uCycleSrdoErrors = 0;

    Ret = CcmProcess();
    if (Ret == kCopSrdoNotHandledInApp)
    {
        SafetyFault(pNode_p, "CcmProcess: kCopSrdoNotHandledInApp");
    }
    pfnApp_p(pNode_p);

    SafetyProgMonCheck(pNode_p);
    SafetyStatusCheck(pNode_p);
    SafetyDiagnostics(pNode_p);
}
