/*
 * obdcfg.h - capacities of the two dictionaries (objdict_sensor.h,
 * objdict_actuator.h); their init functions are named in objdict_*.c.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

#define SDO_MAX_SERVER_IN_OBD          1
#define SDO_MAX_CLIENT_IN_OBD          0
#define PDO_MAX_RXPDO_IN_OBD           0
#define PDO_MAX_TXPDO_IN_OBD           0
#define HBC_MAX_CONSUMER_IN_OBD        0
#define EMCP_MAX_ERROR_ENTRIES_IN_OBD  4
#define NMTM_MAX_SLAVE_ENTRIES         0
#define SRDO_MAX_SRDO_IN_OBD           1

#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  8
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  8
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   10
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   10

#endif
