/*
 * obdcfg.h of the C API benchmark (bench/capi): room for 64 SRDOs, two
 * receive and two transmit PDOs, one SDO server.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

#define SDO_MAX_SERVER_IN_OBD          1
#define SDO_MAX_CLIENT_IN_OBD          0
#define PDO_MAX_RXPDO_IN_OBD           2
#define PDO_MAX_TXPDO_IN_OBD           2
#define SRDO_MAX_SRDO_IN_OBD           64
#define HBC_MAX_CONSUMER_IN_OBD        1
#define EMCP_MAX_ERROR_ENTRIES_IN_OBD  4
#define NMTM_MAX_SLAVE_ENTRIES         1

#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  8
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  8
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   8
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   8

#define OD_BUILDER_KEY                 0x12345678L

#endif
