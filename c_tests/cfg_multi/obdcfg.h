/*
 * obdcfg.h of the two-instance C tests: capacities of the test dictionaries (each instance has its own) and the OBD
 * callbacks they name.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

#define SDO_MAX_SERVER_IN_OBD          2
#define SDO_MAX_CLIENT_IN_OBD          1
#define PDO_MAX_RXPDO_IN_OBD           1
#define PDO_MAX_TXPDO_IN_OBD           1
#define SRDO_MAX_SRDO_IN_OBD           2
#define HBC_MAX_CONSUMER_IN_OBD        2
#define EMCP_MAX_ERROR_ENTRIES_IN_OBD  4
#define NMTM_MAX_SLAVE_ENTRIES         4

#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  8
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  8
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   16
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   16

#define OD_BUILDER_KEY                 0x12345678L

/* OBD callbacks of the test application (c_tests/test_util.c). */
tCopKernel PUBLIC TestCbVeto (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p);
tCopKernel PUBLIC TestCbRecord (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p);

#endif
