/*
 * peer_harness.h - the C side of the python-canopen interoperability tests.
 *
 * libcop_peer.so holds this library (built from peer/cfg), the simulated
 * CAN bus of examples_c/sim, the dictionary peer/objdict.h, the container
 * of its dynamic OD (peer/peer_dynod.dcf) and the small API below, which
 * peer/tests/copbus.py loads with ctypes. One simulated node (node 0 of the
 * bus) runs the stack; every frame it sends is handed
 * to Python with PeerTakeSent, every frame Python sends enters the bus
 * with PeerInject, so python-canopen is the only other node on the bus.
 *
 * Time is the simulation's virtual clock (ticks of 100 us): Python moves it
 * with PeerAdvanceTicks in step with the wall clock, because python-canopen
 * waits in real time.
 *
 * All functions return a tCopKernel value (0 = kCopSuccessful) unless said
 * otherwise. Like the CCM API, the harness is single-threaded: the Python
 * side serialises every call with one lock.
 */
#ifndef PEER_HARNESS_H
#define PEER_HARNESS_H

#include "cop.h"

/* ---- life cycle ------------------------------------------------------------- */

/* Resets the simulated bus and the event log, initialises the stack with
 * node-ID bNodeId_p (CcmInitCANopen), attaches the application variables of
 * the DOMAIN and USERDEF objects (CcmDefineVarTab) and registers the
 * heartbeat consumer and NMT master callbacks. The node stays in
 * INITIALISATION until PeerConnect. Shuts a running stack down first. */
DWORD PeerInit (BYTE bNodeId_p);
DWORD PeerConnect (void);                   /* CcmConnectToNet: boot-up */
DWORD PeerShutdown (void);                  /* CcmShutDownCANopen */
DWORD PeerProcess (void);                   /* CcmProcess */
DWORD PeerProcessLssInitState (void);       /* CcmProcessLssInitState */
BYTE  PeerNodeId (void);                    /* CcmLsssGetNodeId */
DWORD PeerStackVersion (void);              /* CopGetStackVersion */

/* Store / restore: fOn_p 1 registers the simulated memory of
 * examples_c/sim/store_sim.h (CcmSetStoreDriver; it keeps its contents over
 * PeerInit), 0 unregisters it and erases it. The NMT callback calls
 * CcmInitStore at EnterInitialising; PeerInitStoreResult is what it
 * returned last. */
DWORD PeerStoreUse (int fOn_p);
DWORD PeerInitStoreResult (void);

/* ---- bus and clock ---------------------------------------------------------- */

void  PeerAdvanceTicks (DWORD dwTicks_p);
DWORD PeerTicks (void);
/* Number of nodes that received the frame (0 when the node does not
 * listen to the identifier), -1 for a bad DLC. */
int   PeerInject (DWORD dwId_p, BYTE bRtr_p, BYTE bDlc_p, CONST BYTE* pbData_p);
/* 1 and the oldest frame the node sent, or 0 when there is none. */
int   PeerTakeSent (DWORD* pdwId_p, BYTE* pbRtr_p, BYTE* pbDlc_p, BYTE* pbData_p);
void  PeerTrace (int fOn_p);

/* ---- dictionary and NMT ------------------------------------------------------ */

DWORD PeerRead (WORD wIndex_p, BYTE bSub_p, void* pData_p, DWORD* pdwSize_p);
DWORD PeerWrite (WORD wIndex_p, BYTE bSub_p, CONST void* pData_p, DWORD dwSize_p);
BYTE  PeerNodeState (void);                 /* CcmObdGetNodeState */
DWORD PeerNmtExec (WORD wCommand_p);        /* CcmNmtsExecCommand */

/* The dictionary as the library sees it: entry n (0, 1, ...) of the tables
 * objdef.h generated, in part order. 1 when it exists, 0 after the last.
 * Array entries (kObdAccArray) stand for subindices sub..sub+n-1. */
int PeerOdEntry (unsigned uEntry_p, WORD* pwIndex_p, BYTE* pbSub_p, BYTE* pbType_p,
                 BYTE* pbAccess_p, BYTE* pbKind_p, DWORD* pdwSize_p);
/* The limits of a range-checked entry (native byte order, m_dwSize bytes
 * each). Returns the size, or -1 when the entry has no range. */
int PeerOdLimits (WORD wIndex_p, BYTE bSub_p, BYTE* pbLow_p, BYTE* pbHigh_p, DWORD dwCap_p);

/* ---- events the application callbacks saw ----------------------------------- */

#define PEER_EV_NMT        1    /* NMT callback: dwCode = kNmtEv* */
#define PEER_EV_HBC        2    /* CcmInitHbcEx callback: bNode, dwCode = kNmtErrCtrlEv* */
#define PEER_EV_NMTM       3    /* CcmInitNmtmEx callback: bNode, dwCode = kNmtErrCtrlEv* */
#define PEER_EV_SRDO       4    /* AppSrdoEvent: wIndex */
#define PEER_EV_SRDO_ERROR 5    /* AppSrdoError: wIndex, dwCode = tCopKernel */
#define PEER_EV_GFC        6    /* AppGfcEvent */
#define PEER_EV_SDOC       7    /* SDO client finished: wIndex = client, bNode = state, dwCode = abort */

/* Takes the oldest event: 1, or 0 when there is none. */
int PeerTakeEvent (BYTE* pbKind_p, BYTE* pbNode_p, WORD* pwIndex_p, DWORD* pdwCode_p);

/* CcmSendEmergency: error code, error register, 5 manufacturer bytes. */
DWORD PeerSendEmergency (WORD wErrorCode_p, BYTE bErrorRegister_p, CONST BYTE* pbManufacturer_p);

/* ---- heartbeat consumer and NMT master --------------------------------------- */

DWORD PeerHbcDefine (BYTE bNode_p, WORD wTimeMs_p, BYTE bSubindex_p);   /* CcmHbcDefineProducerTab */
DWORD PeerHbcNodeState (BYTE bNode_p, BYTE* pbState_p);                 /* CcmHbcGetNodeState */
DWORD PeerNmtmCommand (BYTE bNode_p, WORD wCommand_p);                  /* CcmSendNmtCommand */

/* ---- SDO client (channel 0x1280) ---------------------------------------------- */

/* CcmSdocDefineClientTab: server node-ID, COB-IDs client->server and
 * server->client, timeout in ticks (all four fields valid). */
DWORD PeerSdocDefine (BYTE bServer_p, DWORD dwTxCobId_p, DWORD dwRxCobId_p, DWORD dwTimeoutTicks_p);
/* CcmSdocStartTransfer on the harness's own buffer: a download sends
 * dwLen_p bytes of pbData_p, an upload receives at most dwLen_p bytes.
 * iType_p is the tSdocType (kSdocTypeSegDown 0, kSdocTypeSegUp 1,
 * kSdocTypeBlockDown 2, kSdocTypeBlockUp 3). */
DWORD PeerSdocStart (WORD wIndex_p, BYTE bSub_p, int iType_p, CONST BYTE* pbData_p, DWORD dwLen_p);
DWORD PeerSdocState (DWORD* pdwState_p, DWORD* pdwAbort_p);             /* CcmSdocGetState */
DWORD PeerSdocBytes (DWORD* pdwBytes_p);                                /* SdocGetTransmittedBytes */
/* Copies up to dwMax_p bytes of the transfer buffer; returns the count. */
DWORD PeerSdocData (BYTE* pbOut_p, DWORD dwMax_p);

/* ---- SRDO --------------------------------------------------------------------- */

DWORD PeerSendSrdo (WORD wIndex_p);                       /* CcmSendSrdo */
DWORD PeerCalcSrdoCrc (WORD wIndex_p, WORD* pwCrc_p);     /* CcmCalcSrdoCrc */
DWORD PeerCheckSrdoConfig (WORD* pwIndex_p);              /* CcmCheckSrdoConfig */
DWORD PeerSrdoState (WORD wIndex_p, BYTE* pbState_p);     /* CcmGetSrdoState */

/* ---- dynamic object dictionary ------------------------------------------------- */

/* DynBuildOd with the container dcf2bin made from peer/peer_dynod.dcf at
 * build time (peer/CMakeLists.txt) and the process image
 * abPeerProcessImage_g. On success padwPi_p (5 DWORDs, may be NULL)
 * receives the tProcessImageDscrpt results: image size the container
 * needs, input offset, input size, output offset, output size. The image
 * is cleared before the build. */
DWORD PeerDynBuildOd (DWORD* padwPi_p);
DWORD PeerDynDestroyOd (void);              /* DynDestroyOd */
/* Size of the built-in container in bytes. */
DWORD PeerDynContainerSize (void);

#define PEER_PROCESS_IMAGE_SIZE 64u

extern BYTE abPeerProcessImage_g[PEER_PROCESS_IMAGE_SIZE];   /* ctypes in_dll */

/* ---- application variables named by objdict.h (ctypes in_dll) ---------------------- */

#define PEER_DOMAIN_SIZE 300u

extern tObdUnsigned8  abPeerDomain_g[PEER_DOMAIN_SIZE];    /* 0x2002 */
extern tObdUnsigned32 dwPeerUser_g;                        /* 0x2003 */
extern tObdUnsigned8  bPeerRange_g;                        /* 0x2020/3 */
extern tObdUnsigned8  bPeerSafeOut_g, bPeerSafeOutInv_g;   /* 0x2030/1, 0x2031/1 */
extern tObdUnsigned16 wPeerSafeOut_g, wPeerSafeOutInv_g;   /* 0x2030/2, 0x2031/2 */
extern tObdUnsigned8  bPeerSafeIn_g, bPeerSafeInInv_g;     /* 0x2040/1, 0x2041/1 */
extern tObdUnsigned16 wPeerSafeIn_g, wPeerSafeInInv_g;     /* 0x2040/2, 0x2041/2 */

#endif /* PEER_HARNESS_H */
