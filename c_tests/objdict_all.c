/*
 * objdict_all.c - the test dictionary objdict_all.h as tables (objdef.h).
 * Its init function has the default name ObdInitRam.
 */
#define OBD_OBJDICT_FILE "objdict_all.h"
#include "objdef.h"
