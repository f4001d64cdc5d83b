/* obdcfg.h of the dcf2bin test node: the library's default capacities. */
#ifndef OBDCFG_H
#define OBDCFG_H
#endif
