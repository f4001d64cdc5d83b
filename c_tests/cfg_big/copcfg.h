/*
 * copcfg.h of the second test library: the switches that change the
 * binary interface differ from c_tests/cfg - tObdSize is a DWORD, SRDO
 * granularity 16 (8 mapping entries), tCdrvMsg carries a receive timestamp.
 * (The PDO mapping entry count, the last part of the signature, changes in
 * c_tests/cfg_pdobits.)
 */
#ifndef COPCFG_H
#define COPCFG_H

#define COP_MAX_INSTANCES          1
#define CCM_MODULE_INTEGRATION     (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_SRDO)

#define CDRV_TIMESTAMP             TRUE
#define OBD_SUPPORTED_OBJ_SIZE     OBD_OBJ_SIZE_BIG
#define SRDO_GRANULARITY           16

#endif
