/*
 * nmtm.h - compatibility header: the SYS TEC stack declared its NMT master
 * module here. In this library tNmtmSlaveInfo, tNmtmSlaveState and the
 * kNmtm* bits are in cop_types.h and the CCM functions (CcmNmtmGetSlaveInfo,
 * CcmConfigLgm, ...) in cop.h; the module-level Nmtm* functions do not
 * exist. This file only keeps existing #include lines working.
 */
#ifndef COP_COMPAT_NMTM_H
#define COP_COMPAT_NMTM_H

#include "cop.h"

#endif
