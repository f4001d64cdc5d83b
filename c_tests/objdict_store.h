// objdict_store.h - objdict_all.h with the store / restore objects 0x1010 /
// 0x1011 (CiA 301 7.5.2.13 / 7.5.2.14), for test_store.c.

#define OBJDICT_ALL_WITH_STORE
#include "objdict_all.h"
