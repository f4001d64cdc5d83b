/*
 * peer_harness.c - the C side of the python-canopen interoperability tests
 * (see peer_harness.h): the application of the peer node (callbacks,
 * variables) and thin wrappers that ctypes can call.
 */
#include <string.h>

#include "cdrv_sim.h"
#include "peer_harness.h"
#include "store_sim.h"

/* abPeerDynodContainer_l: peer/peer_dynod.dcf as a container (dcf2bin) */
#include "peer_dynod_container.h"

#define PEER_SIM_NODE   0u      /* the stack runs as node 0 of the simulated bus */
#define PEER_EVENTS     256u
#define PEER_SDOC_INDEX 0x1280u
#define PEER_SDOC_BUF   1024u

/* ---- application variables ------------------------------------------------------- */

tObdUnsigned8  abPeerDomain_g[PEER_DOMAIN_SIZE];
tObdUnsigned32 dwPeerUser_g;
tObdUnsigned8  bPeerRange_g;
tObdUnsigned8  bPeerSafeOut_g;
tObdUnsigned8  bPeerSafeOutInv_g;
tObdUnsigned16 wPeerSafeOut_g;
tObdUnsigned16 wPeerSafeOutInv_g;
tObdUnsigned8  bPeerSafeIn_g;
tObdUnsigned8  bPeerSafeInInv_g;
tObdUnsigned16 wPeerSafeIn_g;
tObdUnsigned16 wPeerSafeInInv_g;

/* ---- event log ----------------------------------------------------------------------- */

typedef struct
{
    BYTE  m_bKind;
    BYTE  m_bNode;
    WORD  m_wIndex;
    DWORD m_dwCode;
} tPeerEvent;

static tPeerEvent aPeerEvents_g[PEER_EVENTS];
static unsigned   uPeerEventHead_g;
static unsigned   uPeerEventCount_g;

static void PeerLog (BYTE bKind_p, BYTE bNode_p, WORD wIndex_p, DWORD dwCode_p)
{
    tPeerEvent* pEv;

    if (uPeerEventCount_g == PEER_EVENTS)
    {
        /* keep the newest events */
        uPeerEventHead_g = (uPeerEventHead_g + 1u) % PEER_EVENTS;
        uPeerEventCount_g--;
    }
    pEv = &aPeerEvents_g[(uPeerEventHead_g + uPeerEventCount_g) % PEER_EVENTS];
    pEv->m_bKind = bKind_p;
    pEv->m_bNode = bNode_p;
    pEv->m_wIndex = wIndex_p;
    pEv->m_dwCode = dwCode_p;
    uPeerEventCount_g++;
}

int PeerTakeEvent (BYTE* pbKind_p, BYTE* pbNode_p, WORD* pwIndex_p, DWORD* pdwCode_p)
{
    tPeerEvent Ev;

    if (uPeerEventCount_g == 0u)
    {
        return 0;
    }
    Ev = aPeerEvents_g[uPeerEventHead_g];
    uPeerEventHead_g = (uPeerEventHead_g + 1u) % PEER_EVENTS;
    uPeerEventCount_g--;
    if (pbKind_p != NULL)
    {
        *pbKind_p = Ev.m_bKind;
    }
    if (pbNode_p != NULL)
    {
        *pbNode_p = Ev.m_bNode;
    }
    if (pwIndex_p != NULL)
    {
        *pwIndex_p = Ev.m_wIndex;
    }
    if (pdwCode_p != NULL)
    {
        *pdwCode_p = Ev.m_dwCode;
    }
    return 1;
}

/* ---- callbacks of the application ----------------------------------------------------- */

static tCopKernel PeerInitStoreResult_g = kCopCcmStoreHwError;

/* As the SYS TEC slave: CcmInitStore at EnterInitialising, and on. */
static tCopKernel PUBLIC PeerNmtCallback (tNmtEvent NmtEvent_p)
{
    PeerLog(PEER_EV_NMT, 0, 0, (DWORD) NmtEvent_p);
    if (NmtEvent_p == kNmtEvEnterInitialising)
    {
        PeerInitStoreResult_g = CcmInitStore();
    }
    return kCopSuccessful;
}

DWORD PeerStoreUse (int fOn_p)
{
    if (!fOn_p)
    {
        SimStoreReset();
    }
    return (DWORD) CcmSetStoreDriver(fOn_p ? SimStoreDriver() : NULL);
}

DWORD PeerInitStoreResult (void)
{
    return (DWORD) PeerInitStoreResult_g;
}

static tCopKernel PUBLIC PeerHbcCallback (BYTE bNodeId_p, tNmtErrCtrlEvent HbcEvent_p)
{
    PeerLog(PEER_EV_HBC, bNodeId_p, 0, (DWORD) HbcEvent_p);
    return kCopSuccessful;
}

static tCopKernel PUBLIC PeerNmtmCallback (BYTE bNodeId_p, tNmtErrCtrlEvent NmtmEvent_p)
{
    PeerLog(PEER_EV_NMTM, bNodeId_p, 0, (DWORD) NmtmEvent_p);
    return kCopSuccessful;
}

static void PUBLIC PeerSdocFinished (tSdocCbFinishParam MEM* pParam_p)
{
    PeerLog(PEER_EV_SDOC, (BYTE) pParam_p->m_SdocState, pParam_p->m_wClientIndex, pParam_p->m_dwAbortCode);
}

tCopKernel PUBLIC AppSrdoEvent (WORD wSrdoCommuIndex_p)
{
    PeerLog(PEER_EV_SRDO, 0, wSrdoCommuIndex_p, 0);
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    BYTE bState = 0;

    PeerLog(PEER_EV_SRDO_ERROR, 0, wSrdoCommuIndex_p, (DWORD) ErrorCode_p);
    /* A safety application reacts here (safe state); the peer only
     * acknowledges: status bits 6-7 = 10 (manual 2.9.2). */
    if (CcmGetSrdoState(&bState, wSrdoCommuIndex_p) == kCopSuccessful)
    {
        (void) CcmSetSrdoState((BYTE) ((bState & 0x30u) | 0x80u), wSrdoCommuIndex_p);
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppGfcEvent (void)
{
    PeerLog(PEER_EV_GFC, 0, 0, 0);
    return kCopSuccessful;
}

tCopKernel PUBLIC AppProgMonEvent (tProgMonEvent Event_p)
{
    (void) Event_p;         /* one per SRDO and cycle: not logged */
    return kCopSuccessful;
}

/* ---- life cycle ------------------------------------------------------------------------- */

static tCcmInitParam InitParam_g;
static int           fPeerRunning_g;
static int           fPeerDynOd_g;      /* a DynBuildOd succeeded, no DynDestroyOd yet */

/* Gives a dynamic OD back before the stack goes away, so that the next
 * PeerInit starts with the static dictionary and a free pool. */
static void PeerDropDynOd (void)
{
    if (fPeerDynOd_g)
    {
        (void) DynDestroyOd();
        fPeerDynOd_g = 0;
    }
}

DWORD PeerInit (BYTE bNodeId_p)
{
    static tVarParam aVarTab[2];
    tCopKernel Ret;

    PeerDropDynOd();
    if (fPeerRunning_g)
    {
        (void) CcmShutDownCANopen();
        fPeerRunning_g = 0;
    }
    SimReset();
    uPeerEventHead_g = 0;
    uPeerEventCount_g = 0;
    memset(abPeerDomain_g, 0, sizeof(abPeerDomain_g));
    dwPeerUser_g = 0;

    Ret = SimSelectNode(PEER_SIM_NODE);
    if (Ret != kCopSuccessful)
    {
        return (DWORD) Ret;
    }
    memset(&InitParam_g, 0, sizeof(InitParam_g));
    InitParam_g.m_bInitNodeId = bNodeId_p;
    InitParam_g.m_BaudIndex = kBdi500kBaud;
    InitParam_g.m_dwAmr = 0xFFFFFFFFUL;
    InitParam_g.m_dwAcr = 0;
    InitParam_g.m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    InitParam_g.m_fpNmtEventCallback = PeerNmtCallback;
    InitParam_g.m_fpObdInitRam = ObdInitRam;
    Ret = CcmInitCANopen(&InitParam_g, kCcmFirstInstance);
    if (Ret != kCopSuccessful)
    {
        return (DWORD) Ret;
    }
    fPeerRunning_g = 1;

    memset(aVarTab, 0, sizeof(aVarTab));
    aVarTab[0].m_bValidFlag = kVarValidSize | kVarValidData;
    aVarTab[0].m_wIndex = 0x2002;
    aVarTab[0].m_bSubindex = 0x00;
    aVarTab[0].m_Size = (tObdSize) sizeof(abPeerDomain_g);
    aVarTab[0].m_pData = abPeerDomain_g;
    aVarTab[1].m_bValidFlag = kVarValidSize | kVarValidData;
    aVarTab[1].m_wIndex = 0x2003;
    aVarTab[1].m_bSubindex = 0x00;
    aVarTab[1].m_Size = (tObdSize) sizeof(dwPeerUser_g);
    aVarTab[1].m_pData = &dwPeerUser_g;
    Ret = CcmDefineVarTab(aVarTab, 2);
    if (Ret != kCopSuccessful)
    {
        return (DWORD) Ret;
    }
    /* The USERDEF default reaches the variable with the next reset; set it
     * now so that a fresh node reads 0x5EED0001 like the EDS says. */
    dwPeerUser_g = 0x5EED0001UL;

    Ret = CcmInitHbcEx(PeerHbcCallback);
    if (Ret != kCopSuccessful)
    {
        return (DWORD) Ret;
    }
    return (DWORD) CcmInitNmtmEx(PeerNmtmCallback);
}

DWORD PeerConnect (void)
{
    return (DWORD) CcmConnectToNet();
}

DWORD PeerShutdown (void)
{
    PeerDropDynOd();
    fPeerRunning_g = 0;
    return (DWORD) CcmShutDownCANopen();
}

DWORD PeerProcess (void)
{
    return (DWORD) CcmProcess();
}

DWORD PeerProcessLssInitState (void)
{
    return (DWORD) CcmProcessLssInitState();
}

BYTE PeerNodeId (void)
{
    return CcmLsssGetNodeId();
}

DWORD PeerStackVersion (void)
{
    return CopGetStackVersion();
}

/* ---- bus and clock -------------------------------------------------------------------------- */

void PeerAdvanceTicks (DWORD dwTicks_p)
{
    SimAdvanceTicks(dwTicks_p);
}

DWORD PeerTicks (void)
{
    return (DWORD) TgtGetTickCount();
}

int PeerInject (DWORD dwId_p, BYTE bRtr_p, BYTE bDlc_p, CONST BYTE* pbData_p)
{
    return SimInject(dwId_p, bRtr_p, bDlc_p, pbData_p);
}

int PeerTakeSent (DWORD* pdwId_p, BYTE* pbRtr_p, BYTE* pbDlc_p, BYTE* pbData_p)
{
    return SimTakeSent(pdwId_p, pbRtr_p, pbDlc_p, pbData_p);
}

void PeerTrace (int fOn_p)
{
    SimSetTrace(fOn_p);
}

/* ---- dictionary and NMT ------------------------------------------------------------------------ */

DWORD PeerRead (WORD wIndex_p, BYTE bSub_p, void* pData_p, DWORD* pdwSize_p)
{
    tObdSize Size;
    tCopKernel Ret;

    if (pdwSize_p == NULL)
    {
        return (DWORD) kCopInvalidParam;
    }
    Size = (tObdSize) *pdwSize_p;
    Ret = CcmReadObject(wIndex_p, bSub_p, pData_p, &Size);
    *pdwSize_p = (DWORD) Size;
    return (DWORD) Ret;
}

DWORD PeerWrite (WORD wIndex_p, BYTE bSub_p, CONST void* pData_p, DWORD dwSize_p)
{
    return (DWORD) CcmWriteObject(wIndex_p, bSub_p, pData_p, (tObdSize) dwSize_p);
}

BYTE PeerNodeState (void)
{
    return CcmObdGetNodeState();
}

DWORD PeerNmtExec (WORD wCommand_p)
{
    return (DWORD) CcmNmtsExecCommand((tNmtCommand) wCommand_p);
}

DWORD PeerSendEmergency (WORD wErrorCode_p, BYTE bErrorRegister_p, CONST BYTE* pbManufacturer_p)
{
    tEmcParam Emcy;

    memset(&Emcy, 0, sizeof(Emcy));
    Emcy.m_wEmcyErrorCode = wErrorCode_p;
    Emcy.m_bErrorRegister = bErrorRegister_p;
    if (pbManufacturer_p != NULL)
    {
        memcpy(Emcy.m_abManufactErrorCode, pbManufacturer_p, sizeof(Emcy.m_abManufactErrorCode));
    }
    return (DWORD) CcmSendEmergency(&Emcy);
}

/* The part tables ObdInitRam hands the stack (the tables are constant, so
 * asking for them again gives the very tables the stack uses). */
static CONST tObdSubEntry ROM* PeerOdFind (unsigned uEntry_p, WORD* pwIndex_p)
{
    tObdRamParam Ram;
    tObdEntryPtr apPart[4];
    unsigned uPart;
    unsigned n = 0;

    memset(&Ram, 0, sizeof(Ram));
    if (ObdInitRam(&Ram) != kCopSuccessful)
    {
        return NULL;
    }
    apPart[0] = Ram.m_pGenericPart;
    apPart[1] = Ram.m_pManufacturerPart;
    apPart[2] = Ram.m_pDevicePart;
    apPart[3] = Ram.m_pUserPart;
    for (uPart = 0; uPart < 4u; uPart++)
    {
        tObdEntryPtr pEntry = apPart[uPart];

        for (; (pEntry != NULL) && (pEntry->m_wIndex != OBD_TABLE_INDEX_END); pEntry++)
        {
            unsigned uSub;

            for (uSub = 0; uSub < pEntry->m_bCount; uSub++)
            {
                if (n == uEntry_p)
                {
                    *pwIndex_p = pEntry->m_wIndex;
                    return &pEntry->m_pSubIndex[uSub];
                }
                n++;
            }
        }
    }
    return NULL;
}

int PeerOdEntry (unsigned uEntry_p, WORD* pwIndex_p, BYTE* pbSub_p, BYTE* pbType_p,
                 BYTE* pbAccess_p, BYTE* pbKind_p, DWORD* pdwSize_p)
{
    WORD wIndex = 0;
    CONST tObdSubEntry ROM* pSub = PeerOdFind(uEntry_p, &wIndex);

    if ((pSub == NULL) || (pwIndex_p == NULL) || (pbSub_p == NULL) || (pbType_p == NULL) ||
        (pbAccess_p == NULL) || (pbKind_p == NULL) || (pdwSize_p == NULL))
    {
        return 0;
    }
    *pwIndex_p = wIndex;
    *pbSub_p = pSub->m_bSubIndex;
    *pbType_p = pSub->m_bType;
    *pbAccess_p = pSub->m_bAccess;
    *pbKind_p = pSub->m_bKind;
    *pdwSize_p = pSub->m_dwSize;
    return 1;
}

int PeerOdLimits (WORD wIndex_p, BYTE bSub_p, BYTE* pbLow_p, BYTE* pbHigh_p, DWORD dwCap_p)
{
    unsigned n;

    for (n = 0;; n++)
    {
        WORD wIndex = 0;
        CONST tObdSubEntry ROM* pSub = PeerOdFind(n, &wIndex);
        CONST BYTE ROM* pbValues;

        if (pSub == NULL)
        {
            return -1;
        }
        if ((wIndex != wIndex_p) || (pSub->m_bSubIndex != bSub_p))
        {
            continue;
        }
        if (((pSub->m_bAccess & kObdAccRange) == 0) || (pSub->m_pDefault == NULL) ||
            (pSub->m_dwSize > dwCap_p) || (pbLow_p == NULL) || (pbHigh_p == NULL))
        {
            return -1;
        }
        /* {default, low, high}, each m_dwSize bytes (objdef.h) */
        pbValues = (CONST BYTE ROM*) pSub->m_pDefault;
        memcpy(pbLow_p, pbValues + pSub->m_dwSize, pSub->m_dwSize);
        memcpy(pbHigh_p, pbValues + 2u * pSub->m_dwSize, pSub->m_dwSize);
        return (int) pSub->m_dwSize;
    }
}

/* ---- dynamic object dictionary ----------------------------------------------------------------- */

BYTE abPeerProcessImage_g[PEER_PROCESS_IMAGE_SIZE];

DWORD PeerDynBuildOd (DWORD* padwPi_p)
{
    /* DynBuildOd takes a non-const pointer; it only reads the container */
    static BYTE abContainer[sizeof(abPeerDynodContainer_l)];
    tProcessImageDscrpt Pi;
    tCopKernel Ret;

    memcpy(abContainer, abPeerDynodContainer_l, sizeof(abContainer));
    memset(abPeerProcessImage_g, 0, sizeof(abPeerProcessImage_g));
    memset(&Pi, 0, sizeof(Pi));
    Pi.m_pbProcessImage = abPeerProcessImage_g;
    Pi.m_dwProcessImageSize = sizeof(abPeerProcessImage_g);
    Ret = DynBuildOd(abContainer, &Pi);
    if (Ret != kCopSuccessful)
    {
        return (DWORD) Ret;
    }
    fPeerDynOd_g = 1;
    if (padwPi_p != NULL)
    {
        padwPi_p[0] = Pi.m_dwProcessImageSize;
        padwPi_p[1] = Pi.m_dwDynPIOffsetIn;
        padwPi_p[2] = Pi.m_dwDynPISizeIn;
        padwPi_p[3] = Pi.m_dwDynPIOffsetOut;
        padwPi_p[4] = Pi.m_dwDynPISizeOut;
    }
    return (DWORD) kCopSuccessful;
}

DWORD PeerDynDestroyOd (void)
{
    fPeerDynOd_g = 0;
    return (DWORD) DynDestroyOd();
}

DWORD PeerDynContainerSize (void)
{
    return (DWORD) sizeof(abPeerDynodContainer_l);
}

/* ---- heartbeat consumer and NMT master ------------------------------------------------------------ */

DWORD PeerHbcDefine (BYTE bNode_p, WORD wTimeMs_p, BYTE bSubindex_p)
{
    tHbcProdParam Producer;

    Producer.wHeartbeatTime_p = wTimeMs_p;
    Producer.bProducerNodeId_p = bNode_p;
    Producer.bSubindex_p = bSubindex_p;
    return (DWORD) CcmHbcDefineProducerTab(&Producer, 1);
}

DWORD PeerHbcNodeState (BYTE bNode_p, BYTE* pbState_p)
{
    return (DWORD) CcmHbcGetNodeState(bNode_p, pbState_p);
}

DWORD PeerNmtmCommand (BYTE bNode_p, WORD wCommand_p)
{
    return (DWORD) CcmSendNmtCommand(bNode_p, (tNmtCommand) wCommand_p);
}

/* ---- SDO client ----------------------------------------------------------------------------------- */

static BYTE abPeerSdocBuf_g[PEER_SDOC_BUF];

DWORD PeerSdocDefine (BYTE bServer_p, DWORD dwTxCobId_p, DWORD dwRxCobId_p, DWORD dwTimeoutTicks_p)
{
    tSdocParam Client;

    memset(&Client, 0, sizeof(Client));
    Client.m_bValidFlags = kSdocValidAllParams;
    Client.m_TimeOut = (tTime) dwTimeoutTicks_p;
    Client.m_wClientIndex = PEER_SDOC_INDEX;
    Client.m_dwRxCanId = dwRxCobId_p;
    Client.m_dwTxCanId = dwTxCobId_p;
    Client.m_bServerNodeId = bServer_p;
    return (DWORD) CcmSdocDefineClientTab(&Client, 1);
}

DWORD PeerSdocStart (WORD wIndex_p, BYTE bSub_p, int iType_p, CONST BYTE* pbData_p, DWORD dwLen_p)
{
    tSdocTransferParam Transfer;

    if (dwLen_p > sizeof(abPeerSdocBuf_g))
    {
        return (DWORD) kCopInvalidParam;
    }
    memset(abPeerSdocBuf_g, 0, sizeof(abPeerSdocBuf_g));
    if (((iType_p == kSdocTypeSegDown) || (iType_p == kSdocTypeBlockDown)) && (pbData_p != NULL))
    {
        memcpy(abPeerSdocBuf_g, pbData_p, dwLen_p);
    }
    memset(&Transfer, 0, sizeof(Transfer));
    Transfer.m_wClientIndex = PEER_SDOC_INDEX;
    Transfer.m_wObjIndex = wIndex_p;
    Transfer.m_bObjSubIndex = bSub_p;
    Transfer.m_pData = abPeerSdocBuf_g;
    Transfer.m_DataLen = (tObdSize) dwLen_p;
    Transfer.m_TimeOut = 0;     /* the channel's timeout */
    Transfer.m_SdocType = (tSdocType) iType_p;
    Transfer.m_pfnCbFinished = PeerSdocFinished;
    return (DWORD) CcmSdocStartTransfer(&Transfer);
}

DWORD PeerSdocState (DWORD* pdwState_p, DWORD* pdwAbort_p)
{
    tSdocState State = 0;
    DWORD dwAbort = 0;
    tCopKernel Ret = CcmSdocGetState(PEER_SDOC_INDEX, &State, &dwAbort);

    if (pdwState_p != NULL)
    {
        *pdwState_p = (DWORD) State;
    }
    if (pdwAbort_p != NULL)
    {
        *pdwAbort_p = dwAbort;
    }
    return (DWORD) Ret;
}

DWORD PeerSdocBytes (DWORD* pdwBytes_p)
{
    return (DWORD) SdocGetTransmittedBytes(PEER_SDOC_INDEX, pdwBytes_p);
}

DWORD PeerSdocData (BYTE* pbOut_p, DWORD dwMax_p)
{
    DWORD n = (dwMax_p < sizeof(abPeerSdocBuf_g)) ? dwMax_p : (DWORD) sizeof(abPeerSdocBuf_g);

    if (pbOut_p == NULL)
    {
        return 0;
    }
    memcpy(pbOut_p, abPeerSdocBuf_g, n);
    return n;
}

/* ---- SRDO --------------------------------------------------------------------------------------------- */

DWORD PeerSendSrdo (WORD wIndex_p)
{
    return (DWORD) CcmSendSrdo(wIndex_p);
}

DWORD PeerCalcSrdoCrc (WORD wIndex_p, WORD* pwCrc_p)
{
    return (DWORD) CcmCalcSrdoCrc(wIndex_p, pwCrc_p);
}

DWORD PeerCheckSrdoConfig (WORD* pwIndex_p)
{
    return (DWORD) CcmCheckSrdoConfig(pwIndex_p);
}

DWORD PeerSrdoState (WORD wIndex_p, BYTE* pbState_p)
{
    return (DWORD) CcmGetSrdoState(pbState_p, wIndex_p);
}
