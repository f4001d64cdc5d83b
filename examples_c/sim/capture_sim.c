/*
 * capture_sim.c - captures of the simulated bus (host builds): a pcap file
 * of SocketCAN frames for Wireshark / tshark and a "candump -l" log for
 * can-utils' canplayer. See cdrv_sim.h (SimCapture) for the use.
 *
 * Formats written here:
 *  - pcap (tcpdump.org "pcap file format"): a 24-byte file header (magic
 *    0xA1B2C3D4 = microsecond timestamps, version 2.4, link type 227
 *    LINKTYPE_CAN_SOCKETCAN), then per frame a 16-byte record header
 *    (seconds, microseconds, captured and original length) and the 16
 *    bytes of a Linux struct can_frame: the identifier word in network
 *    byte order with CAN_EFF_FLAG (0x80000000) for 29-bit identifiers and
 *    CAN_RTR_FLAG (0x40000000) for remote frames, the length, three zero
 *    bytes, eight data bytes. Header fields are written little-endian,
 *    whatever the host, so the files are the same on every machine.
 *  - candump -l: "(1700000000.000100) can0 101#0102FEFD", 3 or 8 hex
 *    digits of identifier, "#R<len>" for a remote frame; the interface
 *    names the bus (can0, can1, ... as SimSetBus chose).
 *
 * With several buses the pcap file holds the frames of all of them (a
 * SocketCAN record has no interface field); the candump log tells them
 * apart.
 *
 * Timestamps are the simulated clock: tick 0 of the first scenario is
 * 1700000000 s, one tick is 100 us, and the capture clock only moves
 * forward (a wrap of the 32-bit tick counter, or SimReset, continues from
 * the last frame).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cdrv_sim.h"
#include "capture_sim.h"

#define CAPTURE_EPOCH_S      1700000000UL
#define CAPTURE_LINKTYPE     227UL          /* LINKTYPE_CAN_SOCKETCAN */
#define CAPTURE_RECORD       16UL           /* struct can_frame */
#define CAPTURE_EFF_FLAG     0x80000000UL   /* CAN_EFF_FLAG */
#define CAPTURE_RTR_FLAG     0x40000000UL   /* CAN_RTR_FLAG */

static FILE*              pPcap_g;
static FILE*              pCandump_g;
static int                fEnvChecked_g;
static int                fHaveLast_g;
static DWORD              dwLastTick_g;
static unsigned long long ullElapsedTicks_g;

static void PutLe32 (BYTE* pb_p, unsigned long dw_p)
{
    pb_p[0] = (BYTE) (dw_p & 0xFFUL);
    pb_p[1] = (BYTE) ((dw_p >> 8) & 0xFFUL);
    pb_p[2] = (BYTE) ((dw_p >> 16) & 0xFFUL);
    pb_p[3] = (BYTE) ((dw_p >> 24) & 0xFFUL);
}

static void CaptureClose (void)
{
    if (pPcap_g != NULL)
    {
        (void) fclose(pPcap_g);
        pPcap_g = NULL;
    }
    if (pCandump_g != NULL)
    {
        (void) fclose(pCandump_g);
        pCandump_g = NULL;
    }
}

int SimCapture (const char* pszPcap_p, const char* pszCandump_p)
{
    BYTE abHeader[24];

    CaptureClose();
    fHaveLast_g = 0;
    ullElapsedTicks_g = 0;
    if ((pszPcap_p != NULL) && (pszPcap_p[0] != '\0'))
    {
        pPcap_g = fopen(pszPcap_p, "wb");
        if (pPcap_g == NULL)
        {
            return -1;
        }
        memset(abHeader, 0, sizeof(abHeader));
        PutLe32(&abHeader[0], 0xA1B2C3D4UL);
        abHeader[4] = 2;                       /* version 2.4 */
        abHeader[6] = 4;
        PutLe32(&abHeader[16], CAPTURE_RECORD); /* snapshot length */
        PutLe32(&abHeader[20], CAPTURE_LINKTYPE);
        if (fwrite(abHeader, sizeof(abHeader), 1, pPcap_g) != 1)
        {
            CaptureClose();
            return -1;
        }
    }
    if ((pszCandump_p != NULL) && (pszCandump_p[0] != '\0'))
    {
        pCandump_g = fopen(pszCandump_p, "w");
        if (pCandump_g == NULL)
        {
            CaptureClose();
            return -1;
        }
    }
    return 0;
}

void SimCaptureAtReset (void)
{
    if (!fEnvChecked_g)
    {
        const char* pszPcap = getenv("COP_SIM_PCAP");
        const char* pszCandump = getenv("COP_SIM_CANDUMP");

        fEnvChecked_g = 1;
        if (((pszPcap != NULL) && (pszPcap[0] != '\0')) ||
            ((pszCandump != NULL) && (pszCandump[0] != '\0')))
        {
            if (SimCapture(pszPcap, pszCandump) != 0)
            {
                fprintf(stderr, "sim: capture files of COP_SIM_PCAP / COP_SIM_CANDUMP not created\n");
            }
        }
    }
    /* the clock of the new scenario starts at 0; the capture goes on */
    if (fHaveLast_g)
    {
        dwLastTick_g = 0;
    }
}

void SimCaptureFrame (CONST tSimFrame* pFrame_p)
{
    unsigned long long ullMicros;
    unsigned long dwSec;
    unsigned long dwUsec;
    unsigned long dwWord;
    BYTE abRecord[16 + CAPTURE_RECORD];
    BYTE bLen;
    BYTE i;

    if ((pPcap_g == NULL) && (pCandump_g == NULL))
    {
        return;
    }
    if (fHaveLast_g)
    {
        ullElapsedTicks_g += (DWORD) (pFrame_p->m_dwTick - dwLastTick_g);
    }
    else
    {
        ullElapsedTicks_g = pFrame_p->m_dwTick;
        fHaveLast_g = 1;
    }
    dwLastTick_g = pFrame_p->m_dwTick;
    ullMicros = ullElapsedTicks_g * 100ULL + pFrame_p->m_wSubTickUs;
    dwSec = CAPTURE_EPOCH_S + (unsigned long) (ullMicros / 1000000ULL);
    dwUsec = (unsigned long) (ullMicros % 1000000ULL);
    bLen = (pFrame_p->m_bDlc > 8) ? 8 : pFrame_p->m_bDlc;

    if (pPcap_g != NULL)
    {
        memset(abRecord, 0, sizeof(abRecord));
        PutLe32(&abRecord[0], dwSec);
        PutLe32(&abRecord[4], dwUsec);
        PutLe32(&abRecord[8], CAPTURE_RECORD);
        PutLe32(&abRecord[12], CAPTURE_RECORD);
        dwWord = (unsigned long) (pFrame_p->m_dwId & 0x1FFFFFFFUL);
        if ((pFrame_p->m_dwId & (DWORD) CAN_FRAME_FORMAT_MASK) != 0)
        {
            dwWord |= CAPTURE_EFF_FLAG;
        }
        if (pFrame_p->m_bRtr)
        {
            dwWord |= CAPTURE_RTR_FLAG;
        }
        abRecord[16] = (BYTE) ((dwWord >> 24) & 0xFFUL);   /* network byte order */
        abRecord[17] = (BYTE) ((dwWord >> 16) & 0xFFUL);
        abRecord[18] = (BYTE) ((dwWord >> 8) & 0xFFUL);
        abRecord[19] = (BYTE) (dwWord & 0xFFUL);
        abRecord[20] = bLen;
        if (!pFrame_p->m_bRtr)
        {
            memcpy(&abRecord[24], pFrame_p->m_abData, bLen);
        }
        if (fwrite(abRecord, sizeof(abRecord), 1, pPcap_g) != 1)
        {
            fprintf(stderr, "sim: pcap capture stopped (write failed)\n");
            (void) fclose(pPcap_g);
            pPcap_g = NULL;
        }
        else
        {
            (void) fflush(pPcap_g);
        }
    }
    if (pCandump_g != NULL)
    {
        if ((pFrame_p->m_dwId & (DWORD) CAN_FRAME_FORMAT_MASK) != 0)
        {
            fprintf(pCandump_g, "(%lu.%06lu) can%u %08lX#", dwSec, dwUsec, (unsigned) pFrame_p->m_bBus,
                    (unsigned long) (pFrame_p->m_dwId & 0x1FFFFFFFUL));
        }
        else
        {
            fprintf(pCandump_g, "(%lu.%06lu) can%u %03lX#", dwSec, dwUsec, (unsigned) pFrame_p->m_bBus,
                    (unsigned long) (pFrame_p->m_dwId & 0x7FFUL));
        }
        if (pFrame_p->m_bRtr)
        {
            fprintf(pCandump_g, "R%u", (unsigned) bLen);
        }
        else
        {
            for (i = 0; i < bLen; i++)
            {
                fprintf(pCandump_g, "%02X", (unsigned) pFrame_p->m_abData[i]);
            }
        }
        fputc('\n', pCandump_g);
        (void) fflush(pCandump_g);
    }
}
