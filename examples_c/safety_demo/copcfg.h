/*
 * copcfg.h - configuration of the safety demo: two CiA 304 safety nodes
 * (an E-stop / speed-limit sensor and an actuator with a safe output).
 * Both nodes run in one process on the simulated bus, so both dictionaries
 * share this configuration; on real hardware each board has its own copy.
 * The library is built from this folder (COP_CONFIG_DIR).
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES             1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME            FALSE
#define CCM_MODULE_INTEGRATION        (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_SRDO)

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
#define SRDO_USE_PROGMONITOR          TRUE
/* A lost inverted frame is found as soon as its SRVT has passed, not only
 * when the next frame or the SCT check finds it. */
#define SRDO_CHECK_SRVT_BEFORE_1STRX  TRUE

#endif
