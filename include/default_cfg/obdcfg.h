/*
 * obdcfg.h - defaults-only dictionary capacities.
 *
 * Sets nothing: every capacity (SDO_MAX_SERVER_IN_OBD, SRDO_MAX_SRDO_IN_OBD,
 * CDRV_MAX_*_BUFF_ENTRIES_*, OBD_INIT_RAM_NAME, ...) takes its copdef.h
 * default. An application's own obdcfg.h also declares the OBD callbacks its
 * objdict.h names.
 */
#ifndef OBDCFG_H
#define OBDCFG_H

#endif
