// objdict_all.h - a test dictionary that uses every macro of the objdict.h
// language (SYS TEC manual L-1024, SYSTEC_API.md section 6), written the way
// ODBuilder writes them: numeric type and access codes, one macro per line.
//
// Expected values are checked by test_objdict.c and test_obd_callbacks.c.

#define OBD_DEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_DEFINE_MACRO

OBD_BEGIN ()

    OBD_BEGIN_PART_GENERIC ()

        // 0x1000 device type (constant)
        OBD_BEGIN_INDEX_ROM(0x1000, 0x01, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1000, 0x00, 0x07, 0x01, tObdUnsigned32, Device_Type, 0x00020191)
        OBD_END_INDEX(0x1000)

        // 0x1001 error register
        OBD_BEGIN_INDEX_RAM(0x1001, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR(0x1001, 0x00, 0x05, 0x01, tObdUnsigned8, Error_Register, 0x00)
        OBD_END_INDEX(0x1001)

        // 0x1008 device name (constant string)
        OBD_BEGIN_INDEX_ROM(0x1008, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, 0x01, Manufacturer_Device_Name, "cop test node")
        OBD_END_INDEX(0x1008)

        // 0x1009 hardware version (string in RAM, up to 8 characters)
        OBD_BEGIN_INDEX_RAM(0x1009, 0x01, NULL)
            OBD_SUBINDEX_RAM_VSTRING(0x1009, 0x00, 0x03, Manufacturer_Hardware_Version, 8, "HW1")
        OBD_END_INDEX(0x1009)

        // 0x100A software version (the library's version string)
        OBD_BEGIN_INDEX_ROM(0x100A, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x100A, 0x00, 0x01, Manufacturer_Software_Version, DEFINED_STRING_VERSION)
        OBD_END_INDEX(0x100A)

#if defined(OBJDICT_ALL_WITH_STORE)
        // 0x1010 store parameters, 0x1011 restore default parameters
        OBD_BEGIN_INDEX_RAM(0x1010, 0x05, CcmCbStore)
            OBD_SUBINDEX_ROM_VAR(0x1010, 0x00, 0x05, 0x01, tObdUnsigned8, Largest_Subindex, 0x04)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x01, 0x07, 0x03, tObdUnsigned32, Save_All, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x02, 0x07, 0x03, tObdUnsigned32, Save_Communication, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x03, 0x07, 0x03, tObdUnsigned32, Save_Application, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1010, 0x04, 0x07, 0x03, tObdUnsigned32, Save_Manufacturer, 0x00000001)
        OBD_END_INDEX(0x1010)
        OBD_BEGIN_INDEX_RAM(0x1011, 0x05, CcmCbRestore)
            OBD_SUBINDEX_ROM_VAR(0x1011, 0x00, 0x05, 0x01, tObdUnsigned8, Largest_Subindex, 0x04)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x01, 0x07, 0x03, tObdUnsigned32, Restore_All, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x02, 0x07, 0x03, tObdUnsigned32, Restore_Communication, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x03, 0x07, 0x03, tObdUnsigned32, Restore_Application, 0x00000001)
            OBD_SUBINDEX_RAM_VAR(0x1011, 0x04, 0x07, 0x03, tObdUnsigned32, Restore_Manufacturer, 0x00000001)
        OBD_END_INDEX(0x1011)
#endif

        // 0x1017 producer heartbeat time
        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        // 0x1018 identity
        OBD_BEGIN_INDEX_RAM(0x1018, 0x05, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_entries, 0x4)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, 0x07, 0x01, tObdUnsigned32, Vendor_Id, 0x00000123)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x02, 0x07, 0x01, tObdUnsigned32, Product_Code, 0x00004711)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x03, 0x07, 0x01, tObdUnsigned32, Revision_Number, DEFINED_OBJ1018_VERSION)
            OBD_SUBINDEX_RAM_VAR(0x1018, 0x04, 0x07, 0x01, tObdUnsigned32, Serial_Number, 0x00000042)
        OBD_END_INDEX(0x1018)

        // SDO servers and client
        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)
        OBD_CREATE_SDOS(0x1201, 1, 0x80000000, 0x80000000, 0x05)
        OBD_CREATE_SDOC(0x1280, 0, 0x80000000, 0x80000000, 0x03)

        // SRDO (CiA 304): SRDO 1 transmits 0x2040/0x2041, SRDO 2 receives into 0x2042/0x2043
        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 1, 25, 20, 0x101, 0x102)
        OBD_CREATE_SRDO_COMMU(0x1302, 1, 2, 100, 20, 0x103, 0x104)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 2)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Safe_Out_Normal, 0x20400108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Safe_Out_Inverted, 0x20410108)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_BEGIN_SRDO_MAPP(0x1382, 1, 2)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x01, 1, Safe_In_Normal, 0x20420108)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x02, 1, Safe_In_Inverted, 0x20430108)
        OBD_END_SRDO_MAPP(0x1382)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(2)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
            OBD_SUBINDEX_SRDO_CRC(0x02, Crc_Srdo_2, 0x1234)
        OBD_END_SRDO_CRC()

        // PDOs (disabled: COB-ID bit 31)
        OBD_CREATE_RXPDO_COMMU(0x1400, 0, 0x80000200, 0xFF, 0, 0)
        OBD_CREATE_RXPDO_MAPP(0x1600, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)
        OBD_CREATE_TXPDO_COMMU(0x1800, 0, 0x80000180, 0xFE, 10, 100)
        OBD_CREATE_TXPDO_MAPP(0x1A00, 0, 1, 0x20400108, 0, 0, 0, 0, 0, 0, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        // 0x2000 one variable per basic type
        OBD_BEGIN_INDEX_RAM(0x2000, 0x0E, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2000, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x0D)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x01, kObdTypBool, kObdAccRW, tObdBoolean, V_Bool, 1)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x02, kObdTypInt8, kObdAccRW, tObdInteger8, V_Int8, -5)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x03, kObdTypInt16, kObdAccRW, tObdInteger16, V_Int16, -1000)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x04, kObdTypInt32, kObdAccRW, tObdInteger32, V_Int32, -100000)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x05, kObdTypUInt8, kObdAccRW, tObdUnsigned8, V_UInt8, 0xA5)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x06, kObdTypUInt16, kObdAccRW, tObdUnsigned16, V_UInt16, 0xBEEF)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x07, kObdTypUInt32, kObdAccRW, tObdUnsigned32, V_UInt32, 0xDEADBEEF)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x08, kObdTypReal32, kObdAccRW, tObdReal32, V_Real32, 1.5)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x09, kObdTypInt24, kObdAccRW, tObdInteger24, V_Int24, -3)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x0A, kObdTypUInt24, kObdAccRW, tObdUnsigned24, V_UInt24, 0x123456)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x0B, kObdTypInt64, kObdAccRW, tObdInteger64, V_Int64, -2)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x0C, kObdTypUInt64, kObdAccRW, tObdUnsigned64, V_UInt64, 0x0102030405060708ULL)
            OBD_SUBINDEX_RAM_VAR(0x2000, 0x0D, kObdTypReal64, kObdAccRW, tObdReal64, V_Real64, -0.25)
        OBD_END_INDEX(0x2000)

        // 0x2001 value ranges
        OBD_BEGIN_INDEX_RAM(0x2001, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2001, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_VAR_RG(0x2001, 0x01, 0x06, 0x03, tObdUnsigned16, Range_U16, 100, 10, 1000)
            OBD_SUBINDEX_RAM_VAR_RG(0x2001, 0x02, 0x03, 0x03, tObdInteger16, Range_I16, 0, -100, 100)
        OBD_END_INDEX(0x2001)

        // 0x2002 application variables
        OBD_BEGIN_INDEX_RAM(0x2002, 0x04, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2002, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x03)
            OBD_SUBINDEX_RAM_EXTVAR(0x2002, 0x01, 0x07, 0x03, tObdUnsigned32, dwTestExtVar_g, 0x11223344)
            OBD_SUBINDEX_RAM_EXTVAR_RG(0x2002, 0x02, 0x05, 0x03, tObdUnsigned8, bTestExtVarRg_g, 5, 1, 10)
            OBD_SUBINDEX_RAM_EXTVAR_NOINIT(0x2002, 0x03, 0x06, 0x03, tObdUnsigned16, wTestExtNoInit_g)
        OBD_END_INDEX(0x2002)

        // 0x2003 strings
        OBD_BEGIN_INDEX_RAM(0x2003, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2003, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_ROM_VSTRING(0x2003, 0x01, 0x01, Rom_String, "constant")
            OBD_SUBINDEX_RAM_VSTRING(0x2003, 0x02, 0x03, Ram_String, 12, "hello")
        OBD_END_INDEX(0x2003)

        // 0x2004 variable without default
        OBD_BEGIN_INDEX_RAM(0x2004, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR_NOINIT(0x2004, 0x00, 0x07, 0x03, tObdUnsigned32, No_Init)
        OBD_END_INDEX(0x2004)

        // 0x2005 domain
        OBD_BEGIN_INDEX_RAM(0x2005, 0x01, NULL)
            OBD_SUBINDEX_RAM_DOMAIN(0x2005, 0x00, 0x03, Domain)
        OBD_END_INDEX(0x2005)

        // 0x2006 user-defined variables (attached with CcmDefineVarTab)
        OBD_BEGIN_INDEX_RAM(0x2006, 0x04, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2006, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x03)
            OBD_SUBINDEX_RAM_USERDEF(0x2006, 0x01, 0x07, 0x03, tObdUnsigned32, User_U32, 0x0000CAFE)
            OBD_SUBINDEX_RAM_USERDEF_RG(0x2006, 0x02, 0x03, 0x03, tObdInteger16, User_I16_Rg, 7, -50, 50)
            OBD_SUBINDEX_RAM_USERDEF_NOINIT(0x2006, 0x03, 0x05, 0x03, tObdUnsigned8, User_U8)
        OBD_END_INDEX(0x2006)

        // 0x2010..0x2012 arrays
        OBD_ROM_INDEX_RAM_ARRAY(0x2010, 4, NULL, 0x05, 0x0B, tObdUnsigned8, Array_U8, 0x11)
        OBD_ROM_INDEX_RAM_EXTARRAY(0x2011, 3, NULL, 0x06, 0x03, tObdUnsigned16, awTestExtArray_g, 0x2222)
        OBD_ROM_INDEX_RAM_VARARRAY(0x2012, 2, NULL, 0x07, 0x03, tObdUnsigned32, Var_Array, 0x33333333)

        // 0x2020 callback that refuses the value 0x0BAD
        OBD_BEGIN_INDEX_RAM(0x2020, 0x01, TestCbVeto)
            OBD_SUBINDEX_RAM_VAR(0x2020, 0x00, 0x06, 0x03, tObdUnsigned16, Vetoed, 0x0001)
        OBD_END_INDEX(0x2020)

        // 0x2021 callback that records every event
        OBD_BEGIN_INDEX_RAM(0x2021, 0x03, TestCbRecord)
            OBD_SUBINDEX_ROM_VAR(0x2021, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x2021, 0x01, 0x07, 0x03, tObdUnsigned32, Recorded, 0x00000010)
            OBD_SUBINDEX_RAM_VSTRING(0x2021, 0x02, 0x03, Recorded_String, 16, "")
        OBD_END_INDEX(0x2021)

        // 0x2030 write-only and read-only variables
        OBD_BEGIN_INDEX_RAM(0x2030, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2030, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x2030, 0x01, 0x05, 0x02, tObdUnsigned8, Write_Only, 0x00)
            OBD_SUBINDEX_RAM_VAR(0x2030, 0x02, 0x05, 0x01, tObdUnsigned8, Read_Only, 0x77)
        OBD_END_INDEX(0x2030)

        // 0x2040..0x2043 SRDO data (mappable)
        OBD_BEGIN_INDEX_RAM(0x2040, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2040, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x2040, 0x01, 0x05, 0x0B, tObdUnsigned8, Safe_Out, 0x00)
        OBD_END_INDEX(0x2040)
        OBD_BEGIN_INDEX_RAM(0x2041, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2041, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x2041, 0x01, 0x05, 0x0B, tObdUnsigned8, Safe_Out_Inv, 0xFF)
        OBD_END_INDEX(0x2041)
        OBD_BEGIN_INDEX_RAM(0x2042, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2042, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x2042, 0x01, 0x05, 0x0B, tObdUnsigned8, Safe_In, 0x00)
        OBD_END_INDEX(0x2042)
        OBD_BEGIN_INDEX_RAM(0x2043, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2043, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_VAR(0x2043, 0x01, 0x05, 0x0B, tObdUnsigned8, Safe_In_Inv, 0xFF)
        OBD_END_INDEX(0x2043)

    OBD_END_PART ()

    // the device part is empty
    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
