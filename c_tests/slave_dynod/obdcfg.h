/*
 * obdcfg.h - capacities of the slave, as ODBuilder writes them for a node
 * whose PDOs all come from its container: 0 RPDOs and 0 TPDOs in the
 * static dictionary (the PDOs DynBuildOd creates take their state from its
 * pool).
 */
#ifndef OBDCFG_H
#define OBDCFG_H
#define PDO_MAX_RXPDO_IN_OBD           0
#define PDO_MAX_TXPDO_IN_OBD           0
#define SDO_MAX_SERVER_IN_OBD          1
#define SDO_MAX_CLIENT_IN_OBD          0
#define HBC_MAX_CONSUMER_IN_OBD        1
#define EMCP_MAX_ERROR_ENTRIES_IN_OBD  4
#define NMTM_MAX_SLAVE_ENTRIES         4
#define EMCC_MAX_CONSUMER              10
#define SRDO_MAX_SRDO_IN_OBD           0
#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  10
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  10
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   10
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   10
#endif
