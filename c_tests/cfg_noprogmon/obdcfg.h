/*
 * obdcfg.h of c_tests/cfg_noprogmon: the capacities of c_tests/cfg.
 */
#include "../cfg/obdcfg.h"
