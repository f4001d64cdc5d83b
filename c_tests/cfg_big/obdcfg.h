/*
 * obdcfg.h of the second test library.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

#define SDO_MAX_SERVER_IN_OBD          1
#define SRDO_MAX_SRDO_IN_OBD           2
#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH  4
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH  4
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW   8
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW   8

/* Test callbacks (declared so that test_util.c compiles in both configurations). */
tCopKernel PUBLIC TestCbVeto (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p);
tCopKernel PUBLIC TestCbRecord (CCM_DECL_INSTANCE_HDL_ tObdCbParam MEM* pParam_p);

#endif
