/*
 * obdcfg.h of c_tests/cfg_nogfc: the capacities of c_tests/cfg.
 */
#include "../cfg/obdcfg.h"
