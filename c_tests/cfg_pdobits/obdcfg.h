/*
 * obdcfg.h of the PDO bit-mapping test library (c_tests/cfg_pdobits): one
 * RPDO and one TPDO per dictionary.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

#define SDO_MAX_SERVER_IN_OBD          1
#define PDO_MAX_RXPDO_IN_OBD           1
#define PDO_MAX_TXPDO_IN_OBD           1
#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  4
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  4
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   16
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   16

/* Test callbacks (declared so that test_util.c compiles in every configuration). */
tCopKernel PUBLIC TestCbVeto (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p);
tCopKernel PUBLIC TestCbRecord (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p);

#endif
