/*
 * test_multi.c - two stack instances in one program (c_tests/cfg_multi,
 * COP_MAX_INSTANCES 2): every Ccm* function and every callback takes the
 * instance handle, the module functions (Srdo*) the instance pointer.
 *
 *   instance A: simulated controller 0, objdict_all.h (ObdInitRam),
 *               node-ID 2; SRDO 1 transmits 0x2040/0x2041 on 0x101/0x102;
 *   instance B: simulated controller 1, objdict_srdo_peer.h
 *               (ObdInitRamSrdoPeer), node-ID 5; SRDO 1 receives 0x101/0x102
 *               into bPeerIn_g / bPeerInInv_g.
 *
 * Checked: the codes of CcmInitCANopen (kCopInvalidInstanceParam for a NULL
 * handle pointer, kCopInvalidParam for an unknown tCcmInitCall,
 * kCopNoFreeInstance when both instances exist); each instance its own
 * dictionary, node-ID, driver instance (controller) and callbacks, each
 * callback with its own instance's handle; an SRDO from A received by B
 * with the manual's AppSrdoEvent handshake (2.9.1) through B's handle; a
 * call into the other instance from inside a callback; every exported
 * function with a handle of no instance (kCopIllegalInstance) and with the
 * handle of a shut-down instance; the two instances on one shared bus and
 * on two separate buses.
 */
#include <string.h>

#include "test_check.h"
#include "cdrv_sim.h"

#if (COP_MAX_INSTANCES != 2)
#error "test_multi.c is built with c_tests/cfg_multi (COP_MAX_INSTANCES 2)"
#endif

#define SIM_A   0
#define SIM_B   1
#define ID_A    2
#define ID_B    5
#define NO_HDL  2       /* a handle of no slot (>= COP_MAX_INSTANCES) */

tCopKernel PUBLIC ObdInitRam (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamSrdoPeer (void MEM* pInitParam_p);

/* The variables objdict_all.h names (EXTVAR, EXTARRAY). */
tObdUnsigned32 dwTestExtVar_g;
tObdUnsigned8  bTestExtVarRg_g;
tObdUnsigned16 wTestExtNoInit_g;
tObdUnsigned16 awTestExtArray_g[3];
extern tObdUnsigned8 bPeerIn_g;
extern tObdUnsigned8 bPeerInInv_g;

static tCopInstanceHdl hA_g = CCM_ILLINSTANCE_HDL;
static tCopInstanceHdl hB_g = CCM_ILLINSTANCE_HDL;

/* ---- what the callbacks saw, per handle ---------------------------------------------- */

#define SLOTS 3     /* handles 0, 1 and "other" */

static unsigned SlotOf (tCopInstanceHdl h_p)
{
    return (h_p < 2) ? h_p : 2;
}

static unsigned auNmtEvents_g[SLOTS];
static tCopInstanceHdl hPublishedAtStart_g = 0xEE;
static unsigned auSrdoEvents_g[SLOTS];
static unsigned auSrdoErrors_g[SLOTS];
static unsigned auGfcEvents_g[SLOTS];
static unsigned auProgMon_g[SLOTS];
static unsigned auObdEvents_g[SLOTS];
static unsigned uHandshakeFailures_g;
static BYTE     bOtherStateInCallback_g;
static int      fCallOtherInstance_g;

static tCopKernel PUBLIC AppNmtEvent (CCM_DECL_INSTANCE_HDL_ tNmtEvent NmtEvent_p)
{
    auNmtEvents_g[SlotOf(InstanceHandle)]++;
    if (NmtEvent_p == kNmtEvEnterInitialising)
    {
        /* CcmInitCANopen wrote the handle before the start-up events */
        hPublishedAtStart_g = (InstanceHandle == 0) ? hA_g : hB_g;
    }
    return kCopSuccessful;
}

/* Manual 2.9.1, per instance: the status byte of the instance that
 * received the SRDO, through that instance's handle. */
tCopKernel PUBLIC AppSrdoEvent (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p)
{
    BYTE bSrdoState_l;
    tCopKernel Ret;

    auSrdoEvents_g[SlotOf(InstanceHandle)]++;
    Ret = CcmGetSrdoState(InstanceHandle, &bSrdoState_l, wSrdoCommuIndex_p);
    if ((Ret != kCopSuccessful) || ((bSrdoState_l & 0x30) != 0x00))
    {
        uHandshakeFailures_g++;
        return kCopSuccessful;
    }
    if (fCallOtherInstance_g)
    {
        /* the other instance from inside this one's callback */
        bOtherStateInCallback_g = CcmObdGetNodeState((tCopInstanceHdl) (InstanceHandle ^ 1));
    }
    Ret = CcmSetSrdoState(InstanceHandle, (BYTE) (bSrdoState_l | 0x30), wSrdoCommuIndex_p);
    if (Ret != kCopSuccessful)
    {
        uHandshakeFailures_g++;
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoError (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    BYTE bSrdoState_l = 0;

    (void) ErrorCode_p;
    auSrdoErrors_g[SlotOf(InstanceHandle)]++;
    if (CcmGetSrdoState(InstanceHandle, &bSrdoState_l, wSrdoCommuIndex_p) == kCopSuccessful)
    {
        (void) CcmSetSrdoState(InstanceHandle, (BYTE) (bSrdoState_l | 0xB0), wSrdoCommuIndex_p);
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppGfcEvent (CCM_DECL_INSTANCE_HDL)
{
    auGfcEvents_g[SlotOf(InstanceHandle)]++;
    return kCopSuccessful;
}

tCopKernel PUBLIC AppProgMonEvent (CCM_DECL_INSTANCE_HDL_ tProgMonEvent Event_p)
{
    (void) Event_p;
    auProgMon_g[SlotOf(InstanceHandle)]++;
    return kCopSuccessful;
}

/* The OBD callbacks objdict_all.h names (obdcfg.h). */
tCopKernel PUBLIC TestCbVeto (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p)
{
    (void) pParam_p;
    auObdEvents_g[SlotOf(InstanceHandle)]++;
    return kCopSuccessful;
}

tCopKernel PUBLIC TestCbRecord (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p)
{
    (void) pParam_p;
    auObdEvents_g[SlotOf(InstanceHandle)]++;
    return kCopSuccessful;
}

/* ---- helpers --------------------------------------------------------------------------- */

static tCcmInitParam aInit_g[2];

static tCcmInitParam* InitParam (BYTE bNode_p, BYTE bNodeId_p, tObdInitRam fpObd_p)
{
    tCcmInitParam* p = &aInit_g[bNode_p];

    memset(p, 0, sizeof(*p));
    p->m_bInitNodeId = bNodeId_p;
    p->m_BaudIndex = kBdi500kBaud;
    p->m_dwAmr = 0xFFFFFFFFUL;
    p->m_HwParam.m_ZeroBasedCanNo.m_bCanNo = bNode_p;
    p->m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    p->m_fpNmtEventCallback = AppNmtEvent;
    p->m_fpObdInitRam = fpObd_p;
    return p;
}

static void Clear (void)
{
    memset(auNmtEvents_g, 0, sizeof(auNmtEvents_g));
    memset(auSrdoEvents_g, 0, sizeof(auSrdoEvents_g));
    memset(auSrdoErrors_g, 0, sizeof(auSrdoErrors_g));
    memset(auGfcEvents_g, 0, sizeof(auGfcEvents_g));
    memset(auProgMon_g, 0, sizeof(auProgMon_g));
    memset(auObdEvents_g, 0, sizeof(auObdEvents_g));
    uHandshakeFailures_g = 0;
}

/* Starts both instances: A on controller 0, B on controller 1. */
static void InitBoth (void)
{
    SimSelectNode(SIM_A);
    CHECK_RET(CcmInitCANopen(&hA_g, InitParam(SIM_A, ID_A, ObdInitRam), kCcmFirstInstance), kCopSuccessful);
    SimSelectNode(SIM_B);
    CHECK_RET(CcmInitCANopen(&hB_g, InitParam(SIM_B, ID_B, ObdInitRamSrdoPeer), kCcmAdditionalInstance),
              kCopSuccessful);
}

static tCopKernel MakeValid (tCopInstanceHdl h_p)
{
    BYTE bValid = 0xA5;
    WORD wIndex;
    WORD wCrc;
    tCopKernel Ret;
    tCopInstanceHdl h = h_p;

    for (wIndex = 0x1301; wIndex <= 0x1302; wIndex++)
    {
        /* CcmCalcSrdoCrc takes the instance pointer (srdo.h, manual 2.8.8) */
        if (CcmCalcSrdoCrc(&h, wIndex, &wCrc) != kCopSuccessful)
        {
            continue;
        }
        Ret = CcmWriteObject(h_p, 0x13FF, (BYTE) (wIndex - 0x1300), &wCrc, sizeof(wCrc));
        if (Ret != kCopSuccessful)
        {
            return Ret;
        }
    }
    return CcmWriteObject(h_p, 0x13FE, 0, &bValid, sizeof(bValid));
}

static void ProcessBoth (void)
{
    CHECK_RET(CcmProcess(hA_g), kCopSuccessful);
    CHECK_RET(CcmProcess(hB_g), kCopSuccessful);
}

/* The next frame on the bus, compared by identifier and the bus it was on. */
static void ExpectFrame (const char* pszWhat_p, DWORD dwId_p, BYTE bBus_p)
{
    tSimFrame Frame;

    if (!SimTakeSentFrame(&Frame))
    {
        printf("%s: no frame, expected %03lX\n", pszWhat_p, (unsigned long) dwId_p);
        iTestFailures_g++;
        return;
    }
    if ((Frame.m_dwId != dwId_p) || (Frame.m_bBus != bBus_p))
    {
        printf("%s: %03lX on bus %u, expected %03lX on bus %u\n", pszWhat_p, (unsigned long) Frame.m_dwId,
               (unsigned) Frame.m_bBus, (unsigned long) dwId_p, (unsigned) bBus_p);
        iTestFailures_g++;
    }
}

static void Drain (void)
{
    while (SimTakeSentFrame(NULL))
    {
    }
}

/* ---- CcmInitCANopen --------------------------------------------------------------------- */

static void InitCodes (void)
{
    tCopInstanceHdl h = 0x77;

    /* before any instance: every handle is refused */
    CHECK_RET(CcmProcess(0), kCopIllegalInstance);
    CHECK_RET(CcmProcess(1), kCopIllegalInstance);
    CHECK_RET(CcmProcess(NO_HDL), kCopIllegalInstance);
    CHECK_RET(CcmProcess(CCM_ILLINSTANCE_HDL), kCopIllegalInstance);

    SimSelectNode(SIM_A);
    CHECK_RET(CcmInitCANopen(NULL, InitParam(SIM_A, ID_A, ObdInitRam), kCcmFirstInstance),
              kCopInvalidInstanceParam);
    CHECK_RET(CcmInitCANopen(&h, InitParam(SIM_A, ID_A, ObdInitRam), 7), kCopInvalidParam);
    CHECK_RET(CcmInitCANopen(&h, NULL, kCcmFirstInstance), kCopInvalidParam);
    CHECK_EQ(SimRxCapacity(SIM_A, 0), 0);                   /* no driver was started */

    Clear();
    InitBoth();
    CHECK_EQ(hA_g, 0);
    CHECK_EQ(hB_g, 1);
    CHECK_EQ(hPublishedAtStart_g, 1);                      /* B's handle, written before its events */
    CHECK_EQ(auNmtEvents_g[0], 5);                          /* the five start-up events of each */
    CHECK_EQ(auNmtEvents_g[1], 5);
    CHECK_EQ(auNmtEvents_g[2], 0);

    /* a third instance: none free, the handle says so */
    h = 0x77;
    CHECK_RET(CcmInitCANopen(&h, InitParam(SIM_A, ID_A, ObdInitRam), kCcmAdditionalInstance),
              kCopNoFreeInstance);
    CHECK_EQ(h, CCM_ILLINSTANCE_HDL);
}

/* ---- each instance its own dictionary, driver and node ------------------------------------ */

static void OwnParts (void)
{
    BYTE b = 0;
    tObdSize Size = sizeof(b);
    DWORD dw = 0;

    /* dictionaries: 0x2040 exists only in A's, 0x2050 only in B's */
    CHECK_RET(CcmReadObject(hA_g, 0x2040, 1, &b, &Size), kCopSuccessful);
    Size = sizeof(b);
    CHECK_RET(CcmReadObject(hB_g, 0x2040, 1, &b, &Size), kCopObdIndexNotExist);
    Size = sizeof(b);
    CHECK_RET(CcmReadObject(hB_g, 0x2050, 1, &b, &Size), kCopSuccessful);
    Size = sizeof(b);
    CHECK_RET(CcmReadObject(hA_g, 0x2050, 1, &b, &Size), kCopObdIndexNotExist);

    /* an OBD callback gets the handle of the instance whose object it is */
    dw = 0x1234;
    CHECK_RET(CcmWriteObject(hA_g, 0x2020, 0, &dw, 2), kCopSuccessful);
    CHECK(auObdEvents_g[0] > 0);
    CHECK_EQ(auObdEvents_g[1], 0);
    CHECK_EQ(auObdEvents_g[2], 0);

    /* drivers: each instance defined its identifiers on its own controller */
    CHECK(SimIsIdDefined(SIM_A, 0x600 + ID_A) != 0);
    CHECK_EQ(SimIsIdDefined(SIM_B, 0x600 + ID_A), 0);
    CHECK(SimIsIdDefined(SIM_B, 0x600 + ID_B) != 0);
    CHECK_EQ(SimIsIdDefined(SIM_A, 0x600 + ID_B), 0);
    CHECK_EQ(SimIsIdDefined(SIM_B, 0x101), 2);              /* B receives SRDO 1, high buffer */

    /* boot-ups: each node with its own node-ID */
    Drain();
    CHECK_RET(CcmConnectToNet(hA_g), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(hB_g), kCopSuccessful);
    ExpectFrame("boot-up A", 0x700 + ID_A, 0);
    ExpectFrame("boot-up B", 0x700 + ID_B, 0);
    CHECK_EQ(CcmObdGetNodeState(hA_g), kNodeStatePreOperational);
    CHECK_EQ(CcmObdGetNodeState(hB_g), kNodeStatePreOperational);
    CHECK_EQ(CcmObdGetNodeState(NO_HDL), 0);                /* as before CcmInitCANopen */

    /* a local NMT command reaches only its instance */
    CHECK_RET(CcmNmtsExecCommand(hA_g, kNmtCommStartRemoteNode), kCopSuccessful);
    ProcessBoth();
    CHECK_EQ(CcmObdGetNodeState(hA_g), kNodeStateOperational);
    CHECK_EQ(CcmObdGetNodeState(hB_g), kNodeStatePreOperational);
    CHECK_RET(CcmNmtsExecCommand(hA_g, kNmtCommEnterPreOperational), kCopSuccessful);
    ProcessBoth();
    Drain();
}

/* ---- an SRDO from A to B on the shared bus --------------------------------------------------- */

static void SrdoAcross (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    BYTE b;
    tCopInstanceHdl hCopy = hA_g;
    tCopPtrInstance pSrdoA = &hCopy;
    BYTE bState = 0;

    CHECK_RET(MakeValid(hA_g), kCopSuccessful);
    CHECK_RET(MakeValid(hB_g), kCopSuccessful);
    CHECK_EQ(SimInject(0x000, 0, 2, abStartAll), 2);        /* both receive NMT */
    ProcessBoth();
    CHECK_EQ(CcmObdGetNodeState(hA_g), kNodeStateOperational);
    CHECK_EQ(CcmObdGetNodeState(hB_g), kNodeStateOperational);
    SimAdvanceMs(5);        /* the first-send delay: 0.5 ms x node-ID (CiA 304) */
    ProcessBoth();
    Drain();
    Clear();

    b = 0x3C;
    CHECK_RET(CcmWriteObject(hA_g, 0x2040, 1, &b, 1), kCopSuccessful);
    b = 0xC3;
    CHECK_RET(CcmWriteObject(hA_g, 0x2041, 1, &b, 1), kCopSuccessful);
    CHECK_RET(CcmSendSrdo(hA_g, 0x1301), kCopSuccessful);
    ExpectFrame("SRDO 1 normal from A", 0x101, 0);
    ExpectFrame("SRDO 1 inverted from A", 0x102, 0);
    CHECK_EQ(auSrdoEvents_g[0], 1);                         /* A's own transmission */
    fCallOtherInstance_g = 1;
    bOtherStateInCallback_g = 0;
    CHECK_RET(CcmProcess(hB_g), kCopSuccessful);
    fCallOtherInstance_g = 0;
    CHECK_EQ(auSrdoEvents_g[1], 1);                         /* B's reception, B's handle */
    CHECK_EQ(auSrdoEvents_g[2], 0);
    CHECK_EQ(uHandshakeFailures_g, 0);
    CHECK_EQ(auSrdoErrors_g[0] + auSrdoErrors_g[1] + auSrdoErrors_g[2], 0);
    CHECK_EQ(bOtherStateInCallback_g, kNodeStateOperational);  /* A, from inside B's callback */
    CHECK_EQ(bPeerIn_g, 0x3C);
    CHECK_EQ(bPeerInInv_g, 0xC3);
    CHECK_RET(CcmGetSrdoState(hB_g, &bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState & 0x30, 0x30);                          /* processed by B's handshake */

    /* the module functions: the instance pointer points to the handle */
    CHECK_RET(SrdoSend(NULL, 0x1301), kCopInvalidInstanceParam);
    CHECK_RET(SrdoSend(pSrdoA, 0x1301), kCopSuccessful);
    ExpectFrame("SRDO 1 normal (SrdoSend)", 0x101, 0);
    ExpectFrame("SRDO 1 inverted (SrdoSend)", 0x102, 0);
    CHECK_RET(SrdoGetState(pSrdoA, &bState, 0x1301), kCopSuccessful);
    CHECK_RET(SrdoGetState(pSrdoA, &bState, 0x1302), kCopSuccessful);
    hCopy = hB_g;
    CHECK_RET(SrdoSend(pSrdoA, 0x1301), kCopSrdoRxTxConflict);     /* B's SRDO 1 receives */
    hCopy = NO_HDL;
    CHECK_RET(SrdoSend(pSrdoA, 0x1301), kCopIllegalInstance);
    /* SrdoAddInstance: the pointer variable names the instance and gets
     * the library's pointer of it */
    hCopy = hB_g;
    CHECK_RET(SrdoAddInstance(NULL, NULL), kCopInvalidInstanceParam);
    CHECK_RET(SrdoAddInstance(&pSrdoA, NULL), kCopInvalidParam);
    CHECK(pSrdoA != (tCopPtrInstance) &hCopy);
    CHECK_EQ(*(tCopInstanceHdl*) pSrdoA, hB_g);
    CHECK_RET(SrdoGetState(pSrdoA, &bState, 0x1301), kCopSuccessful);
    Drain();
    ProcessBoth();
    Drain();
}

/* ---- every function with a handle of no instance ------------------------------------------------ */

/* Every exported function with handle h. A handle of no slot
 * (fShutDown_p 0) is refused by all of them with kCopIllegalInstance; the
 * handle of a shut-down instance gives what a single-instance build gives
 * before CcmInitCANopen: kCopIllegalInstance, except for the functions that
 * may be called before it (the dynamic OD, the store driver) and a refusal
 * of the arguments that comes first. */
static void EveryFunction (tCopInstanceHdl h, int fShutDown_p)
{
    const tCopKernel Expected_p = kCopIllegalInstance;
    BYTE b = 0;
    WORD w = 0;
    DWORD dw = 0;
    tObdSize Size = sizeof(b);
    tEmcParam Emc;
    tVarParam Var;
    tCobParam Cob;
    tNmtmSlaveParam Slave;
    tNmtmSlaveInfo Info;
    tHbcProdParam Hbc;
    tSdocParam Sdoc;
    tSdocTransferParam Transfer;
    tSdocState SdocState;
    tPdoParam Pdo;
    tPdoStaticParam PdoStatic;
    tTimeOfDay Tod;
    tSrdoCommuParam Commu;
    tSrdoMappParam Mapp;
    tSrdoInitParam SrdoInit_;
    tProcessImageDscrpt Image;
    tCopKernel Code;
    BYTE abSeg[4];
    tCopInstanceHdl hCopy = h;
    tCopPtrInstance p = &hCopy;

    memset(&Emc, 0, sizeof(Emc));
    memset(&Var, 0, sizeof(Var));
    memset(&Cob, 0, sizeof(Cob));
    memset(&Slave, 0, sizeof(Slave));
    memset(&Info, 0, sizeof(Info));
    memset(&Hbc, 0, sizeof(Hbc));
    memset(&Sdoc, 0, sizeof(Sdoc));
    memset(&Transfer, 0, sizeof(Transfer));
    memset(&Pdo, 0, sizeof(Pdo));
    memset(&PdoStatic, 0, sizeof(PdoStatic));
    memset(&Tod, 0, sizeof(Tod));
    memset(&SrdoInit_, 0, sizeof(SrdoInit_));
    memset(&Image, 0, sizeof(Image));
    memset(abSeg, 0, sizeof(abSeg));

    CHECK_RET(CcmShutDownCANopen(h), Expected_p);
    CHECK_RET(CcmConnectToNet(h), Expected_p);
    CHECK_RET(CcmProcess(h), Expected_p);
    CHECK_RET(CcmProcessLssInitState(h), Expected_p);
    CHECK_RET(CcmReadObject(h, 0x1000, 0, &dw, &Size), Expected_p);
    CHECK_RET(CcmWriteObject(h, 0x1017, 0, &w, sizeof(w)), Expected_p);
    CHECK_EQ(CcmObdGetNodeState(h), 0);
    CHECK_EQ(CcmLsssGetNodeId(h), 0);
    CHECK_RET(CcmNmtsExecCommand(h, kNmtCommStartRemoteNode), Expected_p);
    CcmRegisterErrorCallback(h, NULL);
    CHECK_RET(CcmConfigHbp(h, 100), Expected_p);
    CHECK_RET(CcmConfigEmcp(h, 0x82), Expected_p);
    CHECK_RET(CcmSendEmergency(h, &Emc), Expected_p);
    CHECK_RET(CcmDefineVarTab(h, &Var, 0), Expected_p);
    CHECK_RET(CcmCobGetParam(h, &Cob), Expected_p);
    CHECK_RET(DynBuildOd(h, abSeg, &Image), fShutDown_p ? kCopDynInvalidConfig : Expected_p);
    CHECK_RET(DynGetLastError(h, &w, &b, &dw, &Code), fShutDown_p ? kCopSuccessful : Expected_p);
    CHECK_RET(DynDestroyOd(h), Expected_p);
    CHECK_RET(CcmInitEmcc(h), Expected_p);
    CHECK_RET(CcmInitEmccEx(h, NULL), Expected_p);
    CHECK_RET(CcmEmccDefineProducerTab(h, abSeg, 1), Expected_p);
    CHECK_RET(CcmInitNmtm(h), Expected_p);
    CHECK_RET(CcmInitNmtmEx(h, NULL), Expected_p);
    CHECK_RET(CcmDefineSlaveTab(h, abSeg, 1), Expected_p);
    CHECK_RET(CcmSendNmtCommand(h, 3, kNmtCommStartRemoteNode), Expected_p);
    CHECK_RET(CcmBootNetwork(h), Expected_p);
    CHECK_RET(CcmTriggerNodeGuard(h, 3), Expected_p);
    CHECK_RET(CcmConfigLgm(h, 3, &Slave), Expected_p);
    CHECK_RET(CcmNmtmGetSlaveInfo(h, 3, &Info), Expected_p);
    CHECK_RET(CcmInitHbc(h), Expected_p);
    CHECK_RET(CcmInitHbcEx(h, NULL), Expected_p);
    CHECK_RET(CcmHbcDefineProducerTab(h, &Hbc, 1), Expected_p);
    CHECK_RET(CcmHbcGetNodeState(h, 3, &b), Expected_p);
    CHECK_RET(CcmSdocDefineClientTab(h, &Sdoc, 1), Expected_p);
    CHECK_RET(CcmSdocStartTransfer(h, &Transfer), fShutDown_p ? kCopInvalidParam : Expected_p);
    CHECK_RET(CcmSdocAbort(h, 0x1280, 0x08000000UL), Expected_p);
    CHECK_RET(CcmSdocGetState(h, 0x1280, &SdocState, &dw), Expected_p);
    CHECK_RET(SdocGetTransmittedBytes(p, 0x1280, &dw), Expected_p);
    CHECK_RET(CcmDefinePdoTab(h, &Pdo, 1), Expected_p);
    CHECK_RET(CcmDefineStaticPdoTab(h, &PdoStatic, 1), Expected_p);
    CHECK_RET(CcmSignalStaticPdo(h, 0x1800), Expected_p);
    CHECK_RET(CcmSignalCheckVar(h), Expected_p);
    CHECK_RET(CcmSignalVar(h, &dwTestExtVar_g), Expected_p);
    CHECK_RET(CcmSendPdo(h, 0x1800), Expected_p);
    CHECK_RET(CcmInitSyncConsumer(h), Expected_p);
    CHECK_RET(CcmConfigSyncConsumer(h, 0x80, 0), Expected_p);
    CcmEnterCriticalSectionPdoProcess(h);
    CcmLeaveCriticalSectionPdoProcess(h);
    CHECK_RET(CcmClearPreDefinedErrorField(h), Expected_p);
    CHECK_RET(CcmInitLgs(h), Expected_p);
    CHECK_RET(CcmConfigLgs(h, 100, 3), Expected_p);
    CHECK_RET(CcmConfigSyncProducer(h, 0x40000080UL, 1000), Expected_p);
    CHECK_RET(CcmTspSend(h, 0x100, &Tod), Expected_p);
    CHECK_RET(CcmSetStoreDriver(h, NULL), fShutDown_p ? kCopSuccessful : Expected_p);
    CHECK_RET(CcmInitStore(h), Expected_p);
    CHECK_RET(CcmStoreCheckArchivState(h, kObdPartGen), Expected_p);
    CHECK_RET(CcmStoreRestoreDefault(h), Expected_p);
    CHECK_RET(CcmSendSrdo(h, 0x1301), Expected_p);
    CHECK_RET(SrdoSend(p, 0x1301), Expected_p);
    CHECK_RET(CcmCheckSrdoConfig(h, &w), Expected_p);
    CHECK_RET(SrdoCheckConfig(p, &w), Expected_p);
    CHECK_RET(CcmSendGfc(h), Expected_p);
    CHECK_RET(SrdoSendGfc(p), Expected_p);
    CHECK_RET(CcmGetSrdoState(h, &b, 0x1301), Expected_p);
    CHECK_RET(SrdoGetState(p, &b, 0x1301), Expected_p);
    CHECK_RET(CcmSetSrdoState(h, 0x30, 0x1301), Expected_p);
    CHECK_RET(SrdoSetState(p, 0x30, 0x1301), Expected_p);
    CHECK_RET(CcmGetSrdoParam(h, 0x1301, &Commu, &Mapp), Expected_p);
    CHECK_RET(SrdoGetCommuParam(p, 0x1301, &Commu), Expected_p);
    CHECK_RET(SrdoGetMappParam(p, 0x1301, &Mapp), Expected_p);
    CHECK_RET(CcmCalcSrdoCrc(p, 0x1301, &w), Expected_p);
    CHECK_RET(SrdoCalcSrdoCrc(p, 0x1301, NULL, &w), Expected_p);
    CHECK_RET(SrdoInit(&p, &SrdoInit_), Expected_p);
    p = &hCopy;
    CHECK_RET(SrdoAddInstance(&p, &SrdoInit_), Expected_p);
    p = &hCopy;
    CHECK_RET(SrdoDeleteInstance(p), Expected_p);
    CHECK_RET(SrdoNmtEvent(p, kNmtEvEnterPreOperational), Expected_p);
    CHECK_RET(SrdoProcess(p), Expected_p);
}

static void Handles (void)
{
    BYTE b = 0;
    tObdSize Size = sizeof(b);

    EveryFunction(NO_HDL, 0);
    EveryFunction(CCM_ILLINSTANCE_HDL, 0);
    /* A and B still run */
    ProcessBoth();
    Drain();

    /* B shut down: its handle is refused everywhere, A goes on */
    CHECK_RET(CcmShutDownCANopen(hB_g), kCopSuccessful);
    CHECK_EQ(SimRxCapacity(SIM_B, 1), 0);                   /* B's driver instance deleted */
    CHECK(SimRxCapacity(SIM_A, 1) != 0);                    /* A's kept */
    EveryFunction(hB_g, 1);
    CHECK_RET(CcmProcess(hA_g), kCopSuccessful);
    CHECK_RET(CcmReadObject(hA_g, 0x2040, 1, &b, &Size), kCopSuccessful);

    /* an instance on the dictionary tables of another (the same
     * ObdInitRam): refused, they would share every value */
    SimSelectNode(SIM_B);
    hB_g = 0x77;
    CHECK_RET(CcmInitCANopen(&hB_g, InitParam(SIM_B, ID_B, ObdInitRam), kCcmAdditionalInstance),
              kCopInvalidParam);
    CHECK_EQ(hB_g, CCM_ILLINSTANCE_HDL);
    CHECK_EQ(SimRxCapacity(SIM_B, 1), 0);                   /* no driver started */

    /* the slot is free again: the next instance takes handle 1 */
    SimSelectNode(SIM_B);
    hB_g = CCM_ILLINSTANCE_HDL;
    CHECK_RET(CcmInitCANopen(&hB_g, InitParam(SIM_B, ID_B, ObdInitRamSrdoPeer), kCcmAdditionalInstance),
              kCopSuccessful);
    CHECK_EQ(hB_g, 1);
    CHECK_RET(CcmShutDownCANopen(hA_g), kCopSuccessful);
    CHECK_RET(CcmShutDownCANopen(hB_g), kCopSuccessful);
    CHECK_RET(CcmShutDownCANopen(hB_g), kCopIllegalInstance);
}

/* ---- two separate buses -------------------------------------------------------------------------- */

static void SeparateBuses (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    BYTE b;

    SimReset();
    SimSetBus(SIM_B, 1);
    Clear();
    InitBoth();
    CHECK_RET(CcmConnectToNet(hA_g), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(hB_g), kCopSuccessful);
    ExpectFrame("boot-up A on bus 0", 0x700 + ID_A, 0);
    ExpectFrame("boot-up B on bus 1", 0x700 + ID_B, 1);
    CHECK_RET(MakeValid(hA_g), kCopSuccessful);
    CHECK_RET(MakeValid(hB_g), kCopSuccessful);
    CHECK_EQ(SimInject(0x000, 0, 2, abStartAll), 1);        /* bus 0: A only */
    SimSetInjectBus(1);
    CHECK_EQ(SimInject(0x000, 0, 2, abStartAll), 1);        /* bus 1: B only */
    ProcessBoth();
    SimAdvanceMs(5);
    ProcessBoth();
    Drain();
    b = 0x5A;
    CHECK_RET(CcmWriteObject(hA_g, 0x2040, 1, &b, 1), kCopSuccessful);
    b = 0xA5;
    CHECK_RET(CcmWriteObject(hA_g, 0x2041, 1, &b, 1), kCopSuccessful);
    CHECK_RET(CcmSendSrdo(hA_g, 0x1301), kCopSuccessful);
    ExpectFrame("SRDO 1 normal on bus 0", 0x101, 0);
    ExpectFrame("SRDO 1 inverted on bus 0", 0x102, 0);
    CHECK_EQ(SimRxPending(SIM_B), 0);                       /* nothing crossed to bus 1 */
    CHECK_RET(CcmProcess(hB_g), kCopSuccessful);
    CHECK_EQ(auSrdoEvents_g[1], 0);
    CHECK_RET(CcmShutDownCANopen(hA_g), kCopSuccessful);
    CHECK_RET(CcmShutDownCANopen(hB_g), kCopSuccessful);
}

int main (void)
{
    SimReset();
    SimSetTrace(1);
    InitCodes();
    OwnParts();
    SrdoAcross();
    Handles();
    SeparateBuses();
    return TEST_DONE("test_multi");
}
