/*
 * obdcfg.h of the compile-only static-mapping test: the capacities of
 * c_tests/cfg.
 */
#include "../cfg/obdcfg.h"
