/*
 * copcfg.h - configuration of the two-channel safety example: one program
 * with four stack instances on two CAN controllers per board, the SIL 3
 * structure of the safety manual (section 1.6, figure 3: two channels, two
 * CAN controllers). Each channel is one instance; the sensor board and the
 * actuator board each have two. The library is built from this folder
 * (COP_CONFIG_DIR); with COP_MAX_INSTANCES > 1 every Ccm* function and every
 * App* callback takes the instance handle.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES             4
#define CDRV_MAX_INSTANCES            COP_MAX_INSTANCES
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME            FALSE
#define CCM_MODULE_INTEGRATION        (CCM_MODULE_NMTS | CCM_MODULE_SRDO)

/* manual 2.2: the SRDO module needs these driver settings */
#define CDRV_CAN_SPEC                 CAN20A
#define CDRV_USE_HIGHBUFF             TRUE
#define CDRV_USE_BASIC_CAN            TRUE
#define CDRV_USE_IDVALID              TRUE
#define CDRV_TIMESTAMP                FALSE

#define OBD_SUPPORTED_OBJ_SIZE        OBD_OBJ_SIZE_SMALL

/* manual 2.4 */
#define SRDO_GRANULARITY              8
#define SRDO_USE_STATIC_MAPPING       FALSE
#define SRDO_USE_GFC                  TRUE
#define SRDO_USE_PROGMONITOR          FALSE
#define SRDO_CHECK_SRVT_BEFORE_1STRX  TRUE

#endif
