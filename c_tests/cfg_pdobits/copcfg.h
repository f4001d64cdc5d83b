/*
 * copcfg.h of the PDO bit-mapping test library: the switches of c_tests/cfg
 * with PDO_USE_BIT_MAPPING TRUE and PDO_GRANULARITY 64, the configuration
 * the dynamic OD manual (L-1087d, chapter 4) asks for to map BOOLEANs
 * anywhere in a PDO. PDO_MAX_MAPPENTRIES becomes 64 (copdef.h), so
 * tPdoParam and the mapping objects 0x1600/0x1A00 have 64 entries and the
 * link-time signature ends in _pe64; every other binary-interface switch
 * equals c_tests/cfg.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME         FALSE
#define CCM_MODULE_INTEGRATION     (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_PDO)

#define CDRV_CAN_SPEC              CAN20A
#define CDRV_TIMESTAMP             FALSE

#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_SMALL

#define PDO_USE_BIT_MAPPING        TRUE
#define PDO_GRANULARITY            64

#endif
