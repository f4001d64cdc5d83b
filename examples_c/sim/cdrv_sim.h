/*
 * cdrv_sim.h - a simulated CAN bus for running CANopen nodes on a PC.
 *
 * cdrv_sim.c implements the CAN driver contract of the SYS TEC stack
 * (every Cdrv* function of cop_app.h) and the target functions (Tgt*) on a
 * bus that exists only in memory, so that an unchanged application, its
 * objdict.h and this library run on a host, one process, no hardware:
 *
 *  - up to SIM_MAX_NODES nodes. Each node is one instance of the library.
 *    In a single-instance build (host builds keep several, see
 *    CopSimSelectInstance) SimSelectNode(n) makes node n current: the Ccm*
 *    calls that follow address its stack and the Cdrv* calls the stack
 *    makes act on its controller. In a multi-instance build
 *    (COP_MAX_INSTANCES > 1) the Ccm* calls name their instance by handle;
 *    SimSelectNode(n) names the controller the next CcmInitCANopen gives
 *    its instance (CdrvInit / CdrvAddInstance return node n's address as
 *    the driver's instance pointer), and every later Cdrv* call acts on the
 *    controller of its instance pointer;
 *  - per node a high- and a low-priority receive queue with the capacities
 *    the dictionary gave CdrvInit (CDRV_MAX_RX_BUFF_ENTRIES_HIGH/LOW, at
 *    most SIM_QUEUE_MAX). A node receives only the identifiers it defined
 *    with CdrvDefineCanId - exactly like a controller with an acceptance
 *    filter, which shows that the stack subscribes everything it needs -
 *    into the queue that definition asked for (kMtbHighPrio);
 *  - a frame a node sends is on the bus at once: every other node with a
 *    matching filter receives it (a controller does not receive its own
 *    frames), in the order the frames were sent - or, with the physical
 *    model of a bus (SimSetBitRate), after its transmit buffer, the
 *    arbitration and its bit time;
 *  - receive timestamps (tCdrvMsg.m_Time, current tick) when the
 *    configuration has CDRV_TIMESTAMP;
 *  - receive overrun: a frame for a full queue is lost and the node's status
 *    gets kCdrvRxBuffHighOverrun / kCdrvRxBuffLowOverrun (CdrvGetStatus;
 *    CdrvResetStatus clears bits);
 *  - a virtual clock: TgtGetTickCount counts ticks of 100 us and only moves
 *    with SimAdvanceTicks / SimAdvanceMs, so runs are repeatable;
 *  - an external node for test harnesses and PC tools: SimInject puts a
 *    frame on the bus from outside, SimTakeSent hands out the frames the
 *    nodes sent, oldest first;
 *  - a trace in candump format ("  can0  702   [1]  00"), printed to stdout
 *    while enabled (SimSetTrace);
 *  - captures (host builds): a pcap file of SocketCAN frames (link type
 *    227, for Wireshark / tshark) and a "candump -l" log (for canplayer) of
 *    every frame that reaches the bus, timestamped with the virtual clock
 *    (SimCapture, or the environment variables COP_SIM_PCAP and
 *    COP_SIM_CANDUMP, read at the first SimReset);
 *  - fault hooks: refuse the next N transmissions of a node
 *    (CdrvWriteMsg returns kCopCdrvTxBuffHighOverrun / ...LowOverrun), drop
 *    the next frame with a given identifier (it never reaches the bus).
 *
 * Identifiers: 11-bit values, or 29-bit values with CAN_FRAME_FORMAT_MASK
 * (bit 29) set in the dwId arguments of this API.
 *
 * Typical use (one node, node-ID 2, in a test or on a PC):
 *
 *     SimReset();
 *     SimSetTrace(1);
 *     SimSelectNode(0);
 *     CcmInitCANopen(&InitParam, kCcmFirstInstance);
 *     CcmConnectToNet();
 *     SimInject(0x000, 0, 2, abStartAll);           // NMT start all
 *     CcmProcess();
 *     while (SimTakeSent(&dwId, &bRtr, &bDlc, abData)) { ... }
 *     SimAdvanceMs(10);
 *
 * The simulation is single-threaded, like the CCM API.
 */
#ifndef CDRV_SIM_H
#define CDRV_SIM_H

#include "cop.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SIM_MAX_NODES     8     /* nodes (library instances) on the bus */
#define SIM_QUEUE_MAX     64    /* largest receive queue per priority */
#define SIM_LOG_MAX       1024  /* frames kept for SimTakeSent */
#define SIM_EXTERNAL_NODE 0xFF  /* sender of frames put on the bus by SimInject */
#define SIM_MAX_BUSES     4     /* buses with a physical model and counters */

/* A frame as the bus saw it. */
typedef struct
{
    DWORD m_dwId;           /* identifier, CAN_FRAME_FORMAT_MASK set for 29 bit */
    BYTE  m_bRtr;           /* 1 = remote request */
    BYTE  m_bDlc;           /* 0..8 */
    BYTE  m_abData[8];
    BYTE  m_bSender;        /* node index, or SIM_EXTERNAL_NODE */
    BYTE  m_bBus;           /* the bus it was on (SimSetBus), 0 by default */
    DWORD m_dwTick;         /* TgtGetTickCount() when it was on the bus (a
                               physical bus: at its end of frame) */
    WORD  m_wSubTickUs;     /* a physical bus: microseconds of the end of
                               frame after m_dwTick (0..99); else 0 */
} tSimFrame;

/* Counters of one bus since SimReset (SimGetBusStats). */
typedef struct
{
    unsigned long long m_ullFrames;     /* frames carried */
    unsigned long long m_ullBits;       /* their bits, stuff bits and intermission included */
    unsigned long long m_ullBusyNs;     /* the time the bus carried them (physical bus) */
    unsigned long long m_ullElapsedNs;  /* the time since SimReset */
    unsigned long long m_ullTxRefused;  /* CdrvWriteMsg refused by a full transmit buffer (physical bus) */
    unsigned long long m_ullRxLostHigh; /* frames lost in full high receive buffers, all nodes */
    unsigned long long m_ullRxLostLow;  /* frames lost in full low receive buffers, all nodes */
} tSimBusStats;

/* Forgets everything: nodes, queues, filters, log, faults; clock to 0;
 * node 0 selected. Call before CcmInitCANopen of a new scenario. */
void SimReset (void);

/* Selects the node the next Ccm* and Cdrv* calls address (also selects the
 * library instance with CopSimSelectInstance). kCopSuccessful, or
 * kCopIllegalInstance for bNode_p >= SIM_MAX_NODES. */
tCopKernel SimSelectNode (BYTE bNode_p);
BYTE       SimSelectedNode (void);

/* The virtual clock. */
void  SimAdvanceTicks (DWORD dwTicks_p);
void  SimAdvanceMs (DWORD dwMs_p);

/* Candump-style trace of every frame on the bus to stdout (0 = off). */
void SimSetTrace (int fOn_p);

/* Puts a frame on the bus from outside (an external node): every node with
 * a matching filter receives it. Returns the number of nodes that queued
 * it, or -1 for an invalid DLC. */
int SimInject (DWORD dwId_p, BYTE bRtr_p, BYTE bDlc_p, CONST BYTE* pbData_p);

/* Takes the oldest frame a node sent (bus order). 1 when a frame was
 * returned, 0 when none is waiting. pbData_p receives 8 bytes; any pointer
 * may be NULL. */
int SimTakeSent (DWORD* pdwId_p, BYTE* pbRtr_p, BYTE* pbDlc_p, BYTE* pbData_p);
int SimTakeSentFrame (tSimFrame* pFrame_p);
/* Number of frames waiting for SimTakeSent. */
unsigned SimSentPending (void);

/* The candump line of a frame ("  can0  702   [1]  00", no newline) into
 * pszLine_p (at least 64 bytes). Returns its length, -1 for bad arguments. */
int SimFormatCandump (CONST tSimFrame* pFrame_p, char* pszLine_p, unsigned uSize_p);

/* Captures (host builds, capture_sim.c): writes every frame that reaches the
 * bus into a pcap file (SocketCAN, link type 227) and/or a candump -l log;
 * NULL or "" leaves a format out, both closes the capture. The files are
 * created (truncated). Timestamps: tick 0 of the first scenario is Unix
 * time 1700000000 s, one tick 100 us, only forward (SimReset continues).
 * 0, or -1 when a file cannot be created. Without SIM_CAPTURE (the TMS570
 * target programs) it does not exist. */
int SimCapture (const char* pszPcap_p, const char* pszCandump_p);

/* Fault hooks. */
void SimRefuseTx (BYTE bNode_p, unsigned uCount_p);   /* next uCount_p CdrvWriteMsg of the node fail */
void SimDropNextId (DWORD dwId_p);                     /* next frame with this identifier is lost */
void SimRaiseStatus (BYTE bNode_p, WORD wBits_p);      /* sets tCdrvStatus bits (kCdrvBusOff, ...); CdrvResetStatus clears */
void SimSilence (BYTE bNode_p, int fSilent_p);         /* the node's controller sends nothing (a silent channel) */
void SimCorruptNextId (DWORD dwId_p, BYTE bXor_p);     /* next frame with this identifier has data byte 0 XORed */

/* Several buses (CAN lines): a node is on bus 0 unless SimSetBus puts it on
 * another (before its CdrvInit); frames reach only the nodes of their bus,
 * and the trace names it (can0, can1, ...). SimInject sends on the bus
 * SimSetInjectBus chose (0 after SimReset). */
void SimSetBus (BYTE bNode_p, BYTE bBus_p);
void SimSetInjectBus (BYTE bBus_p);

/* The physical model of bus bBus_p (< SIM_MAX_BUSES), off after SimReset
 * (the ideal bus above). With a bit rate of 10000 .. 1000000 bit/s:
 *  - a frame takes its length in bits at that rate: SOF to the end of the
 *    end of frame field with the stuff bits (ISO 11898-1:2015 10.4.2, 10.5,
 *    SimFrameBits), then 3 bits of intermission before the next SOF;
 *  - CdrvWriteMsg queues the frame in the node's high (kMtbHighPrio) or low
 *    transmit buffer, of the capacity CdrvInit was given (m_TxBuffHigh /
 *    m_TxBuffLow, at least 1, at most SIM_QUEUE_MAX); a full buffer
 *    refuses it (kCopCdrvTxBuffHighOverrun / ...LowOverrun). Each node
 *    offers the oldest frame of its high buffer, else of its low buffer;
 *  - when the bus is idle the lowest identifier among the offered frames
 *    wins arbitration (base before extended format with the same base
 *    identifier, data before remote), the lower node number on a tie,
 *    frames of SimInject (queued unbounded up to SIM_QUEUE_MAX) last;
 *  - the frame reaches the receive buffers at the end of its end of frame
 *    field while SimAdvanceTicks / SimAdvanceMs move the clock: its
 *    timestamp (m_dwTick, tCdrvMsg.m_Time with CDRV_TIMESTAMP) is the tick
 *    of that moment, m_wSubTickUs the microseconds after it (captures);
 *  - SimInject returns 0 for a queued frame (it arrives later).
 * Set it before the nodes send; 0 makes the bus ideal again and forgets
 * the frames waiting. In host builds the environment variable
 * COP_SIM_BIT_RATE (bit/s), read at every SimReset, sets it for every bus,
 * so an unchanged program runs on the physical model. kCopSuccessful, or kCopInvalidParam for another bit
 * rate or bus. */
tCopKernel SimSetBitRate (BYTE bBus_p, DWORD dwBitRate_p);

/* Bits of a frame on the bus from SOF to the end of the end of frame
 * field, stuff bits included, without the intermission. */
unsigned SimFrameBits (CONST tSimFrame* pFrame_p);

/* The counters of bus bBus_p (zeros for a bus >= SIM_MAX_BUSES). */
void SimGetBusStats (BYTE bBus_p, tSimBusStats* pStats_p);

/* Inspection (tests). */
int      SimIsIdDefined (BYTE bNode_p, DWORD dwId_p); /* 0 undefined, 1 low, 2 high priority */
unsigned SimRxPending (BYTE bNode_p);                  /* frames waiting in both receive queues */
WORD     SimGetStatus (BYTE bNode_p);                  /* the node's tCdrvStatus bits */
unsigned SimRxCapacity (BYTE bNode_p, int fHigh_p);    /* queue capacity from CdrvInit */
unsigned SimTxPending (BYTE bNode_p);                  /* frames in both transmit buffers (physical bus) */

#ifdef __cplusplus
}
#endif

#endif /* CDRV_SIM_H */
