/*
 * actuator_ch_a.c - the actuator dictionary of channel A (ObdInitRamActuatorA).
 */
#define OBD_INIT_RAM_NAME ObdInitRamActuatorA
#define OBD_OBJDICT_FILE  "objdict_channel_actuator.h"
#include "objdef.h"
