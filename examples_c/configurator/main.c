/*
 * main.c - the configurator example: three CANopen nodes of this library on
 * the simulated bus, one process, every frame printed in candump format.
 *
 *   node 1  configurator.c  NMT master and configuration tool (SDO client),
 *                           consumer of the safety data
 *   node 2  ionode.c        the I/O node of examples_c/io_node
 *   node 3  safety_node.c   a safety node configured over SDO
 *
 * The board-level frame work (start-up of each node, the main loop calling
 * CcmProcess) is here; on real hardware each node is its own board. The
 * SRDO callbacks the library calls by name are shared by nodes 1 and 3 (node
 * 2 has no SRDO objects) and hand the call to the node the simulation runs.
 * Exit code 0 when the configurator saw everything it expected.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "cdrv_sim.h"
#include "configurator.h"

#define RUN_MS_MAX 2000

void Log (const char* pszWho_p, const char* pszFormat_p, ...)
{
    va_list Args;
    DWORD dwTicks = (DWORD) TgtGetTickCount();

    printf("[%4lu.%lu ms] %-12s ", (unsigned long) (dwTicks / 10), (unsigned long) (dwTicks % 10), pszWho_p);
    va_start(Args, pszFormat_p);
    vprintf(pszFormat_p, Args);
    va_end(Args);
    printf("\n");
}

/* ---- the SRDO callbacks (manual 2.9), per node ----------------------------------- */

tCopKernel PUBLIC AppSrdoEvent (WORD wSrdoCommuIndex_p)
{
    if (SimSelectedNode() == SIM_CONFIGURATOR)
    {
        ConfiguratorSrdoEvent(wSrdoCommuIndex_p);
    }
    else
    {
        SafetyNodeSrdoEvent(wSrdoCommuIndex_p);
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p)
{
    if (SimSelectedNode() == SIM_CONFIGURATOR)
    {
        ConfiguratorSrdoError(wSrdoCommuIndex_p, ErrorCode_p);
    }
    else
    {
        SafetyNodeSrdoError(wSrdoCommuIndex_p, ErrorCode_p);
    }
    return kCopSuccessful;
}

tCopKernel PUBLIC AppGfcEvent (void)
{
    Log((SimSelectedNode() == SIM_CONFIGURATOR) ? "configurator" : "node 3", "AppGfcEvent");
    return kCopSuccessful;
}

/* ---- start-up of one board ------------------------------------------------------- */

static tCcmInitParam aInitParam_g[3];

static tCopKernel StartNode (BYTE bSim_p, BYTE bNodeId_p, tObdInitRam fpObdInitRam_p, tCcmNmtEventCallback fpNmt_p)
{
    tCcmInitParam* pInit = &aInitParam_g[bSim_p];
    tCopKernel Ret;

    SimSelectNode(bSim_p);
    memset(pInit, 0, sizeof(*pInit));
    pInit->m_bInitNodeId = bNodeId_p;
    pInit->m_BaudIndex = kBdi500kBaud;
    (void) TgtGetBitrateTable(0, &pInit->m_pBdiTable, &pInit->m_wSizeOfBdiTab);
    pInit->m_dwAmr = 0xFFFFFFFFUL;
    pInit->m_dwAcr = 0;
    pInit->m_HwParam.m_ZeroBasedCanNo.m_bCanNo = 0;
    pInit->m_fpCanInterruptEnable = TgtEnableCanInterrupt;
    pInit->m_fpNmtEventCallback = fpNmt_p;
    pInit->m_fpObdInitRam = fpObdInitRam_p;
    Ret = CcmInitCANopen(pInit, kCcmFirstInstance);
    if (Ret == kCopSuccessful)
    {
        Ret = CcmConnectToNet();
    }
    if (Ret != kCopSuccessful)
    {
        printf("node %u: start-up failed: 0x%04X\n", (unsigned) bNodeId_p, (unsigned) Ret);
    }
    return Ret;
}

int main (void)
{
    unsigned uMs;
    int iResult;
    int fRunning = 1;

    printf("cop configurator example: node 1 configures node 2 (I/O, seed 004) and node 3 (safety) over SDO\n");
    printf("frames are shown as candump lines (  can0  <id>   [<dlc>]  <data>)\n");
    SimReset();
    SimSetTrace(1);

    /* the configurator first, so that it hears the slaves' boot-up */
    if ((StartNode(SIM_CONFIGURATOR, ID_CONFIGURATOR, ObdInitRamConfigurator, ConfiguratorNmtEvent) != kCopSuccessful))
    {
        return 1;
    }
    SimSelectNode(SIM_CONFIGURATOR);
    ConfiguratorStart();
    (void) SimTakeSentFrame(NULL);
    if ((StartNode(SIM_IO_NODE, ID_IO_NODE, ObdInitRamIoNode, IoNodeNmtEvent) != kCopSuccessful) ||
        (StartNode(SIM_SAFETY_NODE, ID_SAFETY_NODE, ObdInitRamSafetyNode, SafetyNodeNmtEvent) != kCopSuccessful))
    {
        return 1;
    }

    /* one pass per ms: the configurator's script, then every node's cycle */
    for (uMs = 0; fRunning && (uMs < RUN_MS_MAX); uMs++)
    {
        SimSelectNode(SIM_CONFIGURATOR);
        fRunning = ConfiguratorStep();

        SimSelectNode(SIM_IO_NODE);
        IoNodeCycle();
        (void) CcmProcess();

        SimSelectNode(SIM_SAFETY_NODE);
        (void) CcmProcess();
        SafetyNodeCycle();

        SimSelectNode(SIM_CONFIGURATOR);
        (void) CcmProcess();

        SimAdvanceMs(1);
    }

    SimSelectNode(SIM_CONFIGURATOR);
    iResult = ConfiguratorResult();
    for (uMs = 0; uMs < 3; uMs++)
    {
        SimSelectNode((BYTE) uMs);
        (void) CcmShutDownCANopen();
    }
    printf("configurator: %s\n", (iResult == 0) ? "PASSED" : "FAILED");
    return iResult;
}
