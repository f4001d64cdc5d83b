/*
 * manual_app.h - what the test driver sees of manual_app.c, the
 * application code of the SYS TEC safety manual (section 2.9).
 */
#ifndef MANUAL_APP_H
#define MANUAL_APP_H

#include "cop.h"

/* A variable field of an SRDO (manual 2.6): up to 8 contiguous bytes. */
typedef struct
{
    BYTE m_abSrdoData[8];
} tSrdoVarField;

extern tSrdoVarField SrdoNormalData;
extern tSrdoVarField SrdoInversData;

/* The application's weights for the program-flow monitor (2.9.4). */
enum
{
    kPMonSctChecked                  = 0x0001,
    kPMonSctNotCheckedItIsTx         = 0x0002,
    kPMonSctNotCheckedItIsInvalid    = 0x0004,
    kPMonSctNotCheckedNotOperational = 0x0008,
    kPMonSrdoError                   = 0x0010,
    kPMonSrdoReceived                = 0x0020,
    kPMonSrdoTransmitted             = 0x0040
};
extern WORD wPMonValue_g;

/* The NMT state as the NMT callback stores it for the main loop (2.9.5). */
enum
{
    kNotOperational   = 0,
    kEnterOperational = 1
};
extern BYTE bSrdoState;
extern tSrdoCommuParam SrdoCommuParam;

/* How often the manual's "safety-critical error" branches ran, how often
 * outputs were switched on (AppSrdoEvent) and off (AppSrdoError,
 * AppGfcEvent). */
extern unsigned uSafetyCritical_g;
extern unsigned uOutputsOn_g;
extern unsigned uOutputsOff_g;
extern tCopKernel LastSrdoError_g;

tCopKernel PUBLIC AppCbNmtEvent (tNmtEvent NmtEvent_p);

#endif
