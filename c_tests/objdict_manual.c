/*
 * objdict_manual.c - objdict_manual.h as tables (ObdInitRam), built with
 * c_tests/cfg_manual.
 */
#define OBD_OBJDICT_FILE "objdict_manual.h"
#include "objdef.h"
