/*
 * capture_sim.h - the simulated bus's captures (host builds only; the
 * TMS570 target programs build cdrv_sim.c without them). The bus calls
 * these when cdrv_sim.c is compiled with SIM_CAPTURE defined to 1 (the
 * CMake function cop_add_sim does so); applications use SimCapture of
 * cdrv_sim.h.
 */
#ifndef CAPTURE_SIM_H
#define CAPTURE_SIM_H

#include "cdrv_sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* SimReset: at the first call, opens the files the environment names
 * (COP_SIM_PCAP, COP_SIM_CANDUMP); the capture clock goes on. */
void SimCaptureAtReset (void);

/* A frame that reached the bus (after the fault hooks). */
void SimCaptureFrame (CONST tSimFrame* pFrame_p);

#ifdef __cplusplus
}
#endif

#endif /* CAPTURE_SIM_H */
