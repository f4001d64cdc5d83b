/*
 * target.h - compatibility header: the SYS TEC stack declared basic types,
 * return codes, instance macros or the driver/target contract here. In this
 * library they are in cop_types.h (types) and cop_app.h (Cdrv* and Tgt*
 * prototypes); this file only keeps existing #include lines working.
 *
 * The storage driver for 0x1010 / 0x1011 (store / restore) is the
 * structure tCopStoreDriver of cop_types.h, registered at run time with
 * CcmSetStoreDriver: an application without one links and starts as
 * before (CcmInitStore returns kCopCcmStoreHwError, nothing is stored).
 */
#ifndef COP_COMPAT_TARGET_H
#define COP_COMPAT_TARGET_H

#include "cop_types.h"
#include "cop_app.h"

#endif
