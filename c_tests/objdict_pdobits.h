// objdict_pdobits.h - dictionary of test_pdo_bits.c: one RPDO and one TPDO,
// two BOOLEANs (0x2100/1, 0x2100/2) and an UNSIGNED8 (0x2101/1), all
// mappable. The TPDO's default mapping puts both BOOLEANs into one bit
// each and the UNSIGNED8 behind them from bit 2 (PDO_USE_BIT_MAPPING).
// Compiled twice (objdict_pdobits.c, objdict_pdobits_peer.c) for the two
// nodes of the test.

#define OBD_DEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_DEFINE_MACRO

OBD_BEGIN ()

    OBD_BEGIN_PART_GENERIC ()

        OBD_BEGIN_INDEX_ROM(0x1000, 0x01, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1000, 0x00, 0x07, 0x01, tObdUnsigned32, Device_Type, 0x00000000)
        OBD_END_INDEX(0x1000)

        OBD_BEGIN_INDEX_RAM(0x1001, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR(0x1001, 0x00, 0x05, 0x01, tObdUnsigned8, Error_Register, 0x00)
        OBD_END_INDEX(0x1001)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_RXPDO_COMMU(0x1400, 0, 0x80000200, 0xFF, 0, 0)
        OBD_CREATE_RXPDO_MAPP(0x1600, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)
        OBD_CREATE_TXPDO_COMMU(0x1800, 0, 0x80000180, 0xFF, 0, 0)
        OBD_CREATE_TXPDO_MAPP(0x1A00, 0, 3, 0x21000101, 0x21000201, 0x21010108, 0, 0, 0, 0, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2100, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2100, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x2100, 0x01, 0x01, 0x0B, tObdBoolean, Bit_A, 0x00)
            OBD_SUBINDEX_RAM_VAR(0x2100, 0x02, 0x01, 0x0B, tObdBoolean, Bit_B, 0x00)
        OBD_END_INDEX(0x2100)

        OBD_BEGIN_INDEX_RAM(0x2101, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2101, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x2101, 0x01, 0x05, 0x0B, tObdUnsigned8, Byte_C, 0x00)
        OBD_END_INDEX(0x2101)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
