/*
 * cop_config.h - the link-time configuration signature.
 *
 * Some switches of copcfg.h change the binary interface between the
 * application and the library: the width of tObdSize, the size of
 * tSrdoMappParam, the layout of tCdrvMsg, the size of tPdoParam, the width
 * of tCobHdl in tCobParam. The library is built from the same
 * copcfg.h (COP_CONFIG_DIR) and exports exactly one byte whose name encodes
 * those switches:
 *
 *   CopLibAbi_os<1|2|4>_gr<8|16|32|64>_sm<0|1>_pm<0|1>_ts<0|1>_id<11|29>_pe<8|64>_ch<8|16>[_in<2..8>]
 *
 *   os  sizeof(tObdSize)            (OBD_SUPPORTED_OBJ_SIZE)
 *   gr  SRDO_GRANULARITY            (SRDO_MAX_MAPPENTRIES = 128 / gr)
 *   sm  SRDO_USE_STATIC_MAPPING
 *   pm  PDO_USE_STATIC_MAPPING
 *   ts  CDRV_TIMESTAMP              (tCdrvMsg.m_Time)
 *   id  CDRV_CAN_SPEC               (tCanId WORD or DWORD)
 *   pe  PDO_MAX_MAPPENTRIES         (tPdoParam.m_adwMappParam; 64 with
 *                                   PDO_USE_BIT_MAPPING and PDO_GRANULARITY 64)
 *   ch  COB_MORE_THAN_128_ENTRIES   (tCobHdl BYTE or WORD, CcmCobGetParam)
 *   in  COP_MAX_INSTANCES           (only when more than 1: every Ccm*
 *                                   function and callback takes the
 *                                   instance handle)
 *
 * This header builds the same name from the application's configuration.
 * objdef.h stores its address in tObdRamParam.m_pbAbiSignature, so an
 * application compiled with a configuration the library was not built with
 * fails to link ("undefined reference to CopLibAbi_..."), instead of
 * misreading structures at run time. CcmInitCANopen also compares the
 * address (kCopWrongSignature).
 */
#ifndef COP_CONFIG_H
#define COP_CONFIG_H

#include "cop_types.h"

/* Normalise each switch to the token used in the name. */
#if (OBD_SUPPORTED_OBJ_SIZE == OBD_OBJ_SIZE_BIG)
#define COP_ABI_OS_ os4
#elif (OBD_SUPPORTED_OBJ_SIZE == OBD_OBJ_SIZE_MIDDLE)
#define COP_ABI_OS_ os2
#else
#define COP_ABI_OS_ os1
#endif

#if (SRDO_GRANULARITY == 64)
#define COP_ABI_GR_ gr64
#elif (SRDO_GRANULARITY == 32)
#define COP_ABI_GR_ gr32
#elif (SRDO_GRANULARITY == 16)
#define COP_ABI_GR_ gr16
#else
#define COP_ABI_GR_ gr8
#endif

#if (SRDO_USE_STATIC_MAPPING != FALSE)
#define COP_ABI_SM_ sm1
#else
#define COP_ABI_SM_ sm0
#endif

#if (PDO_USE_STATIC_MAPPING != FALSE)
#define COP_ABI_PM_ pm1
#else
#define COP_ABI_PM_ pm0
#endif

#if (CDRV_TIMESTAMP != FALSE)
#define COP_ABI_TS_ ts1
#else
#define COP_ABI_TS_ ts0
#endif

#if (CDRV_CAN_SPEC == CAN20B)
#define COP_ABI_ID_ id29
#else
#define COP_ABI_ID_ id11
#endif

#if (PDO_MAX_MAPPENTRIES == 64)
#define COP_ABI_PE_ pe64
#else
#define COP_ABI_PE_ pe8
#endif

#if (COB_MORE_THAN_128_ENTRIES != FALSE)
#define COP_ABI_CH_ ch16
#else
#define COP_ABI_CH_ ch8
#endif

/* The instance count is part of the name only where it is more than one
 * (a single-instance build keeps the name it always had). */
#if (COP_MAX_INSTANCES == 1)
#define COP_ABI_CHIN_ COP_ABI_CH_
#elif (COP_MAX_INSTANCES == 2)
#define COP_ABI_CHIN_ COP_ABI_PASTE_IN_(COP_ABI_CH_, _in2)
#elif (COP_MAX_INSTANCES == 3)
#define COP_ABI_CHIN_ COP_ABI_PASTE_IN_(COP_ABI_CH_, _in3)
#elif (COP_MAX_INSTANCES == 4)
#define COP_ABI_CHIN_ COP_ABI_PASTE_IN_(COP_ABI_CH_, _in4)
#elif (COP_MAX_INSTANCES == 5)
#define COP_ABI_CHIN_ COP_ABI_PASTE_IN_(COP_ABI_CH_, _in5)
#elif (COP_MAX_INSTANCES == 6)
#define COP_ABI_CHIN_ COP_ABI_PASTE_IN_(COP_ABI_CH_, _in6)
#elif (COP_MAX_INSTANCES == 7)
#define COP_ABI_CHIN_ COP_ABI_PASTE_IN_(COP_ABI_CH_, _in7)
#elif (COP_MAX_INSTANCES == 8)
#define COP_ABI_CHIN_ COP_ABI_PASTE_IN_(COP_ABI_CH_, _in8)
#else
#error "COP_MAX_INSTANCES must be 1..8"
#endif
#define COP_ABI_PASTE_IN2_(ch, in) ch##in
#define COP_ABI_PASTE_IN_(ch, in) COP_ABI_PASTE_IN2_(ch, in)

/* Two levels so that the arguments are expanded before pasting. */
#define COP_ABI_NAME_PASTE_(os, gr, sm, pm, ts, id, pe, ch) \
    CopLibAbi_##os##_##gr##_##sm##_##pm##_##ts##_##id##_##pe##_##ch
#define COP_ABI_NAME_(os, gr, sm, pm, ts, id, pe, ch) COP_ABI_NAME_PASTE_(os, gr, sm, pm, ts, id, pe, ch)

/* The signature symbol of this configuration (defined by the library). */
#define COP_ABI_SIGNATURE \
    COP_ABI_NAME_(COP_ABI_OS_, COP_ABI_GR_, COP_ABI_SM_, COP_ABI_PM_, COP_ABI_TS_, COP_ABI_ID_, COP_ABI_PE_, \
                  COP_ABI_CHIN_)

#ifdef __cplusplus
extern "C" {
#endif

extern CONST BYTE COP_ABI_SIGNATURE;

#ifdef __cplusplus
}
#endif

#endif /* COP_CONFIG_H */
