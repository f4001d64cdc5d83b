// objdict_actuator.h - dictionary of the actuator: one SRDO (off until it is
// configured), the GFC parameter and two mappable bytes.

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

        OBD_BEGIN_INDEX_ROM(0x1008, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, 0x01, Manufacturer_Device_Name, "host actuator")
        OBD_END_INDEX(0x1008)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_BEGIN_INDEX_RAM(0x1018, 0x05, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_entries, 0x4)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, 0x07, 0x01, tObdUnsigned32, Vendor_Id, 0x00000000)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x02, 0x07, 0x01, tObdUnsigned32, Product_Code, 0x00000304)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x03, 0x07, 0x01, tObdUnsigned32, Revision_Number, 0x00010000)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x04, 0x07, 0x01, tObdUnsigned32, Serial_Number, 0x00000001)
        OBD_END_INDEX(0x1018)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 0, 0, 0, 0x101, 0x102)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 2)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Value_Normal, 0x21000108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Value_Inverted, 0x21000208)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(1)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2100, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2100, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x2100, 0x01, 0x05, 0x0B, tObdUnsigned8, Value, 0x00)
            OBD_SUBINDEX_RAM_VAR(0x2100, 0x02, 0x05, 0x0B, tObdUnsigned8, Value_Inv, 0xFF)
        OBD_END_INDEX(0x2100)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
