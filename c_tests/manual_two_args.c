/*
 * manual_two_args.c - must NOT compile: the manual's example call
 * CcmGetSrdoParam (0x1301, &SrdoCommuParam) (section 2.9.5) has two
 * arguments, the prototype (manual 2.8.6, SYSTEC_API.md section 3) three.
 */
#include "cop.h"

tSrdoCommuParam SrdoCommuParam;

tCopKernel ManualTwoArguments (void);
tCopKernel ManualTwoArguments (void)
{
    return CcmGetSrdoParam(0x1301, &SrdoCommuParam);
}
