// objdict.h - the static (firmware) part of the example's dictionary: the
// communication objects and one RPDO and one TPDO, both invalid and
// without mapping. Everything else - the PDO configuration and the network
// variables it carries - comes from the DCF through DynBuildOd.

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

        OBD_BEGIN_INDEX_RAM(0x1018, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_entries, 0x1)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, 0x07, 0x01, tObdUnsigned32, Vendor_Id, 0x00000000)
        OBD_END_INDEX(0x1018)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_RXPDO_COMMU(0x1400, 0, 0x80000200, 0xFF, 0, 0)
        OBD_CREATE_RXPDO_MAPP(0x1600, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)
        OBD_CREATE_TXPDO_COMMU(0x1800, 0, 0x80000180, 0xFF, 0, 0)
        OBD_CREATE_TXPDO_MAPP(0x1A00, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()
    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
