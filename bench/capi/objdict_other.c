/*
 * objdict_other.c - bench/capi/objdict.h once more as tables of their own
 * (ObdInitRamOther): the dictionary of instance 0 in a two-instance build
 * (each instance needs its own tables).
 */
#define OBD_INIT_RAM_NAME ObdInitRamOther
#define OBD_OBJDICT_FILE  "objdict.h"
#include "objdef.h"
