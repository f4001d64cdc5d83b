/*
 * obdcfg.h of the interoperability peer: capacities of peer/objdict.h.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

#define SDO_MAX_SERVER_IN_OBD          1
#define SDO_MAX_CLIENT_IN_OBD          1
#define SRDO_MAX_SRDO_IN_OBD           1
#define HBC_MAX_CONSUMER_IN_OBD        2
#define NMTM_MAX_SLAVE_ENTRIES         4

#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  16
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  16
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   32
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   32

#endif
