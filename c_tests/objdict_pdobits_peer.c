/*
 * objdict_pdobits_peer.c - objdict_pdobits.h once more
 * (ObdInitRamPdoBitsPeer): the consuming node of test_pdo_bits.c has its
 * own copy of every object.
 */
#define OBD_INIT_RAM_NAME ObdInitRamPdoBitsPeer
#define OBD_OBJDICT_FILE  "objdict_pdobits.h"
#include "objdef.h"
