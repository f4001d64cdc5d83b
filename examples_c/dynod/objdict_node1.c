/*
 * objdict_node1.c - the example dictionary for node 1. Both nodes run in
 * one program on the simulated bus, so each gets its own copy of the tables
 * and variables (all generated data is static) and its own init function.
 */
#define OBD_INIT_RAM_NAME ObdInitRamNode1
#include "objdef.h"
