/*
 * copcfg.h - configuration of the I/O node example: an NMT slave with
 * heartbeat producer and SDO server, no PDO and no SRDO, objects up to 255
 * bytes, 11-bit identifiers. The library is built from this folder
 * (COP_CONFIG_DIR), so both sides of the binary interface agree.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES           1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME          FALSE
#define CCM_MODULE_INTEGRATION      (CCM_MODULE_NMTS | CCM_MODULE_HBP)

#define CDRV_CAN_SPEC               CAN20A
#define CDRV_USE_HIGHBUFF           TRUE
#define CDRV_USE_IDVALID            TRUE
#define CDRV_TIMESTAMP              FALSE

#define OBD_SUPPORTED_OBJ_SIZE      OBD_OBJ_SIZE_SMALL
#define SDOS_DEFAULT_TIMEOUT        5000        /* 0.5 s in ticks of 100 us */

#endif
