/*
 * objdef.h - turns the application's objdict.h into this library's
 * dictionary tables and generates the init function ObdInitRam.
 *
 * Use: exactly one C file per dictionary (normally objdict.c) contains
 *
 *     #include "objdef.h"
 *
 * with the application's objdict.h, obdcfg.h and copcfg.h on the include
 * path. objdef.h includes cop.h, then obdcfg.h, then includes objdict.h
 * (or the file named by OBD_OBJDICT_FILE) once per pass with one pass switch
 * defined; obdmacro.h defines the macro family for that pass:
 *
 *   1. OBD_CREATE_CHECKS         inside an enum: counts OBD_CREATE_SRDO_COMMU,
 *                                which must not exceed SRDO_MAX_SRDO_IN_OBD
 *                                (the library's SRDO capacity; the running
 *                                numbers must stay below it as well)
 *   2. OBD_CREATE_ROM_DATA       constants (defaults, ranges, strings)
 *   3. OBD_CREATE_RAM_DATA       variables, string buffers, tObdVarEntry
 *                                slots, extern declarations, SRDO callbacks
 *   4. OBD_CREATE_SUBINDEX_TAB   tObdSubEntry tables, one per index
 *   5. OBD_CREATE_INDEX_TAB      tObdEntry tables, one per part, each ending
 *                                with index 0xFFFF (empty parts allowed)
 *   6. OBD_CREATE_INIT_FUNCTION  inside OBD_INIT_RAM_NAME(): store the part
 *                                tables and the SRDO callbacks
 *
 * Everything generated is `static`, so two dictionaries (two C files with
 * different OBD_INIT_RAM_NAME and OBD_OBJDICT_FILE) can live in one program.
 * The only external symbol is the init function:
 *
 *     tCopKernel PUBLIC OBD_INIT_RAM_NAME (void MEM* pInitParam_p);
 *
 * (ObdInitRam unless obdcfg.h names it otherwise). Its address goes into
 * tCcmInitParam.m_fpObdInitRam; CcmInitCANopen calls it with a
 * tObdRamParam, which it fills with the part tables, the address of the
 * configuration signature (cop_config.h - the reason a program built with a
 * different configuration fails to link), the SRDO callbacks, the CAN driver
 * buffers sized by CDRV_MAX_{RX,TX}_BUFF_ENTRIES_{HIGH,LOW} and
 * SRDO_MAX_SRDO_IN_OBD. With a NULL argument it does nothing and returns
 * kCopSuccessful (the tables are constant; nothing needs restoring).
 *
 * Table layout produced for each macro (see obdmacro.h for the parameters):
 *   ROM_VAR            kind ROM, m_pDefault -> the constant, write bit removed
 *   RAM_VAR            kind RAM, m_pCurrent -> static variable = default
 *   *_RG               kObdAccRange, m_pDefault -> {default, low, high}
 *   RAM_EXTVAR         kind RAM, m_pCurrent -> the application's `name`
 *   ROM_VSTRING        kind ROM_VSTRING, m_dwSize = strlen(default)
 *   RAM_VSTRING        kind RAM_VSTRING, char[size + 1] = default, m_dwSize = size
 *   DOMAIN, USERDEF    kind VAR_ENTRY, m_pCurrent -> a static tObdVarEntry the
 *                      application fills with CcmDefineVarTab
 *   *_NOINIT           no default (m_pDefault NULL)
 *   ROM_INDEX_RAM_*ARRAY  sub 0 = cnt (constant UNSIGNED8) and one entry at
 *                      sub 1 with kObdAccArray whose storage is the element
 *                      array (subindex n is element n-1)
 *   SDO/PDO/SRDO       complete parameter objects (layouts in obdmacro.h)
 *
 * Differences from the SYS TEC objdef.h: the subindex tables are always
 * constant (no RAM copies, OBD_USE_VARIABLE_SUBINDEX_TAB has no effect);
 * the OD-builder key is not stored; default values are converted with a
 * cast to dtyp, so structure types (TIME_OF_DAY) need the _NOINIT forms.
 *
 * PDO mapping objects have PDO_MAX_MAPPENTRIES entries: 8, or 64 with
 * PDO_USE_BIT_MAPPING and PDO_GRANULARITY 64. OBD_CREATE_*PDO_MAPP names
 * the defaults of subindices 1..8 as in the SYS TEC macro set; subindices
 * 9..64 (added through PDO_SUBINDEX_BIT_MAPPING) default to 0.
 */
#ifndef OBJDEF_H
#define OBJDEF_H

#include "cop.h"
#include "obdcfg.h"
#include "copdef.h"         /* section B: capacities obdcfg.h left out */
#include "cop_config.h"

#ifndef OBD_OBJDICT_FILE
#define OBD_OBJDICT_FILE "objdict.h"
#endif

/* ---- capacity checks ---------------------------------------------------------- */
#if (NMTM_MAX_SLAVE_ENTRIES > 127)
#error "NMTM_MAX_SLAVE_ENTRIES must not exceed 127"
#endif
#if (HBC_MAX_CONSUMER_IN_OBD > 127)
#error "HBC_MAX_CONSUMER_IN_OBD must not exceed 127"
#endif
#if (EMCP_MAX_ERROR_ENTRIES_IN_OBD > 254)
#error "EMCP_MAX_ERROR_ENTRIES_IN_OBD must not exceed 254"
#endif
#if (SDO_MAX_SERVER_IN_OBD < 1) || (SDO_MAX_SERVER_IN_OBD > 128)
#error "SDO_MAX_SERVER_IN_OBD must be 1..128"
#endif
#if (SDO_MAX_CLIENT_IN_OBD > 128)
#error "SDO_MAX_CLIENT_IN_OBD must not exceed 128"
#endif
#if (PDO_MAX_RXPDO_IN_OBD > 512)
#error "PDO_MAX_RXPDO_IN_OBD must not exceed 512"
#endif
#if (PDO_MAX_TXPDO_IN_OBD > 512)
#error "PDO_MAX_TXPDO_IN_OBD must not exceed 512"
#endif
#if (SRDO_MAX_SRDO_IN_OBD > 64)
#error "SRDO_MAX_SRDO_IN_OBD must not exceed 64 (0x1301..0x1340)"
#endif
#if (CDRV_MAX_RX_BUFF_ENTRIES_HIGH < 0) || (CDRV_MAX_TX_BUFF_ENTRIES_HIGH < 0) || \
    (CDRV_MAX_RX_BUFF_ENTRIES_LOW < 0) || (CDRV_MAX_TX_BUFF_ENTRIES_LOW < 0)
#error "CDRV_MAX_*_BUFF_ENTRIES_* must not be negative"
#endif

/* ---- helpers of obdmacro.h (kept across passes) ------------------------------ */

/* Names of the generated objects. */
#define COP_OBD_DEF(ind, sub) xDef##ind##_##sub##_g
#define COP_OBD_CUR(ind, sub) xCur##ind##_##sub##_g
#define COP_OBD_VAR(ind, sub) VarEntry##ind##_##sub##_g
#define COP_OBD_ACUR(ind)     axCur##ind##_g
#define COP_OBD_AVAR(ind)     aVarEntry##ind##_g
#define COP_OBD_SUBTAB(ind)   aObdSubEntry##ind##_g
#define COP_OBD_COUNT(ind)    (sizeof(COP_OBD_SUBTAB(ind)) / sizeof(tObdSubEntry))

/* The SRDO callback table (defined by OBD_CREATE_SRDO_CFG_VALID; an
 * objdict.h with SRDO objects but without 0x13FE does not compile). */
#define COP_OBD_SRDO_CALLBACKS aSrdoAppCallbacks_from_OBD_CREATE_SRDO_CFG_VALID_g

/* Access of a constant: write removed, const set. */
#define COP_OBD_ROM_ACC(acc) ((BYTE) (((acc) & ~kObdAccWrite) | kObdAccConst))

/* One tObdSubEntry initialiser (this library's field order). */
#define COP_OBD_SUBENTRY(sub, typ, acc, kind, size, def, cur) \
    { (BYTE) (sub), (BYTE) (typ), (BYTE) (acc), (BYTE) (kind), (DWORD) (size), \
      (CONST void ROM*) (def), (void MEM*) (cur) },

/* One tObdEntry initialiser. */
#define COP_OBD_INDEX(ind, count, call) \
    { (WORD) (ind), &COP_OBD_SUBTAB(ind)[0], (BYTE) (count), (tObdCallback) (call) },

/* File-scope compile-time check with a readable name. */
#define COP_OBD_CHECK(cond, what) typedef char CopObdCheck_##what[(cond) ? 1 : -1];

/* Parameters of the protocol objects: default, variable, table entry. */
#define COP_OBD_PARAM_ROM(type, ind, sub, val) static CONST type ROM COP_OBD_DEF(ind, sub) = (type) (val);
#define COP_OBD_PARAM_RAM(type, ind, sub, val) static type MEM COP_OBD_CUR(ind, sub) = (type) (val);
#define COP_OBD_PARAM_ENTRY(ind, sub, typ, acc, type) \
    COP_OBD_SUBENTRY(sub, typ, acc, kObdKindRam, sizeof(type), &COP_OBD_DEF(ind, sub), &COP_OBD_CUR(ind, sub))
#define COP_OBD_CONST_U8_ENTRY(ind, sub) \
    COP_OBD_SUBENTRY(sub, kObdTypUInt8, kObdAccCR, kObdKindRom, sizeof(BYTE), &COP_OBD_DEF(ind, sub), NULL)
#define COP_OBD_ARRAY_COUNT_ENTRY(ind) COP_OBD_CONST_U8_ENTRY(ind, 0x00)
#define COP_OBD_SDOS_COBID_ACC(ind) (((ind) == 0x1200) ? kObdAccR : kObdAccSRW)
#define COP_OBD_PDO_MAPP_ENTRY(ind, sub, typ, type) \
    COP_OBD_SUBENTRY(sub, typ, PDO_STATIC_MAPPING_ONEOF(kObdAccCR, kObdAccSRW), \
                     PDO_STATIC_MAPPING_ONEOF(kObdKindRom, kObdKindRam), sizeof(type), \
                     &COP_OBD_DEF(ind, sub), PDO_STATIC_MAPPING_ONEOF(NULL, &COP_OBD_CUR(ind, sub)))
#define COP_OBD_SRDO_MAPP_ENTRY(ind, sub, typ, type) \
    COP_OBD_SUBENTRY(sub, typ, SRDO_STATIC_MAPPING_ONEOF(kObdAccCR, kObdAccSRW), \
                     SRDO_STATIC_MAPPING_ONEOF(kObdKindRom, kObdKindRam), sizeof(type), \
                     &COP_OBD_DEF(ind, sub), SRDO_STATIC_MAPPING_ONEOF(NULL, &COP_OBD_CUR(ind, sub)))

#if (SRDO_USE_GFC != FALSE)
#define COP_OBD_APP_GFC_EVENT AppGfcEvent
#else
#define COP_OBD_APP_GFC_EVENT NULL
#endif
#if (SRDO_USE_PROGMONITOR != FALSE)
#define COP_OBD_APP_PROGMON_EVENT AppProgMonEvent
#else
#define COP_OBD_APP_PROGMON_EVENT NULL
#endif

/* Helpers with the names of the SYS TEC objdef.h, for objdict.h files that
 * use them. Each keeps or drops its arguments according to the
 * configuration. */
#if (PDO_USE_STATIC_MAPPING != FALSE)
#define PDO_STATIC_MAPPING_ONEOF(a, b) a
#else
#define PDO_STATIC_MAPPING_ONEOF(a, b) b
#endif
#if (SRDO_USE_STATIC_MAPPING != FALSE)
#define SRDO_STATIC_MAPPING_ONEOF(a, b) a
#else
#define SRDO_STATIC_MAPPING_ONEOF(a, b) b
#endif
#define CCM_SUBINDEX_RAM_ONLY(...)
#define CCM_SUBINDEX_RAM_ONEOF(a, b) a
/* PDO mapping subindices 9..64: one entry of a mapping object's table,
 * kept only when the mapping objects have 64 entries (bit mapping with
 * PDO_GRANULARITY 64). def and cur as in tObdSubEntry; cur is NULL with
 * PDO_USE_STATIC_MAPPING (the entries are constants then). */
#if (PDO_MAX_MAPPENTRIES == 64)
#define PDO_SUBINDEX_BIT_MAPPING(sub, typ, acc, def, cur) \
    COP_OBD_SUBENTRY(sub, typ, acc, PDO_STATIC_MAPPING_ONEOF(kObdKindRom, kObdKindRam), sizeof(DWORD), def, cur)
#define COP_OBD_PDO_BITS_ONLY(...) __VA_ARGS__
#else
#define PDO_SUBINDEX_BIT_MAPPING(sub, typ, acc, def, cur)
#define COP_OBD_PDO_BITS_ONLY(...)
#endif
/* Subindex sub (9..64) of mapping object ind: default 0 (one constant per
 * object), current value element i of the object's array. */
#define COP_OBD_PDO_BIT_ENTRY(ind, sub, i) \
    PDO_SUBINDEX_BIT_MAPPING(sub, kObdTypUInt32, PDO_STATIC_MAPPING_ONEOF(kObdAccCR, kObdAccSRW), \
                             &COP_OBD_DEF(ind, MappBits), PDO_STATIC_MAPPING_ONEOF(NULL, &COP_OBD_ACUR(ind)[i]))
#define COP_OBD_PDO_BIT_ENTRIES(ind) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x09,  0) COP_OBD_PDO_BIT_ENTRY(ind, 0x0A,  1) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x0B,  2) COP_OBD_PDO_BIT_ENTRY(ind, 0x0C,  3) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x0D,  4) COP_OBD_PDO_BIT_ENTRY(ind, 0x0E,  5) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x0F,  6) COP_OBD_PDO_BIT_ENTRY(ind, 0x10,  7) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x11,  8) COP_OBD_PDO_BIT_ENTRY(ind, 0x12,  9) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x13, 10) COP_OBD_PDO_BIT_ENTRY(ind, 0x14, 11) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x15, 12) COP_OBD_PDO_BIT_ENTRY(ind, 0x16, 13) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x17, 14) COP_OBD_PDO_BIT_ENTRY(ind, 0x18, 15) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x19, 16) COP_OBD_PDO_BIT_ENTRY(ind, 0x1A, 17) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x1B, 18) COP_OBD_PDO_BIT_ENTRY(ind, 0x1C, 19) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x1D, 20) COP_OBD_PDO_BIT_ENTRY(ind, 0x1E, 21) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x1F, 22) COP_OBD_PDO_BIT_ENTRY(ind, 0x20, 23) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x21, 24) COP_OBD_PDO_BIT_ENTRY(ind, 0x22, 25) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x23, 26) COP_OBD_PDO_BIT_ENTRY(ind, 0x24, 27) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x25, 28) COP_OBD_PDO_BIT_ENTRY(ind, 0x26, 29) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x27, 30) COP_OBD_PDO_BIT_ENTRY(ind, 0x28, 31) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x29, 32) COP_OBD_PDO_BIT_ENTRY(ind, 0x2A, 33) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x2B, 34) COP_OBD_PDO_BIT_ENTRY(ind, 0x2C, 35) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x2D, 36) COP_OBD_PDO_BIT_ENTRY(ind, 0x2E, 37) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x2F, 38) COP_OBD_PDO_BIT_ENTRY(ind, 0x30, 39) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x31, 40) COP_OBD_PDO_BIT_ENTRY(ind, 0x32, 41) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x33, 42) COP_OBD_PDO_BIT_ENTRY(ind, 0x34, 43) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x35, 44) COP_OBD_PDO_BIT_ENTRY(ind, 0x36, 45) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x37, 46) COP_OBD_PDO_BIT_ENTRY(ind, 0x38, 47) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x39, 48) COP_OBD_PDO_BIT_ENTRY(ind, 0x3A, 49) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x3B, 50) COP_OBD_PDO_BIT_ENTRY(ind, 0x3C, 51) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x3D, 52) COP_OBD_PDO_BIT_ENTRY(ind, 0x3E, 53) \
    COP_OBD_PDO_BIT_ENTRY(ind, 0x3F, 54) COP_OBD_PDO_BIT_ENTRY(ind, 0x40, 55)
#define OBD_END_SUBINDEX()
#define OBD_MAX_ARRAY_SUBENTRIES 2
#if (CDRV_USE_HIGHBUFF != FALSE)
#define CDRV_HIGHBUFF_ONLY(...) __VA_ARGS__
#else
#define CDRV_HIGHBUFF_ONLY(...)
#endif
#define CDRV_CREATE_BUFFER_HIGH(...) __VA_ARGS__
#define CDRV_CREATE_BUFFER_LOW(...)  __VA_ARGS__
#if ((CCM_MODULE_INTEGRATION) & CCM_MODULE_NMTM)
#define CCM_NMTM_ONLY(...) __VA_ARGS__
#else
#define CCM_NMTM_ONLY(...)
#endif
#if ((CCM_MODULE_INTEGRATION) & CCM_MODULE_HBC)
#define CCM_HBC_ONLY(...) __VA_ARGS__
#else
#define CCM_HBC_ONLY(...)
#endif
#if ((CCM_MODULE_INTEGRATION) & CCM_MODULE_EMCC)
#define CCM_EMCC_ONLY(...) __VA_ARGS__
#else
#define CCM_EMCC_ONLY(...)
#endif
#if ((CCM_MODULE_INTEGRATION) & CCM_MODULE_PDO)
#define CCM_PDO_ONLY(...) __VA_ARGS__
#else
#define CCM_PDO_ONLY(...)
#endif
#if ((CCM_MODULE_INTEGRATION) & CCM_MODULE_SDOC)
#define CCM_SDOC_ONLY(...) __VA_ARGS__
#else
#define CCM_SDOC_ONLY(...)
#endif
#if ((CCM_MODULE_INTEGRATION) & CCM_MODULE_SRDO)
#define CCM_SRDO_ONLY(...) __VA_ARGS__
#else
#define CCM_SRDO_ONLY(...)
#endif
#if (EMCP_USE_PREDEF_ERROR_FIELD != FALSE)
#define CCM_PREDEFERR_ONLY(...) __VA_ARGS__
#else
#define CCM_PREDEFERR_ONLY(...)
#endif
#define NMTM_CREATE_TABLE(...)   __VA_ARGS__
#define HBC_CREATE_TABLE(...)    __VA_ARGS__
#define EMCC_CREATE_TABLE(...)   __VA_ARGS__
#define PDO_CREATE_RX_TABLE(...) __VA_ARGS__
#define PDO_CREATE_TX_TABLE(...) __VA_ARGS__
#define SDOC_CREATE_TABLE(...)   __VA_ARGS__
#define SRDO_CREATE_TABLE(...)   __VA_ARGS__

/* ---- CAN driver buffers (tCdrvMsg arrays handed to CdrvInit) --------------------- */
#if (CDRV_USE_HIGHBUFF != FALSE) && (CDRV_MAX_RX_BUFF_ENTRIES_HIGH > 0)
static tCdrvMsg MEM aCanRxMsgBufferHigh_g[CDRV_MAX_RX_BUFF_ENTRIES_HIGH];
#define COP_OBD_RX_HIGH_BUFFER aCanRxMsgBufferHigh_g
#define COP_OBD_RX_HIGH_COUNT  CDRV_MAX_RX_BUFF_ENTRIES_HIGH
#else
#define COP_OBD_RX_HIGH_BUFFER NULL
#define COP_OBD_RX_HIGH_COUNT  0
#endif
#if (CDRV_USE_HIGHBUFF != FALSE) && (CDRV_MAX_TX_BUFF_ENTRIES_HIGH > 0)
static tCdrvMsg MEM aCanTxMsgBufferHigh_g[CDRV_MAX_TX_BUFF_ENTRIES_HIGH];
#define COP_OBD_TX_HIGH_BUFFER aCanTxMsgBufferHigh_g
#define COP_OBD_TX_HIGH_COUNT  CDRV_MAX_TX_BUFF_ENTRIES_HIGH
#else
#define COP_OBD_TX_HIGH_BUFFER NULL
#define COP_OBD_TX_HIGH_COUNT  0
#endif
#if (CDRV_MAX_RX_BUFF_ENTRIES_LOW > 0)
static tCdrvMsg MEM aCanRxMsgBufferLow_g[CDRV_MAX_RX_BUFF_ENTRIES_LOW];
#define COP_OBD_RX_LOW_BUFFER aCanRxMsgBufferLow_g
#define COP_OBD_RX_LOW_COUNT  CDRV_MAX_RX_BUFF_ENTRIES_LOW
#else
#define COP_OBD_RX_LOW_BUFFER NULL
#define COP_OBD_RX_LOW_COUNT  0
#endif
#if (CDRV_MAX_TX_BUFF_ENTRIES_LOW > 0)
static tCdrvMsg MEM aCanTxMsgBufferLow_g[CDRV_MAX_TX_BUFF_ENTRIES_LOW];
#define COP_OBD_TX_LOW_BUFFER aCanTxMsgBufferLow_g
#define COP_OBD_TX_LOW_COUNT  CDRV_MAX_TX_BUFF_ENTRIES_LOW
#else
#define COP_OBD_TX_LOW_BUFFER NULL
#define COP_OBD_TX_LOW_COUNT  0
#endif

/* ---- pass 1: checks ---------------------------------------------------------------- */
#define OBD_CREATE_CHECKS
enum { CopObdNumberOfSrdoCommuObjects_g = 0
#include OBD_OBJDICT_FILE
};
#undef OBD_CREATE_CHECKS
COP_OBD_CHECK(CopObdNumberOfSrdoCommuObjects_g <= SRDO_MAX_SRDO_IN_OBD,
              more_OBD_CREATE_SRDO_COMMU_than_SRDO_MAX_SRDO_IN_OBD)

/* ---- pass 2: constants ----------------------------------------------------------- */
#define OBD_CREATE_ROM_DATA
#include OBD_OBJDICT_FILE
#undef OBD_CREATE_ROM_DATA

/* ---- pass 3: variables -------------------------------------------------------------- */
#define OBD_CREATE_RAM_DATA
#include OBD_OBJDICT_FILE
#undef OBD_CREATE_RAM_DATA

/* ---- pass 4: subindex tables --------------------------------------------------------- */
#define OBD_CREATE_SUBINDEX_TAB
#include OBD_OBJDICT_FILE
#undef OBD_CREATE_SUBINDEX_TAB

/* ---- pass 5: part tables ---------------------------------------------------------------- */
#define OBD_CREATE_INDEX_TAB
#include OBD_OBJDICT_FILE
#undef OBD_CREATE_INDEX_TAB

/* ---- pass 6: the init function ------------------------------------------------------------ */
#define COP_OBD_INIT_PARAM pObdRamParam_l

tCopKernel PUBLIC OBD_INIT_RAM_NAME (void MEM* pInitParam_p);

COPDLLEXPORT tCopKernel PUBLIC OBD_INIT_RAM_NAME (void MEM* pInitParam_p)
{
    tObdRamParam MEM* pObdRamParam_l;

    if (pInitParam_p == NULL)
    {
        return kCopSuccessful;
    }
    pObdRamParam_l = (tObdRamParam MEM*) pInitParam_p;

    pObdRamParam_l->m_pGenericPart      = NULL;
    pObdRamParam_l->m_pManufacturerPart = NULL;
    pObdRamParam_l->m_pDevicePart       = NULL;
    pObdRamParam_l->m_pUserPart         = NULL;
    pObdRamParam_l->m_pbAbiSignature    = &COP_ABI_SIGNATURE;
    pObdRamParam_l->m_pSrdoCallbacks    = NULL;
    pObdRamParam_l->m_RxBuffHigh.m_pBufferBase = COP_OBD_RX_HIGH_BUFFER;
    pObdRamParam_l->m_RxBuffHigh.m_MaxEntries  = (tCdrvBuffIndex) COP_OBD_RX_HIGH_COUNT;
    pObdRamParam_l->m_TxBuffHigh.m_pBufferBase = COP_OBD_TX_HIGH_BUFFER;
    pObdRamParam_l->m_TxBuffHigh.m_MaxEntries  = (tCdrvBuffIndex) COP_OBD_TX_HIGH_COUNT;
    pObdRamParam_l->m_RxBuffLow.m_pBufferBase  = COP_OBD_RX_LOW_BUFFER;
    pObdRamParam_l->m_RxBuffLow.m_MaxEntries   = (tCdrvBuffIndex) COP_OBD_RX_LOW_COUNT;
    pObdRamParam_l->m_TxBuffLow.m_pBufferBase  = COP_OBD_TX_LOW_BUFFER;
    pObdRamParam_l->m_TxBuffLow.m_MaxEntries   = (tCdrvBuffIndex) COP_OBD_TX_LOW_COUNT;
    pObdRamParam_l->m_wSrdoCount = (WORD) SRDO_MAX_SRDO_IN_OBD;

#define OBD_CREATE_INIT_FUNCTION
#include OBD_OBJDICT_FILE
#undef OBD_CREATE_INIT_FUNCTION

    return kCopSuccessful;
}

#undef COP_OBD_INIT_PARAM

#endif /* OBJDEF_H */
