// objdict.h - object dictionary of the I/O node (CiA 401 style): 8 digital
// inputs (0x6000), 8 digital outputs (0x6200), 2 analog inputs (0x6401).
// The I/O values live in the application's arrays (main.c), the dictionary
// points at them (EXTARRAY).

#define OBD_DEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_DEFINE_MACRO

OBD_BEGIN ()

    OBD_BEGIN_PART_GENERIC ()

        OBD_BEGIN_INDEX_ROM(0x1000, 0x01, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1000, 0x00, 0x07, 0x01, tObdUnsigned32, Device_Type, 0x000F0191)
        OBD_END_INDEX(0x1000)

        OBD_BEGIN_INDEX_RAM(0x1001, 0x01, NULL)
            OBD_SUBINDEX_RAM_VAR(0x1001, 0x00, 0x05, 0x01, tObdUnsigned8, Error_Register, 0x00)
        OBD_END_INDEX(0x1001)

        OBD_BEGIN_INDEX_ROM(0x1008, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x1008, 0x00, 0x01, Manufacturer_Device_Name, "cop io-node")
        OBD_END_INDEX(0x1008)

        OBD_BEGIN_INDEX_ROM(0x1009, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x1009, 0x00, 0x01, Manufacturer_Hardware_Version, "1.0")
        OBD_END_INDEX(0x1009)

        OBD_BEGIN_INDEX_ROM(0x100A, 0x01, NULL)
            OBD_SUBINDEX_ROM_VSTRING(0x100A, 0x00, 0x01, Manufacturer_Software_Version, DEFINED_STRING_VERSION)
        OBD_END_INDEX(0x100A)

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_BEGIN_INDEX_RAM(0x1018, 0x05, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x00, 0x05, 0x01, tObdUnsigned8, Number_of_entries, 0x4)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x01, 0x07, 0x01, tObdUnsigned32, Vendor_Id, 0x00000000)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x02, 0x07, 0x01, tObdUnsigned32, Product_Code, 0x00000401)
            OBD_SUBINDEX_ROM_VAR(0x1018, 0x03, 0x07, 0x01, tObdUnsigned32, Revision_Number, DEFINED_OBJ1018_VERSION)
            OBD_SUBINDEX_RAM_VAR(0x1018, 0x04, 0x07, 0x01, tObdUnsigned32, Serial_Number, 0x00000001)
        OBD_END_INDEX(0x1018)

        // default SDO server: COB-IDs 0x600/0x580 + node-ID
        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()
    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()

        OBD_ROM_INDEX_RAM_EXTARRAY(0x6000, 1, NULL, 0x05, 0x09, tObdUnsigned8, abDigitalInputs_g, 0x00)
        OBD_ROM_INDEX_RAM_EXTARRAY(0x6200, 1, NULL, 0x05, 0x0B, tObdUnsigned8, abDigitalOutputs_g, 0x00)
        OBD_ROM_INDEX_RAM_EXTARRAY(0x6401, 2, NULL, 0x03, 0x09, tObdInteger16, aiAnalogInputs_g, 0)

    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
