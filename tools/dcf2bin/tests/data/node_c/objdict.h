// objdict.h - the static dictionary of the dcf2bin test node: identity
// with vendor-ID only, heartbeat, one RPDO and one TPDO (invalid, no
// mapping), a ranged setpoint and an application variable.

#define OBD_DEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_DEFINE_MACRO

OBD_BEGIN ()

    OBD_BEGIN_PART_GENERIC ()

        OBD_BEGIN_INDEX_ROM(0x1000, 0x01, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1000, 0x00, 0x07, 0x01, tObdUnsigned32, Device_Type, 0x00000191)
        OBD_END_INDEX(0x1000)

        OBD_BEGIN_INDEX_RAM(0x1001, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR(0x1001, 0x00, 0x05, 0x01, tObdUnsigned8, Error_Register, 0x00)
        OBD_END_INDEX(0x1001)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_BEGIN_INDEX_RAM(0x1018, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_entries, 0x1)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, 0x07, 0x01, tObdUnsigned32, Vendor_Id, 0x00000123)
        OBD_END_INDEX(0x1018)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_RXPDO_COMMU(0x1400, 0, 0x80000200, 0xFF, 0, 0)
        OBD_CREATE_RXPDO_MAPP(0x1600, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)
        OBD_CREATE_TXPDO_COMMU(0x1800, 0, 0x80000180, 0xFF, 0, 0)
        OBD_CREATE_TXPDO_MAPP(0x1A00, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2100, 0x03, NULL)
            OBD_SUBINDEX_RAM_VAR(0x2100, 0x00, 0x05, 0x01, tObdUnsigned8, Setpoints, 0x2)
            OBD_SUBINDEX_RAM_VAR_RG(0x2100, 0x01, 0x03, 0x0B, tObdInteger16, Setpoint_1, 0, -50, 50)
            OBD_SUBINDEX_RAM_EXTVAR(0x2100, 0x02, 0x07, 0x0B, tObdUnsigned32, dwAppCounter_g, 0)
        OBD_END_INDEX(0x2100)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
