// objdict_srdo_peer.h - the SRDO partner of objdict_all.h on the simulated
// bus (two-node SRDO/GFC tests, c_tests/cfg):
//
//   SRDO 1 (0x1301): receive, SCT 100 ms, SRVT 20 ms, COB-IDs 0x101/0x102
//                    (objdict_all.h's transmit SRDO), into bPeerIn_g /
//                    bPeerInInv_g; mapping subindices 3 and 4 are spare
//                    (sub 0 = 2), so a test can map up to four entries
//   SRDO 2 (0x1302): transmit, refresh time 50 ms, SRVT 20 ms, COB-IDs
//                    0x103/0x104, from bPeerOut_g / bPeerOutInv_g
//
// 0x2054 holds two 64-bit mappable objects (a mapping longer than 8 bytes);
// 0x6200 (4 x UNSIGNED8) and 0x6300 (2 x UNSIGNED16) are the objects the
// CRC vectors of SAFETY_BEHAVIOUR.md section 3 map.
// The init function is ObdInitRamSrdoPeer.

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
        OBD_CREATE_SRDO_COMMU(0x1301, 0, 2, 100, 20, 0x101, 0x102)
        OBD_CREATE_SRDO_COMMU(0x1302, 1, 1, 50, 20, 0x103, 0x104)
        OBD_BEGIN_SRDO_MAPP(0x1381, 0, 2)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x01, 0, Peer_In, 0x20500108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x02, 0, Peer_In_Inv, 0x20510108)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x03, 0, Spare_3, 0x00000000)
            OBD_SUBINDEX_SRDO_MAPP(0x1381, 0x04, 0, Spare_4, 0x00000000)
        OBD_END_SRDO_MAPP(0x1381)
        OBD_BEGIN_SRDO_MAPP(0x1382, 1, 2)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x01, 1, Peer_Out, 0x20520108)
            OBD_SUBINDEX_SRDO_MAPP(0x1382, 0x02, 1, Peer_Out_Inv, 0x20530108)
        OBD_END_SRDO_MAPP(0x1382)
        OBD_CREATE_SRDO_CFG_VALID()
        OBD_BEGIN_SRDO_CRC(2)
            OBD_SUBINDEX_SRDO_CRC(0x01, Crc_Srdo_1)
            OBD_SUBINDEX_SRDO_CRC(0x02, Crc_Srdo_2)
        OBD_END_SRDO_CRC()

    OBD_END_PART ()

    OBD_BEGIN_PART_MANUFACTURER ()

        OBD_BEGIN_INDEX_RAM(0x2050, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2050, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_EXTVAR(0x2050, 0x01, 0x05, 0x0B, tObdUnsigned8, bPeerIn_g, 0x00)
        OBD_END_INDEX(0x2050)
        OBD_BEGIN_INDEX_RAM(0x2051, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2051, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_EXTVAR(0x2051, 0x01, 0x05, 0x0B, tObdUnsigned8, bPeerInInv_g, 0xFF)
        OBD_END_INDEX(0x2051)
        OBD_BEGIN_INDEX_RAM(0x2052, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2052, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_EXTVAR(0x2052, 0x01, 0x05, 0x0B, tObdUnsigned8, bPeerOut_g, 0x00)
        OBD_END_INDEX(0x2052)
        OBD_BEGIN_INDEX_RAM(0x2053, 0x02, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2053, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x01)
            OBD_SUBINDEX_RAM_EXTVAR(0x2053, 0x01, 0x05, 0x0B, tObdUnsigned8, bPeerOutInv_g, 0xFF)
        OBD_END_INDEX(0x2053)
        OBD_BEGIN_INDEX_RAM(0x2054, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x2054, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x2054, 0x01, kObdTypUInt64, 0x0B, tObdUnsigned64, Wide_1, 0)
            OBD_SUBINDEX_RAM_VAR(0x2054, 0x02, kObdTypUInt64, 0x0B, tObdUnsigned64, Wide_2, 0)
        OBD_END_INDEX(0x2054)

    OBD_END_PART ()

    // the objects the CRC vectors of SAFETY_BEHAVIOUR.md section 3 map: a
    // mapping entry must name an object that exists (manual 2.5)
    OBD_BEGIN_PART_DEVICE ()

        OBD_BEGIN_INDEX_RAM(0x6200, 0x05, NULL)
            OBD_SUBINDEX_ROM_VAR(0x6200, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x04)
            OBD_SUBINDEX_RAM_VAR(0x6200, 0x01, 0x05, 0x0B, tObdUnsigned8, Byte_1, 0x00)
            OBD_SUBINDEX_RAM_VAR(0x6200, 0x02, 0x05, 0x0B, tObdUnsigned8, Byte_2, 0x00)
            OBD_SUBINDEX_RAM_VAR(0x6200, 0x03, 0x05, 0x0B, tObdUnsigned8, Byte_3, 0x00)
            OBD_SUBINDEX_RAM_VAR(0x6200, 0x04, 0x05, 0x0B, tObdUnsigned8, Byte_4, 0x00)
        OBD_END_INDEX(0x6200)
        OBD_BEGIN_INDEX_RAM(0x6300, 0x03, NULL)
            OBD_SUBINDEX_ROM_VAR(0x6300, 0x00, 0x05, 0x01, tObdUnsigned8, Count, 0x02)
            OBD_SUBINDEX_RAM_VAR(0x6300, 0x01, 0x06, 0x0B, tObdUnsigned16, Word_1, 0x0000)
            OBD_SUBINDEX_RAM_VAR(0x6300, 0x02, 0x06, 0x0B, tObdUnsigned16, Word_2, 0x0000)
        OBD_END_INDEX(0x6300)

    OBD_END_PART ()

OBD_END ()

#define OBD_UNDEFINE_MACRO
    #include "obdmacro.h"
#undef OBD_UNDEFINE_MACRO
