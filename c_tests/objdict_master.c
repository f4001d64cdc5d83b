/*
 * objdict_master.c - objdict_master.h as tables (ObdInitRamMaster) and the
 * variables it maps.
 */
#define OBD_INIT_RAM_NAME ObdInitRamMaster
#define OBD_OBJDICT_FILE  "objdict_master.h"
#include "objdef.h"

tObdUnsigned8 bMasterIn_g;
tObdUnsigned8 bMasterOut_g;
