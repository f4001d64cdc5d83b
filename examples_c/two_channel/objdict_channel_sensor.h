// objdict_channel_sensor.h - dictionary of one channel of the two-channel
// safety sensor (node-ID 1 on its channel's bus). Compiled once per channel
// (sensor_ch_a.c, sensor_ch_b.c), so each instance has its own objects.
//
// SRDO 1 (0x1301) sends the channel's safety value (a speed limit in mm/s)
// as a normal and an inverted copy every 20 ms: 0x2100/1 and 0x2101/1.
// Direction 1, refresh time 20 ms, SRVT 10 ms, COB-IDs 0x101/0x102; the
// application makes the configuration valid (CRC into 0x13FF, 0xA5 into
// 0x13FE) before the node is started (main.c).
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
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, 0x01, Manufacturer_Device_Name, "cop two-channel sensor")
        OBD_END_INDEX(0x1008)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_BEGIN_INDEX_RAM(0x1018, 0x05, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_entries, 0x4)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, 0x07, 0x01, tObdUnsigned32, Vendor_Id, 0x00000000)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x02, 0x07, 0x01, tObdUnsigned32, Product_Code, 0x00000304)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x03, 0x07, 0x01, tObdUnsigned32, Revision_Number, DEFINED_OBJ1018_VERSION)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x04, 0x07, 0x01, tObdUnsigned32, Serial_Number, 0x00000001)
        OBD_END_INDEX(0x1018)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        // safety objects, in the order of manual 2.10.2
        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 1, 20, 10, 0x101, 0x102)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 2)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Value_Normal, 0x21000110)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Value_Inverted, 0x21010110)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(1)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        // the safety value of this channel: normal and inverted copy
        OBD_BEGIN_INDEX_RAM(0x2100, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2100, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x2100, 0x01, 0x06, 0x0B, tObdUnsigned16, Speed_Limit_Normal, 0x0000)
        OBD_END_INDEX(0x2100)
        OBD_BEGIN_INDEX_RAM(0x2101, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2101, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x2101, 0x01, 0x06, 0x0B, tObdUnsigned16, Speed_Limit_Inverted, 0xFFFF)
        OBD_END_INDEX(0x2101)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
