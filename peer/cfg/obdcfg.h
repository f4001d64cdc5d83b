/*
 * obdcfg.h of the interoperability peer: capacities of peer/objdict.h.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

/* the default SDO server and one more (0x1201) */
#define SDO_MAX_SERVER_IN_OBD          2
#define SDO_MAX_CLIENT_IN_OBD          1
#define SRDO_MAX_SRDO_IN_OBD           1
#define HBC_MAX_CONSUMER_IN_OBD        2
#define NMTM_MAX_SLAVE_ENTRIES         4
/* TPDO 1 (0x1800/0x1A00), which the dynamic OD reconfigures; no RPDO. */
#define PDO_MAX_RXPDO_IN_OBD           0
#define PDO_MAX_TXPDO_IN_OBD           1

#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  16
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  16
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   32
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   32

#endif
