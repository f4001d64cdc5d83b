/*
 * objdict_pdobits.c - objdict_pdobits.h as tables (ObdInitRamPdoBits), the
 * producing node of test_pdo_bits.c.
 */
#define OBD_INIT_RAM_NAME ObdInitRamPdoBits
#define OBD_OBJDICT_FILE  "objdict_pdobits.h"
#include "objdef.h"
