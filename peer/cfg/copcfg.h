/*
 * copcfg.h of the interoperability peer (peer/): a safety slave that also
 * has an SDO client, a heartbeat consumer and the NMT master, so that
 * python-canopen can meet every service from both sides. Objects up to
 * 4 GiB (tObdSize DWORD): the peer's string and domain are longer than 255
 * bytes. A dynamic object dictionary (peer/peer_dynod.dcf, DynBuildOd) with
 * the switches the dynamic OD manual (L-1087d, chapter 4) names: user OD,
 * variable subindex tables and PDO bit mapping, so that the container can
 * map a BOOLEAN as one bit into the TPDO it reconfigures.
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          1
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#define COP_USE_SMALL_TIME         FALSE
#define CCM_MODULE_INTEGRATION     (CCM_MODULE_LSSS | CCM_MODULE_NMTS | CCM_MODULE_NMTM | CCM_MODULE_HBP | \
                                    CCM_MODULE_HBC | CCM_MODULE_SDOC | CCM_MODULE_SRDO | CCM_MODULE_PDO)

#define CDRV_CAN_SPEC              CAN20A
#define CDRV_USE_HIGHBUFF          TRUE
#define CDRV_USE_IDVALID           TRUE
#define CDRV_TIMESTAMP             FALSE

#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_BIG

#define SRDO_GRANULARITY           8
#define SRDO_USE_STATIC_MAPPING    FALSE
#define SRDO_USE_GFC               TRUE
#define SRDO_USE_PROGMONITOR       TRUE

#define OBD_USE_DYNAMIC_OD         TRUE
#define OBD_USER_OD                TRUE
#define OBD_USE_VARIABLE_SUBINDEX_TAB TRUE
#define OBD_DYNAMIC_POOL_SIZE      8192

/* BOOLEANs as single bits; granularity 8 keeps 8 mapping entries per PDO. */
#define PDO_USE_BIT_MAPPING        TRUE

/* The SDO server collects a segmented download in one buffer: large
 * enough for the peer's longest object (the 300-byte domain). */
#define SDOS_BUFFER_SIZE           512

#endif
