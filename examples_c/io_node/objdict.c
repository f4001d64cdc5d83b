/*
 * objdict.c - the I/O node's dictionary (objdict.h) as tables; defines
 * ObdInitRam.
 */
#include "objdef.h"
