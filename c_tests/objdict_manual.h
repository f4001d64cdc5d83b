// objdict_manual.h - dictionary of the receiving safety node that the
// application code of manual 2.9 (test_manual_app.c) runs on; static SRDO
// mapping (c_tests/cfg_manual).
//
// SRDO 1 (0x1301): factory direction 0; AppCbNmtEvent writes direction 2
// (receive) as in manual 2.9.5. SCT 25 ms, SRVT 20 ms, COB-IDs 0x101/0x102.
// Static mapping (manual 2.6, figure 7): normal data 0x2000/1, 0x2000/2,
// inverted data 0x2100/1, 0x2100/2, one byte each. The four objects are
// USERDEF: the application attaches them to its two variable fields
// SrdoNormalData / SrdoInversData with CcmDefineVarTab.
// The CRC default 0x3074 is what a configuration tool computes for the
// configuration the application completes (direction 2): CRC-16/XMODEM over
// 02 19 00 14 01 01 00 00 02 01 00 00 04 01 08 01 00 20 02 08 01 00 21
// 03 08 02 00 20 04 08 02 00 21 (SAFETY_BEHAVIOUR.md section 3).

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

        OBD_BEGIN_INDEX_RAM(0x1017, 0x01, HbpCbConfigHeartbeat)
            OBD_SUBINDEX_RAM_VAR(0x1017, 0x00, 0x06, 0x83, tObdUnsigned16, Producer_Heartbeat_Time, 0x0)
        OBD_END_INDEX(0x1017)

        OBD_CREATE_SDOS(0x1200, 0, 0x600, 0x580, 0x00)

        OBD_CREATE_SRDO_GFC_PARAM()
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 0, 25, 20, 0x101, 0x102)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 4)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Normal_Dig_1, 0x20000108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Invers_Dig_1, 0x21000108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x03, 0, Normal_Dig_2, 0x20000208)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x04, 0, Invers_Dig_2, 0x21000208)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(1)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1, 0x3074)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2000, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2000, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_USERDEF(0x2000, 0x01, 0x05, 0x0B, tObdUnsigned8, Normal_Dig_1, 0x00)
            OBD_SUBINDEX_RAM_USERDEF(0x2000, 0x02, 0x05, 0x0B, tObdUnsigned8, Normal_Dig_2, 0x00)
        OBD_END_INDEX(0x2000)

        OBD_BEGIN_INDEX_RAM(0x2100, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2100, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_USERDEF(0x2100, 0x01, 0x05, 0x0B, tObdUnsigned8, Invers_Dig_1, 0xFF)
            OBD_SUBINDEX_RAM_USERDEF(0x2100, 0x02, 0x05, 0x0B, tObdUnsigned8, Invers_Dig_2, 0xFF)
        OBD_END_INDEX(0x2100)

    OBD_END_PART ()

    OBD_BEGIN_PART_DEVICE ()
    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
