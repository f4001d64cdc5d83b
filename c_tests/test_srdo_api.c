/*
 * test_srdo_api.c - every exported SRDO/GFC function of the dynamic-mapping
 * build (c_tests/cfg) with at least one success and one refusal and the
 * exact tCopKernel code of each, on two nodes of the simulated bus:
 *
 *   node A (simulated node 0): objdict_all.h, node-ID 2: SRDO 1 transmits
 *          on 0x101/0x102, SRDO 2 (receive 0x103/0x104 by default) is
 *          reconfigured during the test;
 *   node P (simulated node 1): objdict_srdo_peer.h, node-ID 5: SRDO 1
 *          receives 0x101/0x102, SRDO 2 transmits on 0x103/0x104.
 *
 * CCM functions: CcmSendSrdo (one SRDO and 0 = all), CcmCheckSrdoConfig,
 * CcmSendGfc, CcmGetSrdoState, CcmSetSrdoState, CcmGetSrdoParam (NULL
 * skipping, the tSrdoMappParam pointers), CcmCalcSrdoCrc with the five
 * public vectors of SAFETY_BEHAVIOUR.md section 3. Module functions:
 * SrdoInit, SrdoAddInstance, SrdoDeleteInstance, SrdoNmtEvent, SrdoSend,
 * SrdoProcess, SrdoCheckConfig, SrdoSendGfc, SrdoGetState, SrdoSetState,
 * SrdoGetCommuParam, SrdoGetMappParam, SrdoCalcSrdoCrc.
 * (CcmStaticDefineSrdoVarFields / SrdoStaticDefineVarFields exist only with
 * static mapping: test_srdo_static.c.)
 */
#include "test_util.h"

#define SIM_A   0
#define SIM_P   1
#define ID_A    2
#define ID_P    5

extern tObdUnsigned8 bPeerIn_g;
extern tObdUnsigned8 bPeerInInv_g;
extern tObdUnsigned8 bPeerOut_g;
extern tObdUnsigned8 bPeerOutInv_g;
tCopKernel PUBLIC ObdInitRamSrdoPeer (void MEM* pInitParam_p);

static void Nmt (BYTE bCommand_p, BYTE bNode_p)
{
    BYTE abData[2];

    abData[0] = bCommand_p;
    abData[1] = bNode_p;
    SimInject(0x000, 0, 2, abData);
}

/* One CcmProcess on both nodes. */
static void ProcessBoth (void)
{
    SimSelectNode(SIM_A);
    (void) CcmProcess();
    SimSelectNode(SIM_P);
    (void) CcmProcess();
}

static int SawError (tCopKernel Code_p)
{
    unsigned i;

    for (i = 0; (i < uTestSrdoErrors_g) && (i < TEST_MAX_SRDO_ERRORS); i++)
    {
        if (aTestSrdoErrors_g[i] == Code_p)
        {
            return 1;
        }
    }
    return 0;
}

/* ---- the CRC of SAFETY_BEHAVIOUR.md section 3, written down independently --------- */

static WORD Crc16Xmodem (const BYTE* pbData_p, unsigned uLen_p)
{
    WORD wCrc = 0;
    unsigned i;
    int iBit;

    for (i = 0; i < uLen_p; i++)
    {
        wCrc ^= (WORD) (pbData_p[i] << 8);
        for (iBit = 0; iBit < 8; iBit++)
        {
            wCrc = (WORD) ((wCrc & 0x8000) ? ((wCrc << 1) ^ 0x1021) : (wCrc << 1));
        }
    }
    return wCrc;
}

static unsigned PutLe (BYTE* pb_p, DWORD dwValue_p, unsigned uBytes_p)
{
    unsigned i;

    for (i = 0; i < uBytes_p; i++)
    {
        pb_p[i] = (BYTE) (dwValue_p >> (8 * i));
    }
    return uBytes_p;
}

typedef struct
{
    BYTE  m_bDirection;
    WORD  m_wSct;
    BYTE  m_bSrvt;
    DWORD m_dwCob1;
    DWORD m_dwCob2;
    BYTE  m_bCount;
    DWORD m_adwMapp[4];
    WORD  m_wCrc;
} tCrcVector;

/* The byte stream of section 3: direction, SCT, SRVT, COB-ID 1, COB-ID 2,
 * mapping count, then per entry its subindex and the entry, multi-byte
 * fields little-endian. */
static unsigned CrcStream (const tCrcVector* pV_p, BYTE* pb_p)
{
    unsigned n = 0;
    BYTE i;

    pb_p[n++] = pV_p->m_bDirection;
    n += PutLe(&pb_p[n], pV_p->m_wSct, 2);
    pb_p[n++] = pV_p->m_bSrvt;
    n += PutLe(&pb_p[n], pV_p->m_dwCob1, 4);
    n += PutLe(&pb_p[n], pV_p->m_dwCob2, 4);
    pb_p[n++] = pV_p->m_bCount;
    for (i = 0; i < pV_p->m_bCount; i++)
    {
        pb_p[n++] = (BYTE) (i + 1);
        n += PutLe(&pb_p[n], pV_p->m_adwMapp[i], 4);
    }
    return n;
}

/* Writes a complete SRDO 1 configuration on the selected node (PRE-OPERATIONAL). */
static void WriteSrdo1 (const tCrcVector* pV_p)
{
    BYTE i;

    CHECK_RET(TestWriteU8(0x1301, 1, 0), kCopSuccessful);      /* COB-IDs and mapping need direction 0 */
    CHECK_RET(TestWriteU32(0x1301, 5, pV_p->m_dwCob1), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1301, 6, pV_p->m_dwCob2), kCopSuccessful);
    CHECK_RET(TestWriteU16(0x1301, 2, pV_p->m_wSct), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1301, 3, pV_p->m_bSrvt), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1381, 0, 0), kCopSuccessful);
    for (i = 0; i < pV_p->m_bCount; i++)
    {
        CHECK_RET(TestWriteU32(0x1381, (BYTE) (i + 1), pV_p->m_adwMapp[i]), kCopSuccessful);
    }
    CHECK_RET(TestWriteU8(0x1381, 0, pV_p->m_bCount), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1301, 1, pV_p->m_bDirection), kCopSuccessful);
}

/* The five public vectors of SAFETY_BEHAVIOUR.md section 3 ("CRC (object
 * 0x13FF)", table "Public test vectors"), each computed through
 * CcmCalcSrdoCrc and SrdoCalcSrdoCrc from parameters written into the
 * dictionary, and through the algorithm above from the byte stream. */
static void CrcVectors (void)
{
    static CONST tCrcVector aVector[5] = {
        { 1, 25, 20, 0x101, 0x102, 2, { 0x62000108, 0x62000208, 0, 0 }, 0xD879 },
        { 2, 25, 20, 0x101, 0x102, 2, { 0x62000108, 0x62000208, 0, 0 }, 0x7764 },
        { 1, 25, 20, 0x101, 0x102, 4, { 0x62000108, 0x62000208, 0x62000308, 0x62000408 }, 0xE57E },
        { 1, 25, 20, 0x101, 0x102, 4, { 0x63000110, 0x63000210, 0x62000108, 0x62000208 }, 0x25EA },
        { 2, 25, 20, 0x101, 0x102, 4, { 0x63000110, 0x63000210, 0x62000108, 0x62000208 }, 0xA3AF },
    };
    /* section 3: "Byte stream of the first row" */
    static CONST BYTE abFirstRow[23] = {
        0x01, 0x19, 0x00, 0x14, 0x01, 0x01, 0x00, 0x00, 0x02, 0x01, 0x00, 0x00,
        0x02, 0x01, 0x08, 0x01, 0x00, 0x62, 0x02, 0x08, 0x02, 0x00, 0x62 };
    static CONST BYTE abCheck[9] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };
    BYTE abStream[40];
    unsigned uLen;
    unsigned v;
    WORD wCrc;

    CHECK_EQ(Crc16Xmodem(abCheck, 9), 0x31C3);              /* CRC-16/XMODEM check value */
    uLen = CrcStream(&aVector[0], abStream);
    CHECK_EQ(uLen, sizeof(abFirstRow));
    CHECK(memcmp(abStream, abFirstRow, sizeof(abFirstRow)) == 0);

    SimSelectNode(SIM_P);
    for (v = 0; v < 5; v++)
    {
        WriteSrdo1(&aVector[v]);
        uLen = CrcStream(&aVector[v], abStream);
        CHECK_EQ(Crc16Xmodem(abStream, uLen), aVector[v].m_wCrc);
        wCrc = 0;
        CHECK_RET(CcmCalcSrdoCrc(0x1301, &wCrc), kCopSuccessful);
        CHECK_EQ(wCrc, aVector[v].m_wCrc);
        wCrc = 0;
        CHECK_RET(SrdoCalcSrdoCrc(0x1301, NULL, &wCrc), kCopSuccessful);
        CHECK_EQ(wCrc, aVector[v].m_wCrc);
    }
    /* refusals */
    CHECK_RET(CcmCalcSrdoCrc(0x1301, NULL), kCopInvalidParam);
    CHECK_RET(CcmCalcSrdoCrc(0x1303, &wCrc), kCopSrdoNotExist);
    CHECK_RET(CcmCalcSrdoCrc(0x1300, &wCrc), kCopSrdoNotExist);
    CHECK_RET(SrdoCalcSrdoCrc(0x1301, &wCrc, &wCrc), kCopInvalidParam);  /* the entry must be NULL (manual 2.11.13) */
    CHECK_RET(SrdoCalcSrdoCrc(0x1303, NULL, &wCrc), kCopSrdoNotExist);

    /* reset communication: the dictionary's parameters again */
    CHECK_RET(CcmNmtsExecCommand(kNmtCommResetCommunication), kCopSuccessful);
    TestProcess(1);
    CHECK_EQ(TestReadU8(0x1301, 1), 2);
    CHECK_EQ(TestReadU8(0x1381, 0), 2);
    CHECK_EQ(TestReadU8(0x13FE, 0), 0);
}

/* ---- the configuration check ---------------------------------------------------- */

static void ExpectCheck (tCopKernel Expected_p, WORD wExpectedIndex_p)
{
    WORD wIndex = 0xFFFF;

    CHECK_RET(CcmCheckSrdoConfig(&wIndex), Expected_p);
    if (Expected_p != kCopSuccessful)
    {
        CHECK_EQ(wIndex, wExpectedIndex_p);
    }
    wIndex = 0xFFFF;
    CHECK_RET(SrdoCheckConfig(&wIndex), Expected_p);
    if (Expected_p != kCopSuccessful)
    {
        CHECK_EQ(wIndex, wExpectedIndex_p);
    }
}

/* Recomputes both CRCs, then writes 0xA5: the check's code. */
static tCopKernel Declare (void)
{
    return TestSrdoMakeValid();
}

static void CheckConfigCodes (void)
{
    static CONST tCrcVector Wide = {
        2, 100, 20, 0x101, 0x102, 4, { 0x20540140, 0x20540240, 0x20540140, 0x20540240 }, 0 };
    static CONST tCrcVector Nibble = {
        2, 100, 20, 0x101, 0x102, 2, { 0x20500104, 0x20510104, 0, 0 }, 0 };
    static CONST tCrcVector Missing = {
        2, 100, 20, 0x101, 0x102, 2, { 0x20FF0108, 0x20510108, 0, 0 }, 0 };
    WORD wIndex = 0;

    SimSelectNode(SIM_P);
    /* factory state: 0x13FF holds 0 for both SRDOs */
    ExpectCheck(kCopSrdoCfgCrcError, 0x1301);
    CHECK_RET(TestWriteU8(0x13FE, 0, 0xA5), kCopSrdoCfgCrcError);
    CHECK_EQ(TestReadU8(0x13FE, 0), 0);
    CHECK_RET(CcmCheckSrdoConfig(NULL), kCopInvalidParam);
    CHECK_RET(SrdoCheckConfig(NULL), kCopInvalidParam);

    CHECK_RET(Declare(), kCopSuccessful);
    CHECK_EQ(TestReadU8(0x13FE, 0), 0xA5);
    ExpectCheck(kCopSuccessful, 0);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSuccessful);

    /* a changed parameter: 0x13FE drops to 0 before anything else */
    CHECK_RET(TestWriteU8(0x1302, 3, 25), kCopSuccessful);
    CHECK_EQ(TestReadU8(0x13FE, 0), 0);
    ExpectCheck(kCopSrdoCfgCrcError, 0x1302);

    /* SCT 0 of an active SRDO (written while it was off) */
    CHECK_RET(TestWriteU8(0x1302, 3, 20), kCopSuccessful);
    CHECK_RET(TestWriteU16(0x1302, 2, 0), kCopSrdoCfgTimingError);       /* not while active */
    CHECK_RET(TestWriteU8(0x1302, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU16(0x1302, 2, 0), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1302, 1, 1), kCopSuccessful);
    CHECK_RET(Declare(), kCopSrdoCfgTimingError);
    ExpectCheck(kCopSrdoCfgTimingError, 0x1302);
    /* SRVT above the SCT of a receive SRDO */
    CHECK_RET(TestWriteU8(0x1302, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU16(0x1302, 2, 50), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1302, 1, 1), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1301, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU16(0x1301, 2, 10), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1301, 1, 2), kCopSuccessful);
    CHECK_RET(Declare(), kCopSrdoCfgTimingError);
    ExpectCheck(kCopSrdoCfgTimingError, 0x1301);
    CHECK_RET(TestWriteU8(0x1301, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU16(0x1301, 2, 100), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1301, 1, 2), kCopSuccessful);
    CHECK_RET(Declare(), kCopSuccessful);

    /* COB-IDs: written one at a time, checked as a pair */
    CHECK_RET(TestWriteU32(0x1302, 6, 0x106), kCopSrdoInvalidCfg);       /* not while active */
    CHECK_RET(TestWriteU8(0x1302, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1302, 6, 0x103), kCopSrdoCfgIdError);       /* COB-ID 2 must be even */
    CHECK_RET(TestWriteU32(0x1302, 5, 0x181), kCopSrdoCfgIdError);       /* beyond 0x17F */
    CHECK_RET(TestWriteU32(0x1302, 6, 0x106), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1302, 1, 1), kCopSuccessful);
    CHECK_RET(Declare(), kCopSrdoCfgIdError);
    ExpectCheck(kCopSrdoCfgIdError, 0x1302);
    /* the COB-IDs of SRDO 1 a second time */
    CHECK_RET(TestWriteU8(0x1302, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1302, 5, 0x101), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1302, 6, 0x102), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1302, 1, 1), kCopSuccessful);
    CHECK_RET(Declare(), kCopSrdoCanIdAlreadyInUse);
    ExpectCheck(kCopSrdoCanIdAlreadyInUse, 0x1302);
    /* switched off, the same COB-IDs are no conflict */
    CHECK_RET(TestWriteU8(0x1302, 1, 0), kCopSuccessful);
    CHECK_RET(Declare(), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1302, 5, 0x103), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1302, 6, 0x104), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1302, 1, 1), kCopSuccessful);

    /* mapping */
    CHECK_RET(TestWriteU32(0x1381, 1, 0x20500108), kCopSrdoInvalidCfg);  /* not while active */
    WriteSrdo1(&Missing);
    CHECK_RET(Declare(), kCopSrdoErrorMapp);
    ExpectCheck(kCopSrdoErrorMapp, 0x1301);
    CHECK_RET(TestWriteU8(0x1381, 0, 5), kCopSrdoInvalidCfg);            /* active */
    CHECK_RET(TestWriteU8(0x1301, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1381, 0, 5), kCopSrdoErrorMapp);             /* only 4 entries */
    CHECK_RET(TestWriteU8(0x1381, 0, 3), kCopSuccessful);                /* odd */
    CHECK_RET(TestWriteU8(0x1301, 1, 2), kCopSuccessful);
    CHECK_RET(Declare(), kCopSrdoErrorMapp);
    WriteSrdo1(&Wide);                                                   /* 16 bytes of normal data */
    CHECK_RET(Declare(), kCopSrdoLengthExceeded);
    ExpectCheck(kCopSrdoLengthExceeded, 0x1301);
    /* an entry must map its object exactly (4 bits of an 8-bit object);
     * kCopSrdoGranularityMismatch needs a granularity above 8:
     * test_srdo_granularity.c */
    WriteSrdo1(&Nibble);
    CHECK_RET(Declare(), kCopSrdoErrorMapp);
    ExpectCheck(kCopSrdoErrorMapp, 0x1301);

    CHECK_RET(CcmNmtsExecCommand(kNmtCommResetCommunication), kCopSuccessful);
    TestProcess(1);
    CHECK_EQ(TestReadU8(0x13FE, 0), 0);
}

/* ---- transmission ------------------------------------------------------------------ */

static void SetA (BYTE bNormal_p, BYTE bInverted_p)
{
    SimSelectNode(SIM_A);
    CHECK_RET(TestWriteU8(0x2040, 1, bNormal_p), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2041, 1, bInverted_p), kCopSuccessful);
}

static void Transmission (void)
{
    static CONST BYTE ab5A[1] = { 0x5A };
    static CONST BYTE abA5[1] = { 0xA5 };
    static CONST BYTE ab33[1] = { 0x33 };
    static CONST BYTE abCC[1] = { 0xCC };
    unsigned uEvents;
    WORD wIndex = 0;

    /* PRE-OPERATIONAL */
    SimSelectNode(SIM_A);
    TestDrainSent();
    CHECK_RET(CcmSendSrdo(0x1301), kCopSrdoNmtError);
    CHECK_RET(SrdoSend(0x1301), kCopSrdoNmtError);
    CHECK_RET(CcmSendGfc(), kCopSrdoNmtError);
    CHECK_RET(SrdoSendGfc(), kCopSrdoNmtError);
    CHECK_RET(CcmSendSrdo(0), kCopSrdoNmtError);    /* "all": the first error, nothing sent */
    CHECK_EQ(SimSentPending(), 0);

    /* OPERATIONAL without a valid configuration, GFC parameter 0 */
    Nmt(0x01, ID_A);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    SimAdvanceMs(2);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSrdoInvalidCfg);
    CHECK_RET(CcmSendGfc(), kCopSrdoInvalid);
    CHECK_RET(TestWriteU8(0x1300, 0, 1), kCopSrdoNmtError);         /* no SRDO object changes in OPERATIONAL */
    CHECK_EQ(SimSentPending(), 0);

    /* PRE-OPERATIONAL again: SRDO 2 off, GFC on, configuration valid */
    Nmt(0x80, ID_A);
    TestProcess(1);
    CHECK_RET(TestWriteU8(0x1302, 1, 0), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1300, 0, 1), kCopSuccessful);
    CHECK_RET(TestSrdoMakeValid(), kCopSuccessful);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSuccessful);
    SetA(0x5A, 0xA5);
    TestDrainSent();
    Nmt(0x01, ID_A);
    TestProcess(1);

    /* first transmission 0.5 ms x node-ID = 1 ms after entering OPERATIONAL */
    CHECK_RET(CcmSendSrdo(0x1301), kCopSrdoNmtError);
    SimAdvanceTicks(5);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSrdoNmtError);
    SimAdvanceTicks(5);
    uEvents = uTestSrdoEvents_g;
    CHECK_RET(CcmSendSrdo(0x1301), kCopSuccessful);
    TestExpectFrame("SRDO 1 normal", 0x101, 1, ab5A);
    TestExpectFrame("SRDO 1 inverted", 0x102, 1, abA5);
    CHECK_EQ(uTestSrdoEvents_g, uEvents + 1);
    CHECK_EQ(bTestLastSrdoNode_g, SIM_A);
    CHECK_RET(SrdoSend(0x1301), kCopSuccessful);
    TestExpectFrame("SRDO 1 normal (SrdoSend)", 0x101, 1, ab5A);
    TestExpectFrame("SRDO 1 inverted (SrdoSend)", 0x102, 1, abA5);

    /* refusals in OPERATIONAL */
    CHECK_RET(CcmSendSrdo(0x1302), kCopSrdoInvalid);                /* direction 0 */
    CHECK_RET(SrdoSend(0x1302), kCopSrdoInvalid);
    CHECK_RET(CcmSendSrdo(0x1303), kCopSrdoNotExist);
    CHECK_RET(CcmSendSrdo(0x1341), kCopSrdoNotExist);
    CHECK_RET(SrdoSend(0x1310), kCopSrdoNotExist);
    CHECK_RET(CcmSendSrdo(0), kCopSuccessful);                       /* the one transmit SRDO */
    TestExpectFrame("all: SRDO 1 normal", 0x101, 1, ab5A);
    TestExpectFrame("all: SRDO 1 inverted", 0x102, 1, abA5);
    CHECK_EQ(SimSentPending(), 0);

    /* data not inverted: nothing is sent, AppSrdoError(kCopSrdoDataError) */
    SetA(0x5A, 0x00);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSrdoDataError);
    CHECK(SawError(kCopSrdoDataError));
    CHECK_EQ(SimSentPending(), 0);

    /* the driver refuses the frame: its code, also in AppSrdoError */
    SetA(0x5A, 0xA5);
    SimRefuseTx(SIM_A, 1);
    CHECK_RET(CcmSendSrdo(0x1301), kCopCdrvTxBuffHighOverrun);
    CHECK(SawError(kCopCdrvTxBuffHighOverrun));
    CHECK_EQ(SimSentPending(), 0);

    /* two transmit SRDOs: SRDO 2 sends 0x2042/0x2043 on 0x105/0x106 */
    Nmt(0x80, ID_A);
    TestProcess(1);
    CHECK_RET(TestWriteU32(0x1302, 5, 0x105), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1302, 6, 0x106), kCopSuccessful);
    CHECK_RET(TestWriteU16(0x1302, 2, 40), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1302, 1, 1), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2042, 1, 0x33), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2043, 1, 0xCC), kCopSuccessful);
    CHECK_RET(TestSrdoMakeValid(), kCopSuccessful);
    Nmt(0x01, ID_A);
    TestProcess(1);
    SimAdvanceMs(1);
    TestDrainSent();
    CHECK_RET(CcmSendSrdo(0), kCopSuccessful);
    TestExpectFrame("all: SRDO 1 normal", 0x101, 1, ab5A);
    TestExpectFrame("all: SRDO 1 inverted", 0x102, 1, abA5);
    TestExpectFrame("all: SRDO 2 normal", 0x105, 1, ab33);
    TestExpectFrame("all: SRDO 2 inverted", 0x106, 1, abCC);
    /* with 0 every transmit SRDO is tried, the first error returned */
    SetA(0x5A, 0x00);
    CHECK_RET(CcmSendSrdo(0), kCopSrdoDataError);
    TestExpectFrame("all after an error: SRDO 2 normal", 0x105, 1, ab33);
    TestExpectFrame("all after an error: SRDO 2 inverted", 0x106, 1, abCC);
    SetA(0x5A, 0xA5);
}

/* ---- reception, state, parameters, GFC on the partner --------------------------------- */

static void Reception (void)
{
    static CONST BYTE ab3C[1] = { 0x3C };
    static CONST BYTE abC3[1] = { 0xC3 };
    tSrdoCommuParam Commu;
    tSrdoMappParam Mapp;
    BYTE bState = 0;
    unsigned uGfc;

    /* P: GFC parameter 0 first (GFC ignored), then a valid configuration */
    SimSelectNode(SIM_P);
    uGfc = uTestGfcEvents_g;
    SimSelectNode(SIM_A);
    CHECK_RET(CcmSendGfc(), kCopSuccessful);
    TestExpectFrame("GFC", 0x001, 0, NULL);
    SimSelectNode(SIM_P);
    TestProcess(1);
    CHECK_EQ(uTestGfcEvents_g, uGfc);                               /* 0x1300 = 0 on P */
    CHECK_RET(TestWriteU8(0x1300, 0, 1), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1300, 0, 2), kCopObdValueToHigh);
    CHECK_RET(TestSrdoMakeValid(), kCopSuccessful);
    Nmt(0x01, ID_P);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);

    /* GFC from A reaches P's AppGfcEvent */
    SimSelectNode(SIM_A);
    CHECK_RET(SrdoSendGfc(), kCopSuccessful);
    TestExpectFrame("GFC (SrdoSendGfc)", 0x001, 0, NULL);
    SimSelectNode(SIM_P);
    TestProcess(1);
    CHECK_EQ(uTestGfcEvents_g, uGfc + 1);
    CHECK_EQ(bTestLastGfcNode_g, SIM_P);

    /* a valid pair from A */
    SimSelectNode(SIM_A);
    SetA(0x3C, 0xC3);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSuccessful);
    TestExpectFrame("A -> P normal", 0x101, 1, ab3C);
    TestExpectFrame("A -> P inverted", 0x102, 1, abC3);
    SimSelectNode(SIM_P);
    pfnTestSrdoEventHook_g = TestSrdoEventHandshake;
    TestProcess(1);
    pfnTestSrdoEventHook_g = NULL;
    CHECK_EQ(bTestLastSrdoNode_g, SIM_P);
    CHECK_EQ(wTestLastSrdoIndex_g, 0x1301);
    CHECK_EQ(bPeerIn_g, 0x3C);
    CHECK_EQ(bPeerInInv_g, 0xC3);

    /* status byte */
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState, 0x30);                                          /* processed by the handshake */
    CHECK_RET(SrdoGetState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState, 0x30);
    CHECK_RET(CcmGetSrdoState(NULL, 0x1301), kCopInvalidParam);
    CHECK_RET(SrdoGetState(NULL, 0x1301), kCopInvalidParam);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1303), kCopSrdoNotExist);
    CHECK_RET(SrdoGetState(&bState, 0x1303), kCopSrdoNotExist);
    CHECK_RET(CcmSetSrdoState(0xFF, 0x1301), kCopSuccessful);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState, 0xF0);                                          /* bits 0-3 reserved */
    CHECK_RET(SrdoSetState(0x00, 0x1301), kCopSuccessful);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState, 0x00);
    CHECK_RET(CcmSetSrdoState(0x30, 0x1303), kCopSrdoNotExist);
    CHECK_RET(SrdoSetState(0x30, 0x1300), kCopSrdoNotExist);

    /* parameters: the communication part and the mapped variables */
    memset(&Commu, 0xEE, sizeof(Commu));
    memset(&Mapp, 0xEE, sizeof(Mapp));
    CHECK_RET(CcmGetSrdoParam(0x1301, &Commu, &Mapp), kCopSuccessful);
    CHECK_EQ(Commu.m_bDirection, 2);
    CHECK_EQ(Commu.m_wSct, 100);
    CHECK_EQ(Mapp.m_bNoOfMappedObjects, 2);
    CHECK(Mapp.m_apMappedVariable[0] == (void*) &bPeerIn_g);
    CHECK(Mapp.m_apMappedVariable[1] == (void*) &bPeerInInv_g);
    CHECK(Mapp.m_apMappedVariable[2] == NULL);
    memset(&Commu, 0xEE, sizeof(Commu));
    memset(&Mapp, 0xEE, sizeof(Mapp));
    CHECK_RET(CcmGetSrdoParam(0x1302, NULL, &Mapp), kCopSuccessful);     /* NULL is skipped */
    CHECK(Mapp.m_apMappedVariable[0] == (void*) &bPeerOut_g);
    CHECK(Mapp.m_apMappedVariable[1] == (void*) &bPeerOutInv_g);
    CHECK_RET(CcmGetSrdoParam(0x1302, &Commu, NULL), kCopSuccessful);
    CHECK_EQ(Commu.m_bDirection, 1);
    CHECK_EQ(Commu.m_wSct, 50);
    CHECK_RET(CcmGetSrdoParam(0x1302, NULL, NULL), kCopSuccessful);
    CHECK_RET(CcmGetSrdoParam(0x1303, &Commu, &Mapp), kCopSrdoNotExist);
    CHECK_RET(CcmGetSrdoParam(0x1303, NULL, NULL), kCopSrdoNotExist);
    memset(&Commu, 0, sizeof(Commu));
    CHECK_RET(SrdoGetCommuParam(0x1301, &Commu), kCopSuccessful);
    CHECK_EQ(Commu.m_bDirection, 2);
    CHECK_RET(SrdoGetCommuParam(0x1301, NULL), kCopInvalidParam);
    CHECK_RET(SrdoGetCommuParam(0x1303, &Commu), kCopSrdoNotExist);
    memset(&Mapp, 0, sizeof(Mapp));
    CHECK_RET(SrdoGetMappParam(0x1302, &Mapp), kCopSuccessful);
    CHECK_EQ(Mapp.m_bNoOfMappedObjects, 2);
    CHECK(Mapp.m_apMappedVariable[0] == (void*) &bPeerOut_g);
    CHECK_RET(SrdoGetMappParam(0x1302, NULL), kCopInvalidParam);
    CHECK_RET(SrdoGetMappParam(0x1303, &Mapp), kCopSrdoNotExist);

    /* P cannot send its receive SRDO; its transmit SRDO goes out */
    CHECK_RET(CcmSendSrdo(0x1301), kCopSrdoRxTxConflict);
    CHECK_RET(SrdoSend(0x1301), kCopSrdoRxTxConflict);
}

/* ---- receive overruns: only a buffer that can hold SRDO frames raises kCopSrdoOverrun ------- */

/*
 * SRDO and GFC identifiers are defined in the driver's high buffer
 * (kCdrvMsgHigh), so an overrun of the low buffer loses non-safety frames
 * only: no SRDO error (SAFETY_BEHAVIOUR.md section 5, "A received frame that
 * overwrites an unprocessed one"). An overrun of the high buffer, or the
 * controller's own overrun (kCdrvOverrun, buffer unknown), still is one.
 */
static void RxOverruns (void)
{
    static CONST BYTE abUpload1000[8] = { 0x40, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00 };
    static CONST BYTE ab3C[1] = { 0x3C };
    static CONST BYTE abC3[1] = { 0xC3 };
    unsigned i;
    unsigned uEvents;
    unsigned uErrors;

    /* P's low buffer (CDRV_MAX_RX_BUFF_ENTRIES_LOW) overflows with SDO requests */
    SimSelectNode(SIM_P);
    TestProcess(1);
    TestDrainSent();
    for (i = 0; i < SimRxCapacity(SIM_P, 0); i++)
    {
        CHECK_EQ(SimInject(0x600 + ID_P, 0, 8, abUpload1000), 1);     /* queued at P */
    }
    CHECK_EQ(SimInject(0x600 + ID_P, 0, 8, abUpload1000), 0);         /* lost */
    CHECK_EQ(SimGetStatus(SIM_P) & kCdrvRxBuffLowOverrun, kCdrvRxBuffLowOverrun);
    CHECK_EQ(SimGetStatus(SIM_P) & kCdrvRxBuffHighOverrun, 0);

    /* then a valid pair from A: its event, no SRDO error */
    SimSelectNode(SIM_A);
    SetA(0x3C, 0xC3);
    CHECK_RET(CcmSendSrdo(0x1301), kCopSuccessful);
    TestExpectFrame("A -> P normal after a low overrun", 0x101, 1, ab3C);
    TestExpectFrame("A -> P inverted after a low overrun", 0x102, 1, abC3);
    SimSelectNode(SIM_P);
    uEvents = uTestSrdoEvents_g;
    uErrors = uTestSrdoErrors_g;
    pfnTestSrdoEventHook_g = TestSrdoEventHandshake;
    TestProcess(2);
    pfnTestSrdoEventHook_g = NULL;
    CHECK_EQ(uTestSrdoEvents_g, uEvents + 1);
    CHECK_EQ(uTestSrdoErrors_g, uErrors);
    CHECK_EQ(SimGetStatus(SIM_P) & kCdrvRxBuffLowOverrun, 0);       /* taken and cleared */
    TestDrainSent();

    /* the high buffer's overrun and the controller's are SRDO errors */
    uErrors = uTestSrdoErrors_g;
    pfnTestSrdoErrorHook_g = TestSrdoErrorHandshake;
    SimRaiseStatus(SIM_P, kCdrvRxBuffHighOverrun);
    TestProcess(1);
    CHECK_EQ(uTestSrdoErrors_g, uErrors + 1);
    CHECK(SawError(kCopSrdoOverrun));
    uErrors = uTestSrdoErrors_g;
    SimRaiseStatus(SIM_P, kCdrvOverrun);
    TestProcess(1);
    CHECK_EQ(uTestSrdoErrors_g, uErrors + 1);
    pfnTestSrdoErrorHook_g = NULL;
    TestDrainSent();
}

/* ---- the remaining module functions ---------------------------------------------------------- */

static void ModuleFunctions (void)
{
    static CONST BYTE abBad[1] = { 0x11 };
    static CONST BYTE ab3C[1] = { 0x3C };
    static CONST BYTE abC3[1] = { 0xC3 };
    tSrdoInitParam Init;
    unsigned uEvents;

    SimSelectNode(SIM_P);
    TestDrainSent();

    /* SrdoProcess: an error the application does not acknowledge */
    SimInject(0x101, 0, 1, abBad);
    SimInject(0x102, 0, 1, abBad);
    CHECK_RET(SrdoProcess(), kCopSrdoNotHandledInApp);
    CHECK(SawError(kCopSrdoNotHandledInApp));
    /* ... and one it does (manual 2.9.2) */
    pfnTestSrdoErrorHook_g = TestSrdoErrorHandshake;
    SimInject(0x101, 0, 1, abBad);
    SimInject(0x102, 0, 1, abBad);
    CHECK_RET(SrdoProcess(), kCopSuccessful);
    pfnTestSrdoErrorHook_g = NULL;
    CHECK_RET(SrdoProcess(), kCopSuccessful);

    /* SrdoNmtEvent: events that agree with the node's state */
    CHECK_RET(SrdoNmtEvent(kNmtEvEnterOperational), kCopSuccessful);
    CHECK_RET(SrdoNmtEvent(kNmtEvResetCommunication), kCopSuccessful);
    CHECK_RET(SrdoNmtEvent(kNmtEvEnterPreOperational), kCopSrdoNmtError);
    CHECK_RET(SrdoNmtEvent(kNmtEvEnterStopped), kCopSrdoNmtError);
    CHECK_RET(SrdoNmtEvent(0x77), kCopSrdoNmtError);

    /* SrdoDeleteInstance stops every SRDO until the next OPERATIONAL */
    SimAdvanceMs(3);
    CHECK_RET(CcmSendSrdo(0x1302), kCopSuccessful);
    CHECK_EQ(TestDrainSent(), 2);
    CHECK_RET(SrdoDeleteInstance(), kCopSuccessful);
    CHECK_RET(CcmSendSrdo(0x1302), kCopSrdoNmtError);
    uEvents = uTestSrdoEvents_g;
    SimInject(0x101, 0, 1, ab3C);
    SimInject(0x102, 0, 1, abC3);
    TestProcess(1);
    CHECK_EQ(uTestSrdoEvents_g, uEvents);                           /* not received */
    Nmt(0x80, ID_P);
    TestProcess(1);
    Nmt(0x01, ID_P);
    TestProcess(1);
    SimAdvanceMs(3);
    CHECK_RET(CcmSendSrdo(0x1302), kCopSuccessful);
    CHECK_EQ(TestDrainSent(), 2);

    /* SrdoInit / SrdoAddInstance: re-read the objects, stop until OPERATIONAL */
    memset(&Init, 0, sizeof(Init));
    Init.m_bGranularity = SRDO_GRANULARITY;
    CHECK_RET(SrdoInit(NULL), kCopInvalidParam);
    CHECK_RET(SrdoAddInstance(NULL), kCopInvalidParam);
    Init.m_bGranularity = 16;
    CHECK_RET(SrdoInit(&Init), kCopSrdoGranularityMismatch);
    CHECK_RET(SrdoAddInstance(&Init), kCopSrdoGranularityMismatch);
    Init.m_bGranularity = SRDO_GRANULARITY;
    CHECK_RET(SrdoInit(&Init), kCopSuccessful);
    CHECK_RET(CcmSendSrdo(0x1302), kCopSrdoNmtError);
    CHECK_RET(SrdoAddInstance(&Init), kCopSuccessful);
    Nmt(0x80, ID_P);
    TestProcess(1);
    Nmt(0x01, ID_P);
    TestProcess(1);
    SimAdvanceMs(3);
    CHECK_RET(CcmSendSrdo(0x1302), kCopSuccessful);
    CHECK_EQ(TestDrainSent(), 2);
}

/* ---- before CcmInitCANopen ----------------------------------------------------------------- */

static void BeforeInit (void)
{
    tSrdoInitParam Init;
    tSrdoCommuParam Commu;
    tSrdoMappParam Mapp;
    WORD wValue = 0;
    BYTE bState = 0;

    memset(&Init, 0, sizeof(Init));
    Init.m_bGranularity = SRDO_GRANULARITY;
    SimSelectNode(SIM_A);
    CHECK_RET(SrdoInit(&Init), kCopIllegalInstance);
    CHECK_RET(SrdoAddInstance(&Init), kCopIllegalInstance);
    CHECK_RET(SrdoDeleteInstance(), kCopIllegalInstance);
    CHECK_RET(SrdoNmtEvent(kNmtEvEnterOperational), kCopIllegalInstance);
    CHECK_RET(SrdoSend(0x1301), kCopIllegalInstance);
    CHECK_RET(SrdoProcess(), kCopIllegalInstance);
    CHECK_RET(SrdoCheckConfig(&wValue), kCopIllegalInstance);
    CHECK_RET(SrdoSendGfc(), kCopIllegalInstance);
    CHECK_RET(SrdoGetState(&bState, 0x1301), kCopIllegalInstance);
    CHECK_RET(SrdoSetState(0, 0x1301), kCopIllegalInstance);
    CHECK_RET(SrdoGetCommuParam(0x1301, &Commu), kCopIllegalInstance);
    CHECK_RET(SrdoGetMappParam(0x1301, &Mapp), kCopIllegalInstance);
    CHECK_RET(SrdoCalcSrdoCrc(0x1301, NULL, &wValue), kCopIllegalInstance);
    CHECK_RET(CcmCalcSrdoCrc(0x1301, &wValue), kCopIllegalInstance);
    CHECK_RET(CcmGetSrdoParam(0x1301, &Commu, &Mapp), kCopIllegalInstance);
}

int main (void)
{
    SimReset();
    SimSetTrace(1);
    TestSrdoClear();

    BeforeInit();
    CHECK_RET(TestInitNode(SIM_A, ID_A, ObdInitRam, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(TestInitNode(SIM_P, ID_P, ObdInitRamSrdoPeer, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    ProcessBoth();
    TestDrainSent();

    CrcVectors();
    CheckConfigCodes();
    Transmission();
    Reception();
    RxOverruns();
    ModuleFunctions();

    SimSelectNode(SIM_A);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    SimSelectNode(SIM_P);
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_srdo_api");
}
