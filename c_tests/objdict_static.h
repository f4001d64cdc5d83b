// objdict_static.h - static SRDO mapping test dictionary (c_tests/cfg_manual,
// test_srdo_static.c). The mapped objects are application arrays
// (EXTARRAY), so each SRDO's normal and inverted data are contiguous
// variable fields, as CcmStaticDefineSrdoVarFields wants them.
//
//   SRDO 1 (0x1301): receive, SCT 50 ms, SRVT 20 ms, 0x101/0x102;
//                    normal data abStaticNormal_g[0..1], inverted
//                    abStaticInverted_g[0..1]
//   SRDO 2 (0x1302): off; its mapping holds 16 bytes of normal data
//                    (two 64-bit objects) - more than an SRDO can carry

#define OBD_DEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_DEFINE_MACRO

OBD_BEGIN ()

    OBD_BEGIN_PART_GENERIC ()

        OBD_BEGIN_INDEX_ROM(0x1000, 0x01, NULL)
            OBD_SUBINDEX_ROM_VAR(0x1000, 0x00, 0x07, 0x01, tObdUnsigned32, Device_Type, 0x00000000)
        OBD_END_INDEX(0x1000)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 2, 50, 20, 0x101, 0x102)
        OBD_CREATE_SRDO_COMMU(0x1302, 1, 0, 50, 20, 0x103, 0x104)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 4)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Normal_1, 0x20000108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Inverted_1, 0x21000108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x03, 0, Normal_2, 0x20000208)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x04, 0, Inverted_2, 0x21000208)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_BEGIN_SRDO_MAPP(0x1382, 1, 4)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x01, 1, Wide_Normal_1, 0x22000140)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x02, 1, Wide_Inverted_1, 0x22010140)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x03, 1, Wide_Normal_2, 0x22000240)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x04, 1, Wide_Inverted_2, 0x22010240)
        OBD_END_SRDO_MAPP(0x1382)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(2)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
            OBD_SUBINDEX_SRDO_CRC(0x02, Crc_Srdo_2)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_ROM_INDEX_RAM_EXTARRAY(0x2000, 2, NULL, 0x05, 0x0B, tObdUnsigned8, abStaticNormal_g, 0x00)
        OBD_ROM_INDEX_RAM_EXTARRAY(0x2100, 2, NULL, 0x05, 0x0B, tObdUnsigned8, abStaticInverted_g, 0xFF)
        OBD_ROM_INDEX_RAM_EXTARRAY(0x2200, 2, NULL, kObdTypUInt64, 0x0B, tObdUnsigned64, aqwWideNormal_g, 0)
        OBD_ROM_INDEX_RAM_EXTARRAY(0x2201, 2, NULL, kObdTypUInt64, 0x0B, tObdUnsigned64, aqwWideInverted_g, 0)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
