// objdict_configurator.h - dictionary of the configurator (node-ID 1): two
// SDO client channels (0x1280 -> I/O node 2, 0x1281 -> safety node 3,
// defined at run time with CcmSdocDefineClientTab) and one receive SRDO
// that consumes the safety node's data (COB-IDs 0x105/0x106, the
// predefined connection set of node 3):
//   0x2100/1 guard door closed (1) / open (0)   0x2101/1 inverted
//   0x2100/2 tool position in 0.1 mm           0x2101/2 inverted
// The SRDO's factory state is "off"; the application configures it at
// reset communication (configurator.c).

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
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, 0x01, Manufacturer_Device_Name, "cop configurator")
        OBD_END_INDEX(0x1008)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)
        OBD_CREATE_SDOC(0x1280, 0, 0x80000000, 0x80000000, 0x00)
        OBD_CREATE_SDOC(0x1281, 1, 0x80000000, 0x80000000, 0x00)

        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 0, 0, 0, 0x105, 0x106)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 4)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Door_Normal, 0x21000108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Door_Inverted, 0x21010108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x03, 0, Position_Normal, 0x21000210)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x04, 0, Position_Inverted, 0x21010210)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(1)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2100, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2100, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2100, 0x01, 0x05, 0x0B, tObdUnsigned8, bCfgDoorClosed_g, 0x00)
            OBD_SUBINDEX_RAM_EXTVAR(0x2100, 0x02, 0x06, 0x0B, tObdUnsigned16, wCfgPosition_g, 0)
        OBD_END_INDEX(0x2100)
        OBD_BEGIN_INDEX_RAM(0x2101, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2101, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2101, 0x01, 0x05, 0x0B, tObdUnsigned8, bCfgDoorClosedInv_g, 0xFF)
            OBD_SUBINDEX_RAM_EXTVAR(0x2101, 0x02, 0x06, 0x0B, tObdUnsigned16, wCfgPositionInv_g, 0xFFFF)
        OBD_END_INDEX(0x2101)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
