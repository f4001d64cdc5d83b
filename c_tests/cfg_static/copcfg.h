/*
 * copcfg.h of a compile-only test: static SRDO and PDO mapping (constant
 * mapping objects, CcmStaticDefineSrdoVarFields), CAN 2.0B identifiers,
 * objects up to 64 KiB.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          1
#define CCM_MODULE_INTEGRATION     (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_PDO | CCM_MODULE_SRDO)
#define CDRV_CAN_SPEC              CAN20B
#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_MIDDLE
#define SRDO_GRANULARITY           8
#define SRDO_USE_STATIC_MAPPING    TRUE
#define PDO_USE_STATIC_MAPPING     TRUE
#define SRDO_USE_GFC               FALSE
#define SRDO_USE_PROGMONITOR       FALSE

#endif
