/*
 * link_mismatch_main.c - a complete small program (dictionary objdict_min.c,
 * simulated driver, this main). CTest links it against a library built with
 * a different configuration and expects the link to fail on the missing
 * configuration signature (test_abi_mismatch_fails_to_link), and against
 * the matching library, where it links (test_abi_match_links); in both
 * instance forms (test_abi_instances_*).
 */
#include <string.h>

#include "cdrv_sim.h"

tCopKernel PUBLIC ObdInitRamMin (void MEM* pInitParam_p);

/* The application arrays objdict_min.h names. */
tObdUnsigned8 abTestDigitalIn_g[1];
tObdInteger16 aiTestAnalogIn_g[2];

int main (void)
{
    tCcmInitParam InitParam;

    memset(&InitParam, 0, sizeof(InitParam));
    InitParam.m_bInitNodeId = 1;
    InitParam.m_fpObdInitRam = ObdInitRamMin;
    SimReset();
#if (COP_MAX_INSTANCES > 1)
    {
        tCopInstanceHdl Handle;
        return (CcmInitCANopen(&Handle, &InitParam, kCcmFirstInstance) == kCopSuccessful) ? 0 : 1;
    }
#else
    return (CcmInitCANopen(&InitParam, kCcmFirstInstance) == kCopSuccessful) ? 0 : 1;
#endif
}
