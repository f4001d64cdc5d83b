/*
 * libc.c - the freestanding C library of the target programs: formatted
 * output, memory and string functions, a fixed heap, exit. Output goes to
 * the Linux write system call, which qemu-armeb passes to the host; on a
 * board, TgtWrite (start.S) is the one function to replace (a UART).
 *
 * Only what the demo, the simulated bus and the C tests use is here. The
 * library itself (libcop.a) needs only memcpy, memmove, memset, memcmp
 * and their __aeabi_* forms.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* start.S */
int TgtWrite (int iFd_p, const void* pBuf_p, size_t uLen_p);
void TgtExit (int iCode_p) __attribute__((noreturn));

/* --- output ------------------------------------------------------------ */
struct TgtFile
{
    int m_iFd;
};
static struct TgtFile aFiles_g[2] = { { 1 }, { 2 } };
FILE* const stdout = &aFiles_g[0];
FILE* const stderr = &aFiles_g[1];

static char abOutBuf_g[1024];
static size_t uOutLen_g;

int fflush (FILE* pFile_p)
{
    size_t uDone = 0;
    (void) pFile_p;
    while (uDone < uOutLen_g)
    {
        int iRet = TgtWrite(1, abOutBuf_g + uDone, uOutLen_g - uDone);
        if (iRet <= 0)
        {
            break;
        }
        uDone += (size_t) iRet;
    }
    uOutLen_g = 0;
    return 0;
}

static void OutChar (char c_p)
{
    if (uOutLen_g == sizeof(abOutBuf_g))
    {
        (void) fflush(stdout);
    }
    abOutBuf_g[uOutLen_g++] = c_p;
}

/* A formatting sink: the standard output or a bounded string. */
typedef struct
{
    char*  m_pszOut;    /* NULL: standard output */
    size_t m_uSize;     /* capacity of m_pszOut including the NUL */
    size_t m_uCount;    /* characters produced (also beyond m_uSize) */
} tSink;

static void Put (tSink* pSink_p, char c_p)
{
    if (pSink_p->m_pszOut == NULL)
    {
        OutChar(c_p);
    }
    else if (pSink_p->m_uCount + 1 < pSink_p->m_uSize)
    {
        pSink_p->m_pszOut[pSink_p->m_uCount] = c_p;
    }
    pSink_p->m_uCount++;
}

static void PutPadded (tSink* pSink_p, const char* psz_p, size_t uLen_p, int iWidth_p, int fLeft_p, char cPad_p)
{
    int iPad = iWidth_p - (int) uLen_p;
    size_t i;
    if (!fLeft_p)
    {
        /* a sign goes before zero padding */
        if ((cPad_p == '0') && (uLen_p > 0) && (psz_p[0] == '-'))
        {
            Put(pSink_p, '-');
            psz_p++;
            uLen_p--;
        }
        for (; iPad > 0; iPad--)
        {
            Put(pSink_p, cPad_p);
        }
    }
    for (i = 0; i < uLen_p; i++)
    {
        Put(pSink_p, psz_p[i]);
    }
    for (; iPad > 0; iPad--)
    {
        Put(pSink_p, ' ');
    }
}

static int Format (tSink* pSink_p, const char* pszFormat_p, va_list Args_p)
{
    const char* p = pszFormat_p;
    while (*p != '\0')
    {
        char acNum[24];
        int fLeft = 0, iWidth = 0, iPrec = -1, iLong = 0;
        char cPad = ' ';
        unsigned long long uqwValue;
        unsigned uBase = 10;
        int fNeg = 0, fUpper = 0;
        size_t uLen;
        char* pszEnd;

        if (*p != '%')
        {
            Put(pSink_p, *p++);
            continue;
        }
        p++;
        for (;; p++)
        {
            if (*p == '-')      { fLeft = 1; }
            else if (*p == '0') { cPad = '0'; }
            else if ((*p == ' ') || (*p == '+') || (*p == '#')) { /* not used */ }
            else                { break; }
        }
        if (*p == '*')
        {
            iWidth = va_arg(Args_p, int);
            p++;
        }
        while ((*p >= '0') && (*p <= '9'))
        {
            iWidth = (iWidth * 10) + (*p++ - '0');
        }
        if (*p == '.')
        {
            p++;
            iPrec = 0;
            if (*p == '*')
            {
                iPrec = va_arg(Args_p, int);
                p++;
            }
            while ((*p >= '0') && (*p <= '9'))
            {
                iPrec = (iPrec * 10) + (*p++ - '0');
            }
        }
        while ((*p == 'l') || (*p == 'h') || (*p == 'z') || (*p == 't') || (*p == 'j'))
        {
            if (*p == 'l')      { iLong++; }
            else if (*p == 'z') { iLong = 1; }    /* size_t is 32 bits here */
            else if (*p == 'j') { iLong = 2; }
            p++;
        }
        switch (*p)
        {
            case 's':
            {
                const char* psz = va_arg(Args_p, const char*);
                if (psz == NULL)
                {
                    psz = "(null)";
                }
                uLen = 0;
                while ((psz[uLen] != '\0') && ((iPrec < 0) || (uLen < (size_t) iPrec)))
                {
                    uLen++;
                }
                PutPadded(pSink_p, psz, uLen, iWidth, fLeft, ' ');
                p++;
                continue;
            }
            case 'c':
                acNum[0] = (char) va_arg(Args_p, int);
                PutPadded(pSink_p, acNum, 1, iWidth, fLeft, ' ');
                p++;
                continue;
            case '%':
                Put(pSink_p, '%');
                p++;
                continue;
            case 'd':
            case 'i':
            {
                long long qwValue = (iLong >= 2) ? va_arg(Args_p, long long)
                                  : (iLong == 1) ? (long long) va_arg(Args_p, long)
                                                 : (long long) va_arg(Args_p, int);
                fNeg = qwValue < 0;
                uqwValue = fNeg ? (0ULL - (unsigned long long) qwValue) : (unsigned long long) qwValue;
                break;
            }
            case 'p':
                uqwValue = (unsigned long long) (size_t) va_arg(Args_p, void*);
                uBase = 16;
                Put(pSink_p, '0');
                Put(pSink_p, 'x');
                break;
            case 'X':
                fUpper = 1;
                /* fall through */
            case 'x':
                uBase = 16;
                /* fall through */
            case 'u':
            case 'o':
                if (*p == 'o')
                {
                    uBase = 8;
                }
                uqwValue = (iLong >= 2) ? va_arg(Args_p, unsigned long long)
                         : (iLong == 1) ? (unsigned long long) va_arg(Args_p, unsigned long)
                                        : (unsigned long long) va_arg(Args_p, unsigned int);
                break;
            default:
                /* unknown conversion: print it as it stands */
                Put(pSink_p, '%');
                if (*p == '\0')
                {
                    continue;
                }
                Put(pSink_p, *p++);
                continue;
        }
        p++;
        pszEnd = acNum + sizeof(acNum);
        uLen = 0;
        do
        {
            unsigned uDigit = (unsigned) (uqwValue % uBase);
            *--pszEnd = (char) ((uDigit < 10) ? ('0' + uDigit) : ((fUpper ? 'A' : 'a') + uDigit - 10));
            uqwValue /= uBase;
            uLen++;
        } while (uqwValue != 0);
        while ((iPrec > 0) && (uLen < (size_t) iPrec))
        {
            *--pszEnd = '0';
            uLen++;
        }
        if (fNeg)
        {
            *--pszEnd = '-';
            uLen++;
        }
        PutPadded(pSink_p, pszEnd, uLen, iWidth, fLeft, (iPrec >= 0) ? ' ' : cPad);
    }
    if ((pSink_p->m_pszOut != NULL) && (pSink_p->m_uSize > 0))
    {
        size_t uEnd = (pSink_p->m_uCount < pSink_p->m_uSize) ? pSink_p->m_uCount : (pSink_p->m_uSize - 1);
        pSink_p->m_pszOut[uEnd] = '\0';
    }
    return (int) pSink_p->m_uCount;
}

int vsnprintf (char* pszOut_p, size_t uSize_p, const char* pszFormat_p, va_list Args_p)
{
    tSink Sink = { pszOut_p, uSize_p, 0 };
    return Format(&Sink, pszFormat_p, Args_p);
}

int vprintf (const char* pszFormat_p, va_list Args_p)
{
    tSink Sink = { NULL, 0, 0 };
    return Format(&Sink, pszFormat_p, Args_p);
}

int vfprintf (FILE* pFile_p, const char* pszFormat_p, va_list Args_p)
{
    /* standard error is merged into the standard output, in order */
    (void) pFile_p;
    return vprintf(pszFormat_p, Args_p);
}

int printf (const char* pszFormat_p, ...)
{
    va_list Args;
    int iRet;
    va_start(Args, pszFormat_p);
    iRet = vprintf(pszFormat_p, Args);
    va_end(Args);
    return iRet;
}

int fprintf (FILE* pFile_p, const char* pszFormat_p, ...)
{
    va_list Args;
    int iRet;
    va_start(Args, pszFormat_p);
    iRet = vfprintf(pFile_p, pszFormat_p, Args);
    va_end(Args);
    return iRet;
}

int snprintf (char* pszOut_p, size_t uSize_p, const char* pszFormat_p, ...)
{
    va_list Args;
    int iRet;
    va_start(Args, pszFormat_p);
    iRet = vsnprintf(pszOut_p, uSize_p, pszFormat_p, Args);
    va_end(Args);
    return iRet;
}

int sprintf (char* pszOut_p, const char* pszFormat_p, ...)
{
    va_list Args;
    int iRet;
    va_start(Args, pszFormat_p);
    iRet = vsnprintf(pszOut_p, (size_t) -1 / 2, pszFormat_p, Args);
    va_end(Args);
    return iRet;
}

int fputs (const char* psz_p, FILE* pFile_p)
{
    (void) pFile_p;
    while (*psz_p != '\0')
    {
        OutChar(*psz_p++);
    }
    return 0;
}

int puts (const char* psz_p)
{
    (void) fputs(psz_p, stdout);
    OutChar('\n');
    return 0;
}

int putchar (int c_p)
{
    OutChar((char) c_p);
    return c_p;
}

/* --- memory and strings (also called by libcop.a) ---------------------- */
void* memcpy (void* pDst_p, const void* pSrc_p, size_t uLen_p)
{
    unsigned char* pDst = pDst_p;
    const unsigned char* pSrc = pSrc_p;
    while (uLen_p-- > 0)
    {
        *pDst++ = *pSrc++;
    }
    return pDst_p;
}

void* memmove (void* pDst_p, const void* pSrc_p, size_t uLen_p)
{
    unsigned char* pDst = pDst_p;
    const unsigned char* pSrc = pSrc_p;
    if (pDst < pSrc)
    {
        while (uLen_p-- > 0)
        {
            *pDst++ = *pSrc++;
        }
    }
    else
    {
        pDst += uLen_p;
        pSrc += uLen_p;
        while (uLen_p-- > 0)
        {
            *--pDst = *--pSrc;
        }
    }
    return pDst_p;
}

void* memset (void* pDst_p, int iValue_p, size_t uLen_p)
{
    unsigned char* pDst = pDst_p;
    while (uLen_p-- > 0)
    {
        *pDst++ = (unsigned char) iValue_p;
    }
    return pDst_p;
}

int memcmp (const void* pA_p, const void* pB_p, size_t uLen_p)
{
    const unsigned char* pA = pA_p;
    const unsigned char* pB = pB_p;
    for (; uLen_p > 0; uLen_p--, pA++, pB++)
    {
        if (*pA != *pB)
        {
            return (int) *pA - (int) *pB;
        }
    }
    return 0;
}

/* The run-time ABI names (ARM IHI 0043, section 4.3.4) the compilers emit. */
void __aeabi_memcpy (void* pDst_p, const void* pSrc_p, size_t uLen_p)  { (void) memcpy(pDst_p, pSrc_p, uLen_p); }
void __aeabi_memcpy4 (void* pDst_p, const void* pSrc_p, size_t uLen_p) { (void) memcpy(pDst_p, pSrc_p, uLen_p); }
void __aeabi_memcpy8 (void* pDst_p, const void* pSrc_p, size_t uLen_p) { (void) memcpy(pDst_p, pSrc_p, uLen_p); }
void __aeabi_memmove (void* pDst_p, const void* pSrc_p, size_t uLen_p)  { (void) memmove(pDst_p, pSrc_p, uLen_p); }
void __aeabi_memmove4 (void* pDst_p, const void* pSrc_p, size_t uLen_p) { (void) memmove(pDst_p, pSrc_p, uLen_p); }
void __aeabi_memmove8 (void* pDst_p, const void* pSrc_p, size_t uLen_p) { (void) memmove(pDst_p, pSrc_p, uLen_p); }
void __aeabi_memset (void* pDst_p, size_t uLen_p, int iValue_p)  { (void) memset(pDst_p, iValue_p, uLen_p); }
void __aeabi_memset4 (void* pDst_p, size_t uLen_p, int iValue_p) { (void) memset(pDst_p, iValue_p, uLen_p); }
void __aeabi_memset8 (void* pDst_p, size_t uLen_p, int iValue_p) { (void) memset(pDst_p, iValue_p, uLen_p); }
void __aeabi_memclr (void* pDst_p, size_t uLen_p)  { (void) memset(pDst_p, 0, uLen_p); }
void __aeabi_memclr4 (void* pDst_p, size_t uLen_p) { (void) memset(pDst_p, 0, uLen_p); }
void __aeabi_memclr8 (void* pDst_p, size_t uLen_p) { (void) memset(pDst_p, 0, uLen_p); }

size_t strlen (const char* psz_p)
{
    size_t uLen = 0;
    while (psz_p[uLen] != '\0')
    {
        uLen++;
    }
    return uLen;
}

int strcmp (const char* pszA_p, const char* pszB_p)
{
    while ((*pszA_p != '\0') && (*pszA_p == *pszB_p))
    {
        pszA_p++;
        pszB_p++;
    }
    return (int) (unsigned char) *pszA_p - (int) (unsigned char) *pszB_p;
}

int strncmp (const char* pszA_p, const char* pszB_p, size_t uLen_p)
{
    for (; uLen_p > 0; uLen_p--, pszA_p++, pszB_p++)
    {
        if ((*pszA_p != *pszB_p) || (*pszA_p == '\0'))
        {
            return (int) (unsigned char) *pszA_p - (int) (unsigned char) *pszB_p;
        }
    }
    return 0;
}

char* strcpy (char* pszDst_p, const char* pszSrc_p)
{
    char* pszDst = pszDst_p;
    while ((*pszDst++ = *pszSrc_p++) != '\0')
    {
    }
    return pszDst_p;
}

char* strchr (const char* psz_p, int c_p)
{
    for (;; psz_p++)
    {
        if (*psz_p == (char) c_p)
        {
            return (char*) psz_p;
        }
        if (*psz_p == '\0')
        {
            return NULL;
        }
    }
}

int abs (int i_p)
{
    return (i_p < 0) ? -i_p : i_p;
}

/* --- heap: a fixed arena, blocks of 8-byte multiples with a size word;
 * free gives a block back only when it is the last one (the programs
 * allocate once at start-up, or in a stack-like order) ------------------- */
static unsigned long long aqwHeap_g[64 * 1024 / 8];
static size_t uHeapTop_g;   /* in 8-byte units */

void* malloc (size_t uSize_p)
{
    size_t uUnits = ((uSize_p + 7U) / 8U) + 1U;
    void* p;
    if ((uSize_p == 0) || (uUnits > (sizeof(aqwHeap_g) / 8U) - uHeapTop_g))
    {
        return NULL;
    }
    aqwHeap_g[uHeapTop_g] = uUnits;
    p = &aqwHeap_g[uHeapTop_g + 1U];
    uHeapTop_g += uUnits;
    return p;
}

void* calloc (size_t uCount_p, size_t uSize_p)
{
    void* p;
    if ((uSize_p != 0) && (uCount_p > ((size_t) -1) / uSize_p))
    {
        return NULL;
    }
    p = malloc(uCount_p * uSize_p);
    if (p != NULL)
    {
        (void) memset(p, 0, uCount_p * uSize_p);
    }
    return p;
}

void free (void* p_p)
{
    unsigned long long* pqw = p_p;
    size_t uIndex;
    if (pqw == NULL)
    {
        return;
    }
    uIndex = (size_t) (pqw - aqwHeap_g) - 1U;
    if (uIndex + (size_t) aqwHeap_g[uIndex] == uHeapTop_g)
    {
        uHeapTop_g = uIndex;
    }
}

/* --- end of the program ------------------------------------------------ */
void exit (int iCode_p)
{
    (void) fflush(stdout);
    TgtExit(iCode_p);
}

void abort (void)
{
    (void) fputs("abort\n", stdout);
    exit(134);
}

void TgtAssertFailed (const char* pszExpr_p, const char* pszFile_p, int iLine_p)
{
    (void) printf("%s:%d: assertion failed: %s\n", pszFile_p, iLine_p, pszExpr_p);
    abort();
}
