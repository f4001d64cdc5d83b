/*
 * objdict_services.c - objdict_services.h as tables (ObdInitRamServices)
 * and the variable it maps.
 */
#define OBD_INIT_RAM_NAME ObdInitRamServices
#define OBD_OBJDICT_FILE  "objdict_services.h"
#include "objdef.h"

tObdUnsigned8 bServicesOut_g;
