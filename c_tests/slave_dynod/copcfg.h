/*
 * copcfg.h - a slave with the dynamic object dictionary whose process data
 * pass only through the process image (no CcmSignalCheckVar, no
 * CcmSendPdo): CCM_USE_PDO_CHECK_VAR and OBD_DYNAMIC_POOL_SIZE keep their
 * defaults (TRUE, 8192).
 */
#ifndef COPCFG_H
#define COPCFG_H
#define COP_MAX_INSTANCES           1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME          FALSE
#define CCM_MODULE_INTEGRATION      (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_HBC | CCM_MODULE_PDO)
#define CDRV_CAN_SPEC               CAN20A
#define CDRV_USE_HIGHBUFF           TRUE
#define CDRV_USE_IDVALID            TRUE
#define CDRV_TIMESTAMP              FALSE
#define OBD_SUPPORTED_OBJ_SIZE      OBD_OBJ_SIZE_SMALL
#define SDOS_DEFAULT_TIMEOUT        5000
#define OBD_USE_DYNAMIC_OD          TRUE
#define OBD_USER_OD                 TRUE
#define OBD_USE_VARIABLE_SUBINDEX_TAB TRUE
#define PDO_USE_BIT_MAPPING         FALSE
#endif
