/*
 * ionode.c - the I/O node (node-ID 2) of examples_c/io_node, here as one of
 * three nodes: its dictionary is examples_c/io_node/objdict.h unchanged
 * (objdict_ionode.c); the application is the same - inputs into the
 * arrays the dictionary points at, outputs from them.
 */
#include "configurator.h"

/* I/O image the dictionary points at (../io_node/objdict.h, EXTARRAY). */
tObdUnsigned8 abDigitalInputs_g[1];
tObdUnsigned8 abDigitalOutputs_g[1];
tObdInteger16 aiAnalogInputs_g[2];

static BYTE bOutputsApplied_g;

tCopKernel PUBLIC IoNodeNmtEvent (tNmtEvent NmtEvent_p)
{
    switch (NmtEvent_p)
    {
        case kNmtEvResetCommunication:
            return CcmConfigEmcp(0x80 + ID_IO_NODE);

        case kNmtEvEnterPreOperational:
        case kNmtEvEnterStopped:
            abDigitalOutputs_g[0] = 0;
            break;

        default:
            break;
    }
    return kCopSuccessful;
}

/* The board's I/O: read inputs, apply outputs. */
void IoNodeCycle (void)
{
    abDigitalInputs_g[0] = 0x01;        /* input 1 high */
    aiAnalogInputs_g[0] = 0x1234;       /* analog input 1 */
    aiAnalogInputs_g[1] = -1;
    if (abDigitalOutputs_g[0] != bOutputsApplied_g)
    {
        bOutputsApplied_g = abDigitalOutputs_g[0];
        Log("I/O node", "digital outputs now 0x%02X", (unsigned) bOutputsApplied_g);
    }
}
