/*
 * objdict_static.c - objdict_static.h as tables (ObdInitRamStatic) and the
 * variable fields it maps.
 */
#define OBD_INIT_RAM_NAME ObdInitRamStatic
#define OBD_OBJDICT_FILE  "objdict_static.h"
#include "objdef.h"

tObdUnsigned8  abStaticNormal_g[2];
tObdUnsigned8  abStaticInverted_g[2];
tObdUnsigned64 aqwWideNormal_g[2];
tObdUnsigned64 aqwWideInverted_g[2];
