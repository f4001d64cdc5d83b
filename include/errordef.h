/*
 * errordef.h - compatibility header: the SYS TEC stack declared basic types,
 * return codes, instance macros or the driver/target contract here. In this
 * library they are in cop_types.h (types) and cop_app.h (Cdrv* and Tgt*
 * prototypes); this file only keeps existing #include lines working.
 */
#ifndef COP_COMPAT_ERRORDEF_H
#define COP_COMPAT_ERRORDEF_H

#include "cop_types.h"
#include "cop_app.h"

#endif
