// objdict_actuator.h - dictionary of the safety actuator (node-ID 2).
//
// SRDO 1 (0x1301) receives the sensor's two safety values (COB-IDs
// 0x101/0x102, the predefined connection set of node 1) into
//   0x2200/1 E-stop state      0x2201/1 inverted
//   0x2200/2 speed limit       0x2201/2 inverted
// (application variables, actuator.c). The factory state of the SRDO is
// "off"; the application configures it on every reset communication
// (safety_node.c, manual 2.9.5).

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
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, 0x01, Manufacturer_Device_Name, "cop safety actuator")
        OBD_END_INDEX(0x1008)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_BEGIN_INDEX_RAM(0x1018, 0x05, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_entries, 0x4)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, 0x07, 0x01, tObdUnsigned32, Vendor_Id, 0x00000000)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x02, 0x07, 0x01, tObdUnsigned32, Product_Code, 0x00000305)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x03, 0x07, 0x01, tObdUnsigned32, Revision_Number, DEFINED_OBJ1018_VERSION)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x04, 0x07, 0x01, tObdUnsigned32, Serial_Number, 0x00000002)
        OBD_END_INDEX(0x1018)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        // safety objects, in the order of manual 2.10.2
        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 0, 0, 0, 0x101, 0x102)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 4)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, EStop_Normal, 0x22000108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, EStop_Inverted, 0x22010108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x03, 0, Speed_Limit_Normal, 0x22000210)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x04, 0, Speed_Limit_Inverted, 0x22010210)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(1)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        // received safety values: normal copy
        OBD_BEGIN_INDEX_RAM(0x2200, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2200, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2200, 0x01, 0x05, 0x0B, tObdUnsigned8, bActEStop_g, 0x00)
            OBD_SUBINDEX_RAM_EXTVAR(0x2200, 0x02, 0x06, 0x0B, tObdUnsigned16, wActSpeedLimit_g, 0)
        OBD_END_INDEX(0x2200)

        // received safety values: inverted copy
        OBD_BEGIN_INDEX_RAM(0x2201, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2201, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2201, 0x01, 0x05, 0x0B, tObdUnsigned8, bActEStopInv_g, 0xFF)
            OBD_SUBINDEX_RAM_EXTVAR(0x2201, 0x02, 0x06, 0x0B, tObdUnsigned16, wActSpeedLimitInv_g, 0xFFFF)
        OBD_END_INDEX(0x2201)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
