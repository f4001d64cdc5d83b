/*
 * safety_node.h - what the sensor and the actuator of the safety demo have
 * in common: the SRDO parameters each application owns, the status-byte
 * handshake (manual 2.5.3, 2.9.1, 2.9.2), the program-flow monitor (2.9.4),
 * the NMT callback that configures the SRDO (2.9.5) and the diagnostic
 * check of the configuration (2.8.2).
 *
 * On a real board each node is a separate firmware image and has exactly
 * one tSafetyNode. Here both boards run in one process on the simulated
 * bus, so there are two, and the callbacks the library calls by name
 * (AppSrdoEvent, ...) pick the one of the node the simulation has selected.
 */
#ifndef SAFETY_NODE_H
#define SAFETY_NODE_H

#include "cop.h"

#define SAFETY_SRDO          0x1301      /* the one SRDO of each node */
#define SAFETY_DIAG_MS       100         /* diagnostic test interval */

/* SRDO status byte (manual 2.5.3) */
#define SRDO_TRANSFER_MASK   0x30        /* bits 4-5 */
#define SRDO_TRANSFER_OK     0x00
#define SRDO_TRANSFER_FAILED 0x10
#define SRDO_PROCESSED       0x30
#define SRDO_ERROR_MASK      0xC0        /* bits 6-7 */
#define SRDO_ERROR_TOGGLE    0xC0        /* 01 -> 10: "handled by AppSrdoError" */

/* Where the node's SRDO processing is (set by the NMT callback, evaluated
 * in the main loop; manual 2.9.5). */
typedef enum
{
    kSrdoRunNotOperational,
    kSrdoRunEnterOperational,
    kSrdoRunOperational
} tSrdoRun;

typedef enum
{
    kRoleSensor,
    kRoleActuator
} tSafetyRole;

/* The SRDO parameters an application owns and writes itself. */
typedef struct
{
    BYTE  m_bDirection;         /* 1 transmit, 2 receive */
    WORD  m_wSctMs;             /* refresh time (transmit) / SCT (receive) */
    BYTE  m_bSrvtMs;
    DWORD m_dwCobId1;           /* normal data */
    DWORD m_dwCobId2;           /* inverted data */
} tSafetySrdoParam;

typedef struct
{
    /* fixed */
    const char*      m_pszName;
    tSafetyRole      m_Role;
    BYTE             m_bSimNode;            /* slot on the simulated bus */
    BYTE             m_bNodeId;
    tObdInitRam      m_fpObdInitRam;
    tSafetySrdoParam m_Srdo;

    /* run time */
    tCcmInitParam    m_InitParam;
    tSrdoRun         m_SrdoRun;
    tSrdoCommuParam  m_SrdoCommu;           /* read at kNmtEvEnterOperational */
    DWORD            m_dwOperationalSince;  /* tick of kNmtEvEnterOperational */
    DWORD            m_dwLastDiag;          /* tick of the last diagnostic check */
    WORD             m_wConfiguredCrc;      /* what went into 0x13FF */
    int              m_fConfigured;         /* 0xA5 accepted at the last reset communication */
    int              m_fSrdoSeen;           /* AppSrdoEvent/AppSrdoError since OPERATIONAL */
    int              m_fSafetyFault;        /* a fault the node itself detected, latched */

    /* program-flow monitor of the running cycle */
    WORD             m_wPMonValue;          /* sum of AppProgMonEvent weights */
    unsigned         m_uCycleSrdoEvents;    /* AppSrdoEvent calls in this cycle */
    unsigned         m_uCycleSrdoErrors;    /* AppSrdoError calls (not NotHandledInApp) */
} tSafetyNode;

/* The two nodes (main.c). */
extern tSafetyNode aSafetyNode_g[2];

/* The node the simulation has selected, i.e. the board whose code runs. */
tSafetyNode* SafetyCurrentNode (void);

/* "[  12.3 ms] actuator: " in front of every line the applications print. */
void SafetyLog (const tSafetyNode* pNode_p, const char* pszFormat_p, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

const char* SafetyKernelName (tCopKernel Ret_p);

/* Start-up of one board: tCcmInitParam, CcmInitCANopen, CcmConnectToNet. */
tCopKernel SafetyNodeStart (tSafetyNode* pNode_p);

/* One pass of the board's main loop; pfnApp_p is the role's own part (runs
 * after CcmProcess, before the checks). */
void SafetyNodeCycle (tSafetyNode* pNode_p, void (*pfnApp_p) (tSafetyNode* pNode_p));

/* Role hooks (sensor.c, actuator.c). */
void SensorCycle (tSafetyNode* pNode_p);
void ActuatorCycle (tSafetyNode* pNode_p);
void ActuatorSafeState (tSafetyNode* pNode_p, const char* pszReason_p);
void ActuatorSrdoReceived (tSafetyNode* pNode_p);
void ActuatorOperatorReset (void);
void SensorSetEStop (int fPressed_p);
int  ActuatorOutputOn (void);

#endif
