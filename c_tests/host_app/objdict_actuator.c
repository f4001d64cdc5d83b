/* objdict_actuator.c - objdict_actuator.h as tables (ObdInitRamActuator). */
#define OBD_INIT_RAM_NAME ObdInitRamActuator
#define OBD_OBJDICT_FILE  "objdict_actuator.h"
#include "objdef.h"
