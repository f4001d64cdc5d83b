/*
 * ccmmain.h - compatibility header: the SYS TEC stack declared further CCM
 * functions and the stack's own OBD callbacks here. In this library the
 * functions are in cop.h and the callbacks in cop_app.h; this file only keeps
 * existing #include lines working.
 */
#ifndef COP_COMPAT_CCMMAIN_H
#define COP_COMPAT_CCMMAIN_H

#include "cop.h"

#endif
