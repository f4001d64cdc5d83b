/*
 * copcfg.h of the C API benchmark (bench/capi) with two instances:
 * cfg_nopm/copcfg.h (program monitor off) with COP_MAX_INSTANCES 2; the
 * received pair is measured on instance 1.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          2
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME         FALSE
#define CCM_MODULE_INTEGRATION     (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_PDO | CCM_MODULE_SRDO)

#define CDRV_CAN_SPEC              CAN20A
#define CDRV_USE_HIGHBUFF          TRUE
#define CDRV_USE_IDVALID           TRUE
#define CDRV_TIMESTAMP             FALSE

#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_SMALL

#define SRDO_GRANULARITY           8
#define SRDO_USE_STATIC_MAPPING    FALSE
#define SRDO_USE_GFC               TRUE
#define SRDO_USE_PROGMONITOR       FALSE

#endif
