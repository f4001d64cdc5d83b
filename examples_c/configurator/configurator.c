/*
 * configurator.c - node 1, the configurator: the NMT master of the network
 * and a configuration tool with its own SDO client (CcmSdocStartTransfer).
 *
 * What it does, one step at a time (aScript_g):
 *  1. waits for the boot-up of node 2 and node 3 and starts the network
 *     with the NMT broadcast of seed 004 ("start remote node", 000 [2] 01 00);
 *  2. reproduces the three examples of seed 004 against the I/O node
 *     (node 2): write 0x6200/1 = 0xFF, read 0x6000/1, read 0x6401/1, and
 *     compares request and answer on the bus with the seed byte for byte;
 *  3. configures SRDO 1 of the safety node (node 3) over SDO: communication
 *     and mapping parameters, the CRC (computed by the tool, srdo_crc.c) into
 *     0x13FF, 0xA5 into 0x13FE - in PRE-OPERATIONAL, because a safety node
 *     refuses SRDO parameters while OPERATIONAL (shown first);
 *  4. starts node 3 and consumes its safety data with its own receive SRDO
 *     (AppSrdoEvent), while the guard door is opened.
 *
 * Data of SDO transfers are CANopen bytes (little-endian); the tool
 * converts values itself, so it works the same on every CPU.
 */
#include <stdio.h>
#include <string.h>

#include "cdrv_sim.h"
#include "configurator.h"

#define CLIENT_IO      0x1280   /* SDO client channel -> node 2 */
#define CLIENT_SAFETY  0x1281   /* SDO client channel -> node 3 */

/* The safety node's SRDO 1 as the tool configures it: transmit, refresh
 * time 25 ms, SRVT 20 ms, the predefined COB-IDs of node 3, door state and
 * tool position with their inverted copies (objdict_safety.h). */
static CONST tSrdoConfig SafetyNodeSrdo_g = {
    1, 25, 20, 0x105, 0x106, 4, { 0x20000108, 0x20010108, 0x20000210, 0x20010210 } };

/* The configurator's own receive SRDO for the same data
 * (objdict_configurator.h): SCT 60 ms. */
static CONST tSrdoConfig OwnSrdo_g = {
    2, 60, 20, 0x105, 0x106, 4, { 0x21000108, 0x21010108, 0x21000210, 0x21010210 } };

/* SRDO data received from node 3 (objdict_configurator.h) */
tObdUnsigned8  bCfgDoorClosed_g;
tObdUnsigned8  bCfgDoorClosedInv_g;
tObdUnsigned16 wCfgPosition_g;
tObdUnsigned16 wCfgPositionInv_g;

/* ---- the script ------------------------------------------------------------- */

typedef enum
{
    kStepWaitBootups,       /* boot-up of both slaves */
    kStepNmt,               /* CcmSendNmtCommand(m_bNode, m_Command) */
    kStepWrite,             /* SDO download of m_bLen bytes of m_dwValue */
    kStepWriteCrc,          /* SDO download of the CRC of SafetyNodeSrdo_g */
    kStepRead,              /* SDO upload, m_bLen bytes expected = m_dwValue */
    kStepWait,              /* m_dwValue ms */
    kStepOpenDoor,          /* the safety node's door opens */
    kStepEnd
} tStepType;

typedef struct
{
    tStepType   m_Type;
    const char* m_pszWhat;
    WORD        m_wClient;
    WORD        m_wIndex;
    BYTE        m_bSub;
    BYTE        m_bLen;
    DWORD       m_dwValue;
    DWORD       m_dwAbort;          /* the abort code the step must end with (0: none) */
    BYTE        m_bNode;            /* NMT */
    tNmtCommand m_Command;
    int         m_iSeedExample;     /* 1..3: compare with seed 004 */
} tStep;

#define WRITE(what, client, index, sub, len, value) \
    { kStepWrite, what, client, index, sub, len, value, 0, 0, 0, 0 }
#define READ(what, client, index, sub, len, value) \
    { kStepRead, what, client, index, sub, len, value, 0, 0, 0, 0 }
#define NMT(what, node, cmd) \
    { kStepNmt, what, 0, 0, 0, 0, 0, 0, node, cmd, 0 }

static CONST tStep aScript_g[] = {
    { kStepWaitBootups, "wait for the boot-up of node 2 and node 3", 0, 0, 0, 0, 0, 0, 0, 0, 0 },
    NMT("seed 004, network start: NMT start remote node, all nodes", 0, kNmtCommStartRemoteNode),
    { kStepWait, "let the nodes enter OPERATIONAL", 0, 0, 0, 0, 10, 0, 0, 0, 0 },

    /* seed 004, examples 1-3, against the I/O node */
    { kStepWrite, "seed 004 example 1: write 0x6200/1 = 0xFF (8 digital outputs)",
      CLIENT_IO, 0x6200, 1, 1, 0xFF, 0, 0, 0, 1 },
    { kStepRead, "seed 004 example 2: read 0x6000/1 (8 digital inputs)",
      CLIENT_IO, 0x6000, 1, 1, 0x01, 0, 0, 0, 2 },
    { kStepRead, "seed 004 example 3: read 0x6401/1 (analog input 1)",
      CLIENT_IO, 0x6401, 1, 2, 0x1234, 0, 0, 0, 3 },

    /* the safety node: parameters only in PRE-OPERATIONAL */
    { kStepWrite, "node 3 is OPERATIONAL: SRDO 0x1301/1 direction 0 (must be refused)",
      CLIENT_SAFETY, 0x1301, 1, 1, 0, SDOAC_DATA_NOT_TRANSF_DUE_DEVICE_STATE, 0, 0, 0 },
    NMT("node 3 to PRE-OPERATIONAL", ID_SAFETY_NODE, kNmtCommEnterPreOperational),
    { kStepWait, "", 0, 0, 0, 0, 2, 0, 0, 0, 0 },
    WRITE("SRDO 0x1301/1 direction 0 (COB-IDs and mapping only change while off)", CLIENT_SAFETY, 0x1301, 1, 1, 0),
    WRITE("SRDO 0x1301/5 COB-ID normal data 0x105", CLIENT_SAFETY, 0x1301, 5, 4, 0x105),
    WRITE("SRDO 0x1301/6 COB-ID inverted data 0x106", CLIENT_SAFETY, 0x1301, 6, 4, 0x106),
    WRITE("SRDO 0x1301/2 refresh time 25 ms", CLIENT_SAFETY, 0x1301, 2, 2, 25),
    WRITE("SRDO 0x1301/3 SRVT 20 ms", CLIENT_SAFETY, 0x1301, 3, 1, 20),
    WRITE("SRDO mapping 0x1381/0 = 0", CLIENT_SAFETY, 0x1381, 0, 1, 0),
    WRITE("SRDO mapping 0x1381/1 = 0x20000108 (door closed)", CLIENT_SAFETY, 0x1381, 1, 4, 0x20000108),
    WRITE("SRDO mapping 0x1381/2 = 0x20010108 (door closed, inverted)", CLIENT_SAFETY, 0x1381, 2, 4, 0x20010108),
    WRITE("SRDO mapping 0x1381/3 = 0x20000210 (tool position)", CLIENT_SAFETY, 0x1381, 3, 4, 0x20000210),
    WRITE("SRDO mapping 0x1381/4 = 0x20010210 (tool position, inverted)", CLIENT_SAFETY, 0x1381, 4, 4, 0x20010210),
    WRITE("SRDO mapping 0x1381/0 = 4", CLIENT_SAFETY, 0x1381, 0, 1, 4),
    WRITE("SRDO 0x1301/1 direction 1 (transmit)", CLIENT_SAFETY, 0x1301, 1, 1, 1),
    { kStepWriteCrc, "0x13FF/1 = CRC of the configuration", CLIENT_SAFETY, 0x13FF, 1, 2, 0, 0, 0, 0, 0 },
    WRITE("0x13FE = 0xA5: configuration valid (node 3 checks it)", CLIENT_SAFETY, 0x13FE, 0, 1, 0xA5),
    READ("read back 0x13FE", CLIENT_SAFETY, 0x13FE, 0, 1, 0xA5),
    NMT("node 3: NMT start remote node", ID_SAFETY_NODE, kNmtCommStartRemoteNode),
    { kStepWait, "safety data flowing", 0, 0, 0, 0, 100, 0, 0, 0, 0 },
    { kStepOpenDoor, "the guard door at node 3 opens", 0, 0, 0, 0, 0, 0, 0, 0, 0 },
    { kStepWait, "", 0, 0, 0, 0, 60, 0, 0, 0, 0 },
    { kStepEnd, "end of the script", 0, 0, 0, 0, 0, 0, 0, 0, 0 },
};

#define SCRIPT_STEPS (sizeof(aScript_g) / sizeof(aScript_g[0]))

/* Seed 004, examples 1-3: request and answer (identifier 1536+2 / 1408+2).
 * The seed's table of example 3 gives the request's index high byte as
 * 0x40; H(0x6401) is 0x64, as in its answer - 0x64 is used. */
static CONST BYTE aabSeedRequest_g[3][8] = {
    { 0x2F, 0x00, 0x62, 0x01, 0xFF, 0x00, 0x00, 0x00 },
    { 0x40, 0x00, 0x60, 0x01, 0x00, 0x00, 0x00, 0x00 },
    { 0x40, 0x01, 0x64, 0x01, 0x00, 0x00, 0x00, 0x00 } };
static CONST BYTE aabSeedAnswer_g[3][8] = {
    { 0x60, 0x00, 0x62, 0x01, 0x00, 0x00, 0x00, 0x00 },
    { 0x4F, 0x00, 0x60, 0x01, 0x01, 0x00, 0x00, 0x00 },
    { 0x4B, 0x01, 0x64, 0x01, 0x34, 0x12, 0x00, 0x00 } };

/* ---- state ---------------------------------------------------------------------- */

static unsigned uStep_g;
static int      fStepStarted_g;
static DWORD    dwWaitStart_g;
static int      fTransferRunning_g;
static BYTE     abData_g[4];                /* SDO data, CANopen byte order */
static unsigned uBootups_g;
static unsigned uFailures_g;
static unsigned uSeedMatches_g;
static unsigned uSrdoReceived_g;
static int      fDoorOpenSeen_g;
static WORD     wNode3Crc_g;
static tSimFrame LastRequest_g;
static tSimFrame LastAnswer_g;

static void Fail (const char* pszWhy_p)
{
    Log("configurator", "ERROR: %s", pszWhy_p);
    uFailures_g++;
}

static void PutLe (BYTE* pb_p, DWORD dwValue_p, unsigned uLen_p)
{
    unsigned i;

    for (i = 0; i < uLen_p; i++)
    {
        pb_p[i] = (BYTE) (dwValue_p >> (8 * i));
    }
}

static DWORD GetLe (const BYTE* pb_p, unsigned uLen_p)
{
    DWORD dwValue = 0;
    unsigned i;

    for (i = 0; i < uLen_p; i++)
    {
        dwValue |= (DWORD) pb_p[i] << (8 * i);
    }
    return dwValue;
}

/* ---- callbacks ------------------------------------------------------------------ */

static tCopKernel PUBLIC NmtmEvent (BYTE bNodeId_p, tNmtErrCtrlEvent Event_p)
{
    if (Event_p == kNmtErrCtrlEvBootupReceived)
    {
        Log("configurator", "boot-up of node %u", (unsigned) bNodeId_p);
        uBootups_g++;
    }
    return kCopSuccessful;
}

/* Reset communication: the configurator's own receive SRDO (manual 2.9.5),
 * its CRC from the library and, as a check of the tool's algorithm, from
 * srdo_crc.c - both must agree. */
static void ConfigureOwnSrdo (void)
{
    BYTE bOff = 0;
    BYTE bValid = 0xA5;
    WORD wCrcLib = 0;
    WORD wCrcTool = CfgSrdoCrc(&OwnSrdo_g);
    tCopKernel Ret;

    Ret = CcmWriteObject(0x1301, 1, &bOff, 1);
    if (Ret == kCopSuccessful) Ret = CcmWriteObject(0x1301, 5, &OwnSrdo_g.m_dwCobId1, sizeof(DWORD));
    if (Ret == kCopSuccessful) Ret = CcmWriteObject(0x1301, 6, &OwnSrdo_g.m_dwCobId2, sizeof(DWORD));
    if (Ret == kCopSuccessful) Ret = CcmWriteObject(0x1301, 2, &OwnSrdo_g.m_wSctMs, sizeof(WORD));
    if (Ret == kCopSuccessful) Ret = CcmWriteObject(0x1301, 3, &OwnSrdo_g.m_bSrvtMs, sizeof(BYTE));
    if (Ret == kCopSuccessful) Ret = CcmWriteObject(0x1301, 1, &OwnSrdo_g.m_bDirection, sizeof(BYTE));
    if (Ret == kCopSuccessful) Ret = CcmCalcSrdoCrc(0x1301, &wCrcLib);
    if (Ret == kCopSuccessful) Ret = CcmWriteObject(0x13FF, 1, &wCrcLib, sizeof(WORD));
    if (Ret == kCopSuccessful) Ret = CcmWriteObject(0x13FE, 0, &bValid, 1);
    if (Ret != kCopSuccessful)
    {
        Fail("own SRDO configuration refused");
        return;
    }
    Log("configurator", "own receive SRDO 0x1301: SCT %u ms, COB-IDs 0x105/0x106, CRC 0x%04X (CcmCalcSrdoCrc) = "
        "0x%04X (the tool's algorithm)", (unsigned) OwnSrdo_g.m_wSctMs, (unsigned) wCrcLib, (unsigned) wCrcTool);
    if (wCrcLib != wCrcTool)
    {
        Fail("the tool's CRC differs from the library's");
    }
}

tCopKernel PUBLIC ConfiguratorNmtEvent (tNmtEvent NmtEvent_p)
{
    if (NmtEvent_p == kNmtEvResetCommunication)
    {
        ConfigureOwnSrdo();
    }
    return kCopSuccessful;
}

void ConfiguratorSrdoEvent (WORD wSrdoCommuIndex_p)
{
    BYTE bState = 0;
    int fConsistent = ((bCfgDoorClosed_g ^ bCfgDoorClosedInv_g) == 0xFF) &&
                      ((wCfgPosition_g ^ wCfgPositionInv_g) == 0xFFFF);

    uSrdoReceived_g++;
    if (!bCfgDoorClosed_g)
    {
        fDoorOpenSeen_g = 1;
    }
    Log("configurator", "AppSrdoEvent(0x%04X): guard door %s, tool position %u.%u mm%s", (unsigned) wSrdoCommuIndex_p,
        bCfgDoorClosed_g ? "closed" : "OPEN", (unsigned) (wCfgPosition_g / 10), (unsigned) (wCfgPosition_g % 10),
        fConsistent ? "" : " (copies differ!)");
    if (!fConsistent)
    {
        Fail("normal and inverted data differ");
    }
    if (CcmGetSrdoState(&bState, wSrdoCommuIndex_p) == kCopSuccessful)
    {
        (void) CcmSetSrdoState((BYTE) (bState | 0x30), wSrdoCommuIndex_p);
    }
}

void ConfiguratorSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    BYTE bState = 0;

    Log("configurator", "AppSrdoError(0x%04X, %s)", (unsigned) wSrdoCommuIndex_p,
        (ErrorCode_p == kCopSrdoSctTimeout) ? "kCopSrdoSctTimeout: no safety data within the SCT" : "error");
    if ((CcmGetSrdoState(&bState, wSrdoCommuIndex_p) == kCopSuccessful) && ((bState & 0x30) == 0x10))
    {
        (void) CcmSetSrdoState((BYTE) ((bState | 0x30) ^ 0xC0), wSrdoCommuIndex_p);
    }
}

/* ---- the engine --------------------------------------------------------------- */

void ConfiguratorStart (void)
{
    static CONST BYTE abSlaves[2] = { ID_IO_NODE, ID_SAFETY_NODE };
    tSdocParam aClient[2];

    (void) CcmInitNmtmEx(NmtmEvent);
    (void) CcmDefineSlaveTab(abSlaves, 2);
    memset(aClient, 0, sizeof(aClient));
    aClient[0].m_bValidFlags = kSdocValidFlagServerNodeId;
    aClient[0].m_wClientIndex = CLIENT_IO;
    aClient[0].m_bServerNodeId = ID_IO_NODE;
    aClient[1].m_bValidFlags = kSdocValidFlagServerNodeId;
    aClient[1].m_wClientIndex = CLIENT_SAFETY;
    aClient[1].m_bServerNodeId = ID_SAFETY_NODE;
    if (CcmSdocDefineClientTab(aClient, 2) != kCopSuccessful)
    {
        Fail("CcmSdocDefineClientTab");
    }
    wNode3Crc_g = CfgSrdoCrc(&SafetyNodeSrdo_g);
}

/* The bus as the tool's CAN monitor sees it: remembers the last SDO
 * request of the running transfer and its answer. */
static void Monitor (const tStep* pStep_p)
{
    tSimFrame Frame;
    BYTE bServer = (pStep_p->m_wClient == CLIENT_IO) ? ID_IO_NODE : ID_SAFETY_NODE;

    while (SimTakeSentFrame(&Frame))
    {
        if (Frame.m_dwId == 0x600UL + bServer)
        {
            LastRequest_g = Frame;
        }
        else if (Frame.m_dwId == 0x580UL + bServer)
        {
            LastAnswer_g = Frame;
        }
    }
}

static void CompareWithSeed (int iExample_p)
{
    const BYTE* pbReq = aabSeedRequest_g[iExample_p - 1];
    const BYTE* pbAns = aabSeedAnswer_g[iExample_p - 1];

    if ((LastRequest_g.m_dwId == 1536 + 2) && (LastRequest_g.m_bDlc == 8) &&
        (memcmp(LastRequest_g.m_abData, pbReq, 8) == 0) && (LastAnswer_g.m_dwId == 1408 + 2) &&
        (LastAnswer_g.m_bDlc == 8) && (memcmp(LastAnswer_g.m_abData, pbAns, 8) == 0))
    {
        Log("configurator", "request and answer match seed 004 example %d byte for byte", iExample_p);
        uSeedMatches_g++;
    }
    else
    {
        Fail("frames differ from seed 004");
    }
}

static tCopKernel StartTransfer (const tStep* pStep_p, int fUpload_p)
{
    tSdocTransferParam Transfer;

    memset(&Transfer, 0, sizeof(Transfer));
    Transfer.m_wClientIndex = pStep_p->m_wClient;
    Transfer.m_wObjIndex = pStep_p->m_wIndex;
    Transfer.m_bObjSubIndex = pStep_p->m_bSub;
    Transfer.m_pData = abData_g;
    Transfer.m_DataLen = pStep_p->m_bLen;
    Transfer.m_SdocType = fUpload_p ? kSdocTypeSegUp : kSdocTypeSegDown;
    memset(&LastRequest_g, 0, sizeof(LastRequest_g));
    memset(&LastAnswer_g, 0, sizeof(LastAnswer_g));
    return CcmSdocStartTransfer(&Transfer);
}

/* A finished transfer: the result the step expects? */
static void TransferDone (const tStep* pStep_p, tSdocState State_p, DWORD dwAbort_p)
{
    if (pStep_p->m_dwAbort != 0)
    {
        if (dwAbort_p == pStep_p->m_dwAbort)
        {
            Log("configurator", "    refused as expected: SDO abort 0x%08lX", (unsigned long) dwAbort_p);
        }
        else
        {
            Fail("expected an SDO abort");
        }
        return;
    }
    if (State_p != kSdocTransferFinished)
    {
        char szWhy[64];
        sprintf(szWhy, "SDO abort 0x%08lX", (unsigned long) dwAbort_p);
        Fail(szWhy);
        return;
    }
    if (pStep_p->m_Type == kStepRead)
    {
        DWORD dwValue = GetLe(abData_g, pStep_p->m_bLen);
        Log("configurator", "    value 0x%0*lX", 2 * pStep_p->m_bLen, (unsigned long) dwValue);
        if (dwValue != pStep_p->m_dwValue)
        {
            Fail("unexpected value");
        }
    }
    else
    {
        Log("configurator", "    done");
    }
    if (pStep_p->m_iSeedExample != 0)
    {
        CompareWithSeed(pStep_p->m_iSeedExample);
    }
}

int ConfiguratorStep (void)
{
    const tStep* pStep;
    DWORD dwNow = (DWORD) TgtGetTickCount();
    tSdocState State = kSdocTransferNotActive;
    DWORD dwAbort = 0;
    tCopKernel Ret = kCopSuccessful;

    if (uStep_g >= SCRIPT_STEPS)
    {
        return 0;
    }
    pStep = &aScript_g[uStep_g];
    Monitor(pStep);

    if (fTransferRunning_g)
    {
        (void) CcmSdocGetState(pStep->m_wClient, &State, &dwAbort);
        if (State == kSdocTransferRunning)
        {
            return 1;
        }
        fTransferRunning_g = 0;
        TransferDone(pStep, State, dwAbort);
        uStep_g++;
        fStepStarted_g = 0;
        return 1;
    }

    if (!fStepStarted_g && (pStep->m_pszWhat[0] != '\0'))
    {
        Log("configurator", "%s", pStep->m_pszWhat);
    }
    switch (pStep->m_Type)
    {
        case kStepWaitBootups:
            fStepStarted_g = 1;
            if (uBootups_g < 2)
            {
                return 1;
            }
            break;

        case kStepNmt:
            Ret = CcmSendNmtCommand(pStep->m_bNode, pStep->m_Command);
            break;

        case kStepWait:
            if (!fStepStarted_g)
            {
                fStepStarted_g = 1;
                dwWaitStart_g = dwNow;
            }
            if ((dwNow - dwWaitStart_g) < pStep->m_dwValue * 10)
            {
                return 1;
            }
            break;

        case kStepWrite:
        case kStepWriteCrc:
            if (pStep->m_Type == kStepWriteCrc)
            {
                Log("configurator", "    CRC 0x%04X computed by the tool from the values written",
                    (unsigned) wNode3Crc_g);
                PutLe(abData_g, wNode3Crc_g, 2);
            }
            else
            {
                PutLe(abData_g, pStep->m_dwValue, pStep->m_bLen);
            }
            Ret = StartTransfer(pStep, 0);
            fTransferRunning_g = (Ret == kCopSuccessful);
            break;

        case kStepRead:
            memset(abData_g, 0, sizeof(abData_g));
            Ret = StartTransfer(pStep, 1);
            fTransferRunning_g = (Ret == kCopSuccessful);
            break;

        case kStepOpenDoor:
            SafetyNodeOpenDoor();
            break;

        case kStepEnd:
            break;
    }
    if (Ret != kCopSuccessful)
    {
        Fail("the step could not start");
    }
    if (!fTransferRunning_g)
    {
        uStep_g++;
        fStepStarted_g = 0;
    }
    else
    {
        fStepStarted_g = 1;
    }
    return 1;
}

int ConfiguratorResult (void)
{
    int fOk = (uFailures_g == 0) && (uSeedMatches_g == 3) && (uSrdoReceived_g >= 3) && fDoorOpenSeen_g &&
              (uStep_g >= SCRIPT_STEPS);

    Log("configurator", "result: %u of 3 seed 004 examples byte for byte, %u safety SRDOs received, door opening "
        "%s, %u error(s)", uSeedMatches_g, uSrdoReceived_g, fDoorOpenSeen_g ? "seen" : "NOT seen", uFailures_g);
    return fOk ? 0 : 1;
}
