/*
 * copcfg.h - configuration of the dynamic-OD example: NMT slave, heartbeat
 * producer, SDO server and PDOs, with the dynamic object dictionary
 * (seed manual L-1087d chapter 4). The library is built from this folder.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES           1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME          FALSE
#define CCM_MODULE_INTEGRATION      (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_PDO)

#define CDRV_CAN_SPEC               CAN20A
#define CDRV_USE_HIGHBUFF           TRUE
#define CDRV_USE_IDVALID            TRUE
#define CDRV_TIMESTAMP              FALSE

#define OBD_SUPPORTED_OBJ_SIZE      OBD_OBJ_SIZE_SMALL
#define SDOS_DEFAULT_TIMEOUT        5000        /* 0.5 s in ticks of 100 us */

/* Seed chapter 4: the dynamic OD is processed as user OD with variable
 * subindex tables. This library always has the user part and builds the
 * tables in its pool, so only OBD_USE_DYNAMIC_OD decides; the other two are
 * set as the seed asks. OBD_DYNAMIC_POOL_SIZE replaces COP_MALLOC. */
#define OBD_USE_DYNAMIC_OD          TRUE
#define OBD_USER_OD                 TRUE
#define OBD_USE_VARIABLE_SUBINDEX_TAB TRUE
#define OBD_DYNAMIC_POOL_SIZE       4096

#endif
