/*
 * halcogen_stub.h - declarations of the HALCoGen driver functions that
 * cdrv_dcan.c calls, with the parameter types of HALCoGen's can.h and
 * rti.h, so that the sketch compiles here without TI's files. In a
 * firmware project include HALCoGen's own "can.h" and "rti.h" instead.
 */
#ifndef HALCOGEN_STUB_H
#define HALCOGEN_STUB_H

typedef unsigned char uint8;
typedef unsigned int  uint32;

typedef struct canBase canBASE_t;   /* DCAN register block (reg_can.h) */
extern canBASE_t* const canREG1_stub;
#define canREG1 canREG1_stub

/* can.h: message boxes 1..64 as configured in the HALCoGen GUI */
void   canInit (void);
uint32 canTransmit (canBASE_t* node, uint32 messageBox, const uint8* data);
uint32 canGetData (canBASE_t* node, uint32 messageBox, uint8* const data);
uint32 canIsTxMessagePending (canBASE_t* node, uint32 messageBox);
void   canUpdateID (canBASE_t* node, uint32 messageBox, uint32 msgBoxArbitVal);
uint32 canGetID (canBASE_t* node, uint32 messageBox);
uint32 canIsBusOff (canBASE_t* node);
void   canEnableErrorNotification (canBASE_t* node);
/* called by HALCoGen's CAN interrupt handler, defined by the application */
void   canMessageNotification (canBASE_t* node, uint32 messageBox);

/* rti.h */
#define rtiCOUNTER_BLOCK0   0U
#define rtiCOMPARE0         0U
#define rtiNOTIFICATION_COMPARE0 1U
void   rtiInit (void);
void   rtiStartCounter (uint32 counter);
void   rtiEnableNotification (uint32 notification);
/* called by HALCoGen's RTI interrupt handler, defined by the application */
void   rtiNotification (uint32 notification);

/* sys_core.h */
void   _enable_IRQ (void);
#endif
