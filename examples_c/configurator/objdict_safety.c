/*
 * objdict_safety.c - the safety node's dictionary as tables
 * (ObdInitRamSafetyNode).
 */
#define OBD_INIT_RAM_NAME ObdInitRamSafetyNode
#define OBD_OBJDICT_FILE  "objdict_safety.h"
#include "objdef.h"
