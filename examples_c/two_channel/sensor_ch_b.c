/*
 * sensor_ch_b.c - the sensor dictionary of channel B (ObdInitRamSensorB).
 */
#define OBD_INIT_RAM_NAME ObdInitRamSensorB
#define OBD_OBJDICT_FILE  "objdict_channel_sensor.h"
#include "objdef.h"
