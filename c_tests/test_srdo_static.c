/*
 * test_srdo_static.c - CcmStaticDefineSrdoVarFields and
 * SrdoStaticDefineVarFields (static SRDO mapping, c_tests/cfg_manual,
 * objdict_static.h): every refusal with its code, the configuration check
 * that needs the fields, a received pair written straight into them, and
 * CcmGetSrdoParam without tSrdoMappParam.
 */
#include "test_util.h"

#define NODE_ID 4

extern tObdUnsigned8  abStaticNormal_g[2];
extern tObdUnsigned8  abStaticInverted_g[2];
extern tObdUnsigned64 aqwWideNormal_g[2];
extern tObdUnsigned64 aqwWideInverted_g[2];
tCopKernel PUBLIC ObdInitRamStatic (void MEM* pInitParam_p);

int main (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };
    static CONST BYTE abNormal[2] = { 0x12, 0x34 };
    static CONST BYTE abInverted[2] = { 0xED, 0xCB };
    static BYTE abOther[2];
    tSrdoCommuParam Commu;
    tSrdoMappParam Mapp;
    WORD wIndex = 0;

    SimReset();
    SimSetTrace(1);
    TestSrdoClear();

    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1301, abStaticNormal_g, abStaticInverted_g), kCopIllegalInstance);
    CHECK_RET(SrdoStaticDefineVarFields(0x1301, abStaticNormal_g, abStaticInverted_g), kCopIllegalInstance);

    CHECK_RET(TestInitNode(0, NODE_ID, ObdInitRamStatic, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);

    /* without its fields SRDO 1 cannot be declared valid */
    CHECK_RET(TestSrdoMakeValid(), kCopSrdoErrorMapp);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSrdoErrorMapp);
    CHECK_EQ(wIndex, 0x1301);

    /* refusals */
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1301, NULL, abStaticInverted_g), kCopInvalidParam);
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1301, abStaticNormal_g, NULL), kCopInvalidParam);
    CHECK_RET(SrdoStaticDefineVarFields(0x1301, NULL, NULL), kCopInvalidParam);
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1303, abStaticNormal_g, abStaticInverted_g), kCopSrdoNotExist);
    CHECK_RET(SrdoStaticDefineVarFields(0x1300, abStaticNormal_g, abStaticInverted_g), kCopSrdoNotExist);
    /* fields that are not the variables the mapping points to */
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1301, abOther, abStaticInverted_g), kCopSrdoErrorMapp);
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1301, abStaticInverted_g, abStaticNormal_g), kCopSrdoErrorMapp);
    CHECK_RET(SrdoStaticDefineVarFields(0x1301, &abStaticNormal_g[1], abStaticInverted_g), kCopSrdoErrorMapp);
    /* more than 8 bytes of normal data */
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1302, aqwWideNormal_g, aqwWideInverted_g), kCopSrdoLengthExceeded);
    CHECK_RET(SrdoStaticDefineVarFields(0x1302, aqwWideNormal_g, aqwWideInverted_g), kCopSrdoLengthExceeded);

    /* success (both names), then the configuration is valid */
    CHECK_RET(SrdoStaticDefineVarFields(0x1301, abStaticNormal_g, abStaticInverted_g), kCopSuccessful);
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1301, abStaticNormal_g, abStaticInverted_g), kCopSuccessful);
    CHECK_RET(TestSrdoMakeValid(), kCopSuccessful);
    CHECK_RET(CcmCheckSrdoConfig(&wIndex), kCopSuccessful);

    /* the mapping objects are constant with static mapping */
    CHECK_RET(TestWriteU8(0x1381, 0, 2), kCopObdWriteViolation);

    /* OPERATIONAL: the fields cannot change any more */
    SimInject(0x000, 0, 2, abStartAll);
    TestProcess(1);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStateOperational);
    CHECK_RET(CcmStaticDefineSrdoVarFields(0x1301, abStaticNormal_g, abStaticInverted_g), kCopSrdoNmtError);
    CHECK_RET(SrdoStaticDefineVarFields(0x1301, abStaticNormal_g, abStaticInverted_g), kCopSrdoNmtError);

    /* a received pair lands in the fields */
    pfnTestSrdoEventHook_g = TestSrdoEventHandshake;
    SimInject(0x101, 0, 2, abNormal);
    SimInject(0x102, 0, 2, abInverted);
    TestProcess(1);
    CHECK_EQ(uTestSrdoEvents_g, 1);
    CHECK(memcmp(abStaticNormal_g, abNormal, 2) == 0);
    CHECK(memcmp(abStaticInverted_g, abInverted, 2) == 0);

    /* CcmGetSrdoParam: tSrdoMappParam does not exist with static mapping */
    memset(&Commu, 0, sizeof(Commu));
    CHECK_RET(CcmGetSrdoParam(0x1301, &Commu, NULL), kCopSuccessful);
    CHECK_EQ(Commu.m_bDirection, 2);
    CHECK_EQ(Commu.m_wSct, 50);
    /* refused: neither structure is written (the pattern survives) */
    memset(&Commu, 0xA5, sizeof(Commu));
    memset(&Mapp, 0x5A, sizeof(Mapp));
    CHECK_RET(CcmGetSrdoParam(0x1301, &Commu, &Mapp), kCopInvalidParam);
    CHECK_EQ(Commu.m_bDirection, 0xA5);
    CHECK_EQ(Commu.m_wSct, 0xA5A5);
    CHECK_EQ(Mapp.m_bNoOfMappedObjects, 0x5A);
    CHECK_RET(SrdoGetCommuParam(0x1301, &Commu), kCopSuccessful);

    (void) aqwWideInverted_g;
    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_srdo_static");
}
