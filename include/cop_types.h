/*
 * cop_types.h - types, constants and macros of the SYS TEC CANopen C API.
 *
 * Included first by cop.h (whose function prototypes are generated from the
 * library); usable on its own by code that only needs the types (drivers).
 * Names, values and structure layouts are those of the SYS TEC headers, so an
 * existing application compiles unchanged. Where the original leaves a
 * choice to the compiler, this header fixes it; the decisions are:
 *
 *  1. BYTE, WORD, DWORD, BOOL, QWORD, ... are #ifndef-guarded macros as in
 *     the original (a platform header may define them first).
 *  2. DWORD is 32 bits on every target: `unsigned long int` where long has
 *     32 bits (ILP32: TMS570, Cortex-M, so existing `DWORD*` code keeps its
 *     type) and `unsigned int` where long has 64 bits (LP64 hosts). A static
 *     assertion rejects any other width.
 *  3. tFastByte is a DWORD (4 bytes everywhere, as on a 32-bit target).
 *  4. tTime is a DWORD counting ticks of 100 us; COP_USE_SMALL_TIME is
 *     refused. TgtGetTickCount must wrap modulo 2^32.
 *  5. tObdSize follows OBD_SUPPORTED_OBJ_SIZE (BYTE/WORD/DWORD) exactly as in
 *     the original.
 *  6. The 24/32-bit OBD types use the 32-bit DWORD family, so they are 4
 *     bytes on LP64 hosts too.
 *  7. Enumerated types that sit inside structures shared with the library
 *     are fixed-width typedefs with #define'd values (tCdrvBaudIndex is a
 *     BYTE, tMsgTyp a BYTE, ...). tCopKernel stays a C enum: functions
 *     return it (a 32-bit integer at the library edge) and no shared
 *     structure contains it.
 *  8. COP_MAX_INSTANCES (1..8) decides the form of every prototype, as in
 *     the original's instdef.h: with 1, every CCM_DECL_INSTANCE_HDL* /
 *     MCO_DECL_* / *_INSTANCE_* macro is empty (CcmProcess() takes no
 *     argument); with more, every Ccm* function and every callback takes
 *     the BYTE handle first (CcmProcess(InstanceHandle)), CcmInitCANopen
 *     a tCopInstanceHdl* out-parameter, the module functions (Srdo*,
 *     SdocGetTransmittedBytes) and the driver (Cdrv*) a void* instance
 *     pointer. The library is built from the same copcfg.h.
 *  9. The application's copcfg.h is included first (like the original
 *     cop.h does), then copdef.h fills in every switch it leaves out.
 *
 * Layouts of the structures shared with the library (tCdrvMsg, tCcmInitParam,
 * tObdSubEntry, ...) are checked by the C tests (c_tests/test_abi.c) and by
 * the library itself.
 */
#ifndef COP_TYPES_H
#define COP_TYPES_H

#include "copcfg.h"

#define COP_COPDEF_DEFER_OBD_CAPACITIES
#include "copdef.h"
#undef COP_COPDEF_DEFER_OBD_CAPACITIES

/* ======================================================================== */
/* 1. Basic types and qualifiers (global_cop.h)                             */
/* ======================================================================== */

#ifndef NULL
#define NULL ((void *) 0)
#endif

#ifndef _WINDEF_

#ifndef BYTE
#define BYTE unsigned char
#endif
#ifndef WORD
#define WORD unsigned short int
#endif
#ifndef DWORD
#if (defined(__SIZEOF_LONG__) && (__SIZEOF_LONG__ == 8)) || defined(__LP64__) || defined(_LP64)
#define DWORD unsigned int          /* long is 64 bits here: keep DWORD at 32 */
#else
#define DWORD unsigned long int     /* ILP32 targets (and compilers that do not say) */
#endif
#endif
#ifndef BOOL
#define BOOL unsigned char
#endif

#endif /* _WINDEF_ */

/* Signed companion of DWORD, chosen the same way (tObdInteger32). */
#if (defined(__SIZEOF_LONG__) && (__SIZEOF_LONG__ == 8)) || defined(__LP64__) || defined(_LP64)
#define COP_SDWORD signed int
#else
#define COP_SDWORD signed long int
#endif

#ifndef QWORD
#define QWORD long long
#endif
#ifndef SHORT
#define SHORT short int
#endif
#ifndef USHORT
#define USHORT unsigned short int
#endif
#ifndef INT
#define INT int
#endif
#ifndef UINT
#define UINT unsigned int
#endif
#ifndef LONG
#define LONG long int
#endif
#ifndef ULONG
#define ULONG unsigned long int
#endif

/* Memory and linkage qualifiers: empty on 32-bit targets and GCC. */
#ifndef CONST
#define CONST const
#endif
#ifndef ROM
#define ROM
#endif
#ifndef MEM
#define MEM
#endif
#ifndef GENERIC
#define GENERIC
#endif
#ifndef NEAR
#define NEAR
#endif
#ifndef FAR
#define FAR
#endif
#ifndef HWACC
#define HWACC
#endif
#ifndef LARGE
#define LARGE
#endif
#ifndef REENTRANT
#define REENTRANT
#endif
#ifndef PUBLIC
#define PUBLIC
#endif
#ifndef COPDLLEXPORT
#define COPDLLEXPORT
#endif
#ifndef CDRV_REENTRANT
#define CDRV_REENTRANT
#endif

/* Debug macros. Empty unless the platform defines them first. */
#ifndef TRACE0
#define TRACE0(str) ((void) 0)
#endif
#ifndef TRACE1
#define TRACE1(str, p1) ((void) 0)
#endif
#ifndef TRACE2
#define TRACE2(str, p1, p2) ((void) 0)
#endif
#ifndef TRACE3
#define TRACE3(str, p1, p2, p3) ((void) 0)
#endif
#ifndef TRACE4
#define TRACE4(str, p1, p2, p3, p4) ((void) 0)
#endif
#ifndef TRACE5
#define TRACE5(str, p1, p2, p3, p4, p5) ((void) 0)
#endif
#ifndef TRACE6
#define TRACE6(str, p1, p2, p3, p4, p5, p6) ((void) 0)
#endif
#ifndef ASSERT
#define ASSERT(expr) ((void) 0)
#endif
#ifndef ASSERTMSG
#define ASSERTMSG(expr, msg) ((void) 0)
#endif

/* Console output of the SYS TEC target headers (target_cop.h): PRINTF0 ..
 * PRINTF4 take a printf format and 0..4 values. They print through
 * COP_PRINTF, which is printf unless the platform names another function
 * (for example a console driver) before this header; defining PRINTF0 ..
 * PRINTF4 first (as the original allows) replaces them all, for example
 * with empty macros. No bare PRINTF is defined. */
#ifndef PRINTF0
#ifndef COP_PRINTF
#if defined(__has_include)
#if __has_include(<stdio.h>)
#include <stdio.h>
#endif
#else
#include <stdio.h>
#endif
#define COP_PRINTF printf
#endif
#define PRINTF0(arg)                 COP_PRINTF(arg)
#define PRINTF1(arg, p1)             COP_PRINTF(arg, p1)
#define PRINTF2(arg, p1, p2)         COP_PRINTF(arg, p1, p2)
#define PRINTF3(arg, p1, p2, p3)     COP_PRINTF(arg, p1, p2, p3)
#define PRINTF4(arg, p1, p2, p3, p4) COP_PRINTF(arg, p1, p2, p3, p4)
#endif

/* Target memory macros (target_cop.h). They expand to the C library's
 * memcpy / memset / malloc / free, as the original does on 32-bit ARM and
 * Linux targets; a platform may define any of them first (for example as
 * TgtMemCpy / TgtMemSet, declared in cop_app.h). The library itself uses
 * none of them and needs no heap. Unlike the original these expansions are
 * expressions without a trailing ';', so they also work inside if/else.
 * The C library headers are included when the compiler has them (a
 * toolchain without a C library still compiles everything but these
 * macros). */
#ifndef COP_MEMCPY
#if defined(__has_include)
#if __has_include(<string.h>)
#include <string.h>
#endif
#else
#include <string.h>
#endif
#define COP_MEMCPY(dst, src, siz) memcpy((void*) (dst), (const void*) (src), (size_t) (siz))
#endif
#ifndef COP_MEMSET
#if defined(__has_include)
#if __has_include(<string.h>)
#include <string.h>
#endif
#else
#include <string.h>
#endif
#define COP_MEMSET(dst, val, siz) memset((void*) (dst), (int) (val), (size_t) (siz))
#endif
#ifndef COP_MALLOC
#if defined(__has_include)
#if __has_include(<stdlib.h>)
#include <stdlib.h>
#endif
#else
#include <stdlib.h>
#endif
#define COP_MALLOC(dwMemSize_p) malloc((size_t) (dwMemSize_p))
#endif
#ifndef COP_FREE
#if defined(__has_include)
#if __has_include(<stdlib.h>)
#include <stdlib.h>
#endif
#else
#include <stdlib.h>
#endif
#define COP_FREE(pMem_p) free((void*) (pMem_p))
#endif

/* Compile-time assertion usable by C89 compilers (file scope). */
#define COP_PASTE2_(a, b) a##b
#define COP_PASTE2(a, b)  COP_PASTE2_(a, b)
#define COP_STATIC_ASSERT(cond, msg) \
    typedef char COP_PASTE2(cop_static_assert_, msg)[(cond) ? 1 : -1]

COP_STATIC_ASSERT(sizeof(DWORD) == 4, DWORD_must_be_32_bits);
COP_STATIC_ASSERT(sizeof(WORD) == 2, WORD_must_be_16_bits);
COP_STATIC_ASSERT(sizeof(BYTE) == 1, BYTE_must_be_8_bits);

/* ======================================================================== */
/* 1a. Configuration checks and instance macros (instdef.h)                 */
/* ======================================================================== */

#if (COP_MAX_INSTANCES < 1) || (COP_MAX_INSTANCES > 8)
#error "COP_MAX_INSTANCES must be 1..8 (one stack instance per CAN controller)"
#endif
#if (COP_USE_SMALL_TIME != FALSE)
#error "COP_USE_SMALL_TIME must be FALSE: tTime is a 32-bit count of 100 us ticks in this library (a 16-bit tTime saturates after 6.5 s and would change tCdrvMsg)"
#endif
#if (COP_USE_CDRV_FUNCTION_POINTER != FALSE)
#error "COP_USE_CDRV_FUNCTION_POINTER is not supported: the library calls the Cdrv* functions directly"
#endif
#if (OBD_SUPPORTED_OBJ_SIZE != OBD_OBJ_SIZE_SMALL) && (OBD_SUPPORTED_OBJ_SIZE != OBD_OBJ_SIZE_MIDDLE) && (OBD_SUPPORTED_OBJ_SIZE != OBD_OBJ_SIZE_BIG)
#error "OBD_SUPPORTED_OBJ_SIZE must be OBD_OBJ_SIZE_SMALL, OBD_OBJ_SIZE_MIDDLE or OBD_OBJ_SIZE_BIG"
#endif
#if (CDRV_CAN_SPEC != CAN20A) && (CDRV_CAN_SPEC != CAN20B)
#error "CDRV_CAN_SPEC must be CAN20A or CAN20B"
#endif
#if (PDO_GRANULARITY != 8) && (PDO_GRANULARITY != 64)
#error "PDO_GRANULARITY must be 8 or 64"
#endif
/* tPdoParam.m_adwMappParam and the PDO mapping objects of objdef.h come in
 * these two sizes only. */
#if (PDO_MAX_MAPPENTRIES != 8) && (PDO_MAX_MAPPENTRIES != 64)
#error "PDO_MAX_MAPPENTRIES must be 8 or 64"
#endif

typedef BYTE tCopInstanceHdl;
typedef void MEM* tCopPtrInstance;
#define CCM_ILLINSTANCE     NULL
#define CCM_ILLINSTANCE_HDL 0xFF

typedef enum
{
    kStateUnused  = 0x00,
    kStateDeleted = 0x01,
    kStateUsed    = 0xFF
} tInstState;

#if (COP_MAX_INSTANCES == 1)
/* Single-instance forms: no handle parameter anywhere. */
#define CCM_DECL_INSTANCE_HDL           void
#define CCM_DECL_INSTANCE_HDL_
#define CCM_DECL_PTR_INSTANCE_HDL       void
#define CCM_DECL_PTR_INSTANCE_HDL_
#define CCM_INSTANCE_HDL
#define CCM_INSTANCE_HDL_
#define CCM_INSTANCE_PARAM(p)
#define CCM_INSTANCE_PARAM_(p)
#define MCO_DECL_INSTANCE_PTR           void
#define MCO_DECL_INSTANCE_PTR_
#define MCO_DECL_PTR_INSTANCE_PTR       void
#define MCO_DECL_PTR_INSTANCE_PTR_
#define MCO_INSTANCE_PTR
#define MCO_INSTANCE_PTR_
#define MCO_INSTANCE_PARAM(a)
#define MCO_INSTANCE_PARAM_(a)
#define MCO_PTR_INSTANCE_PTR
#define MCO_PTR_INSTANCE_PTR_
#define MCO_ADDR_INSTANCE_PTR_
#else
/* Multi-instance forms (instdef.h): the handle of the CCM layer, the
 * instance pointer of the module and driver layers. A module instance
 * pointer (MCO_*) points to the BYTE that holds the instance's handle:
 * SrdoAddInstance hands out such a pointer, and &bHandle works as well. */
#define CCM_DECL_INSTANCE_HDL           tCopInstanceHdl InstanceHandle
#define CCM_DECL_INSTANCE_HDL_          tCopInstanceHdl InstanceHandle,
#define CCM_DECL_PTR_INSTANCE_HDL       tCopInstanceHdl MEM* pInstanceHandle
#define CCM_DECL_PTR_INSTANCE_HDL_      tCopInstanceHdl MEM* pInstanceHandle,
#define CCM_INSTANCE_HDL                InstanceHandle
#define CCM_INSTANCE_HDL_               InstanceHandle,
#define CCM_INSTANCE_PARAM(p)           p
#define CCM_INSTANCE_PARAM_(p)          p,
#define MCO_DECL_INSTANCE_PTR           void MEM* pInstance
#define MCO_DECL_INSTANCE_PTR_          void MEM* pInstance,
#define MCO_DECL_PTR_INSTANCE_PTR       void MEM* MEM* pInstancePtr
#define MCO_DECL_PTR_INSTANCE_PTR_      void MEM* MEM* pInstancePtr,
#define MCO_INSTANCE_PTR                pInstance
#define MCO_INSTANCE_PTR_               pInstance,
#define MCO_INSTANCE_PARAM(a)           (a)
#define MCO_INSTANCE_PARAM_(a)          (a),
#define MCO_PTR_INSTANCE_PTR            pInstancePtr
#define MCO_PTR_INSTANCE_PTR_           pInstancePtr,
#define MCO_ADDR_INSTANCE_PTR_          &pInstance,
#endif

/* Switches as defined/undefined names, for the conditional prototypes of
 * cop.h (generated; see cbindgen.toml [defines]). */
#if (SRDO_USE_GFC != FALSE)
#define COP_CFG_SRDO_USE_GFC 1
#endif
#if (SRDO_USE_PROGMONITOR != FALSE)
#define COP_CFG_SRDO_USE_PROGMONITOR 1
#endif
#if (SRDO_USE_STATIC_MAPPING != FALSE)
#define COP_CFG_SRDO_STATIC_MAPPING 1
#endif
#if (CDRV_TIMESTAMP != FALSE)
#define COP_CFG_CDRV_TIMESTAMP 1
#endif
#if (CDRV_CAN_SPEC == CAN20B)
#define COP_CFG_CDRV_CAN20B 1
#endif
#if (NMTS_USE_LIFEGUARDING != FALSE)
#define COP_CFG_NMTS_USE_LIFEGUARDING 1
#endif

/* ======================================================================== */
/* Fast types and time (cdrvdef.h, target_cop.h)                             */
/* ======================================================================== */

/* 32-bit targets: DWORD. Four bytes everywhere (decision 3). */
typedef DWORD tFast;
typedef DWORD tFastByte;
typedef DWORD tFastWord;

/* Ticks of 100 us, wrapping modulo 2^32 (decision 4). */
typedef DWORD tTime;

typedef struct
{
    DWORD m_dwMs;       /* milliseconds after midnight */
    WORD  m_wDays;      /* days since 1 January 1984 */
} tTimeOfDay;

/* ======================================================================== */
/* 2. Return codes (errordef.h)                                              */
/* ======================================================================== */

typedef enum
{
    kCopSuccessful                  = 0x0000,
    kCopIllegalInstance             = 0x0001,
    kCopInvalidInstanceParam        = 0x0002,
    kCopNoFreeInstance              = 0x0003,
    kCopWrongSignature              = 0x0004,
    kCopUnsupportedBtrTable         = 0x0005,
    kCopUnsupportedBtrIndex         = 0x0006,
    kCopInvalidNodeId               = 0x0007,
    kCopNoResource                  = 0x0008,
    kCopInvalidParam                = 0x0009,

    kCopCdrvNoMsg                   = 0x0010,
    kCopCdrvMsgHigh                 = 0x0011,
    kCopCdrvMsgLow                  = 0x0012,
    kCopCdrvInitError               = 0x0013,
    kCopCdrvNoFreeChannel           = 0x0014,
    kCopCdrvTxBuffHighOverrun       = 0x0015,
    kCopCdrvTxBuffLowOverrun        = 0x0016,
    kCopCdrvIllegalBdi              = 0x0017,
    kCopCdrvBusy                    = 0x0018,
    kCopCdrvInvalidDriverType       = 0x0019,
    kCopCdrvDriverNotFound          = 0x001A,
    kCopCdrvInvalidBaseAddress      = 0x001B,
    kCopCdrvInvalidParam            = 0x001C,
    kCopCdrvInvalidDevNumber        = 0x001D,
    kCopCdrvDevAlreadyInUse         = 0x001E,
    kCopCdrvHostOsError             = 0x001F,

    kCopCobNoFreeEntry              = 0x0020,
    kCopCobAlreadyExist             = 0x0021,
    kCopCobAllreadyExist            = 0x0021,  /* spelling of the CcmDyn manual, 5.1 */
    kCopCobIllegalHdl               = 0x0022,
    kCopCobIllegalCanId             = 0x0023,
    kCopCobInvalidCanId             = 0x0024,
    kCopCobCdrvStateSet             = 0x0025,
    kCopCobNoFreeEntryHighBuf       = 0x0026,
    kCopCobOwnId                    = 0x0027,
    kCopCobWrongCobType             = 0x0028,

    kCopObdIllegalPart              = 0x0030,
    kCopObdIndexNotExist            = 0x0031,
    kCopObdSubindexNotExist         = 0x0032,
    kCopObdReadViolation            = 0x0033,
    kCopObdWriteViolation           = 0x0034,
    kCopObdAccessViolation          = 0x0035,
    kCopObdUnknownObjectType        = 0x0036,
    kCopObdVarEntryNotExist         = 0x0037,
    kCopObdValueToLow               = 0x0038,
    kCopObdValueToHigh              = 0x0039,
    kCopObdValueLengthError         = 0x003A,
    kCopObdIllegalFloat             = 0x003B,
    kCopObdWrongOdBuilderKey        = 0x003F,

    kCopNmtUnknownCommand           = 0x0040,
    kCopNmtLifeguardVsHeartbeat     = 0x0041,
    kCopNmtBootupNotPossible        = 0x0042,
    kCopNmtHbcWrongCfg              = 0x0043,
    kCopNmtmSlaveNodeExist          = 0x0044,
    kCopNmtmNoFreeSlaveEntry        = 0x0045,
    kCopNmtmSlaveEntryNotExist      = 0x0046,
    kCopNmtStateError               = 0x0047,
    kCopNmtmInvalidSlaveNodeId      = 0x0048,

    kCopSdocInitError               = 0x0050,
    kCopSdocInvalidParam            = 0x0051,
    kCopSdocClientNotExist          = 0x0052,
    kCopSdocBusy                    = 0x0053,
    kCopSdocTransferError           = 0x0054,
    kCopSdocWrongMultiplexor        = 0x0055,
    kCopSdocEntryAlreadyDefined     = 0x0056,
    kCopSdocNoFreeEntry             = 0x0057,
    kCopSdocConfigOrder             = 0x0058,

    kCopSdosInitError               = 0x0060,
    kCopSdosServerNotExist          = 0x0061,
    kCopSdosBusy                    = 0x0062,
    kCopSdosSizeMismatch            = 0x0063,
    kCopSdosNoFreeEntry             = 0x0064,
    kCopSdosEntryAlreadyDefined     = 0x0065,
    kCopSdosConfigOrder             = 0x0066,
    kCopSdosWrongDlc                = 0x0067,
    kCopSdosWrongCcs                = 0x0068,

    kCopPdoNotExist                 = 0x0070,
    kCopPdoLengthExceeded           = 0x0071,
    kCopPdoGranularityMismatch      = 0x0072,
    kCopPdoInitError                = 0x0073,
    kCopPdoErrorPdoEncode           = 0x0074,
    kCopPdoErrorPdoDecode           = 0x0075,
    kCopPdoErrorSend                = 0x0076,
    kCopPdoErrorSyncWin             = 0x0077,
    kCopPdoErrorMapp                = 0x0078,
    kCopPdoVarNotFound              = 0x0079,
    kCopPdoErrorEmcyPdoLen          = 0x007A,
    kCopPdoWriteConstObject         = 0x007B,
    kCopPdoErrorRxEventTimer        = 0x007C,

    kCopLsssResetNode               = 0x0080,
    kCopLsssInvalidNodeId           = 0x0081,

    kCopEmccNoFreeProducerEntry     = 0x0090,
    kCopEmccNodeIdNotExist          = 0x0091,
    kCopEmccNodeIdInvalid           = 0x0092,
    kCopEmccNodeIdExist             = 0x0093,

    kCopDynNoMemory                 = 0x00A0,
    kCopDynInvalidConfig            = 0x00A1,

    kCopHbcEntryNotExist            = 0x00B0,
    kCopHbcEntryAlreadyExist        = 0x00B1,
    kCopHbcNoFreeEntry              = 0x00B2,

    kCopCfgMaConfigError            = 0x00C0,
    kCopCfgMaSdocTimeOut            = 0x00C1,
    kCopCfgMaNoErrorCb              = 0x00C2,
    kCopCfgMaNoFreeConfig           = 0x00C3,
    kCopCfgMaNoConfigData           = 0x00C4,
    kCopCfgMaInvaildSdoc            = 0x00C5,
    kCopCfgMaConfigwithErrors       = 0x00C6,

    kCopLssmIllegalMode             = 0x00D0,
    kCopLssmIllegalState            = 0x00D1,
    kCopLssmBusy                    = 0x00D2,
    kCopLssmIllegalCmd              = 0x00D3,
    kCopLssmTimeout                 = 0x00D4,
    kCopLssmErrorInConfirm          = 0x00D5,

    kCopCcmStoreUnvalidState        = 0x00E0,
    kCopCcmStoreHwError             = 0x00E1,

    kCopSrdoNotExist                = 0x0100,
    kCopSrdoGranularityMismatch     = 0x0101,
    kCopSrdoCfgTimingError          = 0x0102,
    kCopSrdoCfgIdError              = 0x0103,
    kCopSrdoCfgCrcError             = 0x0104,
    kCopSrdoNmtError                = 0x0105,
    kCopSrdoInvalidCfg              = 0x0106,
    kCopSrdoInvalid                 = 0x0107,
    kCopSrdoRxTxConflict            = 0x0108,
    kCopSrdoIllegalCanId            = 0x0109,
    kCopSrdoCanIdAlreadyInUse       = 0x010A,
    kCopSrdoNotInOrder              = 0x010B,
    kCopSrdoSctTimeout              = 0x010C,
    kCopSrdoSrvtTimeout             = 0x010D,
    kCopSrdoCanIdNotValid           = 0x010E,
    kCopSrdoDlcNotValid             = 0x010F,
    kCopSrdoErrorMapp               = 0x0110,
    kCopSrdoDataError               = 0x0111,
    kCopSrdoLengthExceeded          = 0x0112,
    kCopSrdoLengtExceeded           = kCopSrdoLengthExceeded,  /* spelling of the manual */
    kCopSrdoNotHandledInApp         = 0x0113,
    kCopSrdoOverrun                 = 0x0114,

    kCopSdomBusy                    = 0x0121,
    kCopSdomInternStructFull        = 0x0122,
    kCopSdomErrorCbInternError      = 0x0123,
    kCopSdomErrorCbCopError         = 0x0124,

    kCopSrdBusy                     = 0x0130,
    kCopSrdNotRegistered            = 0x0131,
    kCopSrdNoAnswerSdom             = 0x0132,
    kCopSrdNotMasterMode            = 0x0133,
    kCopSrdNotDynConnection         = 0x0134,
    kCopSrdSdomNotUndefSdoc         = 0x0135,

    kCopMgrTaskDeferred             = 0x0140,
    kCopMgrInvalidOperation         = 0x0141,
    kCopMgrInvalidParam             = 0x0142,
    kCopMgrNoFreeEntry              = 0x0144,
    kCopMgrNodeBusy                 = 0x0145,
    kCopMgrSdocTypeAutoRunning      = 0x0146,

    kCopUserSDOAbort                = 0x0800   /* application area 0x0800..0x7FFF */
} tCopKernel;

/* ======================================================================== */
/* Version                                                                   */
/* ======================================================================== */

/* Version word of CopGetStackVersion(): bits 0-7 major, 8-15 minor,
 * 16-31 release. */
#define COP_STACK_VERSION(ver, rev, rel) \
    ((DWORD) (((DWORD) (ver) & 0xFFUL) | (((DWORD) (rev) & 0xFFUL) << 8) | ((DWORD) (rel) << 16)))
#define COP_GET_MAJOR_VERSION(v)   ((BYTE) ((v) & 0xFFUL))
#define COP_GET_MINOR_VERSION(v)   ((BYTE) (((v) >> 8) & 0xFFUL))
#define COP_GET_RELEASE_VERSION(v) ((WORD) (((v) >> 16) & 0xFFFFUL))
/* Object 0x1018 sub 3 (revision number) and a "Vx.y rz" string (0x100A). */
#define COP_OBJ1018_VERSION(ver, rev, rel) \
    ((DWORD) (((DWORD) (ver) << 16) | ((DWORD) (rev) & 0xFFFFUL)))
#define COP_STRING_VERSION(ver, rev, rel) "V" #ver "." #rev " r" #rel

/* This library's version (must match CopGetStackVersion(); c_tests check). */
#define COP_LIB_VERSION_MAJOR   5
#define COP_LIB_VERSION_MINOR   60
#define COP_LIB_VERSION_RELEASE 1
#define COP_LIB_STRING_VERSION_(a, b, c) COP_STRING_VERSION(a, b, c)
#define DEFINED_STACK_VERSION   COP_STACK_VERSION(COP_LIB_VERSION_MAJOR, COP_LIB_VERSION_MINOR, COP_LIB_VERSION_RELEASE)
#define DEFINED_OBJ1018_VERSION COP_OBJ1018_VERSION(COP_LIB_VERSION_MAJOR, COP_LIB_VERSION_MINOR, COP_LIB_VERSION_RELEASE)
#define DEFINED_STRING_VERSION  COP_LIB_STRING_VERSION_(COP_LIB_VERSION_MAJOR, COP_LIB_VERSION_MINOR, COP_LIB_VERSION_RELEASE)

/* ======================================================================== */
/* 9. CAN driver (cdrv.h, cdrvdef.h)                                         */
/* ======================================================================== */

typedef WORD tCdrvBuffIndex;

#if (CDRV_CAN_SPEC == CAN20B)
typedef DWORD tCanId;
#else
typedef WORD tCanId;
#endif

typedef enum
{
    kCdrvInstStateUnused  = 0x00,
    kCdrvInstStateDeleted = 0x01,
    kCdrvInstStateUsed    = 0xFF
} tCdrvInstState;

/* Message type (tMsgTyp, a BYTE) built from the tMsgTypBit bits. */
typedef BYTE tMsgTyp;
typedef BYTE tMsgTypBit;
#define kMtbRecv          0x01
#define kMtbRtr           0x02
#define kMtbFilter        0x03
#define kMtbForce         0x04
#define kMtbFirstMsg      0x20
#define kMtbHighPrio      0x40      /* high-priority buffer (SRDO, NMT) */
#define kMtbExtend        0x80      /* 29-bit identifier */
#define kMsgTypSend       0x00
#define kMsgTypRecv       0x01
#define kMsgTypSendRtrReq 0x02
#define kMsgTypRecvRtrReq 0x03

/* One CAN frame. m_Time (receive time in ticks of 100 us) only with
 * CDRV_TIMESTAMP. Sizes (ARM and x86-64): 14 bytes (CAN20A), 20 (CAN20A +
 * timestamp), 16 (CAN20B), 20 (CAN20B + timestamp). */
typedef struct
{
    tCanId  m_CanId;
    tMsgTyp m_MsgType;
    BYTE    m_bSize;            /* DLC */
    BYTE    m_bChannel_p;
    BYTE    m_bData[8];
#if (CDRV_TIMESTAMP != FALSE)
    tTime   m_Time;
#endif
} tCdrvMsg;

/* Bit rate index (CiA 305 order); a BYTE inside tCcmInitParam. */
typedef BYTE tCdrvBaudIndex;
#define kBdi1MBaud   0
#define kBdi800kBaud 1
#define kBdi500kBaud 2
#define kBdi250kBaud 3
#define kBdi125kBaud 4
#define kBdi100kBaud 5
#define kBdi50kBaud  6
#define kBdi20kBaud  7
#define kBdi10kBaud  8

typedef BYTE tCdrvResetCode;
#define kResetTxBuffHigh 0x01
#define kResetTxBuffLow  0x02
#define kResetTxBuffer   0x03
#define kResetRxBuffHigh 0x04
#define kResetRxBuffLow  0x08
#define kResetRxBuffer   0x0C
#define kResetAllBuffer  0x0F
#define kResetCanCtrl    0x10
#define kResetAll        0x1F

typedef WORD tCdrvStatus;
#define kCdrvNoError           0x0000
#define kCdrvWarningLimitSet   0x0001
#define kCdrvWarningLimitReset 0x0002
#define kCdrvErrorPassiveSet   0x0004
#define kCdrvErrorPassiveReset 0x0008
#define kCdrvBusOff            0x0010
#define kCdrvOverrun           0x0020
#define kCdrvStuffError        0x0040
#define kCdrvFormError         0x0080
#define kCdrvAckError          0x0100
#define kCdrvCrcError          0x0200
#define kCdrvRxBuffHighOverrun 0x0400
#define kCdrvRxBuffLowOverrun  0x1000
#define kCdrvBusOffReset       0x4000
#define kCdrvFirstBusContact   0x8000

typedef enum
{
    kCdrvRxIsr    = 0,
    kCdrvTxIsr    = 1,
    kCdrvErrorIsr = 2
} tCdrvIsrType;

#define CAN_RX_EVENT  0x00000001UL
#define CAN_TX_EVENT  0x01000000UL
#define CAN_ERR_EVENT 0x40000000UL
#define CDRV_SELECT_CHANNEL(a)   (((WORD) 1) << (a))
#define CDRV_SELECT_CHANNEL32(a) (((DWORD) 1) << (a))

typedef void (PUBLIC ROM* tCdrvEnableInt) (BYTE bEnable_p);

/* Controller parameters: a union of controller-specific structures, padded
 * to exactly two pointers so that its size does not depend on which
 * controller structures a driver adds. */
typedef struct
{
    BYTE HWACC* m_pbBaseAddr;
} tMcIoParam;

typedef struct
{
    BYTE m_bCanNo;
} tZeroBasedCanNo;

typedef struct
{
    BYTE m_bCanNo;
} tNonZeroBasedCanNo;

typedef union
{
    tMcIoParam         m_McIoParam;
    tZeroBasedCanNo    m_ZeroBasedCanNo;
    tNonZeroBasedCanNo m_NonZeroBasedCanNo;
    void*              m_apvReserved[2];    /* fixes size and alignment */
} tCdrvHwParam;

COP_STATIC_ASSERT(sizeof(tCdrvHwParam) == 2 * sizeof(void*), tCdrvHwParam_is_two_pointers);

typedef struct
{
    tCdrvMsg MEM*  m_pBufferBase;
    tCdrvBuffIndex m_MaxEntries;
} tCdrvBuffInit;

/* What CdrvInit receives. The high-priority buffers are always present
 * (0 entries when CDRV_USE_HIGHBUFF is FALSE). */
typedef struct
{
    tCdrvBaudIndex  m_BaudIndex;
    CONST void ROM* m_pBdiTable;
    WORD            m_wSizeOfBdiTab;
    DWORD           m_dwAmr;
    DWORD           m_dwAcr;
    tCdrvHwParam    m_HwParam;
    tCdrvBuffInit   m_RxBuffHigh;
    tCdrvBuffInit   m_TxBuffHigh;
    tCdrvBuffInit   m_RxBuffLow;
    tCdrvBuffInit   m_TxBuffLow;
    tCdrvEnableInt  m_fpEnableInterrupt;
} tCdrvInitParam;

/* Diagnostic data of CdrvGetDiagnostic: its layout is the driver's own
 * business (the library never calls the function). */
typedef struct tCdrvDiagnosticTag tCdrvDiagnostic;

/* ======================================================================== */
/* 6. Object dictionary (obd.h, cop.h)                                       */
/* ======================================================================== */

/* Object size (buffer sizes of CcmReadObject/CcmWriteObject, tVarParam). */
#if (OBD_SUPPORTED_OBJ_SIZE == OBD_OBJ_SIZE_BIG)
typedef DWORD tObdSize;
#elif (OBD_SUPPORTED_OBJ_SIZE == OBD_OBJ_SIZE_MIDDLE)
typedef WORD tObdSize;
#else
typedef BYTE tObdSize;
#endif

typedef tFastByte tObdPart;
#define kObdPartNo   0x00
#define kObdPartGen  0x01   /* 0x1000..0x1FFF */
#define kObdPartMan  0x02   /* 0x2000..0x5FFF */
#define kObdPartDev  0x04   /* 0x6000..0x9FFF */
#define kObdPartUsr  0x08   /* dynamic / user OD */
#define kObdPartApp  kObdPartDev
#define kObdPartApp2 (kObdPartMan | kObdPartDev | kObdPartUsr)
#define kObdPartAll  (kObdPartGen | kObdPartMan | kObdPartDev | kObdPartUsr)

typedef tFastByte tObdEvent;
#define kObdEvPreRead         0x00
#define kObdEvPostRead        0x01
#define kObdEvPreWrite        0x02
#define kObdEvPostWrite       0x03
#define kObdEvInitWrite       0x04  /* size check before a write; m_pArg -> tObdSize */
#define kObdEvAbortSdo        0x05
#define kObdEvCheckExist      0x06
#define kObdEvWrStringDomain  0x07

/* Data types (CiA 301 numbers; ODBuilder writes them as bare numbers). */
typedef WORD tObdType;
#define kObdTypBool      0x0001
#define kObdTypInt8      0x0002
#define kObdTypInt16     0x0003
#define kObdTypInt32     0x0004
#define kObdTypUInt8     0x0005
#define kObdTypUInt16    0x0006
#define kObdTypUInt32    0x0007
#define kObdTypReal32    0x0008
#define kObdTypVString   0x0009
#define kObdTypOString   0x000A
#define kObdTypUString   0x000B
#define kObdTypTimeOfDay 0x000C
#define kObdTypTimeDiff  0x000D
#define kObdTypDomain    0x000F
#define kObdTypInt24     0x0010
#define kObdTypReal64    0x0011
#define kObdTypInt40     0x0012
#define kObdTypInt48     0x0013
#define kObdTypInt56     0x0014
#define kObdTypInt64     0x0015
#define kObdTypUInt24    0x0016
#define kObdTypUInt40    0x0018
#define kObdTypUInt48    0x0019
#define kObdTypUInt56    0x001A
#define kObdTypUInt64    0x001B

/* C types of the OBD values. */
typedef unsigned char      tObdBoolean;
typedef signed char        tObdInteger8;
typedef signed short int   tObdInteger16;
typedef COP_SDWORD         tObdInteger32;
typedef DWORD              tObdUnsigned32;
typedef unsigned char      tObdUnsigned8;
typedef unsigned short int tObdUnsigned16;
typedef float              tObdReal32;
typedef unsigned char      tObdDomain;
typedef COP_SDWORD         tObdInteger24;
typedef DWORD              tObdUnsigned24;
typedef QWORD              tObdInteger40;
typedef QWORD              tObdInteger48;
typedef QWORD              tObdInteger56;
typedef QWORD              tObdInteger64;
typedef unsigned long long tObdUnsigned40;
typedef unsigned long long tObdUnsigned48;
typedef unsigned long long tObdUnsigned56;
typedef unsigned long long tObdUnsigned64;
typedef double             tObdReal64;
typedef tTimeOfDay         tObdTimeOfDay;
typedef tTimeOfDay         tObdTimeDifference;

typedef struct
{
    tObdSize       m_Size;
    char GENERIC*  m_pString;
} tObdVString;

typedef struct
{
    tObdSize       m_Size;
    char GENERIC*  m_pDefString;
    char GENERIC*  m_pString;
} tObdVStringDef;

typedef struct
{
    tObdSize       m_DownloadSize;
    tObdSize       m_ObjSize;
    void GENERIC*  m_pData;
} tObdVStringDomain;

/* Access attributes: R read, W write, C const, P PDO-mappable, array,
 * G range-checked, V variable (tObdVarEntry), S stored. */
typedef BYTE tObdAccess;
#define kObdAccRead   0x01
#define kObdAccWrite  0x02
#define kObdAccConst  0x04
#define kObdAccPdo    0x08
#define kObdAccArray  0x10
#define kObdAccRange  0x20
#define kObdAccVar    0x40
#define kObdAccStore  0x80

#define kObdAccR      (kObdAccRead)
#define kObdAccW      (kObdAccWrite)
#define kObdAccRW     (kObdAccWrite | kObdAccRead)
#define kObdAccCR     (kObdAccConst | kObdAccRead)
#define kObdAccGR     (kObdAccRange | kObdAccRead)
#define kObdAccGW     (kObdAccRange | kObdAccWrite)
#define kObdAccGRW    (kObdAccRange | kObdAccWrite | kObdAccRead)
#define kObdAccVR     (kObdAccVar | kObdAccRead)
#define kObdAccVW     (kObdAccVar | kObdAccWrite)
#define kObdAccVRW    (kObdAccVar | kObdAccWrite | kObdAccRead)
#define kObdAccVPR    (kObdAccVar | kObdAccPdo | kObdAccRead)
#define kObdAccVPW    (kObdAccVar | kObdAccPdo | kObdAccWrite)
#define kObdAccVPRW   (kObdAccVar | kObdAccPdo | kObdAccWrite | kObdAccRead)
#define kObdAccVGR    (kObdAccVar | kObdAccRange | kObdAccRead)
#define kObdAccVGW    (kObdAccVar | kObdAccRange | kObdAccWrite)
#define kObdAccVGRW   (kObdAccVar | kObdAccRange | kObdAccWrite | kObdAccRead)
#define kObdAccVGPR   (kObdAccVar | kObdAccRange | kObdAccPdo | kObdAccRead)
#define kObdAccVGPW   (kObdAccVar | kObdAccRange | kObdAccPdo | kObdAccWrite)
#define kObdAccVGPRW  (kObdAccVar | kObdAccRange | kObdAccPdo | kObdAccWrite | kObdAccRead)
#define kObdAccSR     (kObdAccStore | kObdAccRead)
#define kObdAccSW     (kObdAccStore | kObdAccWrite)
#define kObdAccSRW    (kObdAccStore | kObdAccWrite | kObdAccRead)
#define kObdAccSCR    (kObdAccStore | kObdAccConst | kObdAccRead)
#define kObdAccSGR    (kObdAccStore | kObdAccRange | kObdAccRead)
#define kObdAccSGW    (kObdAccStore | kObdAccRange | kObdAccWrite)
#define kObdAccSGRW   (kObdAccStore | kObdAccRange | kObdAccWrite | kObdAccRead)
#define kObdAccSVR    (kObdAccStore | kObdAccVar | kObdAccRead)
#define kObdAccSVW    (kObdAccStore | kObdAccVar | kObdAccWrite)
#define kObdAccSVRW   (kObdAccStore | kObdAccVar | kObdAccWrite | kObdAccRead)
#define kObdAccSVPR   (kObdAccStore | kObdAccVar | kObdAccPdo | kObdAccRead)
#define kObdAccSVPW   (kObdAccStore | kObdAccVar | kObdAccPdo | kObdAccWrite)
#define kObdAccSVPRW  (kObdAccStore | kObdAccVar | kObdAccPdo | kObdAccWrite | kObdAccRead)
#define kObdAccSVGR   (kObdAccStore | kObdAccVar | kObdAccRange | kObdAccRead)
#define kObdAccSVGW   (kObdAccStore | kObdAccVar | kObdAccRange | kObdAccWrite)
#define kObdAccSVGRW  (kObdAccStore | kObdAccVar | kObdAccRange | kObdAccWrite | kObdAccRead)
#define kObdAccSVGPR  (kObdAccStore | kObdAccVar | kObdAccRange | kObdAccPdo | kObdAccRead)
#define kObdAccSVGPW  (kObdAccStore | kObdAccVar | kObdAccRange | kObdAccPdo | kObdAccWrite)
#define kObdAccSVGPRW (kObdAccStore | kObdAccVar | kObdAccRange | kObdAccPdo | kObdAccWrite | kObdAccRead)

/* NMT states of a node (CiA 301 values, CcmObdGetNodeState). */
typedef BYTE tNodeState;
#define kNodeStateInitialisation 0x00
#define kNodeStateStopped        0x04
#define kNodeStateOperational    0x05
#define kNodeStatePreOperational 0x7F

/* Event data of an OBD callback. The callback may set m_dwAbortCode (an
 * SDOAC_* code) when it refuses an access. */
typedef struct
{
    BYTE           m_ObdEvent;      /* kObdEv* */
    WORD           m_wIndex;
    BYTE           m_bSubIndex;
    void GENERIC*  m_pArg;          /* event data, see kObdEv* */
    DWORD          m_dwAbortCode;
} tObdCbParam;

typedef tCopKernel (PUBLIC ROM* tObdCallback) (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p);

typedef tCopKernel (PUBLIC ROM* tVarCallback) (CCM_DECL_INSTANCE_HDL_ void GENERIC* pParam_p);

/* A variable the application attaches to a USERDEF/DOMAIN/VARARRAY object
 * at run time (CcmDefineVarTab). This library always has the callback and
 * argument fields (the original drops them with static PDO mapping). */
typedef struct
{
    void MEM*     m_pData;
    tObdSize      m_Size;
    tVarCallback  m_fpCallback;
    void GENERIC* m_pArg;
} tObdVarEntry;

/* Storage kinds of this library's subindex entries (m_bKind). */
#define kObdKindRam        0    /* m_pCurrent -> m_dwSize bytes of RAM */
#define kObdKindRom        1    /* constant at m_pDefault (m_dwSize bytes) */
#define kObdKindRamVString 2    /* m_pCurrent -> char[m_dwSize + 1], m_pDefault -> NUL-terminated default */
#define kObdKindRomVString 3    /* m_pDefault -> m_dwSize characters */
#define kObdKindVarEntry   4    /* m_pCurrent -> tObdVarEntry (array of them for arrays) */

/* One subindex. The SYS TEC field order, plus m_bKind and m_dwSize so that
 * the library never guesses the width of a C variable. With kObdAccRange,
 * m_pDefault points to three values {default, low, high}. With kObdAccArray
 * the entry stands for subindices sub..sub+n-1 (n = value of subindex 0) and
 * the storage holds the n elements one after the other. */
typedef struct
{
    BYTE            m_bSubIndex;
    BYTE            m_bType;        /* kObdTyp* */
    BYTE            m_bAccess;      /* kObdAcc* */
    BYTE            m_bKind;        /* kObdKind* */
    DWORD           m_dwSize;       /* sizeof the C variable; maximum length of strings */
    CONST void ROM* m_pDefault;
    void MEM*       m_pCurrent;
} tObdSubEntry;

typedef CONST tObdSubEntry ROM* tObdSubEntryPtr;

/* One index. Each part table ends with index OBD_TABLE_INDEX_END. */
typedef struct
{
    WORD            m_wIndex;
    tObdSubEntryPtr m_pSubIndex;
    BYTE            m_bCount;       /* entries in m_pSubIndex */
    tObdCallback    m_fpCallback;
} tObdEntry;

typedef CONST tObdEntry ROM* tObdEntryPtr;

#define OBD_TABLE_INDEX_END 0xFFFF

typedef struct
{
    BYTE  m_bNumberOfMappedObjects;
    DWORD m_aMapObjects[8];
} tObdMappParam;

typedef struct
{
    DWORD m_dwCANId;
    BYTE  m_bTxTyp;
    WORD  m_wInhibitTime;
    WORD  m_wEventTimer;
} tObdCommuParam;

/* ======================================================================== */
/* 5. NMT                                                                    */
/* ======================================================================== */

typedef tFastByte tNmtEvent;
#define kNmtEvEnterInitialising      0x01
#define kNmtEvResetNode              0x02
#define kNmtEvPreResetCommunication  0x03
#define kNmtEvResetCommunication     0x04
#define kNmtEvPostResetCommunication 0x05
#define kNmtEvEnterPreOperational    0x10
#define kNmtEvEnterOperational       0x20
#define kNmtEvEnterStopped           0x30

typedef WORD tNmtCommand;
#define kNmtCommInitialize              0x0000
#define kNmtCommInitBeforePost          0x0101
#define kNmtCommStartRemoteNode         0x0001
#define kNmtCommEnterOperational        kNmtCommStartRemoteNode
#define kNmtCommStopRemoteNode          0x0002
#define kNmtCommEnterStopped            kNmtCommStopRemoteNode
#define kNmtCommEnterPreOperational     0x0080
#define kNmtCommEnterPostPreOperational 0x0180
#define kNmtCommResetNode               0x0081
#define kNmtCommResetCommunication      0x0082

typedef tFastByte tNmtErrCtrlEvent;
#define kNmtErrCtrlEvIdle                 0x00
#define kNmtErrCtrlEvLgConnected          0x10
#define kNmtErrCtrlEvLgMsgLost            0x11
#define kNmtErrCtrlEvLgLostConnection     0x12
#define kNmtErrCtrlEvBootupReceived       0x20
#define kNmtErrCtrlEvLgNodeStateChanged   0x31
#define kNmtErrCtrlEvLgToggleError        0x32
#define kNmtErrCtrlEvLgSuspended          0x33
#define kNmtErrCtrlEvLgNoAnswer           0x34
#define kNmtErrCtrlEvHbcConnected         0x40
#define kNmtErrCtrlEvHbcConnectionLost    0x41
#define kNmtErrCtrlEvHbcNodeStateChanged  0x42
#define kNmtErrCtrlEvUnknown              0xFF

/* ======================================================================== */
/* 4. CCM                                                                    */
/* ======================================================================== */

#define CCM_MODULE_LSSS      0x00000001L
#define CCM_MODULE_LSSM      0x00000002L
#define CCM_MODULE_NMTS      0x00000004L
#define CCM_MODULE_NMTM      0x00000008L
#define CCM_MODULE_HBC       0x00000010L
#define CCM_MODULE_HBP       0x00000020L
#define CCM_MODULE_EMCC      0x00000040L
#define CCM_MODULE_SDOC      0x00000080L
#define CCM_MODULE_PDO       0x00000100L
#define CCM_MODULE_SRDO      0x00000400L
#define CCM_MODULE_DR303_3   0x00000800L
#define CCM_MODULE_COPMGR    0x00001000L
#define CCM_MODULE_SDOM      0x00002000L
#define CCM_MODULE_SRD       0x00004000L
#define CCM_MODULE_CFGMA     0x00008000L
#define CCM_MODULE_CFGMASYS  0x00010000L
#define CCM_MODULE_FLYMA     0x00020000L
#define CCM_MODULE_SDOGWY    0x00040000L

#define INFINITE_TIME         -1
#define CANID_INVALID         0x80000000L
#define CANID_SYNC_PRODUCER   0x40000000L
#define CAN_FRAME_FORMAT_MASK 0x20000000L     /* bit 29: 29-bit identifier */

/* Second argument of CcmInitCANopen (ignored: single instance). */
typedef tFastByte tCcmInitCall;
#define kCcmAdditionalInstance      0x00
#define kCcmFirstInstance           0x01
#define kCcmAddCcmInstFirstCdrvInst 0x02
#define kCcmAddCcmInstAddCdrvInst   0x03

typedef tCopKernel (PUBLIC ROM* tCcmNmtEventCallback) (CCM_DECL_INSTANCE_HDL_ tNmtEvent NmtEvent_p);
typedef tCopKernel (PUBLIC ROM* tObdInitRam) (void MEM* pInitParam_p);
typedef tCopKernel (PUBLIC ROM* tCcmErrorCallback) (CCM_DECL_INSTANCE_HDL_ void MEM* pArg_p, tCopKernel ErrorCode_p);
typedef tCopKernel (PUBLIC ROM* tAppNmtmEventCallback) (CCM_DECL_INSTANCE_HDL_ BYTE bNodeId_p, tNmtErrCtrlEvent NmtmEvent_p);
typedef tCopKernel (PUBLIC ROM* tAppHbcEventCallback) (CCM_DECL_INSTANCE_HDL_ BYTE bNodeId_p, tNmtErrCtrlEvent HbcEvent_p);

/* Storage driver contract (this library's own: the SYS TEC headers declare
 * none). The application's non-volatile memory (EEPROM, flash, a file) for
 * 0x1010 / 0x1011, registered with CcmSetStoreDriver before CcmInitStore.
 * Every function gets m_pArg first and returns kCopSuccessful or an error
 * (any other value: the stack reports kCopCcmStoreHwError, the previous
 * image stays in force). Offsets count from the start of the memory given
 * to the stack (0 .. m_dwSize - 1); the stack uses two halves of it (A/B).
 *   m_fpOpen   optional (NULL): called by CcmInitStore before any access.
 *   m_fpRead   reads dwSize_p bytes at dwOffset_p, any offset and length.
 *   m_fpWrite  writes erased memory; dwOffset_p and dwSize_p are multiples
 *              of m_dwAlign (a power of two, 1 .. 64).
 *   m_fpErase  erases dwSize_p bytes at dwOffset_p (one half at a time;
 *              offsets multiples of 64). A flash driver maps its sectors.
 *   m_fpCommit makes every write so far durable (page buffer, fsync).
 * m_dwConfigKey is written into every image and required of it when it is
 * loaded: OD_BUILDER_KEY, or any signature of the configuration. The
 * structure must stay valid and unchanged while the instance lives (a
 * static). Sizes: 36 bytes on ARM (ILP32), 64 on x86-64. */
typedef struct
{
    void MEM*  m_pArg;
    DWORD      m_dwSize;
    DWORD      m_dwAlign;
    DWORD      m_dwConfigKey;
    tCopKernel (PUBLIC ROM* m_fpOpen)   (void MEM* pArg_p);
    tCopKernel (PUBLIC ROM* m_fpRead)   (void MEM* pArg_p, DWORD dwOffset_p, BYTE MEM* pbData_p, DWORD dwSize_p);
    tCopKernel (PUBLIC ROM* m_fpWrite)  (void MEM* pArg_p, DWORD dwOffset_p, CONST BYTE MEM* pbData_p, DWORD dwSize_p);
    tCopKernel (PUBLIC ROM* m_fpErase)  (void MEM* pArg_p, DWORD dwOffset_p, DWORD dwSize_p);
    tCopKernel (PUBLIC ROM* m_fpCommit) (void MEM* pArg_p);
} tCopStoreDriver;

/* Parameters of CcmInitCANopen. Sizes: 40 bytes on ARM (ILP32), 72 on
 * x86-64. m_BaudIndex is one byte. */
typedef struct
{
    BYTE                 m_bInitNodeId;
    tCdrvBaudIndex       m_BaudIndex;
    CONST void ROM*      m_pBdiTable;
    WORD                 m_wSizeOfBdiTab;
    DWORD                m_dwAmr;
    DWORD                m_dwAcr;
    tCdrvHwParam         m_HwParam;
    tCdrvEnableInt       m_fpCanInterruptEnable;
    tCcmNmtEventCallback m_fpNmtEventCallback;
    tObdInitRam          m_fpObdInitRam;
} tCcmInitParam;

/* Variable table of CcmDefineVarTab. */
typedef struct
{
    BYTE          m_bValidFlag;     /* kVarValid* */
    WORD          m_wIndex;
    BYTE          m_bSubindex;
    tObdSize      m_Size;
    void MEM*     m_pData;
    tVarCallback  m_fpCallback;
    void GENERIC* m_pArg;
} tVarParam;

#define kVarValidSize     0x01
#define kVarValidData     0x02
#define kVarValidCallback 0x04
#define kVarValidArg      0x08
#define kVarValidAll      0x0F

typedef struct
{
    WORD m_wEmcyErrorCode;
    BYTE m_bErrorRegister;
    BYTE m_abManufactErrorCode[5];
    WORD m_wAdditionalInfo;
} tEmcParam;

typedef tCopKernel (PUBLIC ROM* tAppEmccEventCallback) (CCM_DECL_INSTANCE_HDL_ BYTE bNodeId_p, tEmcParam MEM* pEmcParam_p);

typedef struct
{
    WORD wHeartbeatTime_p;
    BYTE bProducerNodeId_p;
    BYTE bSubindex_p;
} tHbcProdParam;

typedef struct
{
    WORD m_wLifeguardTime;      /* ms */
    BYTE m_bLifeguardFactor;
} tNmtmSlaveParam;

/* NMT master view of one slave (nmtm.h): tNmtmSlaveState bits in
 * m_bSlaveState. 0x20 is unused. */
typedef BYTE tNmtmSlaveState;
#define kNmtmStateReset     0x00    /* entry unused */
#define kNmtmStateUsed      0x01    /* entry used (slave in the slave table) */
#define kNmtmBootupReceived 0x02    /* boot-up message received */
#define kNmtmStateLgActive  0x04    /* life guarding active */
#define kNmtmLgReceived     0x08    /* a guarding answer has been received */
#define kNmtmStateNgActive  0x10    /* node guarding active */
#define kNmtmUpdate         0x40    /* a new guarding answer since the last read */
#define kNmtmStateToggleBit 0x80    /* toggle bit of the last guarding answer */

/* CcmNmtmGetSlaveInfo: three bytes, layout of nmtm.h. */
typedef struct
{
    BYTE m_bSlaveState;         /* tNmtmSlaveState bits */
    BYTE m_bLostMsgCount;       /* guarding answers missed in a row */
    BYTE m_bSlaveNodeState;     /* NMT state the slave reported (kNodeState*) */
} tNmtmSlaveInfo;

/* LSS (CiA 305; lsss.h, lss.h). m_bInitNodeId = LSS_INVALID_NODEID starts a
 * node without node-ID where CCM_MODULE_INTEGRATION has CCM_MODULE_LSSS:
 * CcmProcessLssInitState then runs until an LSS master has given it one. */
#define LSS_INVALID_NODEID 0xFF

typedef BYTE tLssMode;
#define kLssModeOperation     0x00  /* LSS waiting state */
#define kLssModeConfiguration 0x01
#define kLssModeSelective     0x02

/* The LSS address: object 0x1018 sub 1..4. */
typedef struct
{
    DWORD m_dwVendorId;
    DWORD m_dwProductCode;
    DWORD m_dwRevisionNr;
    DWORD m_dwSerialNr;
} tLssAddress;

/* Events of the LSS slave module (its callback parameter below). */
typedef tFastByte tLssEvent;
#define kLsssEvEnterConfiguration  0x00
#define kLsssEvConfigureNodeId     0x01
#define kLsssEvConfigureBitTiming  0x02
#define kLsssEvActivateBitTiming   0x03
#define kLsssEvSaveConfiguration   0x04
#define kLsssEvDeactivateBusContact 0x05
#define kLsssEvActivateBusContact  0x06
#define kLsssEvEnterOperation      0x10
#define kLsssEvPreResetNode        0x11

typedef struct
{
    tLssEvent m_bLssEvent;
    BYTE      m_bNodeId;
    BYTE      m_bBtrTableSelector;
    BYTE      m_bBtrIndex;
} tLssCbParam;

typedef tCopKernel (PUBLIC ROM* tLssEventCallback) (CCM_DECL_INSTANCE_HDL_ tLssCbParam MEM* pLssCbParam_p);

/* LSS command specifiers (CiA 305; lss.h tLssCommand). */
typedef BYTE tLssCommand;
#define kLssSwitchModeGlobal   4
#define kLssConfigureNodeId    17
#define kLssConfigureBitTiming 19
#define kLssActivateBitTiming  21
#define kLssStoreConfiguration 23

/* ======================================================================== */
/* 3. SRDO / GFC                                                             */
/* ======================================================================== */

typedef BYTE tSrdoIndex;

#if (SRDO_GRANULARITY == 8)
#define SRDO_MAX_MAPPENTRIES 16
#elif (SRDO_GRANULARITY == 16)
#define SRDO_MAX_MAPPENTRIES 8
#elif (SRDO_GRANULARITY == 32)
#define SRDO_MAX_MAPPENTRIES 4
#elif (SRDO_GRANULARITY == 64)
#define SRDO_MAX_MAPPENTRIES 2
#else
#error "SRDO_GRANULARITY must be 8, 16, 32 or 64"
#endif

typedef struct
{
    BYTE m_bDirection;      /* 0 invalid, 1 Tx, 2 Rx */
    WORD m_wSct;            /* refresh time / SCT in ms */
} tSrdoCommuParam;

typedef struct
{
    BYTE      m_bNoOfMappedObjects;
    void MEM* m_apMappedVariable[SRDO_MAX_MAPPENTRIES];
} tSrdoMappParam;

/* SRDO module initialisation (SrdoInit, manual 2.11.1). The table entries
 * are private to the library: tSrdoTabEntry is an incomplete type. */
typedef struct tSrdoTabEntryTag tSrdoTabEntry;

typedef struct
{
    tSrdoTabEntry MEM* m_pSrdoTable;
    tSrdoIndex         m_SrdoCount;
} tSrdoTabParam;

typedef struct
{
    tSrdoTabParam m_SrdoTabParam;
    BYTE          m_bGranularity;       /* SRDO_GRANULARITY the application expects */
    BYTE MEM*     m_pbSrdoConfigValid;  /* 0x13FE */
} tSrdoInitParam;

typedef tFastByte tProgMonEvent;
#define kSrdoPMEvSctChecked                  0x01
#define kSrdoPMEvSctNotCheckedItIsTx         0x02
#define kSrdoPMEvSctNotCheckedItIsInvalid    0x03
#define kSrdoPMEvSctNotCheckedNotOperational 0x04
#define kSrdoPMEvSrdoError                   0x05
#define kSrdoPMEvSrdoReceived                0x06
#define kSrdoPMEvSrdoTransmitted             0x07

/* ======================================================================== */
/* 7. SDO                                                                    */
/* ======================================================================== */

#define SDOAC_TOGGEL_BIT_ERROR                  0x05030000L
#define SDOAC_TIME_OUT                          0x05040000L
#define SDOAC_UNKNOWN_COMMAND_SPECIFIER         0x05040001L
#define SDOAC_INVALID_BLOCK_SIZE                0x05040002L
#define SDOAC_INVALID_SEQUENCE_NUMBER           0x05040003L
#define SDOAC_CRC_ERROR                         0x05040004L
#define SDOAC_OUT_OF_MEMORY                     0x05040005L
#define SDOAC_UNSUPPORTED_ACCESS                0x06010000L
#define SDOAC_READ_TO_WRITE_ONLY_OBJ            0x06010001L
#define SDOAC_WRITE_TO_READ_ONLY_OBJ            0x06010002L
#define SDOAC_OBJECT_NOT_EXIST                  0x06020000L
#define SDOAC_OBJECT_NOT_MAPPABLE               0x06040041L
#define SDOAC_PDO_LENGTH_EXCEEDED               0x06040042L
#define SDOAC_GEN_PARAM_INCOMPATIBILITY         0x06040043L
#define SDOAC_GEN_INTERNAL_INCOMPATIBILITY      0x06040047L
#define SDOAC_ACCESS_FAILED_DUE_HW_ERROR        0x06060000L
#define SDOAC_DATA_TYPE_LENGTH_NOT_MATCH        0x06070010L
#define SDOAC_DATA_TYPE_LENGTH_TOO_HIGH         0x06070012L
#define SDOAC_DATA_TYPE_LENGTH_TOO_LOW          0x06070013L
#define SDOAC_SUB_INDEX_NOT_EXIST               0x06090011L
#define SDOAC_VALUE_RANGE_EXCEEDED              0x06090030L
#define SDOAC_VALUE_RANGE_TOO_HIGH              0x06090031L
#define SDOAC_VALUE_RANGE_TOO_LOW               0x06090032L
#define SDOAC_MAX_VALUE_LESS_MIN_VALUE          0x06090036L
#define SDOAC_RESOURCE_NOT_AVAILABLE            0x060A0023L
#define SDOAC_GENERAL_ERROR                     0x08000000L
#define SDOAC_DATA_NOT_TRANSF_OR_STORED         0x08000020L
#define SDOAC_DATA_NOT_TRANSF_DUE_LOCAL_CONTROL 0x08000021L
#define SDOAC_DATA_NOT_TRANSF_DUE_DEVICE_STATE  0x08000022L
#define SDOAC_OBJECT_DICTIONARY_NOT_EXIST       0x08000023L

/* SDO server parameters. */
typedef struct
{
    BYTE  m_bValidFlags;
    BYTE  m_bClientNodeID;
    WORD  m_wObjIndex;
    DWORD m_dwRxCANID;
    DWORD m_dwTxCANID;
    DWORD m_dwTimeOut;
} tSdosParam;

#define kSdosParamUnvalidFlags          0x00
#define kSdosParamValidFlagRxCANID      0x01
#define kSdosParamValidFlagTxCANID      0x02
#define kSdosParamValidFlagClientNodeId 0x04
#define kSdosParamValidFlagTimeOut      0x08
#define kSdosParamValidFlagCheck        0x80
#define kSdosParamValidAll              0x0F

/* SDO client (types only; the client API is not part of this library yet). */
typedef tFastByte tSdocState;
#define kSdocTransferNotActive 0
#define kSdocTransferRunning   1
#define kSdocTransferTxAborted 2
#define kSdocTransferRxAborted 3
#define kSdocTransferFinished  4

typedef tFastByte tSdocType;
#define kSdocTypeSegDown   0
#define kSdocTypeSegUp     1
#define kSdocTypeBlockDown 2
#define kSdocTypeBlockUp   3

#define kSdocUnvalidFlags          0x00
#define kSdocValidFlagRxCanId      0x01
#define kSdocValidFlagTxCanId      0x02
#define kSdocValidFlagServerNodeId 0x04
#define kSdocValidFlagTimeOut      0x08
#define kSdocValidFlagCheck        0x80
#define kSdocValidAllParams        0x0F

typedef struct
{
    BYTE  m_bValidFlags;
    tTime m_TimeOut;
    WORD  m_wClientIndex;
    DWORD m_dwRxCanId;
    DWORD m_dwTxCanId;
    BYTE  m_bServerNodeId;
} tSdocParam;

typedef struct
{
    WORD       m_wClientIndex;
    tSdocState m_SdocState;
    DWORD      m_dwAbortCode;
} tSdocCbFinishParam;

typedef void (PUBLIC ROM* tSdocCbFinished) (CCM_DECL_INSTANCE_HDL_ tSdocCbFinishParam MEM* pParamList_p);

typedef struct
{
    WORD            m_wClientIndex;
    WORD            m_wObjIndex;
    BYTE            m_bObjSubIndex;
    void GENERIC*   m_pData;
    tObdSize        m_DataLen;
    tTime           m_TimeOut;
    tSdocType       m_SdocType;
    tSdocCbFinished m_pfnCbFinished;
} tSdocTransferParam;

/* ======================================================================== */
/* 8. PDO and dynamic OD (types only)                                        */
/* ======================================================================== */

typedef tCopKernel (PUBLIC ROM* tPdoCallback) (CCM_DECL_INSTANCE_HDL_ WORD wPdoCommuIndex_p);

#define kPdoTypeSend 0
#define kPdoTypeRecv 1

#define kPdoValidCanId          0x01
#define kPdoValidTxType         0x02
#define kPdoValidInihibitTime   0x04
#define kPdoValidEventTime      0x08
#define kPdoValidNrOfEntries    0x10
#define kPdoValidMappObjects    0x20
#define kPdoValidCallback       0x40
#define kPdoValidCommunication  0x0F
#define kPdoValidMapping        0x30
#define kPdoValidAll            0x7F

typedef struct
{
    BYTE         m_bValidFlag;
    WORD         m_wPdoCommuIndex;
    BYTE         m_bPdoType;
    BYTE         m_bNodeID;
    DWORD        m_dwCanId;
    BYTE         m_bTxTyp;
    WORD         m_wInhibitTime;
    WORD         m_wEventTime;
    BYTE         m_bNrOfEntries;
    /* 8 or 64 entries (copdef.h): part of the link-time signature, _pe<n>
     * in cop_config.h. */
    DWORD        m_adwMappParam[PDO_MAX_MAPPENTRIES];
    tPdoCallback m_fpCallback;
} tPdoParam;

typedef struct
{
    WORD         m_wPdoCommuIndex;
    DWORD        m_dwCanId;
    BYTE         m_bTxTyp;
    WORD         m_wInhibitTime;
    WORD         m_wEventTime;
    BYTE         m_bSize;
    void MEM*    m_pVarData;
    tPdoCallback m_fpCallback;
} tPdoStaticParam;

typedef struct
{
    BYTE          m_bMPdoType;      /* 0 SAM, 1 DAM */
    WORD          m_wIndex;
    BYTE          m_bSubindex;
    void GENERIC* m_pData;
    tObdType      m_ObjType;
} tMPdoParam;

typedef WORD tPdoIndex;
#define PDO_INVALID_INDEX 0x0FFFF

typedef struct
{
    BYTE FAR* m_pbProcessImage;
    DWORD     m_dwProcessImageSize;
    DWORD     m_dwDynPIOffsetIn;
    DWORD     m_dwDynPISizeIn;
    DWORD     m_dwDynPIOffsetOut;
    DWORD     m_dwDynPISizeOut;
} tProcessImageDscrpt;

/* ======================================================================== */
/* 10. COB layer (cob.h)                                                     */
/* ======================================================================== */

/* Reason for a COB callback. */
typedef tFastByte tCobEvent;
#define kCobEvtReceived 0   /* object received */
#define kCobEvtSent     1   /* object sent in answer to a remote frame */

/* COB handle: table bit (Rx / Tx) OR index. Its width follows
 * COB_MORE_THAN_128_ENTRIES as in the original; the library is built from
 * the same copcfg.h, so both sides agree. */
#if (COB_MORE_THAN_128_ENTRIES != FALSE)
typedef WORD tCobHdl;
#define kCobHdlRxTable   0x0000
#define kCobHdlTxTable   0x8000
#define kCobHdlIndexMask 0x7FFF
#define kCobHdlTableMask 0x8000
#define kCobHdlInvalid   0xFFFF
#else
typedef BYTE tCobHdl;
#define kCobHdlRxTable   0x00
#define kCobHdlTxTable   0x80
#define kCobHdlIndexMask 0x7F
#define kCobHdlTableMask 0x80
#define kCobHdlInvalid   0xFF
#endif

#if (COB_MORE_THAN_256_ENTRIES != FALSE)
#if (COB_MORE_THAN_128_ENTRIES == FALSE)
#error "COB_MORE_THAN_256_ENTRIES needs COB_MORE_THAN_128_ENTRIES"
#endif
typedef WORD tCobIdx;
#define COB_INVALID_INDEX 0xFFFF
#else
typedef BYTE tCobIdx;
#define COB_INVALID_INDEX 0xFF
#endif

#if (COB_MORE_THAN_128_ENTRIES != FALSE)
typedef WORD tCobEntryIndex;
#else
typedef BYTE tCobEntryIndex;
#endif

/* COB types (tMsgTyp values with the kMtb* flag bits). */
typedef BYTE tCobType;
#define kCobTypSend         (kMsgTypSend)
#define kCobTypRecv         (kMsgTypRecv)
#define kCobTypRmtSend      (kMsgTypSendRtrReq)
#define kCobTypRmtRecv      (kMsgTypRecvRtrReq)
#define kCobTypForceSend    (kMsgTypSend | kMtbForce)
#define kCobTypForceRmtSend (kMsgTypSendRtrReq | kMtbForce)
#define kCobTypForceRmtRecv (kMsgTypRecvRtrReq | kMtbForce)
#define kCobTypFilter       (kMtbFilter | kMtbForce)
#define kCobTypRtrInvalid   (0x10)
#define kCobReserved1       (kMtbForce)
#define kCobReserved2       (kMtbFirstMsg)
#define kCobReserved3       (kMtbHighPrio)
#define kCobReserved4       (kMtbExtend)

typedef tCopKernel (PUBLIC ROM* tCobCallback) (CCM_DECL_INSTANCE_HDL_ void MEM* pArg_p, tCobEvent Event_p);

/* Parameters of one communication object. Fields m_CobId .. m_pArg are
 * inputs, m_CobHdl selects the entry for CcmCobGetParam, which fills
 * m_CobId, m_bCobType, m_bSize, m_fpCallback (NULL), m_pArg (NULL),
 * m_pbData and m_pbRecvdSize (NULL: the library keeps no frame buffer per
 * object). */
typedef struct
{
    tCanId       m_CobId;
    BYTE         m_bCobType;
    BYTE         m_bSize;
    tCobCallback m_fpCallback;
    void MEM*    m_pArg;
    tCobHdl      m_CobHdl;
    BYTE MEM*    m_pbData;
    BYTE MEM*    m_pbRecvdSize;
} tCobParam;

/* ======================================================================== */
/* Private contract between objdef.h (ObdInitRam) and CcmInitCANopen         */
/* ======================================================================== */

/* The application's SRDO callbacks, collected by objdef.h when objdict.h
 * declares SRDO objects (applications without SRDOs need not define them).
 * AppGfcEvent / AppProgMonEvent are NULL when their switch is FALSE. */
typedef struct
{
    tCopKernel (PUBLIC ROM* m_fpSrdoEvent) (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p);
    tCopKernel (PUBLIC ROM* m_fpSrdoError) (CCM_DECL_INSTANCE_HDL_ WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p);
    tCopKernel (PUBLIC ROM* m_fpGfcEvent) (CCM_DECL_INSTANCE_HDL);
    tCopKernel (PUBLIC ROM* m_fpProgMonEvent) (CCM_DECL_INSTANCE_HDL_ tProgMonEvent Event_p);
} tSrdoAppCallbacks;

/* What ObdInitRam fills in. m_pbAbiSignature is the address of the
 * configuration signature (cop_config.h): the reference makes a program
 * built with another configuration fail to link, and CcmInitCANopen
 * compares the address as a second line of defence. */
typedef struct
{
    tObdEntryPtr                 m_pGenericPart;
    tObdEntryPtr                 m_pManufacturerPart;
    tObdEntryPtr                 m_pDevicePart;
    tObdEntryPtr                 m_pUserPart;
    CONST BYTE ROM*              m_pbAbiSignature;
    CONST tSrdoAppCallbacks ROM* m_pSrdoCallbacks;
    tCdrvBuffInit                m_RxBuffHigh;
    tCdrvBuffInit                m_TxBuffHigh;
    tCdrvBuffInit                m_RxBuffLow;
    tCdrvBuffInit                m_TxBuffLow;
    WORD                         m_wSrdoCount;
} tObdRamParam;

/* Host simulation builds (library built with the std feature) declare
 * CopSimSelectInstance with fixed-width types. */
#if defined(COP_HOST_SIMULATION)
#include <stdint.h>
#endif

#endif /* COP_TYPES_H */
