/*
 * configurator.h - the three applications of the configurator example and
 * what main.c needs of them.
 */
#ifndef CONFIGURATOR_H
#define CONFIGURATOR_H

#include "cop.h"

/* Slots of the simulated bus and node-IDs. */
#define SIM_CONFIGURATOR 0
#define SIM_IO_NODE      1
#define SIM_SAFETY_NODE  2
#define ID_CONFIGURATOR  1
#define ID_IO_NODE       2      /* the node of seed 004 */
#define ID_SAFETY_NODE   3

/* One SRDO's safety parameters as a configuration tool holds them. */
typedef struct
{
    BYTE  m_bDirection;
    WORD  m_wSctMs;             /* refresh time (transmit) / SCT (receive) */
    BYTE  m_bSrvtMs;
    DWORD m_dwCobId1;
    DWORD m_dwCobId2;
    BYTE  m_bMappCount;
    DWORD m_adwMapp[4];
} tSrdoConfig;

/* srdo_crc.c: the 0x13FF checksum of SAFETY_BEHAVIOUR.md section 3,
 * computed by the tool itself. */
WORD CfgSrdoCrc (const tSrdoConfig* pConfig_p);

/* configurator.c */
tCopKernel PUBLIC ObdInitRamConfigurator (void MEM* pInitParam_p);
tCopKernel PUBLIC ConfiguratorNmtEvent (tNmtEvent NmtEvent_p);
void       ConfiguratorStart (void);        /* after CcmConnectToNet */
int        ConfiguratorStep (void);         /* once per ms; 0 when the script is done */
int        ConfiguratorResult (void);       /* 0: everything as expected */
void       ConfiguratorSrdoEvent (WORD wSrdoCommuIndex_p);
void       ConfiguratorSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p);

/* ionode.c */
tCopKernel PUBLIC ObdInitRamIoNode (void MEM* pInitParam_p);
tCopKernel PUBLIC IoNodeNmtEvent (tNmtEvent NmtEvent_p);
void       IoNodeCycle (void);

/* safety_node.c */
tCopKernel PUBLIC ObdInitRamSafetyNode (void MEM* pInitParam_p);
tCopKernel PUBLIC SafetyNodeNmtEvent (tNmtEvent NmtEvent_p);
void       SafetyNodeCycle (void);
void       SafetyNodeOpenDoor (void);       /* the scripted input */
void       SafetyNodeSrdoEvent (WORD wSrdoCommuIndex_p);
void       SafetyNodeSrdoError (WORD wSrdoCommuIndex_p, tCopKernel ErrorCode_p);

/* main.c: "[ 12.0 ms] who: ..." */
void Log (const char* pszWho_p, const char* pszFormat_p, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif
