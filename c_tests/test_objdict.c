/*
 * test_objdict.c - the dictionary objdict_all.h (every macro of the
 * objdict.h language) read and written through CcmReadObject and
 * CcmWriteObject: values and sizes of every storage kind, access refusals,
 * ranges, lengths, application variables, strings, domains, user-defined
 * variables, arrays, the SDO/PDO/SRDO parameter objects, and defaults
 * restored by an NMT reset. Every refused write must leave the value as it
 * was.
 */
#include "test_util.h"

/* Reads an object into a variable of type `type` and compares value and size. */
#define READ_EXPECT(ind, sub, type, expected) \
    do { type v_; tObdSize n_ = (tObdSize) sizeof(v_); memset(&v_, 0, sizeof(v_)); \
         CHECK_RET(CcmReadObject(ind, sub, &v_, &n_), kCopSuccessful); \
         CHECK_EQ(n_, sizeof(type)); CHECK_EQ(v_, (type) (expected)); } while (0)

#define READ_FAILS(ind, sub, code) \
    do { BYTE ab_[16]; tObdSize n_ = (tObdSize) sizeof(ab_); \
         CHECK_RET(CcmReadObject(ind, sub, ab_, &n_), code); } while (0)

#define WRITE_VALUE(ind, sub, type, value, code) \
    do { type v_ = (type) (value); \
         CHECK_RET(CcmWriteObject(ind, sub, &v_, (tObdSize) sizeof(v_)), code); } while (0)

static void ReadString (WORD wIndex_p, BYTE bSub_p, const char* pszExpected_p)
{
    char szBuf[32];
    tObdSize Size = (tObdSize) sizeof(szBuf);

    memset(szBuf, 0, sizeof(szBuf));
    CHECK_RET(CcmReadObject(wIndex_p, bSub_p, szBuf, &Size), kCopSuccessful);
    CHECK_EQ(Size, strlen(pszExpected_p));
    if (strcmp(szBuf, pszExpected_p) != 0)
    {
        printf("0x%04X/%u: read \"%s\", expected \"%s\"\n", (unsigned) wIndex_p, (unsigned) bSub_p, szBuf, pszExpected_p);
        iTestFailures_g++;
    }
}

static void Generic (void)
{
    char szBuf[16];
    tObdSize Size;

    /* constants */
    READ_EXPECT(0x1000, 0, DWORD, 0x00020191UL);
    WRITE_VALUE(0x1000, 0, DWORD, 1, kCopObdWriteViolation);
    READ_EXPECT(0x1000, 0, DWORD, 0x00020191UL);
    READ_EXPECT(0x1001, 0, BYTE, 0);
    WRITE_VALUE(0x1001, 0, BYTE, 1, kCopObdWriteViolation);

    /* strings */
    ReadString(0x1008, 0, "cop test node");
    Size = 4;
    CHECK_RET(CcmReadObject(0x1008, 0, szBuf, &Size), kCopObdValueLengthError);
    ReadString(0x100A, 0, DEFINED_STRING_VERSION);
    ReadString(0x1009, 0, "HW1");
    CHECK_RET(CcmWriteObject(0x1009, 0, "ABCDEFGH", 8), kCopSuccessful);
    ReadString(0x1009, 0, "ABCDEFGH");
    CHECK_RET(CcmWriteObject(0x1009, 0, "ABCDEFGHI", 9), kCopObdValueLengthError);
    ReadString(0x1009, 0, "ABCDEFGH");
    CHECK_RET(CcmWriteObject(0x1009, 0, "xy", 2), kCopSuccessful);
    ReadString(0x1009, 0, "xy");

    /* 0x1017: UNSIGNED16, wrong lengths refused */
    READ_EXPECT(0x1017, 0, WORD, 0);
    WRITE_VALUE(0x1017, 0, WORD, 1000, kCopSuccessful);
    READ_EXPECT(0x1017, 0, WORD, 1000);
    WRITE_VALUE(0x1017, 0, BYTE, 5, kCopObdValueLengthError);
    WRITE_VALUE(0x1017, 0, DWORD, 5, kCopObdValueLengthError);
    READ_EXPECT(0x1017, 0, WORD, 1000);
    WRITE_VALUE(0x1017, 0, WORD, 0, kCopSuccessful);

    /* identity */
    READ_EXPECT(0x1018, 0, BYTE, 4);
    READ_EXPECT(0x1018, 1, DWORD, 0x123);
    READ_EXPECT(0x1018, 3, DWORD, DEFINED_OBJ1018_VERSION);
    READ_EXPECT(0x1018, 4, DWORD, 0x42);
    READ_FAILS(0x1018, 5, kCopObdSubindexNotExist);

    /* SDO server 0x1200 (no sub 3, COB-IDs read-only), 0x1201, client 0x1280 */
    READ_EXPECT(0x1200, 0, BYTE, 2);
    /* objdict.h declares the predefined base; the object shows the COB-ID in
     * use, base + node-ID 2 (CiA 301: 0x1200 holds the COB-IDs in use) */
    READ_EXPECT(0x1200, 1, DWORD, 0x600 + 2);
    READ_EXPECT(0x1200, 2, DWORD, 0x580 + 2);
    READ_FAILS(0x1200, 3, kCopObdSubindexNotExist);
    WRITE_VALUE(0x1200, 1, DWORD, 0x601, kCopObdWriteViolation);
    WRITE_VALUE(0x1200, 0, BYTE, 3, kCopObdWriteViolation);
    READ_EXPECT(0x1201, 0, BYTE, 3);
    READ_EXPECT(0x1201, 1, DWORD, 0x80000000UL);
    READ_EXPECT(0x1201, 2, DWORD, 0x80000000UL);
    READ_EXPECT(0x1201, 3, BYTE, 5);
    WRITE_VALUE(0x1201, 3, BYTE, 7, kCopSuccessful);
    READ_EXPECT(0x1201, 3, BYTE, 7);
    READ_EXPECT(0x1280, 0, BYTE, 3);
    READ_EXPECT(0x1280, 3, BYTE, 3);

    /* PDO parameters */
    READ_EXPECT(0x1400, 0, BYTE, 5);
    READ_EXPECT(0x1400, 1, DWORD, 0x80000202UL);   /* base 0x200 + node-ID 2 (pre-defined connection set) */
    READ_EXPECT(0x1400, 2, BYTE, 0xFF);
    READ_EXPECT(0x1400, 3, WORD, 0);
    READ_FAILS(0x1400, 4, kCopObdSubindexNotExist);
    READ_EXPECT(0x1400, 5, WORD, 0);
    READ_EXPECT(0x1600, 0, BYTE, 0);
    READ_EXPECT(0x1800, 2, BYTE, 0xFE);
    READ_EXPECT(0x1800, 3, WORD, 10);
    READ_EXPECT(0x1800, 5, WORD, 100);
    READ_EXPECT(0x1A00, 0, BYTE, 1);
    READ_EXPECT(0x1A00, 1, DWORD, 0x20400108UL);
    READ_EXPECT(0x1A00, 8, DWORD, 0);
    READ_FAILS(0x1A00, 9, kCopObdSubindexNotExist);

    /* SRDO parameters (CiA 304) */
    READ_EXPECT(0x1300, 0, BYTE, 0);
    READ_EXPECT(0x1301, 0, BYTE, 6);
    READ_EXPECT(0x1301, 1, BYTE, 1);
    READ_EXPECT(0x1301, 2, WORD, 25);
    READ_EXPECT(0x1301, 3, BYTE, 20);
    READ_EXPECT(0x1301, 4, BYTE, 254);
    READ_EXPECT(0x1301, 5, DWORD, 0x101);
    READ_EXPECT(0x1301, 6, DWORD, 0x102);
    WRITE_VALUE(0x1301, 4, BYTE, 1, kCopObdWriteViolation);
    WRITE_VALUE(0x1301, 0, BYTE, 1, kCopObdWriteViolation);
    READ_FAILS(0x1301, 7, kCopObdSubindexNotExist);
    READ_EXPECT(0x1302, 1, BYTE, 2);
    READ_EXPECT(0x1302, 2, WORD, 100);
    READ_EXPECT(0x1302, 5, DWORD, 0x103);
    READ_EXPECT(0x1381, 0, BYTE, 2);
    READ_EXPECT(0x1381, 1, DWORD, 0x20400108UL);
    READ_EXPECT(0x1381, 2, DWORD, 0x20410108UL);
    READ_FAILS(0x1381, 3, kCopObdSubindexNotExist);
    READ_EXPECT(0x1382, 2, DWORD, 0x20430108UL);
    READ_EXPECT(0x13FE, 0, BYTE, 0);
    READ_EXPECT(0x13FF, 0, BYTE, 2);
    READ_EXPECT(0x13FF, 1, WORD, 0);            /* OBD_SUBINDEX_SRDO_CRC(sub, name) */
    READ_EXPECT(0x13FF, 2, WORD, 0x1234);       /* OBD_SUBINDEX_SRDO_CRC(sub, name, val) */
    READ_FAILS(0x13FF, 3, kCopObdSubindexNotExist);
    WRITE_VALUE(0x13FF, 0, BYTE, 3, kCopObdWriteViolation);
}

static void BasicTypes (void)
{
    tObdReal32 fValue = 0;
    tObdReal64 dValue = 0;
    tObdSize Size;

    READ_EXPECT(0x2000, 0, BYTE, 0x0D);
    READ_EXPECT(0x2000, 1, tObdBoolean, 1);
    READ_EXPECT(0x2000, 2, tObdInteger8, -5);
    READ_EXPECT(0x2000, 3, tObdInteger16, -1000);
    READ_EXPECT(0x2000, 4, tObdInteger32, -100000);
    READ_EXPECT(0x2000, 5, tObdUnsigned8, 0xA5);
    READ_EXPECT(0x2000, 6, tObdUnsigned16, 0xBEEF);
    READ_EXPECT(0x2000, 7, tObdUnsigned32, 0xDEADBEEFUL);
    Size = sizeof(fValue);
    CHECK_RET(CcmReadObject(0x2000, 8, &fValue, &Size), kCopSuccessful);
    CHECK_EQ(Size, 4);
    CHECK(fValue == 1.5f);
    READ_EXPECT(0x2000, 9, tObdInteger24, -3);
    READ_EXPECT(0x2000, 10, tObdUnsigned24, 0x123456);
    READ_EXPECT(0x2000, 11, tObdInteger64, -2);
    READ_EXPECT(0x2000, 12, tObdUnsigned64, 0x0102030405060708ULL);
    Size = sizeof(dValue);
    CHECK_RET(CcmReadObject(0x2000, 13, &dValue, &Size), kCopSuccessful);
    CHECK_EQ(Size, 8);
    CHECK(dValue == -0.25);

    /* writes in the variable's own width and byte order */
    WRITE_VALUE(0x2000, 1, tObdBoolean, 0, kCopSuccessful);
    WRITE_VALUE(0x2000, 1, tObdBoolean, 2, kCopObdValueToHigh);
    READ_EXPECT(0x2000, 1, tObdBoolean, 0);
    WRITE_VALUE(0x2000, 3, tObdInteger16, 1234, kCopSuccessful);
    READ_EXPECT(0x2000, 3, tObdInteger16, 1234);
    WRITE_VALUE(0x2000, 10, tObdUnsigned24, 0x00ABCDEF, kCopSuccessful);
    READ_EXPECT(0x2000, 10, tObdUnsigned24, 0x00ABCDEF);
    CHECK_RET(CcmWriteObject(0x2000, 10, "abc", 3), kCopObdValueLengthError);
    READ_EXPECT(0x2000, 10, tObdUnsigned24, 0x00ABCDEF);
    fValue = -7.5f;
    CHECK_RET(CcmWriteObject(0x2000, 8, &fValue, sizeof(fValue)), kCopSuccessful);
    fValue = 0;
    Size = sizeof(fValue);
    CHECK_RET(CcmReadObject(0x2000, 8, &fValue, &Size), kCopSuccessful);
    CHECK(fValue == -7.5f);
    WRITE_VALUE(0x2000, 12, tObdUnsigned64, 0xFFFFFFFFFFFFFFFFULL, kCopSuccessful);
    READ_EXPECT(0x2000, 12, tObdUnsigned64, 0xFFFFFFFFFFFFFFFFULL);
    READ_FAILS(0x2000, 0x0E, kCopObdSubindexNotExist);
    READ_FAILS(0x2000, 0x20, kCopObdSubindexNotExist);
}

static void Ranges (void)
{
    READ_EXPECT(0x2001, 1, WORD, 100);
    WRITE_VALUE(0x2001, 1, WORD, 9, kCopObdValueToLow);
    WRITE_VALUE(0x2001, 1, WORD, 1001, kCopObdValueToHigh);
    READ_EXPECT(0x2001, 1, WORD, 100);
    WRITE_VALUE(0x2001, 1, WORD, 10, kCopSuccessful);
    READ_EXPECT(0x2001, 1, WORD, 10);
    WRITE_VALUE(0x2001, 1, WORD, 1000, kCopSuccessful);
    READ_EXPECT(0x2001, 1, WORD, 1000);
    READ_EXPECT(0x2001, 2, tObdInteger16, 0);
    WRITE_VALUE(0x2001, 2, tObdInteger16, -101, kCopObdValueToLow);
    WRITE_VALUE(0x2001, 2, tObdInteger16, 101, kCopObdValueToHigh);
    READ_EXPECT(0x2001, 2, tObdInteger16, 0);
    WRITE_VALUE(0x2001, 2, tObdInteger16, -100, kCopSuccessful);
    READ_EXPECT(0x2001, 2, tObdInteger16, -100);
}

static void ApplicationVariables (void)
{
    /* CcmInitCANopen reset the dictionary: defaults went into the
     * application's variables, the NOINIT one is untouched. */
    CHECK_EQ(dwTestExtVar_g, 0x11223344UL);
    CHECK_EQ(bTestExtVarRg_g, 5);
    CHECK_EQ(wTestExtNoInit_g, 0x5555);
    dwTestExtVar_g = 0xCAFEBABEUL;
    READ_EXPECT(0x2002, 1, DWORD, 0xCAFEBABEUL);
    WRITE_VALUE(0x2002, 1, DWORD, 0x01020304UL, kCopSuccessful);
    CHECK_EQ(dwTestExtVar_g, 0x01020304UL);
    WRITE_VALUE(0x2002, 2, BYTE, 11, kCopObdValueToHigh);
    WRITE_VALUE(0x2002, 2, BYTE, 0, kCopObdValueToLow);
    CHECK_EQ(bTestExtVarRg_g, 5);
    WRITE_VALUE(0x2002, 2, BYTE, 10, kCopSuccessful);
    CHECK_EQ(bTestExtVarRg_g, 10);
    READ_EXPECT(0x2002, 3, WORD, 0x5555);
    WRITE_VALUE(0x2002, 3, WORD, 0x6666, kCopSuccessful);
    CHECK_EQ(wTestExtNoInit_g, 0x6666);
}

static void Strings (void)
{
    ReadString(0x2003, 1, "constant");
    CHECK_RET(CcmWriteObject(0x2003, 1, "x", 1), kCopObdWriteViolation);
    ReadString(0x2003, 2, "hello");
    CHECK_RET(CcmWriteObject(0x2003, 2, "hello world!", 12), kCopSuccessful);
    ReadString(0x2003, 2, "hello world!");
    CHECK_RET(CcmWriteObject(0x2003, 2, "hello world!!", 13), kCopObdValueLengthError);
    ReadString(0x2003, 2, "hello world!");
}

static unsigned uVarCallbacks_g;
static void*    pVarCallbackArg_g;

static tCopKernel PUBLIC VarCallback (void GENERIC* pParam_p)
{
    uVarCallbacks_g++;
    pVarCallbackArg_g = pParam_p;
    return kCopSuccessful;
}

static void NoInitDomainUserdef (void)
{
    static BYTE abDomain[16];
    static tObdUnsigned32 dwUser;
    static tObdInteger16 iUserRg;
    static tObdUnsigned8 bUser;
    tVarParam aVar[3];
    BYTE abBuf[32];
    tObdSize Size;

    /* NOINIT: static zero, writable */
    READ_EXPECT(0x2004, 0, DWORD, 0);
    WRITE_VALUE(0x2004, 0, DWORD, 7, kCopSuccessful);
    READ_EXPECT(0x2004, 0, DWORD, 7);

    /* DOMAIN: nothing attached yet */
    READ_FAILS(0x2005, 0, kCopObdVarEntryNotExist);
    CHECK_RET(CcmWriteObject(0x2005, 0, "abc", 3), kCopObdVarEntryNotExist);
    memset(aVar, 0, sizeof(aVar));
    aVar[0].m_bValidFlag = kVarValidSize | kVarValidData;
    aVar[0].m_wIndex = 0x2005;
    aVar[0].m_bSubindex = 0;
    aVar[0].m_Size = (tObdSize) sizeof(abDomain);
    aVar[0].m_pData = abDomain;
    CHECK_RET(CcmDefineVarTab(aVar, 1), kCopSuccessful);
    CHECK_RET(CcmWriteObject(0x2005, 0, "0123456789", 10), kCopSuccessful);
    CHECK(memcmp(abDomain, "0123456789", 10) == 0);
    Size = sizeof(abBuf);
    CHECK_RET(CcmReadObject(0x2005, 0, abBuf, &Size), kCopSuccessful);
    CHECK(Size >= 10);
    CHECK(memcmp(abBuf, "0123456789", 10) == 0);
    CHECK_RET(CcmWriteObject(0x2005, 0, abBuf, 17), kCopObdValueLengthError);

    /* USERDEF */
    READ_FAILS(0x2006, 1, kCopObdVarEntryNotExist);
    memset(aVar, 0, sizeof(aVar));
    aVar[0].m_bValidFlag = kVarValidAll;
    aVar[0].m_wIndex = 0x2006;
    aVar[0].m_bSubindex = 1;
    aVar[0].m_Size = (tObdSize) sizeof(dwUser);
    aVar[0].m_pData = &dwUser;
    aVar[0].m_fpCallback = VarCallback;
    aVar[0].m_pArg = &dwUser;
    aVar[1].m_bValidFlag = kVarValidSize | kVarValidData;
    aVar[1].m_wIndex = 0x2006;
    aVar[1].m_bSubindex = 2;
    aVar[1].m_Size = (tObdSize) sizeof(iUserRg);
    aVar[1].m_pData = &iUserRg;
    aVar[2].m_bValidFlag = kVarValidSize | kVarValidData;
    aVar[2].m_wIndex = 0x2006;
    aVar[2].m_bSubindex = 3;
    aVar[2].m_Size = (tObdSize) sizeof(bUser);
    aVar[2].m_pData = &bUser;
    CHECK_RET(CcmDefineVarTab(aVar, 3), kCopSuccessful);
    dwUser = 0x11111111UL;
    READ_EXPECT(0x2006, 1, DWORD, 0x11111111UL);
    WRITE_VALUE(0x2006, 1, DWORD, 0x55AA, kCopSuccessful);
    CHECK_EQ(dwUser, 0x55AA);
    CHECK_EQ(uVarCallbacks_g, 1);
    CHECK(pVarCallbackArg_g == (void*) &dwUser);
    WRITE_VALUE(0x2006, 2, tObdInteger16, 51, kCopObdValueToHigh);
    WRITE_VALUE(0x2006, 2, tObdInteger16, -51, kCopObdValueToLow);
    WRITE_VALUE(0x2006, 2, tObdInteger16, -50, kCopSuccessful);
    CHECK_EQ(iUserRg, -50);
    WRITE_VALUE(0x2006, 3, BYTE, 0x99, kCopSuccessful);
    CHECK_EQ(bUser, 0x99);

    /* refusals of CcmDefineVarTab */
    aVar[0].m_Size = 2;     /* too small for an UNSIGNED32 */
    CHECK_RET(CcmDefineVarTab(aVar, 1), kCopObdValueLengthError);
    aVar[0].m_Size = (tObdSize) sizeof(dwUser);
    aVar[0].m_wIndex = 0x2004;  /* not a USERDEF/DOMAIN object */
    aVar[0].m_bSubindex = 0;
    CHECK_RET(CcmDefineVarTab(aVar, 1), kCopObdVarEntryNotExist);
    aVar[0].m_wIndex = 0x3000;
    CHECK_RET(CcmDefineVarTab(aVar, 1), kCopObdIndexNotExist);
    aVar[0].m_wIndex = 0x2006;
    aVar[0].m_bSubindex = 9;
    CHECK_RET(CcmDefineVarTab(aVar, 1), kCopObdSubindexNotExist);
    CHECK_RET(CcmDefineVarTab(NULL, 1), kCopInvalidParam);

    /* a NULL variable with kVarValidData is a NULL pointer like any other
       (README, API conventions): refused, and no entry of the table is
       taken, not even the valid one before it */
    {
        static tObdUnsigned32 dwOther;
        memset(aVar, 0, sizeof(aVar));
        aVar[0].m_bValidFlag = kVarValidSize | kVarValidData;
        aVar[0].m_wIndex = 0x2006;
        aVar[0].m_bSubindex = 1;
        aVar[0].m_Size = (tObdSize) sizeof(dwOther);
        aVar[0].m_pData = &dwOther;
        aVar[1].m_bValidFlag = kVarValidData;
        aVar[1].m_wIndex = 0x2006;
        aVar[1].m_bSubindex = 3;
        aVar[1].m_pData = NULL;
        dwUser = 0x12345678UL;
        dwOther = 0;
        CHECK_RET(CcmDefineVarTab(aVar, 2), kCopInvalidParam);
        CHECK_RET(CcmDefineVarTab(&aVar[1], 1), kCopInvalidParam);
        READ_EXPECT(0x2006, 1, DWORD, 0x12345678UL);
        WRITE_VALUE(0x2006, 3, BYTE, 0x5A, kCopSuccessful);
        CHECK_EQ(bUser, 0x5A);
        CHECK_EQ(dwOther, 0);
    }
}

static void Arrays (void)
{
    static tObdUnsigned32 adwVar[2];
    tVarParam aVar[2];

    /* RAM array: sub 0 = count (constant), elements restored to the default */
    READ_EXPECT(0x2010, 0, BYTE, 4);
    READ_EXPECT(0x2010, 1, BYTE, 0x11);
    READ_EXPECT(0x2010, 4, BYTE, 0x11);
    READ_FAILS(0x2010, 5, kCopObdSubindexNotExist);
    WRITE_VALUE(0x2010, 3, BYTE, 0x33, kCopSuccessful);
    READ_EXPECT(0x2010, 3, BYTE, 0x33);
    READ_EXPECT(0x2010, 2, BYTE, 0x11);
    READ_EXPECT(0x2010, 4, BYTE, 0x11);
    WRITE_VALUE(0x2010, 0, BYTE, 2, kCopObdWriteViolation);
    WRITE_VALUE(0x2010, 5, BYTE, 2, kCopObdSubindexNotExist);

    /* application array: sub n is element n-1 */
    CHECK_EQ(awTestExtArray_g[0], 0x2222);
    CHECK_EQ(awTestExtArray_g[2], 0x2222);
    awTestExtArray_g[1] = 0x1111;
    READ_EXPECT(0x2011, 0, BYTE, 3);
    READ_EXPECT(0x2011, 2, WORD, 0x1111);
    WRITE_VALUE(0x2011, 3, WORD, 0x3333, kCopSuccessful);
    CHECK_EQ(awTestExtArray_g[2], 0x3333);
    CHECK_EQ(awTestExtArray_g[0], 0x2222);
    READ_FAILS(0x2011, 4, kCopObdSubindexNotExist);

    /* array of attached variables */
    READ_EXPECT(0x2012, 0, BYTE, 2);
    READ_FAILS(0x2012, 1, kCopObdVarEntryNotExist);
    memset(aVar, 0, sizeof(aVar));
    aVar[0].m_bValidFlag = kVarValidSize | kVarValidData;
    aVar[0].m_wIndex = 0x2012;
    aVar[0].m_bSubindex = 1;
    aVar[0].m_Size = (tObdSize) sizeof(adwVar[0]);
    aVar[0].m_pData = &adwVar[0];
    aVar[1] = aVar[0];
    aVar[1].m_bSubindex = 2;
    aVar[1].m_pData = &adwVar[1];
    CHECK_RET(CcmDefineVarTab(aVar, 2), kCopSuccessful);
    WRITE_VALUE(0x2012, 2, DWORD, 0xABCDEF01UL, kCopSuccessful);
    CHECK_EQ(adwVar[1], 0xABCDEF01UL);
    CHECK_EQ(adwVar[0], 0);
    adwVar[0] = 0x77;
    READ_EXPECT(0x2012, 1, DWORD, 0x77);
    READ_FAILS(0x2012, 3, kCopObdSubindexNotExist);
}

static void AccessRights (void)
{
    READ_FAILS(0x2030, 1, kCopObdReadViolation);
    WRITE_VALUE(0x2030, 1, BYTE, 0x12, kCopSuccessful);
    READ_EXPECT(0x2030, 2, BYTE, 0x77);
    WRITE_VALUE(0x2030, 2, BYTE, 0x12, kCopObdWriteViolation);
    READ_EXPECT(0x2030, 2, BYTE, 0x77);
    READ_FAILS(0x3000, 0, kCopObdIndexNotExist);
    READ_FAILS(0x6000, 0, kCopObdIndexNotExist);    /* the device part is empty */
    WRITE_VALUE(0x3000, 0, BYTE, 1, kCopObdIndexNotExist);
    WRITE_VALUE(0x2030, 9, BYTE, 1, kCopObdSubindexNotExist);
}

/* NMT reset node: every object with a default gets it back; NOINIT and
 * application-attached variables without default keep their value. */
static void ResetRestoresDefaults (void)
{
    CHECK_RET(CcmNmtsExecCommand(kNmtCommResetNode), kCopSuccessful);
    TestProcess(3);
    READ_EXPECT(0x2001, 1, WORD, 100);
    READ_EXPECT(0x2000, 3, tObdInteger16, -1000);
    CHECK_EQ(dwTestExtVar_g, 0x11223344UL);
    CHECK_EQ(wTestExtNoInit_g, 0x6666);
    READ_EXPECT(0x2004, 0, DWORD, 7);
    ReadString(0x2003, 2, "hello");
    ReadString(0x1009, 0, "HW1");
    READ_EXPECT(0x2010, 3, BYTE, 0x11);
    READ_EXPECT(0x1201, 3, BYTE, 5);
    CHECK_EQ(CcmObdGetNodeState(), kNodeStatePreOperational);
}

int main (void)
{
    SimReset();
    wTestExtNoInit_g = 0x5555;
    CHECK_RET(TestInitNode(0, 2, ObdInitRam, TestNmtRecorder), kCopSuccessful);
    CHECK_RET(CcmConnectToNet(), kCopSuccessful);
    TestProcess(1);

    Generic();
    BasicTypes();
    Ranges();
    ApplicationVariables();
    Strings();
    NoInitDomainUserdef();
    Arrays();
    AccessRights();
    ResetRestoresDefaults();

    CHECK_RET(CcmShutDownCANopen(), kCopSuccessful);
    return TEST_DONE("test_objdict");
}
