/*
 * copdef.h - default values of every configuration switch.
 *
 * The application configures the stack with two headers of its own:
 *   copcfg.h  switches (protocol options, driver options, OBD options),
 *   obdcfg.h  capacities of its object dictionary (number of SDO servers,
 *             SRDOs, driver buffer entries, ...).
 * Every name below is only defined when neither of them defines it
 * (`#ifndef`), so the application's value always wins.
 *
 * Two sections:
 *   A  switches normally found in copcfg.h. Applied whenever this file is
 *      included.
 *   B  capacities normally found in obdcfg.h. cop_types.h includes this file
 *      right after copcfg.h, long before objdef.h includes obdcfg.h; giving
 *      those names a value at that point would make obdcfg.h redefine them.
 *      cop_types.h therefore defines COP_COPDEF_DEFER_OBD_CAPACITIES around
 *      its include, and objdef.h includes this file once more after
 *      obdcfg.h to apply section B. Included on its own (as the library's
 *      build script does, after copcfg.h and obdcfg.h) both sections apply.
 *
 * The library itself is built from the same files: when the environment
 * variable COP_CONFIG_DIR names the folder holding copcfg.h/obdcfg.h, the
 * build script preprocesses them together with this file and reads back the
 * values, so C and Rust see the same configuration. Settings that change the
 * binary interface are additionally encoded in a link-time signature
 * (cop_config.h): an application compiled with other values does not link.
 *
 * Where the SYS TEC header defaults and the SYS TEC manual disagree, this
 * file follows the manual (SRDO_GRANULARITY 8, SRDO_USE_STATIC_MAPPING
 * FALSE); copcfg.h decides in every case.
 */

/* ======================================================================== */
/* Section A: switches (copcfg.h)                                           */
/* ======================================================================== */
#ifndef COPDEF_H_SECTION_A
#define COPDEF_H_SECTION_A

/* ---- truth values and symbolic values used in configuration headers ---- */
#ifndef TRUE
#define TRUE  0x01
#endif
#ifndef FALSE
#define FALSE 0x00
#endif

/* CAN specification (CDRV_CAN_SPEC) */
#ifndef CAN20A
#define CAN20A 1        /* 11-bit identifiers, tCanId is a WORD */
#endif
#ifndef CAN20B
#define CAN20B 2        /* 29-bit identifiers, tCanId is a DWORD */
#endif

/* Object size classes (OBD_SUPPORTED_OBJ_SIZE) -> width of tObdSize */
#ifndef OBD_OBJ_SIZE_SMALL
#define OBD_OBJ_SIZE_SMALL  0x00    /* tObdSize = BYTE  (objects up to 255 bytes) */
#endif
#ifndef OBD_OBJ_SIZE_MIDDLE
#define OBD_OBJ_SIZE_MIDDLE 0x01    /* tObdSize = WORD  */
#endif
#ifndef OBD_OBJ_SIZE_BIG
#define OBD_OBJ_SIZE_BIG    0x02    /* tObdSize = DWORD */
#endif

/* Process time control of the protocol modules (*_PROCESS_TIME_CONTROL) */
#ifndef FUNCTION_NO_CONTROL
#define FUNCTION_NO_CONTROL        0
#endif
#ifndef FUNCTION_CALL_TIME
#define FUNCTION_CALL_TIME         1
#endif
#ifndef FUNCTION_BREAK_TIME
#define FUNCTION_BREAK_TIME        2
#endif
#ifndef FUNCTION_CALLTIME_INFINITE
#define FUNCTION_CALLTIME_INFINITE -1
#endif

/* SDO CRC modes (SDO_CALCULATE_CRC) */
#ifndef SDO_NO_CRC
#define SDO_NO_CRC      0
#endif
#ifndef SDO_CRC_TABLE
#define SDO_CRC_TABLE   1
#endif
#ifndef SDO_CRC_POLYNOM
#define SDO_CRC_POLYNOM 2
#endif

/* COB layer switches (cob.h): the width of tCobHdl / tCobIdx and the
 * search algorithm. The library keeps no COB tables of its own; the
 * handle width matters for tCobParam (CcmCobGetParam). */
#ifndef COB_MORE_THAN_128_ENTRIES
#define COB_MORE_THAN_128_ENTRIES FALSE
#endif
#ifndef COB_MORE_THAN_256_ENTRIES
#define COB_MORE_THAN_256_ENTRIES FALSE
#endif
#ifndef COB_SEARCHALGO_LIST
#define COB_SEARCHALGO_LIST 0
#endif
#ifndef COB_SEARCHALGO_INDEXARRAY
#define COB_SEARCHALGO_INDEXARRAY 1
#endif
#ifndef COB_SEARCHALGO
#define COB_SEARCHALGO COB_SEARCHALGO_LIST
#endif
/* High precision time (CDRV_USE_HPT) */
#ifndef CDRV_HPT_OFF
#define CDRV_HPT_OFF      0
#endif
#ifndef CDRV_HPT_PRODUCER
#define CDRV_HPT_PRODUCER 1
#endif
#ifndef CDRV_HPT_CONSUMER
#define CDRV_HPT_CONSUMER 2
#endif
#ifndef CDRV_HPT_TYPEMASK
#define CDRV_HPT_TYPEMASK 3
#endif
#ifndef CDRV_HPT_MEASURE
#define CDRV_HPT_MEASURE  16
#endif

/* ---- instances --------------------------------------------------------- */
/* Number of CAN driver instances. This library is a single-instance build. */
#ifndef CDRV_MAX_INSTANCES
#define CDRV_MAX_INSTANCES 1
#endif
/* Number of stack instances; must be 1 (cop_types.h rejects anything else). */
#ifndef COP_MAX_INSTANCES
#define COP_MAX_INSTANCES CDRV_MAX_INSTANCES
#endif
/* The stack calls the Cdrv* functions directly; the function pointer table
 * (m_pCdrvFct in tCcmInitParam) is not supported. */
#ifndef COP_USE_CDRV_FUNCTION_POINTER
#define COP_USE_CDRV_FUNCTION_POINTER FALSE
#endif
/* tTime is a 32-bit counter of 100 us ticks; the 16-bit variant is refused. */
#ifndef COP_USE_SMALL_TIME
#define COP_USE_SMALL_TIME FALSE
#endif
#ifndef CDRV_USE_DELETEINST_FUNC
#define CDRV_USE_DELETEINST_FUNC TRUE
#endif
#ifndef COP_USE_DELETEINST_FUNC
#define COP_USE_DELETEINST_FUNC CDRV_USE_DELETEINST_FUNC
#endif

/* ---- modules ------------------------------------------------------------ */
/* CCM_MODULE_* bits (values in cop_types.h) of the modules the application
 * uses. The default names what this library provides for a slave: NMT
 * slave, heartbeat producer and SRDO. */
#ifndef CCM_MODULE_INTEGRATION
#define CCM_MODULE_INTEGRATION (CCM_MODULE_NMTS | CCM_MODULE_HBP | CCM_MODULE_SRDO)
#endif
#ifndef CCM_USE_STORE_RESTORE
#define CCM_USE_STORE_RESTORE FALSE
#endif
/* TRUE: every CcmProcess compares the mapped data of the TPDOs of
 * transmission type 0, 254 and 255 with what they sent last and sends them
 * when it changed (the application need not call CcmSignalCheckVar). */
#ifndef CCM_USE_PDO_CHECK_VAR
#define CCM_USE_PDO_CHECK_VAR TRUE
#endif

/* ---- CAN driver --------------------------------------------------------- */
#ifndef CDRV_USE_BASIC_CAN
#define CDRV_USE_BASIC_CAN TRUE
#endif
/* CAN20A: 11-bit identifiers (tCanId = WORD); CAN20B: 29-bit (DWORD). */
#ifndef CDRV_CAN_SPEC
#define CDRV_CAN_SPEC CAN20A
#endif
/* High-priority buffers (SRDO frames travel there). */
#ifndef CDRV_USE_HIGHBUFF
#define CDRV_USE_HIGHBUFF TRUE
#endif
#ifndef CDRV_USE_NO_TXBUFF
#define CDRV_USE_NO_TXBUFF FALSE
#endif
#ifndef CDRV_USE_NO_RXBUFF
#define CDRV_USE_NO_RXBUFF FALSE
#endif
/* The stack subscribes every identifier it receives (CdrvDefineCanId). */
#ifndef CDRV_USE_IDVALID
#define CDRV_USE_IDVALID TRUE
#endif
/* tCdrvMsg carries the receive time m_Time (tTime, 100 us ticks). */
#ifndef CDRV_TIMESTAMP
#define CDRV_TIMESTAMP FALSE
#endif
#ifndef CDRV_USE_ERROR_ISR
#define CDRV_USE_ERROR_ISR FALSE
#endif
#ifndef CDRV_IMPLEMENT_RTR
#define CDRV_IMPLEMENT_RTR TRUE
#endif
#ifndef CDRV_USE_HPT
#define CDRV_USE_HPT CDRV_HPT_OFF
#endif
#ifndef CDRV_USED_CAN_CONTROLLER
#define CDRV_USED_CAN_CONTROLLER 0
#endif
#ifndef CDRV_IDINFO_ENTRIES
#define CDRV_IDINFO_ENTRIES 10
#endif
#ifndef CDRV_MAX_RXPOLLING
#define CDRV_MAX_RXPOLLING 10
#endif

/* ---- object dictionary -------------------------------------------------- */
/* Width of tObdSize (CcmReadObject/CcmWriteObject sizes, tVarParam). */
#ifndef OBD_SUPPORTED_OBJ_SIZE
#define OBD_SUPPORTED_OBJ_SIZE OBD_OBJ_SIZE_SMALL
#endif
#ifndef OBD_CHECK_OBJECT_RANGE
#define OBD_CHECK_OBJECT_RANGE FALSE
#endif
#ifndef OBD_CHECK_FLOAT_VALID
#define OBD_CHECK_FLOAT_VALID FALSE
#endif
/* Declares tObdVStringDef / tObdVStringDomain (always declared here). */
#ifndef OBD_USE_STRING_DOMAIN_IN_RAM
#define OBD_USE_STRING_DOMAIN_IN_RAM TRUE
#endif
/* Accepted for compatibility: this library's subindex tables are always
 * constant (no RAM copies). */
#ifndef OBD_USE_VARIABLE_SUBINDEX_TAB
#define OBD_USE_VARIABLE_SUBINDEX_TAB FALSE
#endif
#ifndef OBD_USER_OD
#define OBD_USER_OD FALSE
#endif
#ifndef OBD_USE_DYNAMIC_OD
#define OBD_USE_DYNAMIC_OD FALSE
#endif
/* Bytes of the pool from which the dynamic OD builds its tables. */
#ifndef OBD_DYNAMIC_POOL_SIZE
#define OBD_DYNAMIC_POOL_SIZE 8192
#endif
#ifndef OBD_USE_STORE_RESTORE
#define OBD_USE_STORE_RESTORE CCM_USE_STORE_RESTORE
#endif
#ifndef OBD_INCLUDE_A000_TO_DEVICE_PART
#define OBD_INCLUDE_A000_TO_DEVICE_PART FALSE
#endif
#ifndef OBD_IMPLEMENT_PDO_FCT
#define OBD_IMPLEMENT_PDO_FCT TRUE
#endif
#ifndef OBD_IMPLEMENT_ARRAY_FCT
#define OBD_IMPLEMENT_ARRAY_FCT TRUE
#endif
#ifndef OBD_IMPLEMENT_READ_WRITE
#define OBD_IMPLEMENT_READ_WRITE TRUE
#endif
#ifndef OBD_IMPLEMENT_DEFINE_VAR
#define OBD_IMPLEMENT_DEFINE_VAR TRUE
#endif
#ifndef OBD_IMPLEMENT_INIT_MOD_TAB
#define OBD_IMPLEMENT_INIT_MOD_TAB TRUE
#endif

/* ---- NMT, error control, emergency -------------------------------------- */
#ifndef NMTS_USE_LIFEGUARDING
#define NMTS_USE_LIFEGUARDING TRUE
#endif
#ifndef NMTS_USE_NODEGUARDING
#define NMTS_USE_NODEGUARDING TRUE
#endif
#ifndef NMT_IMP_NMTMHBC_CTRL
#define NMT_IMP_NMTMHBC_CTRL (((CCM_MODULE_INTEGRATION) & (CCM_MODULE_NMTM | CCM_MODULE_HBC)) != 0)
#endif
#ifndef NMT_IMP_NMTSHBP_CTRL
#define NMT_IMP_NMTSHBP_CTRL (((CCM_MODULE_INTEGRATION) & (CCM_MODULE_NMTS | CCM_MODULE_HBP)) != 0)
#endif
#ifndef LSSS_PROCESS_TIME_CONTROL
#define LSSS_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef LSSM_PROCESS_TIME_CONTROL
#define LSSM_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef NMTS_PROCESS_TIME_CONTROL
#define NMTS_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef NMTM_PROCESS_TIME_CONTROL
#define NMTM_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef HBP_PROCESS_TIME_CONTROL
#define HBP_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef HBC_PROCESS_TIME_CONTROL
#define HBC_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef PDO_PROCESS_TIME_CONTROL
#define PDO_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef SDOS_PROCESS_TIME_CONTROL
#define SDOS_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef SDOC_PROCESS_TIME_CONTROL
#define SDOC_PROCESS_TIME_CONTROL FUNCTION_NO_CONTROL
#endif
#ifndef EMCP_USE_PREDEF_ERROR_FIELD
#define EMCP_USE_PREDEF_ERROR_FIELD TRUE
#endif

/* ---- PDO ----------------------------------------------------------------- */
#ifndef PDO_GRANULARITY
#define PDO_GRANULARITY 8
#endif
#ifndef PDO_USE_EVENT_TIMER
#define PDO_USE_EVENT_TIMER FALSE
#endif
#ifndef PDO_USE_SYNC_PDOS
#define PDO_USE_SYNC_PDOS FALSE
#endif
#ifndef PDO_USE_REMOTE_PDOS
#define PDO_USE_REMOTE_PDOS FALSE
#endif
#ifndef PDO_USE_SYNC_PRODUCER
#define PDO_USE_SYNC_PRODUCER FALSE
#endif
#ifndef PDO_USE_BIT_MAPPING
#define PDO_USE_BIT_MAPPING FALSE
#endif
#ifndef PDO_USE_ERROR_CALLBACK
#define PDO_USE_ERROR_CALLBACK FALSE
#endif
/* Part of the link-time signature (tObdVarEntry layout in the original). */
#ifndef PDO_USE_STATIC_MAPPING
#define PDO_USE_STATIC_MAPPING FALSE
#endif
#ifndef PDO_USE_DUMMY_MAPPING
#define PDO_USE_DUMMY_MAPPING TRUE
#endif
#ifndef PDO_USE_MPDO_DAM_PRODUCER
#define PDO_USE_MPDO_DAM_PRODUCER FALSE
#endif
#ifndef PDO_USE_MPDO_DAM_CONSUMER
#define PDO_USE_MPDO_DAM_CONSUMER FALSE
#endif
#ifndef PDO_USE_MPDO_SAM_PRODUCER
#define PDO_USE_MPDO_SAM_PRODUCER FALSE
#endif
#ifndef PDO_USE_MPDO_SAM_CONSUMER
#define PDO_USE_MPDO_SAM_CONSUMER FALSE
#endif
#ifndef PDO_USE_MUX_PDOS
#define PDO_USE_MUX_PDOS ((PDO_USE_MPDO_DAM_PRODUCER != FALSE) || (PDO_USE_MPDO_DAM_CONSUMER != FALSE) || \
                          (PDO_USE_MPDO_SAM_PRODUCER != FALSE) || (PDO_USE_MPDO_SAM_CONSUMER != FALSE))
#endif
#ifndef PDO_USE_ADDITIONAL_API
#define PDO_USE_ADDITIONAL_API OBD_USE_DYNAMIC_OD
#endif
/* Mapping entries per PDO (derived). */
#ifndef PDO_MAX_MAPPENTRIES
#if (PDO_GRANULARITY != 8) && (PDO_USE_BIT_MAPPING != FALSE)
#define PDO_MAX_MAPPENTRIES 64
#else
#define PDO_MAX_MAPPENTRIES 8
#endif
#endif

/* ---- SDO ----------------------------------------------------------------- */
/* Block transfer (CiA 301) is always part of this library and always offers
 * the CRC: SDO_BLOCKTRANSFER and SDO_CALCULATE_CRC are kept for source
 * compatibility only. SDO_BLOCKSIZE_DOWNLOAD is the number of segments per
 * sub-block the SDO server accepts in a block download, SDO_BLOCKSIZE_UPLOAD
 * the number the SDO client accepts in a block upload (1..127 each). */
#ifndef SDO_BLOCKTRANSFER
#define SDO_BLOCKTRANSFER FALSE
#endif
#ifndef SDO_BLOCKSIZE_DOWNLOAD
#define SDO_BLOCKSIZE_DOWNLOAD 6
#endif
#ifndef SDO_BLOCKSIZE_UPLOAD
#define SDO_BLOCKSIZE_UPLOAD 6
#endif
#ifndef SDO_SEGMENTTRANSFER
#define SDO_SEGMENTTRANSFER TRUE
#endif
#ifndef SDO_CALCULATE_CRC
#define SDO_CALCULATE_CRC SDO_NO_CRC
#endif
/* SDO server timeout in ticks of 100 us (5000 = 0.5 s). */
#ifndef SDOS_DEFAULT_TIMEOUT
#define SDOS_DEFAULT_TIMEOUT 5000
#endif
#ifndef SDOC_DEFAULT_TIMEOUT
#define SDOC_DEFAULT_TIMEOUT 5000
#endif
/* SDO server transfer buffer: largest object a segmented transfer moves. */
#ifndef SDOS_BUFFER_SIZE
#define SDOS_BUFFER_SIZE 256
#endif
#ifndef SDOC_USE_ADDITIONAL_API
#define SDOC_USE_ADDITIONAL_API FALSE
#endif

/* ---- SRDO (CiA 304) ------------------------------------------------------ */
/* 8, 16, 32 or 64; SRDO_MAX_MAPPENTRIES = 128 / SRDO_GRANULARITY. */
#ifndef SRDO_GRANULARITY
#define SRDO_GRANULARITY 8
#endif
/* Static mapping (SRDOSTC): mapping objects constant, data in the fields
 * given to CcmStaticDefineSrdoVarFields. */
#ifndef SRDO_USE_STATIC_MAPPING
#define SRDO_USE_STATIC_MAPPING FALSE
#endif
#ifndef SRDO_USE_DUMMY_MAPPING
#define SRDO_USE_DUMMY_MAPPING FALSE
#endif
/* TRUE when 0x1301.. has gaps (running numbers no longer follow the index). */
#ifndef SRDO_ALLOW_GAPS_IN_OD
#define SRDO_ALLOW_GAPS_IN_OD FALSE
#endif
/* Global fail-safe command: CcmSendGfc, AppGfcEvent. */
#ifndef SRDO_USE_GFC
#define SRDO_USE_GFC TRUE
#endif
/* Program-flow monitoring events: AppProgMonEvent. */
#ifndef SRDO_USE_PROGMONITOR
#define SRDO_USE_PROGMONITOR TRUE
#endif
#ifndef SRDO_CHECK_SRVT_BEFORE_1STRX
#define SRDO_CHECK_SRVT_BEFORE_1STRX FALSE
#endif

/* ---- diagnostics ---------------------------------------------------------- */
#ifndef DEF_DEBUG_LVL
#define DEF_DEBUG_LVL 0xE0800000L
#endif

#endif /* COPDEF_H_SECTION_A */

/* ======================================================================== */
/* Section B: capacities (obdcfg.h)                                         */
/* ======================================================================== */
#if !defined(COP_COPDEF_DEFER_OBD_CAPACITIES) && !defined(COPDEF_H_SECTION_B)
#define COPDEF_H_SECTION_B

/* Name of the function objdef.h generates (tCcmInitParam.m_fpObdInitRam). */
#ifndef OBD_INIT_RAM_NAME
#define OBD_INIT_RAM_NAME ObdInitRam
#endif
/* ODBuilder's key; accepted and not checked by this library. */
#ifndef OD_BUILDER_KEY
#define OD_BUILDER_KEY 0x00000000L
#endif
/* Entries of the CAN driver buffers objdef.h allocates and hands to CdrvInit
 * (tCdrvInitParam.m_RxBuffHigh, ...). */
#ifndef CDRV_MAX_RX_BUFF_ENTRIES_HIGH
#define CDRV_MAX_RX_BUFF_ENTRIES_HIGH 10
#endif
#ifndef CDRV_MAX_TX_BUFF_ENTRIES_HIGH
#define CDRV_MAX_TX_BUFF_ENTRIES_HIGH 10
#endif
#ifndef CDRV_MAX_RX_BUFF_ENTRIES_LOW
#define CDRV_MAX_RX_BUFF_ENTRIES_LOW 10
#endif
#ifndef CDRV_MAX_TX_BUFF_ENTRIES_LOW
#define CDRV_MAX_TX_BUFF_ENTRIES_LOW 10
#endif
/* Accepted for compatibility (the library keeps no COB tables). */
#ifndef COB_MAX_RX_COB_ENTRIES
#define COB_MAX_RX_COB_ENTRIES 16
#endif
#ifndef COB_MAX_TX_COB_ENTRIES
#define COB_MAX_TX_COB_ENTRIES 16
#endif
/* Number of SDO servers (0x1200..) and clients (0x1280..) in the OD. */
#ifndef SDO_MAX_SERVER_IN_OBD
#define SDO_MAX_SERVER_IN_OBD 1
#endif
#ifndef SDO_MAX_CLIENT_IN_OBD
#define SDO_MAX_CLIENT_IN_OBD 4
#endif
/* Heartbeat consumers (0x1016 subindices). */
#ifndef HBC_MAX_CONSUMER_IN_OBD
#define HBC_MAX_CONSUMER_IN_OBD 8
#endif
/* Pre-defined error field entries (0x1003). */
#ifndef EMCP_MAX_ERROR_ENTRIES_IN_OBD
#define EMCP_MAX_ERROR_ENTRIES_IN_OBD 8
#endif
/* Emergency producers the consumer can list (CcmEmccDefineProducerTab);
 * the value of the AWorks example obdcfg.h. */
#ifndef EMCC_MAX_CONSUMER
#define EMCC_MAX_CONSUMER 10
#endif
#ifndef NMTM_MAX_SLAVE_ENTRIES
#define NMTM_MAX_SLAVE_ENTRIES 16
#endif
#ifndef PDO_MAX_RXPDO_IN_OBD
#define PDO_MAX_RXPDO_IN_OBD 8
#endif
#ifndef PDO_MAX_TXPDO_IN_OBD
#define PDO_MAX_TXPDO_IN_OBD 8
#endif
/* Number of SRDOs (0x1301..0x1340) the library has room for; 0 = no SRDO
 * objects. objdict.h may declare at most this many OBD_CREATE_SRDO_COMMU
 * (objdef.h checks it; the SYS TEC manual asks for exactly this many). */
#ifndef SRDO_MAX_SRDO_IN_OBD
#define SRDO_MAX_SRDO_IN_OBD 0
#endif

#endif /* section B */
