/*
 * objdict.c - bench/capi/objdict.h as tables (ObdInitRam).
 */
#define OBD_OBJDICT_FILE "objdict.h"
#include "objdef.h"
