/*
 * test_util.h - checks and helpers shared by the C tests.
 *
 * Every test is a small program: it runs its checks, prints each failing one
 * with file and line, and returns 0 when all passed (TEST_DONE). A check that
 * cannot run because the library lacks a feature returns TEST_SKIP (77,
 * reported by CTest as "Skipped" with the reason printed).
 */
#ifndef TEST_UTIL_H
#define TEST_UTIL_H

#include <stdio.h>
#include <string.h>

#include "cdrv_sim.h"

#include "test_check.h"

/* NMT callback that records every event (and prints it when verbose). */
#define TEST_MAX_EVENTS 64
extern tNmtEvent aTestNmtEvents_g[TEST_MAX_EVENTS];
extern unsigned  uTestNmtEventCount_g;
tCopKernel PUBLIC TestNmtRecorder (tNmtEvent NmtEvent_p);
void        TestNmtClear (void);
const char* TestNmtEventName (tNmtEvent NmtEvent_p);

/* CcmInitCANopen for simulated node bSimNode_p (0..7) with node-ID
 * bNodeId_p, the dictionary's init function and an NMT callback. */
tCopKernel TestInitNode (BYTE bSimNode_p, BYTE bNodeId_p, tObdInitRam fpObdInitRam_p, tCcmNmtEventCallback fpNmt_p);

/* Pops the next frame the nodes sent and compares it (dlc bytes of data).
 * Prints the difference and counts a failure when it does not match. */
int  TestExpectFrame (const char* pszWhat_p, DWORD dwId_p, BYTE bDlc_p, const BYTE* pbData_p);
/* Drops every frame waiting for SimTakeSent; returns how many. */
unsigned TestDrainSent (void);
/* Runs CcmProcess of the selected node n times. */
void TestProcess (unsigned n_p);

/* OBD callback logs (TestCbVeto refuses writes of 0x0BAD; TestCbRecord
 * records every event). */
#define TEST_MAX_OBD_EVENTS 64
extern BYTE     abTestObdEvents_g[TEST_MAX_OBD_EVENTS];
extern unsigned uTestObdEventCount_g;
extern tObdSize TestInitWriteSize_g;
void TestObdClear (void);

/* SRDO callback counters (objdict_all.h declares SRDO objects). */
extern unsigned uTestSrdoEvents_g;
extern unsigned uTestSrdoErrors_g;
extern WORD     wTestLastSrdoIndex_g;
extern tCopKernel TestLastSrdoError_g;
#define TEST_MAX_SRDO_ERRORS 16
extern tCopKernel aTestSrdoErrors_g[TEST_MAX_SRDO_ERRORS];   /* in the order reported */
extern unsigned uTestGfcEvents_g;
extern unsigned uTestProgMonEvents_g;
/* SimSelectedNode() during the last SRDO / GFC callback (two-node tests). */
extern BYTE bTestLastSrdoNode_g;
extern BYTE bTestLastGfcNode_g;
/* Optional hooks the SRDO callbacks call after recording (NULL: none), so a
 * test can act like an application (status handshake, nested calls). */
extern void (*pfnTestSrdoEventHook_g) (WORD wSrdoCommuIndex_p);
extern void (*pfnTestSrdoErrorHook_g) (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p);
/* The handshake of manual 2.9.1 / 2.9.2 as hooks. */
void TestSrdoEventHandshake (WORD wSrdoCommuIndex_p);
void TestSrdoErrorHandshake (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p);
/* Clears the SRDO/GFC counters and hooks. */
void TestSrdoClear (void);
/* Declares the current SRDO parameters of the selected node valid: the CRC
 * of every SRDO (CcmCalcSrdoCrc) into 0x13FF, then 0xA5 into 0x13FE.
 * Returns the code of the 0x13FE write (or the first failure). */
tCopKernel TestSrdoMakeValid (void);
/* One-byte and small writes/reads through CcmWriteObject / CcmReadObject. */
tCopKernel TestWriteU8 (WORD wIndex_p, BYTE bSub_p, BYTE bValue_p);
tCopKernel TestWriteU16 (WORD wIndex_p, BYTE bSub_p, WORD wValue_p);
tCopKernel TestWriteU32 (WORD wIndex_p, BYTE bSub_p, DWORD dwValue_p);
BYTE       TestReadU8 (WORD wIndex_p, BYTE bSub_p);

/* Application variables named by objdict_all.h (EXTVAR, EXTARRAY). */
extern tObdUnsigned32 dwTestExtVar_g;
extern tObdUnsigned8  bTestExtVarRg_g;
extern tObdUnsigned16 wTestExtNoInit_g;
extern tObdUnsigned16 awTestExtArray_g[3];

/* Application arrays named by objdict_min.h (EXTARRAY inputs). */
extern tObdUnsigned8 abTestDigitalIn_g[1];
extern tObdInteger16 aiTestAnalogIn_g[2];

/* TestCbRecord refuses this event with kCopObdAccessViolation (0xFF: none). */
extern BYTE bTestCbRefuseEvent_g;

/* Dictionaries of c_tests/ (whichever the test links). */
tCopKernel PUBLIC ObdInitRam (void MEM* pInitParam_p);
tCopKernel PUBLIC ObdInitRamMin (void MEM* pInitParam_p);

#endif
