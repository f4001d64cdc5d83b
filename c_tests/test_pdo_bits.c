/*
 * test_pdo_bits.c - PDO_USE_BIT_MAPPING and PDO_GRANULARITY as a C
 * application sees them. Built twice:
 *
 *   test_pdo_bit_mapping      c_tests/cfg_pdobits: bit mapping, granularity
 *                             64, so PDO_MAX_MAPPENTRIES 64;
 *   test_pdo_bit_mapping_off  c_tests/cfg: the copdef.h defaults (no bit
 *                             mapping, granularity 8, 8 entries).
 *
 * Two nodes on the simulated bus, each with its own copy of
 * objdict_pdobits.h: P (simulated node 0, node-ID 1) produces TPDO 0x181,
 * C (simulated node 1, node-ID 2) consumes it with RPDO 0x1400. Payload
 * layout: CiA 301 section 7.2.2 (mapped objects in order, bit 0 of byte 0
 * first); BOOLEANs as single bits: dynamic OD manual L-1087d, chapter 4.
 */
#include <stddef.h>

#include "test_util.h"
#include "cop_config.h"

#define SIM_P 0
#define SIM_C 1
#define ID_P  1
#define ID_C  2

#define BIT_A  0x21000101UL     /* 0x2100/1 BOOLEAN, one bit */
#define BIT_B  0x21000201UL     /* 0x2100/2 BOOLEAN, one bit */
#define BYTE_A 0x21000108UL     /* 0x2100/1 BOOLEAN as a byte */
#define BYTE_C 0x21010108UL     /* 0x2101/1 UNSIGNED8 */

tCopKernel PUBLIC ObdInitRamPdoBits (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamPdoBitsPeer (void MEM* pInitParam_p);

/* copdef.h derives the entry count from the two switches. */
#if (PDO_USE_BIT_MAPPING != FALSE) && (PDO_GRANULARITY == 64)
_Static_assert(PDO_MAX_MAPPENTRIES == 64, "bit mapping at granularity 64: 64 mapping entries");
#else
_Static_assert(PDO_MAX_MAPPENTRIES == 8, "8 mapping entries");
#endif

/* tPdoParam follows the entry count (src/ffi/pdo.rs asserts the same). */
_Static_assert(offsetof(tPdoParam, m_adwMappParam) == 20, "tPdoParam mapping");
_Static_assert(sizeof(((tPdoParam*) 0)->m_adwMappParam) == 4 * PDO_MAX_MAPPENTRIES, "tPdoParam entries");
_Static_assert(offsetof(tPdoParam, m_fpCallback) ==
               (20 + 4 * PDO_MAX_MAPPENTRIES + sizeof(void*) - 1) / sizeof(void*) * sizeof(void*),
               "tPdoParam callback");

/* The link-time signature names the entry count: the member access below
 * compiles only when COP_ABI_SIGNATURE expands to exactly this name. */
struct tSignatureName { int COP_ABI_SIGNATURE; };
static int SignatureName (const struct tSignatureName* p)
{
#if (PDO_MAX_MAPPENTRIES == 64)
    return p->CopLibAbi_os1_gr8_sm0_pm0_ts0_id11_pe64_ch8;
#else
    return p->CopLibAbi_os1_gr8_sm0_pm0_ts0_id11_pe8_ch8;
#endif
}

static void ProcessNode (BYTE bNode_p)
{
    SimSelectNode(bNode_p);
    (void) CcmProcess();
}

static DWORD ReadU32 (WORD wIndex_p, BYTE bSub_p, tCopKernel Expected_p)
{
    DWORD    dwValue = 0;
    tObdSize Size = sizeof(dwValue);

    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, &dwValue, &Size), Expected_p);
    return dwValue;
}

/* A complete PDO definition with bEntries_p mapping entries alternating
 * between dwEven_p and dwOdd_p. */
static tPdoParam Pdo (WORD wIndex_p, BYTE bType_p, DWORD dwCanId_p, BYTE bEntries_p, DWORD dwEven_p,
                      DWORD dwOdd_p)
{
    tPdoParam P;
    unsigned  i;

    memset(&P, 0, sizeof(P));
    P.m_bValidFlag = kPdoValidAll;
    P.m_wPdoCommuIndex = wIndex_p;
    P.m_bPdoType = bType_p;
    P.m_dwCanId = dwCanId_p;
    P.m_bTxTyp = 255;
    P.m_bNrOfEntries = bEntries_p;
    for (i = 0; (i < bEntries_p) && (i < PDO_MAX_MAPPENTRIES); i++)
    {
        P.m_adwMappParam[i] = ((i % 2) == 0) ? dwEven_p : dwOdd_p;
    }
    return P;
}

static void Dictionary (void)
{
    SimSelectNode(SIM_P);
    CHECK_EQ(TestReadU8(0x1A00, 0), 3);
    CHECK_EQ(ReadU32(0x1A00, 1, kCopSuccessful), BIT_A);
    CHECK_EQ(ReadU32(0x1A00, 3, kCopSuccessful), BYTE_C);
    CHECK_EQ(ReadU32(0x1A00, 8, kCopSuccessful), 0);
#if (PDO_MAX_MAPPENTRIES == 64)
    /* subindices 9..64 exist, default 0, in both mapping objects */
    CHECK_EQ(ReadU32(0x1A00, 0x09, kCopSuccessful), 0);
    CHECK_EQ(ReadU32(0x1A00, 0x40, kCopSuccessful), 0);
    CHECK_EQ(ReadU32(0x1600, 0x40, kCopSuccessful), 0);
    (void) ReadU32(0x1A00, 0x41, kCopObdSubindexNotExist);
#else
    (void) ReadU32(0x1A00, 0x09, kCopObdSubindexNotExist);
    (void) ReadU32(0x1600, 0x09, kCopObdSubindexNotExist);
#endif
}

static void StartBoth (void)
{
    static CONST BYTE abStartAll[2] = { 0x01, 0x00 };

    SimInject(0x000, 0, 2, abStartAll);
    ProcessNode(SIM_P);
    ProcessNode(SIM_C);
    TestDrainSent();
}

#if (PDO_USE_BIT_MAPPING != FALSE)

/* The default mapping of objdict_pdobits.h: two bits and a byte from bit 2. */
static void DefaultBitMapping (void)
{
    /* bit 0 = 1, bit 1 = 0, 0xA5 in bits 2..9 */
    static CONST BYTE abBits[2] = { 0x95, 0x02 };
    tPdoParam P;

    SimSelectNode(SIM_P);
    CHECK_RET(TestWriteU8(0x2100, 1, 1), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2101, 1, 0xA5), kCopSuccessful);
    CHECK_RET(TestWriteU32(0x1800, 1, 0x180 + ID_P), kCopSuccessful);

    SimSelectNode(SIM_C);
    P = Pdo(0x1400, kPdoTypeRecv, 0x180 + ID_P, 3, BIT_A, BIT_B);
    P.m_adwMappParam[2] = BYTE_C;
    CHECK_RET(TestWriteU8(0x2100, 2, 1), kCopSuccessful);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);

    StartBoth();
    SimSelectNode(SIM_P);
    CHECK_RET(CcmSendPdo(0x1800), kCopSuccessful);
    TestExpectFrame("P: two bits and a byte", 0x180 + ID_P, 2, abBits);
    ProcessNode(SIM_C);
    SimSelectNode(SIM_C);
    CHECK_EQ(TestReadU8(0x2100, 1), 1);
    CHECK_EQ(TestReadU8(0x2100, 2), 0);
    CHECK_EQ(TestReadU8(0x2101, 1), 0xA5);
}

#else

/* Without bit mapping a BOOLEAN takes a whole byte; one bit is refused. */
static void WithoutBitMapping (void)
{
    static CONST BYTE abBytes[2] = { 0x01, 0xA5 };
    tPdoParam P;

    SimSelectNode(SIM_P);
    CHECK_RET(TestWriteU8(0x2100, 1, 1), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x2101, 1, 0xA5), kCopSuccessful);
    /* the default mapping has one-bit entries: the PDO cannot become valid */
    CHECK_RET(TestWriteU32(0x1800, 1, 0x180 + ID_P), kCopPdoGranularityMismatch);
    P = Pdo(0x1800, kPdoTypeSend, 0x180 + ID_P, 2, BIT_A, BIT_B);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoGranularityMismatch);
    P = Pdo(0x1800, kPdoTypeSend, 0x180 + ID_P, 2, BYTE_A, BYTE_C);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);

    SimSelectNode(SIM_C);
    P = Pdo(0x1400, kPdoTypeRecv, 0x180 + ID_P, 1, BIT_A, BIT_A);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoGranularityMismatch);
    P = Pdo(0x1400, kPdoTypeRecv, 0x180 + ID_P, 2, BYTE_A, BYTE_C);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);

    StartBoth();
    SimSelectNode(SIM_P);
    CHECK_RET(CcmSendPdo(0x1800), kCopSuccessful);
    TestExpectFrame("P: BOOLEAN byte and UNSIGNED8", 0x180 + ID_P, 2, abBytes);
    ProcessNode(SIM_C);
    SimSelectNode(SIM_C);
    CHECK_EQ(TestReadU8(0x2100, 1), 1);
    CHECK_EQ(TestReadU8(0x2101, 1), 0xA5);
}

#endif

/* Every mapping entry the configuration has, and one more. */
static void AllEntries (void)
{
    tPdoParam P;

    SimSelectNode(SIM_P);
    P = Pdo(0x1800, kPdoTypeSend, 0x180 + ID_P, PDO_MAX_MAPPENTRIES + 1, BYTE_C, BYTE_C);
    CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoLengthExceeded);
    CHECK_RET(TestWriteU32(0x1800, 1, 0x80000000UL + 0x180 + ID_P), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1A00, 0, 0), kCopSuccessful);
    CHECK_RET(TestWriteU8(0x1A00, 0, PDO_MAX_MAPPENTRIES + 1), kCopPdoLengthExceeded);
#if (PDO_MAX_MAPPENTRIES == 64)
    {
        /* 64 BOOLEANs: b0 = 0x2100/1 = 0, b1 = 0x2100/2 = 1, ... */
        static CONST BYTE abAA[8] = { 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA };

        /* a one-bit UNSIGNED8 is no BOOLEAN */
        P = Pdo(0x1800, kPdoTypeSend, 0x180 + ID_P, 1, 0x21010101UL, 0);
        CHECK_RET(CcmDefinePdoTab(&P, 1), kCopPdoErrorMapp);
        /* an entry beyond 8 through the dictionary (CiA 301 mapping procedure) */
        CHECK_RET(TestWriteU32(0x1A00, 0x40, BIT_B), kCopSuccessful);
        CHECK_EQ(ReadU32(0x1A00, 0x40, kCopSuccessful), BIT_B);

        CHECK_RET(TestWriteU8(0x2100, 1, 0), kCopSuccessful);
        CHECK_RET(TestWriteU8(0x2100, 2, 1), kCopSuccessful);
        P = Pdo(0x1800, kPdoTypeSend, 0x180 + ID_P, 64, BIT_A, BIT_B);
        CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);
        CHECK_EQ(TestReadU8(0x1A00, 0), 64);
        CHECK_EQ(ReadU32(0x1A00, 0x3F, kCopSuccessful), BIT_A);

        SimSelectNode(SIM_C);
        CHECK_RET(TestWriteU8(0x2100, 1, 1), kCopSuccessful);
        CHECK_RET(TestWriteU8(0x2100, 2, 0), kCopSuccessful);
        P = Pdo(0x1400, kPdoTypeRecv, 0x180 + ID_P, 64, BIT_A, BIT_B);
        CHECK_RET(CcmDefinePdoTab(&P, 1), kCopSuccessful);
        CHECK_EQ(ReadU32(0x1600, 0x40, kCopSuccessful), BIT_B);
        TestDrainSent();

        SimSelectNode(SIM_P);
        CHECK_RET(CcmSendPdo(0x1800), kCopSuccessful);
        TestExpectFrame("P: 64 BOOLEANs", 0x180 + ID_P, 8, abAA);
        ProcessNode(SIM_C);
        SimSelectNode(SIM_C);
        CHECK_EQ(TestReadU8(0x2100, 1), 0);
        CHECK_EQ(TestReadU8(0x2100, 2), 1);
    }
#else
    (void) ReadU32(0x1A00, 0x09, kCopObdSubindexNotExist);
#endif
}

int main (void)
{
    static CONST struct tSignatureName Zero;

    SimReset();
    SimSetTrace(1);
    CHECK_EQ(SignatureName(&Zero), 0);

    CHECK_RET(TestInitNode(SIM_P, ID_P, ObdInitRamPdoBits, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    CHECK_RET(TestInitNode(SIM_C, ID_C, ObdInitRamPdoBitsPeer, NULL), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestDrainSent();

    Dictionary();
#if (PDO_USE_BIT_MAPPING != FALSE)
    DefaultBitMapping();
#else
    WithoutBitMapping();
#endif
    AllEntries();
    TestDrainSent();
    return TEST_DONE((PDO_MAX_MAPPENTRIES == 64) ? "test_pdo_bit_mapping" : "test_pdo_bit_mapping_off");
}
