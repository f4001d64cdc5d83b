/*
 * objdict.c - the slave's static dictionary (objdict.h) through objdef.h.
 */
#include "objdef.h"
