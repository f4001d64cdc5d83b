/*
 * store_sim.h - a simulated non-volatile memory for the store / restore
 * objects 0x1010 / 0x1011 (tCopStoreDriver, cop_types.h).
 *
 * The memory is a RAM array that keeps its contents across
 * CcmShutDownCANopen / CcmInitCANopen (a simulated restart) and, when a file
 * is named, is loaded from and written to that file (a restart of the whole
 * program). Fault hooks: a power cut after N more bytes erased or written
 * (every later call fails until SimStorePowerOn), a bit flip.
 *
 *     CcmSetStoreDriver(SimStoreDriver());   // before or after CcmInitCANopen
 *     CcmInitStore();                         // in the NMT callback, as usual
 */
#ifndef STORE_SIM_H
#define STORE_SIM_H

#include "cop.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_STORE_SIZE  2048    /* bytes of the simulated memory */
#define SIM_STORE_ALIGN 4       /* write granularity */
#define SIM_STORE_CONFIG_KEY 0x00000001UL   /* m_dwConfigKey (an application uses OD_BUILDER_KEY) */

/* The driver structure (static, valid for the whole program). */
const tCopStoreDriver* SimStoreDriver (void);

/* Erases the whole memory (every byte 0xFF), removes the faults. */
void SimStoreReset (void);

/* Memory contents are loaded from and saved to this file (NULL: RAM only). */
void SimStoreSetFile (const char* pszPath_p);

/* Power fails after dwBytes_p more bytes erased or written. */
void SimStoreCutAfterBytes (DWORD dwBytes_p);

/* Power is back: no cut pending, the memory answers again. */
void SimStorePowerOn (void);

/* Inverts one bit of the memory. */
void SimStoreFlipBit (DWORD dwOffset_p, BYTE bBit_p);

/* Bytes erased or written since SimStoreReset. */
DWORD SimStoreBytesWritten (void);

#ifdef __cplusplus
}
#endif

#endif
