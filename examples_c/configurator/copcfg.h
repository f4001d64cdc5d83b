/*
 * copcfg.h - configuration of the configurator example. Three nodes run in
 * one process on the simulated bus and share this configuration (on real
 * hardware each has its own):
 *   node 1  the configurator: NMT master, SDO client, safety consumer
 *   node 2  the I/O node of examples_c/io_node (its objdict.h unchanged)
 *   node 3  a safety node whose SRDO is configured over SDO
 * The library is built from this folder (COP_CONFIG_DIR).
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES             1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME            FALSE
#define CCM_MODULE_INTEGRATION        (CCM_MODULE_NMTS | CCM_MODULE_NMTM | CCM_MODULE_HBP | \
                                       CCM_MODULE_SDOC | CCM_MODULE_SRDO)

#define CDRV_CAN_SPEC                 CAN20A
#define CDRV_USE_HIGHBUFF             TRUE
#define CDRV_USE_BASIC_CAN            TRUE
#define CDRV_USE_IDVALID              TRUE
#define CDRV_TIMESTAMP                FALSE

#define OBD_SUPPORTED_OBJ_SIZE        OBD_OBJ_SIZE_SMALL
#define SDOS_DEFAULT_TIMEOUT          5000      /* 0.5 s in ticks of 100 us */

#define SRDO_GRANULARITY              8
#define SRDO_USE_STATIC_MAPPING       FALSE
#define SRDO_USE_GFC                  TRUE
#define SRDO_USE_PROGMONITOR          FALSE

#endif
