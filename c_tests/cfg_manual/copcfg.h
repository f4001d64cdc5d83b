/*
 * copcfg.h of the manual-code test (test_manual_app.c) and the static
 * mapping tests: SRDO with static mapping (module SRDOSTC,
 * CcmStaticDefineSrdoVarFields), GFC and program monitor on - the setting
 * the application code of manual 2.9 is written for.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME         FALSE
#define CCM_MODULE_INTEGRATION     (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_SRDO)

#define CDRV_CAN_SPEC              CAN20A
#define CDRV_USE_HIGHBUFF          TRUE
#define CDRV_USE_IDVALID           TRUE
#define CDRV_TIMESTAMP             FALSE

#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_SMALL

#define SRDO_GRANULARITY           8
#define SRDO_USE_STATIC_MAPPING    TRUE
#define SRDO_USE_GFC               TRUE
#define SRDO_USE_PROGMONITOR       TRUE

#endif
