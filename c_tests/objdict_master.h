// objdict_master.h - the master-side test dictionary (c_tests/cfg,
// test_master_api.c and test_pdo_api.c): heartbeat consumer 0x1016 (two
// entries), SDO server and client, one RPDO and one TPDO (disabled until a
// test defines them), and two mappable application variables
// (0x2060/1 bMasterIn_g, 0x2061/1 bMasterOut_g). Init function
// ObdInitRamMaster.

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

        OBD_ROM_INDEX_RAM_ARRAY(0x1016, 2, HbcCbConfigHeartbeat, 0x07, 0x83, tObdUnsigned32, Consumer_Heartbeat_Time, 0x00000000)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)
        OBD_CREATE_SDOC(0x1280, 0, 0x80000000, 0x80000000, 0x00)

        OBD_CREATE_RXPDO_COMMU(0x1400, 0, 0x80000000, 0xFF, 0, 0)
        OBD_CREATE_RXPDO_MAPP(0x1600, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)
        OBD_CREATE_TXPDO_COMMU(0x1800, 0, 0x80000000, 0xFF, 0, 0)
        OBD_CREATE_TXPDO_MAPP(0x1A00, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2060, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2060, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_EXTVAR(0x2060, 0x01, 0x05, 0x0B, tObdUnsigned8, bMasterIn_g, 0x00)
        OBD_END_INDEX(0x2060)
        OBD_BEGIN_INDEX_RAM(0x2061, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2061, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_EXTVAR(0x2061, 0x01, 0x05, 0x0B, tObdUnsigned8, bMasterOut_g, 0x00)
        OBD_END_INDEX(0x2061)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
