/*
 * abi_ilp32.c - compile-only check of the structure layouts on the product
 * target (TMS570: Cortex-R4F, big-endian, ILP32, AAPCS natural alignment),
 * built with arm-none-eabi-gcc when it is installed. The values follow the
 * repr(C) rules with 4-byte pointers and match the 32-bit assertions of
 * src/ffi (tCcmInitParam 40 bytes, tSrdoMappParam 4 + 4 * entries).
 * Also checks that DWORD keeps the original C type unsigned long there, so
 * existing `DWORD*` code compiles without warnings.
 */
#include <stddef.h>

#define OBD_OBJDICT_FILE "objdict_all.h"
#include "objdef.h"

_Static_assert(sizeof(void*) == 4, "ILP32 target");
_Static_assert(__builtin_types_compatible_p(DWORD, unsigned long), "DWORD is unsigned long on ILP32");
_Static_assert(sizeof(tFastByte) == 4 && sizeof(tTime) == 4, "tFastByte, tTime");
/* tCdrvMsg: WORD id 0, type 2, DLC 3, channel 4, data 5..12 = 14 */
_Static_assert(sizeof(tCdrvMsg) == 14 && offsetof(tCdrvMsg, m_bData) == 5, "tCdrvMsg");
/* tCcmInitParam: 0, 1, table 4, size 8, AMR 12, ACR 16, hardware 20 (8),
 * interrupt 28, NMT callback 32, ObdInitRam 36 = 40 */
_Static_assert(offsetof(tCcmInitParam, m_pBdiTable) == 4, "tCcmInitParam.m_pBdiTable");
_Static_assert(offsetof(tCcmInitParam, m_HwParam) == 20, "tCcmInitParam.m_HwParam");
_Static_assert(offsetof(tCcmInitParam, m_fpObdInitRam) == 36 && sizeof(tCcmInitParam) == 40, "tCcmInitParam");
_Static_assert(offsetof(tCopStoreDriver, m_fpOpen) == 16 && sizeof(tCopStoreDriver) == 36, "tCopStoreDriver");
/* tCdrvInitParam: hardware 20, buffers 28/36/44/52 (8 each), interrupt 60 = 64 */
_Static_assert(offsetof(tCdrvInitParam, m_RxBuffHigh) == 28 && sizeof(tCdrvInitParam) == 64, "tCdrvInitParam");
/* tObdSubEntry: 0..3, size 4, default 8, current 12 = 16; tObdEntry 0, 4, 8, 12 = 16 */
_Static_assert(offsetof(tObdSubEntry, m_pCurrent) == 12 && sizeof(tObdSubEntry) == 16, "tObdSubEntry");
_Static_assert(offsetof(tObdEntry, m_fpCallback) == 12 && sizeof(tObdEntry) == 16, "tObdEntry");
/* tObdVarEntry: 0, 4, 8, 12 = 16; tObdCbParam: 0, 2, 4, 8, 12 = 16 */
_Static_assert(sizeof(tObdVarEntry) == 16 && sizeof(tObdCbParam) == 16, "tObdVarEntry, tObdCbParam");
/* tVarParam (tObdSize BYTE): 0, 2, 4, size 5, data 8, callback 12, arg 16 = 20 */
_Static_assert(offsetof(tVarParam, m_pData) == 8 && sizeof(tVarParam) == 20, "tVarParam");
/* tObdRamParam: six pointers 0..20, buffers 24/32/40/48, count 56 = 60 */
_Static_assert(offsetof(tObdRamParam, m_RxBuffHigh) == 24, "tObdRamParam.m_RxBuffHigh");
_Static_assert(offsetof(tObdRamParam, m_wSrdoCount) == 56 && sizeof(tObdRamParam) == 60, "tObdRamParam");
_Static_assert(sizeof(tSrdoMappParam) == 4 + 4 * SRDO_MAX_MAPPENTRIES, "tSrdoMappParam");
_Static_assert(sizeof(tEmcParam) == 10 && sizeof(tSrdoCommuParam) == 4, "tEmcParam, tSrdoCommuParam");
/* tCobParam (vendored SYS TEC cob.h, ARM, CAN 2.0A, BYTE handle): m_CobId 0,
 * m_bCobType 2, m_bSize 3, m_fpCallback 4, m_pArg 8, m_CobHdl 12, m_pbData 16,
 * m_pbRecvdSize 20, sizeof 24 (the same with a WORD handle). */
_Static_assert(offsetof(tCobParam, m_bCobType) == 2 && offsetof(tCobParam, m_bSize) == 3 &&
               offsetof(tCobParam, m_fpCallback) == 4 && offsetof(tCobParam, m_pArg) == 8 &&
               offsetof(tCobParam, m_CobHdl) == 12 && offsetof(tCobParam, m_pbData) == 16 &&
               offsetof(tCobParam, m_pbRecvdSize) == 20 && sizeof(tCobParam) == 24, "tCobParam");
/* tNmtmSlaveInfo (nmtm.h): three BYTEs, alignment 1. */
_Static_assert(sizeof(tNmtmSlaveInfo) == 3 && offsetof(tNmtmSlaveInfo, m_bSlaveNodeState) == 2, "tNmtmSlaveInfo");
