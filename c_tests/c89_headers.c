/*
 * c89_headers.c - every header an application includes, and the names of
 * the SYS TEC modules it uses (COB layer, NMT master view, ami.h, PRINTFn,
 * COP_MEM*), compiled as C89 in the C stage: with -std=gnu89 -Werror and
 * with -std=c89 -pedantic, where the only diagnostics allowed are the three
 * extensions the README names (// comments, long long, variadic macros).
 */
#include "copinc.h"
#include "ccmmain.h"
#include "ami.h"
#include "cob.h"
#include "nmtm.h"
#include "ccmdyn.h"
#include "sdoac.h"
#include "srdo.h"
#include "global_cop.h"
#include "target_cop.h"
#include "cdrvinc.h"

int main (void)
{
    tCobParam      CobParam;
    tNmtmSlaveInfo Info;
    BYTE           abData[4];

    AmiSetWord(abData, 0x1234);
    AmiSetByte(abData, 0x56);
    COP_MEMSET(&CobParam, 0, sizeof(CobParam));
    COP_MEMCPY(&Info, abData, sizeof(Info));
    CobParam.m_CobHdl = kCobHdlRxTable | 0;
    PRINTF2("%u %u\n", (unsigned) AmiGetByte(abData), (unsigned) (Info.m_bSlaveState & kNmtmStateToggleBit));
    return (int) CcmCobGetParam(&CobParam);
}
