/*
 * copinc.h - compatibility header: the SYS TEC stack declared part of its API
 * here. In this library everything lives in cop.h (types in cop_types.h)
 * and ami.h; this file only keeps existing #include lines working.
 */
#ifndef COP_COMPAT_COPINC_H
#define COP_COMPAT_COPINC_H

#include "cop.h"
#include "ami.h"

#endif
