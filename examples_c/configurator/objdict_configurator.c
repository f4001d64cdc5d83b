/*
 * objdict_configurator.c - the configurator's dictionary as tables
 * (ObdInitRamConfigurator).
 */
#define OBD_INIT_RAM_NAME ObdInitRamConfigurator
#define OBD_OBJDICT_FILE  "objdict_configurator.h"
#include "objdef.h"
