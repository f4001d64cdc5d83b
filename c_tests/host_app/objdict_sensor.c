/* objdict_sensor.c - objdict_sensor.h as tables (ObdInitRamSensor). */
#define OBD_INIT_RAM_NAME ObdInitRamSensor
#define OBD_OBJDICT_FILE  "objdict_sensor.h"
#include "objdef.h"
