/*
 * main.c - the host application of the README section "Your own
 * application on the host": two safety nodes, each with its own
 * dictionary, in one program on the simulated CAN bus. The sensor (node-ID
 * 1) sends the global fail-safe command (GFC, CiA 304: identifier 0x001,
 * no data); the actuator (node-ID 2) receives it in AppGfcEvent. The App*
 * callbacks exist once in the program, so they ask SimSelectedNode() which
 * node's stack is calling.
 *
 * Exit status 0 when the actuator, and only the actuator, saw the GFC.
 */
#include <stdio.h>
#include <string.h>

#include "cdrv_sim.h"

#define SIM_SENSOR   0
#define SIM_ACTUATOR 1

/* The init functions objdef.h made from the two dictionaries
 * (OBD_INIT_RAM_NAME in objdict_sensor.c / objdict_actuator.c). */
tCopKernel PUBLIC ObdInitRamSensor (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamActuator (void MEM* pInitParam_p);

static unsigned auGfcSeen_g[2];

/* ---- the SRDO callbacks of the library, shared by both nodes ------------------ */

tCopKernel PUBLIC AppGfcEvent (void)
{
    BYTE bNode = SimSelectedNode();

    printf("%s: AppGfcEvent\n", (bNode == SIM_ACTUATOR) ? "actuator" : "sensor");
    if (bNode < 2)
    {
        auGfcSeen_g[bNode]++;
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoEvent (WORD wSrdoCommuIndex_p)
{
    (void) wSrdoCommuIndex_p;
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    (void) wSrdoCommuIndex_p;
    (void) ErrorCode_p;
    return kCopSuccessful;
}

static tCopKernel PUBLIC AppNmtEvent (tNmtEvent NmtEvent_p)
{
    (void) NmtEvent_p;
    return kCopSuccessful;
}

/* ---- start-up ------------------------------------------------------------------ */

static tCcmInitParam aInit_g[2];

static tCopKernel StartNode (BYTE bSim_p, BYTE bNodeId_p, tObdInitRam fpObdInitRam_p)
{
    tCcmInitParam* pInit = &aInit_g[bSim_p];
    tCopKernel Ret;

    SimSelectNode(bSim_p);
    memset(pInit, 0, sizeof(*pInit));
    pInit->m_bInitNodeId = bNodeId_p;
    pInit->m_BaudIndex = kBdi500kBaud;
    (void) TgtGetBitrateTable(0, &pInit->m_pBdiTable, &pInit->m_wSizeOfBdiTab);
    pInit->m_dwAmr = 0xFFFFFFFFUL;
    pInit->m_dwAcr = 0;
    pInit->m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    pInit->m_fpNmtEventCallback = AppNmtEvent;
    pInit->m_fpObdInitRam = fpObdInitRam_p;
    Ret = CcmInitCANopen(pInit, kCcmFirstInstance);
    if (Ret == kCopSuccessful)
    {
        Ret = CcmConnectToNet();
    }
    if (Ret == kCopSuccessful)
    {
        /* GFC on (0x1300 = 1), OPERATIONAL */
        BYTE bGfc = 1;
        Ret = CcmWriteObject(0x1300, 0, &bGfc, sizeof(bGfc));
    }
    if (Ret == kCopSuccessful)
    {
        Ret = CcmNmtsExecCommand(kNmtCommEnterOperational);
    }
    if (Ret != kCopSuccessful)
    {
        printf("node %u: start-up failed: 0x%04X\n", (unsigned) bSim_p, (unsigned) Ret);
    }
    return Ret;
}

/* Both nodes process for uMs_p ms of bus time. */
static void Run (unsigned uMs_p)
{
    unsigned i;

    for (i = 0; i < uMs_p; i++)
    {
        SimSelectNode(SIM_SENSOR);
        (void) CcmProcess();
        SimSelectNode(SIM_ACTUATOR);
        (void) CcmProcess();
        SimAdvanceMs(1);
    }
}

int main (void)
{
    tCopKernel Ret;

    SimReset();
    if ((StartNode(SIM_SENSOR, 1, ObdInitRamSensor) != kCopSuccessful) ||
        (StartNode(SIM_ACTUATOR, 2, ObdInitRamActuator) != kCopSuccessful))
    {
        return 1;
    }
    Run(10);

    SimSelectNode(SIM_SENSOR);
    Ret = CcmSendGfc();
    printf("sensor: CcmSendGfc: 0x%04X\n", (unsigned) Ret);
    Run(10);

    SimSelectNode(SIM_SENSOR);
    (void) CcmShutDownCANopen();
    SimSelectNode(SIM_ACTUATOR);
    (void) CcmShutDownCANopen();

    if ((Ret != kCopSuccessful) || (auGfcSeen_g[SIM_ACTUATOR] != 1) || (auGfcSeen_g[SIM_SENSOR] != 0))
    {
        printf("FAILED: GFC seen by the sensor %u time(s), by the actuator %u time(s)\n",
               auGfcSeen_g[SIM_SENSOR], auGfcSeen_g[SIM_ACTUATOR]);
        return 1;
    }
    printf("ok: the actuator saw the GFC once\n");
    return 0;
}
