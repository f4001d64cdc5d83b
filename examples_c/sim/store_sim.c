/*
 * store_sim.c - the simulated non-volatile memory of store_sim.h.
 */
#if !defined(SIM_STORE_NO_FILE)      /* SIM_STORE_NO_FILE: RAM only (no stdio files) */
#include <stdio.h>
#endif
#include <string.h>

#include "store_sim.h"

static BYTE  abMem_l[SIM_STORE_SIZE];
static int   fInit_l;
static int   fCutArmed_l;
static DWORD dwCutLeft_l;
static int   fDead_l;
static DWORD dwWritten_l;
static const char* pszFile_l;

static void Init (void)
{
    if (!fInit_l)
    {
        memset(abMem_l, 0xFF, sizeof(abMem_l));
        fInit_l = 1;
    }
}

static void SaveFile (void)
{
#if !defined(SIM_STORE_NO_FILE)
    FILE* f;

    if (pszFile_l == NULL)
    {
        return;
    }
    f = fopen(pszFile_l, "wb");
    if (f != NULL)
    {
        (void) fwrite(abMem_l, 1, sizeof(abMem_l), f);
        (void) fclose(f);
    }
#endif
}

/* One byte erased or written; 0 once the power is cut. */
static int Put (DWORD dwAt_p, BYTE bValue_p)
{
    if (fCutArmed_l)
    {
        if (dwCutLeft_l == 0)
        {
            fDead_l = 1;
            return 0;
        }
        dwCutLeft_l--;
    }
    abMem_l[dwAt_p] = bValue_p;
    dwWritten_l++;
    return 1;
}

static int InRange (DWORD dwOffset_p, DWORD dwSize_p)
{
    return (dwOffset_p <= SIM_STORE_SIZE) && (dwSize_p <= SIM_STORE_SIZE - dwOffset_p);
}

static tCopKernel PUBLIC Open (void MEM* pArg_p)
{
#if !defined(SIM_STORE_NO_FILE)
    FILE* f;
#endif

    (void) pArg_p;
    Init();
#if !defined(SIM_STORE_NO_FILE)
    if (pszFile_l != NULL)
    {
        f = fopen(pszFile_l, "rb");
        if (f != NULL)
        {
            if (fread(abMem_l, 1, sizeof(abMem_l), f) != sizeof(abMem_l))
            {
                memset(abMem_l, 0xFF, sizeof(abMem_l));
            }
            (void) fclose(f);
        }
    }
#endif
    return kCopSuccessful;
}

static tCopKernel PUBLIC Read (void MEM* pArg_p, DWORD dwOffset_p, BYTE MEM* pbData_p, DWORD dwSize_p)
{
    (void) pArg_p;
    Init();
    if (fDead_l || !InRange(dwOffset_p, dwSize_p))
    {
        return kCopCcmStoreHwError;
    }
    memcpy(pbData_p, &abMem_l[dwOffset_p], dwSize_p);
    return kCopSuccessful;
}

static tCopKernel PUBLIC Write (void MEM* pArg_p, DWORD dwOffset_p, CONST BYTE MEM* pbData_p, DWORD dwSize_p)
{
    DWORD i;

    (void) pArg_p;
    Init();
    if (fDead_l || !InRange(dwOffset_p, dwSize_p)
        || (dwOffset_p % SIM_STORE_ALIGN) != 0 || (dwSize_p % SIM_STORE_ALIGN) != 0)
    {
        return kCopCcmStoreHwError;
    }
    for (i = 0; i < dwSize_p; i++)
    {
        if (!Put(dwOffset_p + i, pbData_p[i]))
        {
            SaveFile();
            return kCopCcmStoreHwError;
        }
    }
    return kCopSuccessful;
}

static tCopKernel PUBLIC Erase (void MEM* pArg_p, DWORD dwOffset_p, DWORD dwSize_p)
{
    DWORD i;

    (void) pArg_p;
    Init();
    if (fDead_l || !InRange(dwOffset_p, dwSize_p))
    {
        return kCopCcmStoreHwError;
    }
    for (i = 0; i < dwSize_p; i++)
    {
        if (!Put(dwOffset_p + i, 0xFF))
        {
            SaveFile();
            return kCopCcmStoreHwError;
        }
    }
    return kCopSuccessful;
}

static tCopKernel PUBLIC Commit (void MEM* pArg_p)
{
    (void) pArg_p;
    if (fDead_l)
    {
        return kCopCcmStoreHwError;
    }
    SaveFile();
    return kCopSuccessful;
}

static const tCopStoreDriver Driver_l = {
    NULL, SIM_STORE_SIZE, SIM_STORE_ALIGN, SIM_STORE_CONFIG_KEY,
    Open, Read, Write, Erase, Commit
};

const tCopStoreDriver* SimStoreDriver (void)
{
    return &Driver_l;
}

void SimStoreReset (void)
{
    memset(abMem_l, 0xFF, sizeof(abMem_l));
    fInit_l = 1;
    fCutArmed_l = 0;
    fDead_l = 0;
    dwWritten_l = 0;
}

void SimStoreSetFile (const char* pszPath_p)
{
    pszFile_l = pszPath_p;
}

void SimStoreCutAfterBytes (DWORD dwBytes_p)
{
    fCutArmed_l = 1;
    dwCutLeft_l = dwBytes_p;
}

void SimStorePowerOn (void)
{
    fCutArmed_l = 0;
    fDead_l = 0;
}

void SimStoreFlipBit (DWORD dwOffset_p, BYTE bBit_p)
{
    Init();
    if (dwOffset_p < SIM_STORE_SIZE)
    {
        abMem_l[dwOffset_p] ^= (BYTE) (1u << (bBit_p & 7u));
    }
}

DWORD SimStoreBytesWritten (void)
{
    return dwWritten_l;
}
