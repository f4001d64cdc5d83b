/*
 * objdict_actuator.c - the actuator's dictionary as tables
 * (ObdInitRamActuator).
 */
#define OBD_INIT_RAM_NAME ObdInitRamActuator
#define OBD_OBJDICT_FILE  "objdict_actuator.h"
#include "objdef.h"
