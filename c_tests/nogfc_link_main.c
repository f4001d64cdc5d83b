/*
 * nogfc_link_main.c - must NOT link against the cop_nogfc library: even with
 * its own prototypes the program finds no CcmSendGfc / SrdoSendGfc in a
 * library built with SRDO_USE_GFC FALSE.
 */
#include "cop.h"

tCopKernel CcmSendGfc (void);
tCopKernel SrdoSendGfc (void);

int main (void)
{
    return (int) (CcmSendGfc() + SrdoSendGfc());
}
