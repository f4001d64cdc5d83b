/*
 * nogfc_call.c - must NOT compile with c_tests/cfg_nogfc (-Werror): with
 * SRDO_USE_GFC FALSE cop.h declares no CcmSendGfc (manual 2.8.3, 2.4).
 */
#include "cop.h"

tCopKernel CallGfc (void);
tCopKernel CallGfc (void)
{
    return CcmSendGfc();
}
