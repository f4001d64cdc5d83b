/*
 * static_mapping_api.c - compile-only check (c_tests/cfg_static): with
 * SRDO_USE_STATIC_MAPPING the prototype of CcmStaticDefineSrdoVarFields is
 * visible, without SRDO_USE_GFC the one of CcmSendGfc is not, and the
 * link-time signature names the static mappings and the 29-bit identifiers.
 */
#include "cop.h"
#include "cop_config.h"

/* The signature macro expands to exactly this name (the member access
 * below does not compile otherwise). */
struct tSignatureName { int COP_ABI_SIGNATURE; };
int SignatureName (struct tSignatureName* p);
int SignatureName (struct tSignatureName* p)
{
    return p->CopLibAbi_os2_gr8_sm1_pm1_ts0_id29_pe8_ch8;
}

static BYTE abNormal_g[8];
static BYTE abInverted_g[8];

tCopKernel StaticMappingApi (void);
tCopKernel StaticMappingApi (void)
{
    _Static_assert(sizeof(tCanId) == 4, "CAN20B: tCanId is a DWORD");
    _Static_assert(sizeof(tObdSize) == 2, "OBD_OBJ_SIZE_MIDDLE: tObdSize is a WORD");
    _Static_assert(sizeof(tCdrvMsg) == 16, "tCdrvMsg with a DWORD identifier");
#if defined(COP_CFG_SRDO_USE_GFC)
#error "CcmSendGfc must not be declared without SRDO_USE_GFC"
#endif
    return CcmStaticDefineSrdoVarFields(0x1301, abNormal_g, abInverted_g);
}
