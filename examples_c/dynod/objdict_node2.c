/*
 * objdict_node2.c - the example dictionary for node 2 (see
 * objdict_node1.c).
 */
#define OBD_INIT_RAM_NAME ObdInitRamNode2
#include "objdef.h"
