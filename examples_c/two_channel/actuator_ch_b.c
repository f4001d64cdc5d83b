/*
 * actuator_ch_b.c - the actuator dictionary of channel B (ObdInitRamActuatorB).
 */
#define OBD_INIT_RAM_NAME ObdInitRamActuatorB
#define OBD_OBJDICT_FILE  "objdict_channel_actuator.h"
#include "objdef.h"
