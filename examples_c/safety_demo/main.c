/*
 * main.c - the safety demo: a two-node CiA 304 safety network written the
 * way firmware for the SYS TEC API is written, run on the simulated CAN bus
 * in one process.
 *
 *   node 1, sensor   (sensor.c):   E-stop button and permitted speed, sent
 *                                  in SRDO 1 (COB-IDs 0x101/0x102) every
 *                                  refresh time (20 ms)
 *   node 2, actuator (actuator.c): receives SRDO 1 (SCT 50 ms, SRVT 10 ms)
 *                                  and drives a safe output
 *
 * The common safety code (status handshake, program-flow monitor, the NMT
 * callback that configures the SRDO, diagnostics) is safety_node.c.
 *
 * The script below plays the rest of the world: an NMT master starts the
 * network, the E-stop is pressed and released, the operator presses RESET,
 * and one fault is injected on the bus (an inverted frame is lost). Every
 * frame is printed in candump format between the applications' messages.
 * The exit code is 0 when the actuator behaved as a safety actuator must.
 */
#include <stdio.h>

#include "cdrv_sim.h"
#include "safety_node.h"

tCopKernel PUBLIC ObdInitRamSensor (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamActuator (void MEM* pInitParam_p);

tSafetyNode aSafetyNode_g[2] = {
    /* SRDO parameters: direction, refresh time / SCT, SRVT, COB-IDs (the
     * predefined connection set of node 1) */
    { .m_pszName = "sensor", .m_Role = kRoleSensor, .m_bSimNode = 0, .m_bNodeId = 1,
      .m_fpObdInitRam = ObdInitRamSensor, .m_Srdo = { 1, 20, 10, 0x101, 0x102 } },
    { .m_pszName = "actuator", .m_Role = kRoleActuator, .m_bSimNode = 1, .m_bNodeId = 2,
      .m_fpObdInitRam = ObdInitRamActuator, .m_Srdo = { 2, 50, 10, 0x101, 0x102 } },
};

/* the script, in ms of simulated time */
#define T_NMT_START      5
#define T_ESTOP_PRESSED  100
#define T_ESTOP_RELEASED 150
#define T_RESET_1        200
#define T_FAULT          250
#define T_RESET_2        320
#define T_END            360

static void Say (unsigned uMs_p, const char* pszWhat_p)
{
    printf("\n[%4u.0 ms] ======== %s\n", uMs_p, pszWhat_p);
}

/* What the demo must show; 0 when the actuator did all of it. */
static int fOnAfterStart_g, fOffOnGfc_g, fOffOnFault_g, fOnAfterRecovery_g;

static void Observe (unsigned uMs_p)
{
    int fOn = ActuatorOutputOn();

    if ((uMs_p == T_ESTOP_PRESSED - 1) && fOn)          fOnAfterStart_g = 1;
    if ((uMs_p == T_ESTOP_RELEASED - 1) && !fOn)        fOffOnGfc_g = 1;
    if ((uMs_p == T_RESET_2 - 1) && !fOn)               fOffOnFault_g = 1;
    if ((uMs_p == T_END - 1) && fOn)                    fOnAfterRecovery_g = 1;
}

int main (void)
{
    static CONST BYTE abNmtStartAll[2] = { 0x01, 0x00 };
    DWORD dwVersion = CopGetStackVersion();
    unsigned uMs;
    int fOk;

    printf("cop safety demo (stack V%u.%u r%u): sensor node 1 -> SRDO 1 -> actuator node 2\n",
           (unsigned) COP_GET_MAJOR_VERSION(dwVersion), (unsigned) COP_GET_MINOR_VERSION(dwVersion),
           (unsigned) COP_GET_RELEASE_VERSION(dwVersion));
    printf("frames are shown as candump lines (  can0  <id>   [<dlc>]  <data>)\n");

    SimReset();
    SimSetTrace(1);

    Say(0, "power on: both boards initialise (CcmInitCANopen, CcmConnectToNet)");
    if ((SafetyNodeStart(&aSafetyNode_g[0]) != kCopSuccessful) ||
        (SafetyNodeStart(&aSafetyNode_g[1]) != kCopSuccessful))
    {
        return 1;
    }

    for (uMs = 0; uMs < T_END; uMs++)
    {
        switch (uMs)
        {
            case T_NMT_START:
                Say(uMs, "NMT master: start remote node, all nodes");
                (void) SimInject(0x000, 0, 2, abNmtStartAll);
                break;
            case T_ESTOP_PRESSED:
                Say(uMs, "sensor: the E-stop button is PRESSED (dangerous condition)");
                SensorSetEStop(1);
                break;
            case T_ESTOP_RELEASED:
                Say(uMs, "sensor: the E-stop button is released");
                SensorSetEStop(0);
                break;
            case T_RESET_1:
            case T_RESET_2:
                Say(uMs, "operator presses RESET on the actuator");
                ActuatorOperatorReset();
                break;
            case T_FAULT:
                Say(uMs, "FAULT INJECTION: the next inverted frame 0x102 is lost on the bus");
                SimDropNextId(0x102);
                break;
            default:
                break;
        }

        SafetyNodeCycle(&aSafetyNode_g[0], SensorCycle);
        SafetyNodeCycle(&aSafetyNode_g[1], ActuatorCycle);
        while (SimTakeSentFrame(NULL))
        {
            /* the trace has shown them */
        }
        Observe(uMs);
        SimAdvanceMs(1);
    }

    Say(uMs, "end of the script");
    printf("SRDO 0x1301 CRC (0x13FF/1): sensor 0x%04X, actuator 0x%04X\n",
           (unsigned) aSafetyNode_g[0].m_wConfiguredCrc, (unsigned) aSafetyNode_g[1].m_wConfiguredCrc);
    SimSelectNode(aSafetyNode_g[0].m_bSimNode);
    (void) CcmShutDownCANopen();
    SimSelectNode(aSafetyNode_g[1].m_bSimNode);
    (void) CcmShutDownCANopen();

    fOk = fOnAfterStart_g && fOffOnGfc_g && fOffOnFault_g && fOnAfterRecovery_g &&
          !aSafetyNode_g[0].m_fSafetyFault && !aSafetyNode_g[1].m_fSafetyFault;
    printf("result: output ON after start-up: %s, OFF after the GFC: %s, OFF after the fault: %s, "
           "ON after recovery: %s, node faults: none%s\n",
           fOnAfterStart_g ? "yes" : "NO", fOffOnGfc_g ? "yes" : "NO", fOffOnFault_g ? "yes" : "NO",
           fOnAfterRecovery_g ? "yes" : "NO",
           (aSafetyNode_g[0].m_fSafetyFault || aSafetyNode_g[1].m_fSafetyFault) ? " - NO, see above" : "");
    printf("safety_demo: %s\n", fOk ? "PASSED" : "FAILED");
    return fOk ? 0 : 1;
}
