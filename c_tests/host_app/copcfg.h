/*
 * copcfg.h - configuration of the host application of the README section
 * "Your own application on the host": two safety nodes in one program on
 * the simulated bus. The library is built from this folder
 * (COP_CONFIG_DIR).
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES             1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME            FALSE
#define CCM_MODULE_INTEGRATION        (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_SRDO)

#define CDRV_CAN_SPEC                 CAN20A
#define CDRV_USE_HIGHBUFF             TRUE
#define CDRV_USE_BASIC_CAN            TRUE
#define CDRV_USE_IDVALID              TRUE
#define CDRV_TIMESTAMP                FALSE

#define OBD_SUPPORTED_OBJ_SIZE        OBD_OBJ_SIZE_SMALL

#define SRDO_GRANULARITY              8
#define SRDO_USE_STATIC_MAPPING       FALSE
#define SRDO_USE_GFC                  TRUE
#define SRDO_USE_PROGMONITOR          FALSE

#endif
