/*
 * objdict_store.c - the test dictionary objdict_store.h as tables (objdef.h).
 */
#define OBD_OBJDICT_FILE "objdict_store.h"
#include "objdef.h"
