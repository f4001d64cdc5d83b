/*
 * copcfg.h of the C master test (test_master_app.c): an NMT master with SDO
 * client, heartbeat and EMCY consumers, 32-bit object sizes and the COB
 * switches that make tCobHdl a WORD. Its obdcfg.h lives in another folder
 * (c_tests/cfg_master_od, COP_OBDCFG_DIR), as ODBuilder projects keep it
 * beside objdict.h.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME         FALSE

#define CCM_MODULE_INTEGRATION     (CCM_MODULE_NMTS | CCM_MODULE_NMTM | CCM_MODULE_HBP | CCM_MODULE_HBC | \
                                    CCM_MODULE_EMCC | CCM_MODULE_PDO | CCM_MODULE_SDOC)
#define CCM_USE_STORE_RESTORE      FALSE

#define CDRV_CAN_SPEC              CAN20A
#define CDRV_USE_HIGHBUFF          TRUE
#define CDRV_USE_IDVALID           TRUE
#define CDRV_TIMESTAMP             FALSE

#define COB_MORE_THAN_128_ENTRIES  TRUE
#define COB_MORE_THAN_256_ENTRIES  TRUE

#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_BIG
#define SDOC_USE_ADDITIONAL_API    TRUE

#define SRDO_GRANULARITY           8
#define SRDO_USE_STATIC_MAPPING    FALSE
#define SRDO_USE_GFC               TRUE
#define SRDO_USE_PROGMONITOR       TRUE

#endif
