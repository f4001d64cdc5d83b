/*
 * objdict_ionode.c - the I/O node's dictionary, examples_c/io_node/objdict.h
 * unchanged, as tables (ObdInitRamIoNode). The file is found through this
 * folder, which is on the include path: ../io_node/objdict.h.
 */
#define OBD_INIT_RAM_NAME ObdInitRamIoNode
#define OBD_OBJDICT_FILE  "../io_node/objdict.h"
#include "objdef.h"
