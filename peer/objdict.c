/*
 * objdict.c - the peer's dictionary (objdict.h) as tables (objdef.h).
 */
#include "objdef.h"
