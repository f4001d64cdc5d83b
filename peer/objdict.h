// objdict.h of the interoperability peer: a small safety I/O device as a
// python-canopen master meets it. peer/peer_node.eds describes exactly this
// dictionary (the tests check that both agree, object by object).
//
// Node-ID 5 (the SRDO COB-IDs below are the predefined connection set of
// node 5: 0xFF + 2 * 5 and 0x100 + 2 * 5).

#define OBD_DEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_DEFINE_MACRO

OBD_BEGIN ()

    OBD_BEGIN_PART_GENERIC ()

        // 0x1000 device type: CiA 401 generic I/O with digital in- and outputs
        OBD_BEGIN_INDEX_ROM(0x1000, 0x01, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1000, 0x00, kObdTypUInt32, kObdAccR, tObdUnsigned32, Device_Type, 0x00030191)
        OBD_END_INDEX(0x1000)

        // 0x1001 error register
        OBD_BEGIN_INDEX_RAM(0x1001, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR(0x1001, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Error_Register, 0x00)
        OBD_END_INDEX(0x1001)

        // 0x1008..0x100A names and versions
        OBD_BEGIN_INDEX_ROM(0x1008, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, kObdAccR, Manufacturer_Device_Name, "cop peer node")
        OBD_END_INDEX(0x1008)
        OBD_BEGIN_INDEX_RAM(0x1009, 0x01, NULL)
            OBD_SUBINDEX_RAM_VSTRING(0x1009, 0x00, kObdAccR, Manufacturer_Hardware_Version, 16, "PCB rev. B")
        OBD_END_INDEX(0x1009)
        OBD_BEGIN_INDEX_ROM(0x100A, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x100A, 0x00, kObdAccR, Manufacturer_Software_Version, DEFINED_STRING_VERSION)
        OBD_END_INDEX(0x100A)

        // 0x1010 store parameters (0: nothing is saved until a storage driver
        // is in use), 0x1011 restore default parameters
        OBD_BEGIN_INDEX_RAM(0x1010, 0x03, CcmCbStore)
            OBD_SUBINDEX_ROM_VAR(0x1010, 0x00, kObdTypUInt8, kObdAccCR, tObdUnsigned8, Largest_Subindex, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x01, kObdTypUInt32, kObdAccRW, tObdUnsigned32, Save_All, 0x00000000)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x02, kObdTypUInt32, kObdAccRW, tObdUnsigned32, Save_Communication, 0x00000000)
        OBD_END_INDEX(0x1010)
        OBD_BEGIN_INDEX_RAM(0x1011, 0x03, CcmCbRestore)
            OBD_SUBINDEX_ROM_VAR(0x1011, 0x00, kObdTypUInt8, kObdAccCR, tObdUnsigned8, Largest_Subindex, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x01, kObdTypUInt32, kObdAccRW, tObdUnsigned32, Restore_All, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x02, kObdTypUInt32, kObdAccRW, tObdUnsigned32, Restore_Communication, 0x00000001)
        OBD_END_INDEX(0x1011)

        // 0x1014 COB-ID EMCY (0x80 stands for 0x80 + node-ID)
        OBD_BEGIN_INDEX_RAM(0x1014, 0x01, EmcpCbConfigEmergencyId)
            OBD_SUBINDEX_RAM_VAR(0x1014, 0x00, kObdTypUInt32, kObdAccSRW, tObdUnsigned32, COB_ID_EMCY, 0x80)
        OBD_END_INDEX(0x1014)

        // 0x1016 consumer heartbeat time: node-ID << 16 | time in ms
        OBD_ROM_INDEX_RAM_ARRAY(0x1016, 2, HbcCbConfigHeartbeat, kObdTypUInt32, kObdAccSRW, tObdUnsigned32, Consumer_Heartbeat_Time, 0)

        // 0x1017 producer heartbeat time (ms)
        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, kObdTypUInt16, kObdAccSRW, tObdUnsigned16, Producer_Heartbeat_Time, 0)
        OBD_END_INDEX(0x1017)

        // 0x1018 identity
        OBD_BEGIN_INDEX_RAM(0x1018, 0x05, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Number_of_entries, 0x4)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, kObdTypUInt32, kObdAccR, tObdUnsigned32, Vendor_Id, 0x00000123)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x02, kObdTypUInt32, kObdAccR, tObdUnsigned32, Product_Code, 0x0000C0DE)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x03, kObdTypUInt32, kObdAccR, tObdUnsigned32, Revision_Number, DEFINED_OBJ1018_VERSION)
            OBD_SUBINDEX_RAM_VAR(0x1018, 0x04, kObdTypUInt32, kObdAccR, tObdUnsigned32, Serial_Number, 0x00000005)
        OBD_END_INDEX(0x1018)

        // default SDO server (predefined connection set)
        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        // a second SDO server, delivered without COB-IDs (bit 31): a
        // configuration tool gets its own channel once the master sets them
        OBD_CREATE_SDOS(0x1201, 1, 0x80000000, 0x80000000, 0x00)

        // SDO client: configured at run time (CcmSdocDefineClientTab or SDO)
        OBD_CREATE_SDOC(0x1280, 0, 0x80000000, 0x80000000, 0x00)

        // SRDO (CiA 304): one SRDO, delivered unconfigured (direction 0);
        // the master configures direction, mapping and CRC over SDO.
        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 0, 25, 20, 0x109, 0x10A)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 0)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Srdo_Map_1, 0)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Srdo_Map_2, 0)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x03, 0, Srdo_Map_3, 0)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x04, 0, Srdo_Map_4, 0)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(1)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
        OBD_END_SRDO_CRC()
        // TPDO 1, delivered invalid and unmapped; the dynamic OD
        // (peer/peer_dynod.dcf) reconfigures it (0x80000180 stands for
        // 0x80000180 + node-ID, the predefined connection set)
        OBD_CREATE_TXPDO_COMMU(0x1800, 0, 0x80000180, 0xFF, 0, 0)
        OBD_CREATE_TXPDO_MAPP(0x1A00, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        // 0x2000 one variable of every basic type
        OBD_BEGIN_INDEX_RAM(0x2000, 0x0C, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2000, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Count, 0x0B)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x01, kObdTypBool, kObdAccRW, tObdBoolean, V_Boolean, 1)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x02, kObdTypInt8, kObdAccRW, tObdInteger8, V_Integer8, -8)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x03, kObdTypInt16, kObdAccRW, tObdInteger16, V_Integer16, -1600)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x04, kObdTypInt32, kObdAccRW, tObdInteger32, V_Integer32, -320000)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x05, kObdTypInt64, kObdAccRW, tObdInteger64, V_Integer64, -6400000000LL)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x06, kObdTypUInt8, kObdAccRW, tObdUnsigned8, V_Unsigned8, 0xA8)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x07, kObdTypUInt16, kObdAccRW, tObdUnsigned16, V_Unsigned16, 0xB16B)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x08, kObdTypUInt32, kObdAccRW, tObdUnsigned32, V_Unsigned32, 0xC0FFEE32)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x09, kObdTypUInt64, kObdAccRW, tObdUnsigned64, V_Unsigned64, 0x0123456789ABCDEFULL)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x0A, kObdTypReal32, kObdAccRW, tObdReal32, V_Real32, 3.25)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x0B, kObdTypReal64, kObdAccRW, tObdReal64, V_Real64, -0.15625)
        OBD_END_INDEX(0x2000)

        // 0x2001 long visible string (up to 256 characters)
        OBD_BEGIN_INDEX_RAM(0x2001, 0x01, NULL)
            OBD_SUBINDEX_RAM_VSTRING(0x2001, 0x00, kObdAccRW, Long_String, 256, "cop peer")
        OBD_END_INDEX(0x2001)

        // 0x2002 domain: 300 bytes of the application (CcmDefineVarTab)
        OBD_BEGIN_INDEX_RAM(0x2002, 0x01, NULL)
            OBD_SUBINDEX_RAM_DOMAIN(0x2002, 0x00, kObdAccRW, Domain)
        OBD_END_INDEX(0x2002)

        // 0x2003 user-defined UNSIGNED32 in an application variable (CcmDefineVarTab)
        OBD_BEGIN_INDEX_RAM(0x2003, 0x01, NULL)
            OBD_SUBINDEX_RAM_USERDEF(0x2003, 0x00, kObdTypUInt32, kObdAccRW, tObdUnsigned32, User_U32, 0x5EED0001)
        OBD_END_INDEX(0x2003)

        // 0x2010 access rights: read-only, write-only, constant
        OBD_BEGIN_INDEX_RAM(0x2010, 0x04, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2010, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Count, 0x03)
            OBD_SUBINDEX_RAM_VAR(0x2010, 0x01, kObdTypUInt16, kObdAccR, tObdUnsigned16, Read_Only, 0x1234)
            OBD_SUBINDEX_RAM_VAR(0x2010, 0x02, kObdTypUInt32, kObdAccW, tObdUnsigned32, Write_Only, 0)
            OBD_SUBINDEX_ROM_VAR(0x2010, 0x03, kObdTypUInt8, kObdAccR, tObdUnsigned8, Constant, 0x42)
        OBD_END_INDEX(0x2010)

        // 0x2020 value ranges
        OBD_BEGIN_INDEX_RAM(0x2020, 0x04, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2020, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Count, 0x03)
            OBD_SUBINDEX_RAM_VAR_RG(0x2020, 0x01, kObdTypUInt16, kObdAccRW, tObdUnsigned16, Range_U16, 100, 10, 1000)
            OBD_SUBINDEX_RAM_VAR_RG(0x2020, 0x02, kObdTypInt16, kObdAccRW, tObdInteger16, Range_I16, 0, -100, 100)
            OBD_SUBINDEX_RAM_EXTVAR_RG(0x2020, 0x03, kObdTypUInt8, kObdAccRW, tObdUnsigned8, bPeerRange_g, 5, 1, 10)
        OBD_END_INDEX(0x2020)

        // 0x2030 / 0x2031 safe outputs, normal and inverted (transmit SRDO data)
        OBD_BEGIN_INDEX_RAM(0x2030, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2030, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2030, 0x01, kObdTypUInt8, kObdAccRW | kObdAccPdo, tObdUnsigned8, bPeerSafeOut_g, 0x00)
            OBD_SUBINDEX_RAM_EXTVAR(0x2030, 0x02, kObdTypUInt16, kObdAccRW | kObdAccPdo, tObdUnsigned16, wPeerSafeOut_g, 0x0000)
        OBD_END_INDEX(0x2030)
        OBD_BEGIN_INDEX_RAM(0x2031, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2031, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2031, 0x01, kObdTypUInt8, kObdAccRW | kObdAccPdo, tObdUnsigned8, bPeerSafeOutInv_g, 0xFF)
            OBD_SUBINDEX_RAM_EXTVAR(0x2031, 0x02, kObdTypUInt16, kObdAccRW | kObdAccPdo, tObdUnsigned16, wPeerSafeOutInv_g, 0xFFFF)
        OBD_END_INDEX(0x2031)

        // 0x2040 / 0x2041 safe inputs, normal and inverted (receive SRDO data)
        OBD_BEGIN_INDEX_RAM(0x2040, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2040, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2040, 0x01, kObdTypUInt8, kObdAccRW | kObdAccPdo, tObdUnsigned8, bPeerSafeIn_g, 0x00)
            OBD_SUBINDEX_RAM_EXTVAR(0x2040, 0x02, kObdTypUInt16, kObdAccRW | kObdAccPdo, tObdUnsigned16, wPeerSafeIn_g, 0x0000)
        OBD_END_INDEX(0x2040)
        OBD_BEGIN_INDEX_RAM(0x2041, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2041, 0x00, kObdTypUInt8, kObdAccR, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_EXTVAR(0x2041, 0x01, kObdTypUInt8, kObdAccRW | kObdAccPdo, tObdUnsigned8, bPeerSafeInInv_g, 0xFF)
            OBD_SUBINDEX_RAM_EXTVAR(0x2041, 0x02, kObdTypUInt16, kObdAccRW | kObdAccPdo, tObdUnsigned16, wPeerSafeInInv_g, 0xFFFF)
        OBD_END_INDEX(0x2041)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
