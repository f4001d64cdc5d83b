/*
 * objdict_srdo_peer.c - objdict_srdo_peer.h as tables (ObdInitRamSrdoPeer),
 * a second SRDO dictionary next to objdict_all.c in one program.
 */
#define OBD_INIT_RAM_NAME ObdInitRamSrdoPeer
#define OBD_OBJDICT_FILE  "objdict_srdo_peer.h"
#include "objdef.h"

/* the variables objdict_srdo_peer.h maps */
tObdUnsigned8 bPeerIn_g;
tObdUnsigned8 bPeerInInv_g;
tObdUnsigned8 bPeerOut_g;
tObdUnsigned8 bPeerOutInv_g;
