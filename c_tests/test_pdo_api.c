/*
 * test_pdo_api.c - every PDO function of cop.h (src/ffi/pdo.rs) with
 * success and refusal codes, two nodes on the simulated bus:
 *
 *   node M (simulated node 0): objdict_master.h, node-ID 1: TPDO 0x1800
 *          and RPDO 0x1400, application variables bMasterOut_g/bMasterIn_g;
 *   node A (simulated node 1): objdict_all.h, node-ID 2: TPDO 0x1800
 *          (0x2040/1) and RPDO 0x1400 (0x2042/1).
 *
 * CcmDefinePdoTab, CcmDefineStaticPdoTab, CcmSignalStaticPdo,
 * CcmSignalCheckVar, CcmSignalVar, CcmSendPdo, CcmInitSyncConsumer,
 * CcmConfigSyncConsumer, CcmEnterCriticalSectionPdoProcess /
 * CcmLeaveCriticalSectionPdoProcess, and the per-PDO callbacks.
 */
#include "test_util.h"

#define SIM_M 0
#define SIM_A 1
#define ID_M  1
#define ID_A  2

extern tObdUnsigned8 bMasterIn_g;
extern tObdUnsigned8 bMasterOut_g;
tCopKernel PUBLIC ObdInitRamMaster (void MEM* pInitParam_p);

static unsigned uRxCallbacks_g;
static WORD     wRxCallbackIndex_g;
static unsigned uTxCallbacks_g;

static tCopKernel PUBLIC RxCallback (WORD wPdoCommuIndex_p)
{
    uRxCallbacks_g++;
    wRxCallbackIndex_g = wPdoCommuIndex_p;
    return kCopSuccessful;
}

static tCopKernel PUBLIC TxCallback (WORD wPdoCommuIndex_p)
{
    (void) wPdoCommuIndex_p;
    uTxCallbacks_g++;
    return kCopSuccessful;
}

static BYTE abRxBlock_g[1];         /* M's static RPDO */
static BYTE abTxBlock_g[1];         /* M's static TPDO */

static void ProcessNode (BYTE bNode_p)
{
    SimSelectNode(bNode_p);
    (void) CcmProcess();
}

/* A tPdoParam with every field valid. */
static tPdoParam Pdo (WORD wIndex_p, BYTE bType_p, DWORD dwCanId_p, BYTE bNodeId_p, BYTE bTxType_p,
                      BYTE bEntries_p, DWORD dwMapp_p)
{
    tPdoParam P;

    memset(&P, 0, sizeof(P));
    P.m_bValidFlag = kPdoValidAll;
    P.m_wPdoCommuIndex = wIndex_p;
    P.m_bPdoType = bType_p;
    P.m_bNodeID = bNodeId_p;
    P.m_dwCanId = dwCanId_p;
    P.m_bTxTyp = bTxType_p;
    P.m_bNrOfEntries = bEntries_p;
    P.m_adwMappParam[0] = dwMapp_p;
    return P;
}

static void BeforeInit (void)
{
    tPdoParam P = Pdo(0x1800, kPdoTypeSend, 0x180, ID_A, 254, 1, 0x20400108);
    tPdoStaticParam S;

    memset(&S, 0, sizeof(S));
    S.m_wPdoCommuIndex = 0x1800;
    SimSelectNode(SIM_M);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopIllegalInstance);
    CHECK_RET(CcmDefineStaticPdoTab(&S, 1), kCopIllegalInstance);
    CHECK_RET(CcmSignalStaticPdo(0x1800), kCopIllegalInstance);
    CHECK_RET(CcmSignalCheckVar(), kCopIllegalInstance);
    CHECK_RET(CcmSignalVar(&bMasterOut_g), kCopIllegalInstance);
    CHECK_RET(CcmSendPdo(0x1800), kCopIllegalInstance);
    CHECK_RET(CcmInitSyncConsumer(), kCopIllegalInstance);
    CHECK_RET(CcmConfigSyncConsumer(0x80, 0), kCopIllegalInstance);
    CcmEnterCriticalSectionPdoProcess();       /* ignored without a stack */
    CcmLeaveCriticalSectionPdoProcess();
}

static void DefinePdos (void)
{
    tPdoParam P;
    tPdoParam aTwo[2];

    /* A: TPDO 0x180 + node-ID with 0x2040/1, RPDO from M (0x181) into 0x2042/1 */
    SimSelectNode(SIM_A);
    CHECK_RET(CcmDefinePdoTab(NULL, 1), kCopInvalidParam);
    P = Pdo(0x1805, kPdoTypeSend, 0x180, ID_A, 254, 1, 0x20400108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoNotExist);
    P = Pdo(0x1801, kPdoTypeSend, 0x180, ID_A, 254, 1, 0x20400108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoNotExist);         /* PDO_MAX_TXPDO_IN_OBD 1 */
    P = Pdo(0x1800, kPdoTypeRecv, 0x180, ID_A, 254, 1, 0x20400108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopInvalidParam);        /* type does not match the index */
    P = Pdo(0x1800, kPdoTypeSend, 0x180, ID_A, 0xF1, 1, 0x20400108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopInvalidParam);        /* reserved transmission type */
    P = Pdo(0x1800, kPdoTypeSend, 0x180, ID_A, 254, 1, 0x20000508);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoErrorMapp);        /* 0x2000/5 is not mappable */
    P = Pdo(0x1800, kPdoTypeSend, 0x180, ID_A, 254, 1, 0x2FFF0108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoVarNotFound);      /* no such object */
    P = Pdo(0x1800, kPdoTypeSend, 0x180, ID_A, 254, 9, 0x20400108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoLengthExceeded);   /* more than PDO_MAX_MAPPENTRIES */
    P = Pdo(0x1800, kPdoTypeSend, 0x180, ID_A, 254, 1, 0x20400108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);
    P = Pdo(0x1400, kPdoTypeRecv, 0x181, 0, 254, 1, 0x20420108);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);

    /* M: TPDO 0x181 with bMasterOut_g, a callback after each transmission */
    SimSelectNode(SIM_M);
    aTwo[0] = Pdo(0x1800, kPdoTypeSend, 0x180, ID_M, 254, 1, 0x20610108);
    aTwo[0].m_fpCallback = TxCallback;
    aTwo[1] = Pdo(0x1400, kPdoTypeRecv, 0x182, 0, 254, 1, 0x20600108);
    CHECK_RET(CcmDefinePdoTab(aTwo, 2), kCopSuccessful);
}

static void Transfer (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    static CONST BYTE ab5A[1] = { 0x5A };
    static CONST BYTE ab77[1] = { 0x77 };
    static CONST BYTE ab78[1] = { 0x78 };
    static BYTE bNotMapped;

    /* PRE-OPERATIONAL: no PDO */
    SimSelectNode(SIM_A);
    CHECK_RET(CcmSendPdo(0x1800), kCopNmtStateError);
    SimInject(0x000, 0, 2, abStartAll);
    ProcessNode(SIM_M);
    ProcessNode(SIM_A);
    TestDrainSent();

    /* CcmSendPdo: at once, whatever the transmission type */
    SimSelectNode(SIM_A);
    CHECK_RET(TestWriteU8(0x2040, 1, 0x5A), kCopSuccessful);
    CHECK_RET(CcmSendPdo(0x1800), kCopSuccessful);
    TestExpectFrame("A: CcmSendPdo", 0x180 + ID_A, 1, ab5A);
    CHECK_RET(CcmSendPdo(0x1801), kCopPdoNotExist);
    CHECK_RET(CcmSendPdo(0x1400), kCopPdoNotExist);
    ProcessNode(SIM_M);
    CHECK_EQ(bMasterIn_g, 0x5A);

    /* CcmSignalVar: M's TPDO maps bMasterOut_g */
    SimSelectNode(SIM_M);
    bMasterOut_g = 0x77;
    CHECK_RET(CcmSignalVar(NULL), kCopInvalidParam);
    CHECK_RET(CcmSignalVar(&bNotMapped), kCopPdoVarNotFound);
    CHECK_RET(CcmSignalVar(&bMasterIn_g), kCopPdoVarNotFound);  /* mapped by an RPDO only */
    CHECK_RET(CcmSignalVar(&bMasterOut_g), kCopSuccessful);
    CHECK_EQ(SimSentPending(), 0);                              /* sent by the next cycle */
    ProcessNode(SIM_M);
    TestExpectFrame("M: CcmSignalVar", 0x180 + ID_M, 1, ab77);
    CHECK_EQ(uTxCallbacks_g, 1);
    ProcessNode(SIM_A);
    SimSelectNode(SIM_A);
    CHECK_EQ(TestReadU8(0x2042, 1), 0x77);

    /* CcmSignalCheckVar: only changed data go out */
    SimSelectNode(SIM_M);
    CHECK_RET(CcmSignalCheckVar(), kCopSuccessful);
    ProcessNode(SIM_M);
    CHECK_EQ(SimSentPending(), 0);
    bMasterOut_g = 0x78;
    CHECK_RET(CcmSignalCheckVar(), kCopSuccessful);
    ProcessNode(SIM_M);
    TestExpectFrame("M: CcmSignalCheckVar", 0x180 + ID_M, 1, ab78);
    ProcessNode(SIM_A);
    TestDrainSent();

    /* an invalid COB-ID: nothing to send */
    SimSelectNode(SIM_A);
    CHECK_RET(TestWriteU32(0x1800, 1, 0x80000182UL), kCopSuccessful);
    CHECK_RET(CcmSendPdo(0x1800), kCopPdoErrorSend);
    CHECK_RET(TestWriteU32(0x1800, 1, 0x182), kCopSuccessful);
}

static void StaticPdos (void)
{
    static CONST BYTE ab42[1] = { 0x42 };
    tPdoStaticParam S;
    tPdoStaticParam R;

    SimSelectNode(SIM_M);
    memset(&S, 0, sizeof(S));
    S.m_wPdoCommuIndex = 0x1800;
    S.m_dwCanId = 0x180 + ID_M;
    S.m_bTxTyp = 254;
    S.m_bSize = 1;
    S.m_pVarData = abTxBlock_g;
    memset(&R, 0, sizeof(R));
    R.m_wPdoCommuIndex = 0x1400;
    R.m_dwCanId = 0x180 + ID_A;
    R.m_bTxTyp = 254;
    R.m_bSize = 1;
    R.m_pVarData = abRxBlock_g;
    R.m_fpCallback = RxCallback;

    CHECK_RET(CcmDefineStaticPdoTab(NULL, 1), kCopInvalidParam);
    S.m_pVarData = NULL;
    CHECK_RET(CcmDefineStaticPdoTab(&S, 1), kCopInvalidParam);
    S.m_pVarData = abTxBlock_g;
    S.m_bSize = 9;
    CHECK_RET(CcmDefineStaticPdoTab(&S, 1), kCopPdoLengthExceeded);
    S.m_bSize = 1;
    S.m_wPdoCommuIndex = 0x1805;
    CHECK_RET(CcmDefineStaticPdoTab(&S, 1), kCopPdoNotExist);
    S.m_wPdoCommuIndex = 0x1800;
    S.m_bTxTyp = 0xF1;
    CHECK_RET(CcmDefineStaticPdoTab(&S, 1), kCopInvalidParam);
    S.m_bTxTyp = 254;
    CHECK_RET(CcmDefineStaticPdoTab(&S, 1), kCopSuccessful);
    CHECK_RET(CcmDefineStaticPdoTab(&R, 1), kCopSuccessful);

    /* CcmSignalStaticPdo: the block goes out with the next cycle */
    abTxBlock_g[0] = 0x42;
    CHECK_RET(CcmSignalStaticPdo(0x1400), kCopPdoNotExist);     /* an RPDO */
    CHECK_RET(CcmSignalStaticPdo(0x1805), kCopPdoNotExist);
    CHECK_RET(CcmSignalStaticPdo(0x1800), kCopSuccessful);
    ProcessNode(SIM_M);
    TestExpectFrame("M: static TPDO", 0x180 + ID_M, 1, ab42);
    ProcessNode(SIM_A);
    SimSelectNode(SIM_A);
    CHECK_EQ(TestReadU8(0x2042, 1), 0x42);

    /* A's TPDO lands in M's static block, M's callback runs */
    CHECK_RET(TestWriteU8(0x2040, 1, 0x31), kCopSuccessful);
    CHECK_RET(CcmSendPdo(0x1800), kCopSuccessful);
    ProcessNode(SIM_M);
    CHECK_EQ(abRxBlock_g[0], 0x31);
    CHECK_EQ(uRxCallbacks_g, 1);
    CHECK_EQ(wRxCallbackIndex_g, 0x1400);
    TestDrainSent();
}

static void CriticalSection (void)
{
    /* M holds received PDO data back while the application works on its block */
    SimSelectNode(SIM_M);
    CcmEnterCriticalSectionPdoProcess();
    CcmEnterCriticalSectionPdoProcess();        /* nested */
    SimSelectNode(SIM_A);
    CHECK_RET(TestWriteU8(0x2040, 1, 0x01), kCopSuccessful);
    CHECK_RET(CcmSendPdo(0x1800), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2040, 1, 0x02), kCopSuccessful);
    CHECK_RET(CcmSendPdo(0x1800), kCopSuccessful);
    ProcessNode(SIM_M);
    CHECK_EQ(abRxBlock_g[0], 0x31);
    CHECK_EQ(uRxCallbacks_g, 1);
    SimSelectNode(SIM_M);
    CcmLeaveCriticalSectionPdoProcess();
    ProcessNode(SIM_M);
    CHECK_EQ(abRxBlock_g[0], 0x31);             /* still one level held */
    SimSelectNode(SIM_M);
    CcmLeaveCriticalSectionPdoProcess();
    ProcessNode(SIM_M);
    CHECK_EQ(abRxBlock_g[0], 0x02);             /* the latest one */
    CHECK_EQ(uRxCallbacks_g, 2);
    TestDrainSent();
}

static void Sync (void)
{
    static CONST BYTE ab07[1] = { 0x07 };
    tPdoParam P;

    /* A's TPDO becomes synchronous (every SYNC) */
    SimSelectNode(SIM_A);
    CHECK_RET(TestWriteU8(0x2040, 1, 0x07), kCopSuccessful);
    memset(&P, 0, sizeof(P));
    P.m_bValidFlag = kPdoValidTxType;
    P.m_wPdoCommuIndex = 0x1800;
    P.m_bPdoType = kPdoTypeSend;
    P.m_bTxTyp = 1;
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);
    TestDrainSent();

    CHECK_RET(CcmConfigSyncConsumer(0x80, 0), kCopSuccessful);
    SimInject(0x080, 0, 0, NULL);
    ProcessNode(SIM_A);
    TestExpectFrame("A: TPDO on SYNC 0x80", 0x180 + ID_A, 1, ab07);

    /* another SYNC COB-ID */
    SimSelectNode(SIM_A);
    CHECK_RET(CcmConfigSyncConsumer(0x40000080UL, 0), kCopInvalidParam);   /* producing is CcmConfigSyncProducer's job */
    CHECK_RET(CcmConfigSyncConsumer(0x701, 0), kCopInvalidParam);          /* restricted (NMT error control) */
    CHECK_RET(CcmConfigSyncConsumer(0x85, 0), kCopSuccessful);
    ProcessNode(SIM_A);
    SimInject(0x080, 0, 0, NULL);
    ProcessNode(SIM_A);
    CHECK_EQ(SimSentPending(), 0);
    SimInject(0x085, 0, 0, NULL);
    ProcessNode(SIM_A);
    TestExpectFrame("A: TPDO on SYNC 0x85", 0x180 + ID_A, 1, ab07);

    /* CcmInitSyncConsumer: back to 0x1005, i.e. 0x80 (objdict_all.h has no 0x1005) */
    SimSelectNode(SIM_A);
    CHECK_RET(CcmInitSyncConsumer(), kCopSuccessful);
    ProcessNode(SIM_A);                         /* the receive filter follows in the next cycle */
    SimInject(0x080, 0, 0, NULL);
    ProcessNode(SIM_A);
    TestExpectFrame("A: TPDO on SYNC 0x80 again", 0x180 + ID_A, 1, ab07);
    TestDrainSent();
}

int main (void)
{
    SimReset();
    SimSetTrace(1);

    BeforeInit();
    CHECK_RET(TestInitNode(SIM_M, ID_M, ObdInitRamMaster, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(TestInitNode(SIM_A, ID_A, ObdInitRam, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestDrainSent();

    DefinePdos();
    Transfer();
    StaticPdos();
    CriticalSection();
    Sync();

    SimSelectNode(SIM_A);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    SimSelectNode(SIM_M);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_pdo_api");
}
