/*
 * test_srdo_granularity.c - SRDO_GRANULARITY 16 (library and dictionary
 * built with c_tests/cfg_big): objdict_srdo_peer.h maps 8-bit objects, so the
 * configuration check refuses the mapping with kCopSrdoGranularityMismatch
 * (SAFETY_BEHAVIOUR.md section 2), for CcmCheckSrdoConfig, SrdoCheckConfig
 * and the write of 0xA5 alike; SrdoInit refuses the granularity 8 an
 * application built for the manual's default would pass.
 */
#include "test_util.h"

tCopKernel PUBLIC ObdInitRamSrdoPeer (void MEM* pInitParam_p);

int main (void)
{
    tSrdoInitParam Init;
    WORD wIndex = 0;

    SimReset();
    SimSetTrace(1);
    CHECK_EQ(SRDO_GRANULARITY, 16);
    CHECK_EQ(SRDO_MAX_MAPPENTRIES, 8);
    CHECK_RET(TestInitNode(0, 5, ObdInitRamSrdoPeer, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);

    CHECK_RET(TestSrdoMakeValid(), kCopSrdoGranularityMismatch);
    CHECK_EQ(TestReadU8(0x13FE, 0), 0);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSrdoGranularityMismatch);
    CHECK_EQ(wIndex, 0x1301);
    wIndex = 0;
    CHECK_RET(SrdoCheckConfig(&wIndex), kCopSrdoGranularityMismatch);
    CHECK_EQ(wIndex, 0x1301);

    memset(&Init, 0, sizeof(Init));
    Init.m_bGranularity = 8;
    CHECK_RET(SrdoInit(&Init), kCopSrdoGranularityMismatch);
    Init.m_bGranularity = 16;
    CHECK_RET(SrdoInit(&Init), kCopSuccessful);

    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_srdo_granularity");
}
