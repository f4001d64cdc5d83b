/*
 * srdo_crc.c - the safety configuration checksum (object 0x13FF) as a
 * configuration tool computes it, independent of the node's stack:
 * CRC-16/XMODEM (polynomial 0x1021, initial value 0, no reflection, no
 * final XOR) over direction (1 byte), SCT (2), SRVT (1), COB-ID 1 (4),
 * COB-ID 2 (4), number of mapping entries (1), then per entry its
 * subindex (1) and the entry (4); multi-byte fields little-endian whatever
 * the CPU (SAFETY_BEHAVIOUR.md section 3). The transmission type is not
 * part of it.
 */
#include "configurator.h"

static WORD CrcAdd (WORD wCrc_p, BYTE bData_p)
{
    int iBit;

    wCrc_p ^= (WORD) (bData_p << 8);
    for (iBit = 0; iBit < 8; iBit++)
    {
        wCrc_p = (WORD) ((wCrc_p & 0x8000) ? ((wCrc_p << 1) ^ 0x1021) : (wCrc_p << 1));
    }
    return wCrc_p;
}

static WORD CrcAddLe (WORD wCrc_p, DWORD dwValue_p, unsigned uBytes_p)
{
    unsigned i;

    for (i = 0; i < uBytes_p; i++)
    {
        wCrc_p = CrcAdd(wCrc_p, (BYTE) (dwValue_p >> (8 * i)));
    }
    return wCrc_p;
}

WORD CfgSrdoCrc (const tSrdoConfig* pConfig_p)
{
    WORD wCrc = 0;
    BYTE i;

    wCrc = CrcAddLe(wCrc, pConfig_p->m_bDirection, 1);
    wCrc = CrcAddLe(wCrc, pConfig_p->m_wSctMs, 2);
    wCrc = CrcAddLe(wCrc, pConfig_p->m_bSrvtMs, 1);
    wCrc = CrcAddLe(wCrc, pConfig_p->m_dwCobId1, 4);
    wCrc = CrcAddLe(wCrc, pConfig_p->m_dwCobId2, 4);
    wCrc = CrcAddLe(wCrc, pConfig_p->m_bMappCount, 1);
    for (i = 0; i < pConfig_p->m_bMappCount; i++)
    {
        wCrc = CrcAddLe(wCrc, (DWORD) (i + 1), 1);
        wCrc = CrcAddLe(wCrc, pConfig_p->m_adwMapp[i], 4);
    }
    return wCrc;
}
