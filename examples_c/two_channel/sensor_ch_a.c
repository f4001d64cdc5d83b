/*
 * sensor_ch_a.c - the sensor dictionary of channel A (ObdInitRamSensorA).
 */
#define OBD_INIT_RAM_NAME ObdInitRamSensorA
#define OBD_OBJDICT_FILE  "objdict_channel_sensor.h"
#include "objdef.h"
