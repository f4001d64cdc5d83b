// objdict_safety.h - dictionary of the safety node (node-ID 3) as it leaves
// the factory: SRDO 1 exists but is off (direction 0, no timing, mapping
// empty, no valid configuration). The configurator writes all of it over
// SDO. The node's safety inputs (application variables, safety_node.c):
//   0x2000/1 guard door closed (1) / open (0)   0x2001/1 inverted copy
//   0x2000/2 tool position in 0.1 mm           0x2001/2 inverted copy

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
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, 0x01, Manufacturer_Device_Name, "cop safety door node")
        OBD_END_INDEX(0x1008)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 0, 0, 0, 0x101, 0x102)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 0)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Mapping_1, 0x00000000)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Mapping_2, 0x00000000)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x03, 0, Mapping_3, 0x00000000)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x04, 0, Mapping_4, 0x00000000)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(1)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2000, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2000, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2000, 0x01, 0x05, 0x09, tObdUnsigned8, bDoorClosed_g, 0x00)
            OBD_SUBINDEX_RAM_EXTVAR(0x2000, 0x02, 0x06, 0x09, tObdUnsigned16, wPosition_g, 0)
        OBD_END_INDEX(0x2000)
        OBD_BEGIN_INDEX_RAM(0x2001, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2001, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2001, 0x01, 0x05, 0x09, tObdUnsigned8, bDoorClosedInv_g, 0xFF)
            OBD_SUBINDEX_RAM_EXTVAR(0x2001, 0x02, 0x06, 0x09, tObdUnsigned16, wPositionInv_g, 0xFFFF)
        OBD_END_INDEX(0x2001)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
