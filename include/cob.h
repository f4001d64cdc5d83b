/*
 * cob.h - compatibility header: the SYS TEC stack declared its COB layer
 * here. In this library the COB types (tCobParam, tCobHdl, kCobTyp*, ...)
 * are in cop_types.h and CcmCobGetParam in cop.h; the module-level Cob*
 * functions do not exist (the library keeps no COB tables). This file only
 * keeps existing #include lines working.
 */
#ifndef COP_COMPAT_COB_H
#define COP_COMPAT_COB_H

#include "cop.h"

#endif
