/*
 * objdict_min.c - the minimal test dictionary as tables. A second
 * dictionary in the same program: its init function is ObdInitRamMin and all
 * its data is static, so it coexists with objdict_all.c.
 */
#define OBD_INIT_RAM_NAME ObdInitRamMin
#define OBD_OBJDICT_FILE  "objdict_min.h"
#include "objdef.h"
