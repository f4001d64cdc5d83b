/*
 * test_manual_app.c - the application code of manual 2.9 (manual_app.c)
 * compiled against cop.h with static SRDO mapping (c_tests/cfg_manual) and
 * run on the simulated bus as a receiving safety node (node-ID 3). The
 * test plays the other safety node (SimInject) and the main loop's
 * program-flow check.
 *
 *  - start-up: the NMT callback defines the variable table, hands over the
 *    variable fields, writes direction 2 and 0xA5; the configuration check
 *    accepts the CRC the dictionary carries (0x3074);
 *  - kNmtEvEnterOperational: CcmGetSrdoParam (three arguments) gives
 *    direction 2 and SCT 25 ms;
 *  - a valid pair: AppSrdoEvent, data in the variable fields, status
 *    handled (bits 4-5 = 11);
 *  - a data error and an SCT timeout: AppSrdoError, the handshake sets bits
 *    6-7 to 10 and CcmProcess does not report kCopSrdoNotHandledInApp;
 *  - a GFC: AppGfcEvent;
 *  - every cycle the AppProgMonEvent sum equals the expected value.
 */
#include "test_util.h"
#include "manual_app.h"

#define NODE_ID 3

static WORD wExpectedPMon_g;

/* One main-loop cycle: CcmProcess and the program-flow check. */
static void Cycle (tCopKernel Expected_p, WORD wExpectedPMon_p)
{
    wPMonValue_g = 0;
    CHECK_RET(CcmProcess(), Expected_p);
    if (wPMonValue_g != wExpectedPMon_p)
    {
        printf("program monitor: sum 0x%04X, expected 0x%04X\n", (unsigned) wPMonValue_g, (unsigned) wExpectedPMon_p);
        iTestFailures_g++;
    }
}

int main (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    static CONST BYTE abNormal[2] = { 0x5A, 0x3C };
    static CONST BYTE abInverted[2] = { 0xA5, 0xC3 };
    static CONST BYTE abWrong[2] = { 0x5A, 0x3C };
    BYTE bState = 0;
    WORD wCrc = 0;
    WORD wIndex = 0;

    SimReset();
    SimSetTrace(1);

    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRam, AppCbNmtEvent), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_EQ(uSafetyCritical_g, 0);
    CHECK_EQ(TestReadU8(0x1301, 1), 2);
    CHECK_EQ(TestReadU8(0x13FE, 0), 0xA5);
    CHECK_RET(CcmCalcSrdoCrc(0x1301, &wCrc), kCopSuccessful);
    CHECK_EQ(wCrc, 0x3074);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSuccessful);
    CHECK_EQ(bSrdoState, kNotOperational);

    /* not OPERATIONAL: one "not checked" event per cycle */
    Cycle(kCopSuccessful, kPMonSctNotCheckedNotOperational);

    /* a configuration tool switches the GFC on, then the master starts */
    CHECK_RET(TestWriteU8(0x1300, 0, 1), kCopSuccessful);
    SimInject(0x000, 0, 2, abStartAll);
    Cycle(kCopSuccessful, kPMonSctChecked);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    CHECK_EQ(bSrdoState, kEnterOperational);
    CHECK_EQ(SrdoCommuParam.m_bDirection, 2);
    CHECK_EQ(SrdoCommuParam.m_wSct, 25);

    /* a valid pair */
    SimAdvanceMs(5);
    SimInject(0x101, 0, 2, abNormal);
    SimInject(0x102, 0, 2, abInverted);
    Cycle(kCopSuccessful, kPMonSrdoReceived + kPMonSctChecked);
    CHECK_EQ(uOutputsOn_g, 1);
    CHECK_EQ(SrdoNormalData.m_abSrdoData[0], 0x5A);
    CHECK_EQ(SrdoNormalData.m_abSrdoData[1], 0x3C);
    CHECK_EQ(SrdoInversData.m_abSrdoData[0], 0xA5);
    CHECK_EQ(SrdoInversData.m_abSrdoData[1], 0xC3);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState, 0x30);                 /* processed, no error */

    /* the inverted frame is not inverted: data error, handled */
    SimAdvanceMs(5);
    SimInject(0x101, 0, 2, abNormal);
    SimInject(0x102, 0, 2, abWrong);
    Cycle(kCopSuccessful, kPMonSrdoError + kPMonSctChecked);
    CHECK_EQ(LastSrdoError_g, kCopSrdoDataError);
    CHECK_EQ(uOutputsOff_g, 1);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState, 0xB0);                 /* bits 6-7 = 10, bits 4-5 = 11 */
    CHECK_EQ(SrdoNormalData.m_abSrdoData[0], 0x5A);     /* unchanged */

    /* no valid pair within the SCT (25 ms after the last valid one) */
    SimAdvanceMs(25);
    Cycle(kCopSuccessful, kPMonSrdoError + kPMonSctChecked);
    CHECK_EQ(LastSrdoError_g, kCopSrdoSctTimeout);
    CHECK_EQ(uOutputsOff_g, 2);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState, 0xB0);

    /* valid again */
    SimInject(0x101, 0, 2, abNormal);
    SimInject(0x102, 0, 2, abInverted);
    Cycle(kCopSuccessful, kPMonSrdoReceived + kPMonSctChecked);
    CHECK_EQ(uOutputsOn_g, 2);
    CHECK_RET(CcmGetSrdoState(&bState, 0x1301), kCopSuccessful);
    CHECK_EQ(bState & 0x30, 0x30);

    /* the global fail-safe command */
    SimInject(0x001, 0, 0, NULL);
    Cycle(kCopSuccessful, kPMonSctChecked);
    CHECK_EQ(uOutputsOff_g, 3);

    /* back to PRE-OPERATIONAL: the SRDO is not processed */
    CHECK_RET(CcmNmtsExecCommand(kNmtCommEnterPreOperational), kCopSuccessful);
    CHECK_EQ(bSrdoState, kNotOperational);
    Cycle(kCopSuccessful, kPMonSctNotCheckedNotOperational);

    CHECK_EQ(uSafetyCritical_g, 0);
    (void) wExpectedPMon_g;
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_manual_app");
}
