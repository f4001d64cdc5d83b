/*
 * od_dump.c - prints the static dictionary of a node, for `dcf2bin --check`.
 *
 * Compiled by dcf2bin with the node's folder (copcfg.h, obdcfg.h) and the
 * library's include/ on the include path and OBD_OBJDICT_FILE naming the
 * node's objdict.h: objdef.h turns it into exactly the tables the library
 * runs on. The program calls the generated init function and prints, one
 * line each (numbers hex unless noted):
 *
 *   cfg KEY VALUE(decimal)
 *   index INDEX CALLBACK(0/1)
 *   sub SUB TYPE ACCESS KIND SIZE(dec) COUNT(dec) VALUE LOW HIGH
 *
 * VALUE, LOW and HIGH are the bytes in memory order, `-` when unknown (an
 * application variable the tables only point to), `.` when empty. COUNT is
 * the number of elements of an array entry (kObdAccArray), else 1.
 */
#include "objdef.h"

#include <stdio.h>
#include <string.h>

/* The configuration signature lives in the library; the dump only needs
 * its address to exist. */
CONST BYTE COP_ABI_SIGNATURE = 0;

#define COP_DUMP_KEY(k) printf("cfg %s %ld\n", #k, (long) (k))

static void dump_bytes(const void* p, unsigned long n)
{
    const unsigned char* b = (const unsigned char*) p;
    unsigned long i;
    if (p == NULL) {
        printf(" -");
        return;
    }
    if (n == 0) {
        printf(" .");
        return;
    }
    printf(" ");
    for (i = 0; i < n; ++i) {
        printf("%02X", b[i]);
    }
}

static void dump_part(const tObdEntry* e)
{
    for (; e != NULL && e->m_wIndex != OBD_TABLE_INDEX_END; ++e) {
        unsigned i;
        printf("index %04X %d\n", e->m_wIndex, e->m_fpCallback != NULL);
        for (i = 0; i < e->m_bCount; ++i) {
            const tObdSubEntry* s = &e->m_pSubIndex[i];
            unsigned long size = (unsigned long) s->m_dwSize;
            unsigned long count = 1;
            const unsigned char* range = NULL;
            if ((s->m_bAccess & kObdAccArray) && e->m_pSubIndex[0].m_pDefault != NULL) {
                count = *(const BYTE*) e->m_pSubIndex[0].m_pDefault;
            }
            printf("sub %02X %02X %02X %u %lu %lu", s->m_bSubIndex, s->m_bType, s->m_bAccess,
                   s->m_bKind, size, count);
            switch (s->m_bKind) {
            case kObdKindRam:
                dump_bytes(s->m_pCurrent, size * count);
                break;
            case kObdKindRom:
                dump_bytes(s->m_pDefault, size * count);
                break;
            case kObdKindRamVString:
                if (s->m_pCurrent != NULL) {
                    dump_bytes(s->m_pCurrent, (unsigned long) strlen((const char*) s->m_pCurrent));
                } else {
                    dump_bytes(NULL, 0);
                }
                break;
            case kObdKindRomVString:
                dump_bytes(s->m_pDefault, size);
                break;
            default:
                /* Application variable: the default, when the table has one. */
                dump_bytes(s->m_pDefault, size);
                break;
            }
            if ((s->m_bAccess & kObdAccRange) && s->m_pDefault != NULL) {
                range = (const unsigned char*) s->m_pDefault;
                dump_bytes(range + size, size);
                dump_bytes(range + 2 * size, size);
            } else {
                printf(" - -");
            }
            printf("\n");
        }
    }
}

int main(void)
{
    tObdRamParam param;
    memset(&param, 0, sizeof param);
    if (OBD_INIT_RAM_NAME(&param) != kCopSuccessful) {
        printf("ObdInitRam failed\n");
        return 1;
    }
    /* COP_DUMP_KEYS */
    dump_part(param.m_pGenericPart);
    dump_part(param.m_pManufacturerPart);
    dump_part(param.m_pDevicePart);
    dump_part(param.m_pUserPart);
    return 0;
}
