/*
 * copcfg.h of the interoperability peer (peer/): a safety slave that also
 * has an SDO client, a heartbeat consumer and the NMT master, so that
 * python-canopen can meet every service from both sides. Objects up to
 * 4 GiB (tObdSize DWORD): the peer's string and domain are longer than 255
 * bytes.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME         FALSE
#define CCM_MODULE_INTEGRATION     (CCM_MODULE_NMTS | CCM_MODULE_NMTM | CCM_MODULE_HBP | CCM_MODULE_HBC | \
                                    CCM_MODULE_SDOC | CCM_MODULE_SRDO)

#define CDRV_CAN_SPEC              CAN20A
#define CDRV_USE_HIGHBUFF          TRUE
#define CDRV_USE_IDVALID           TRUE
#define CDRV_TIMESTAMP             FALSE

#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_BIG

#define SRDO_GRANULARITY           8
#define SRDO_USE_STATIC_MAPPING    FALSE
#define SRDO_USE_GFC               TRUE
#define SRDO_USE_PROGMONITOR       TRUE

/* The SDO server collects a segmented download in one buffer: large
 * enough for the peer's longest object (the 300-byte domain). */
#define SDOS_BUFFER_SIZE           512

#endif
