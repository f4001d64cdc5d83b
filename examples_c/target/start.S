/*
 * start.S - start-up of the target programs (ARM mode, Cortex-R4F).
 *
 * Under qemu-armeb (Linux user mode) the kernel has set up the stack and
 * enabled the VFP; _start calls main and passes its result to exit. On a
 * TMS570 the vendor start-up (HALCoGen sys_startup.c) takes this place:
 * it sets the stack pointers of the processor modes, enables the VFP in
 * CPACR/FPEXC, zeroes .bss, copies .data and calls main.
 *
 * TgtWrite and TgtExit are the Linux system calls write (4) and
 * exit_group (248) through "svc 0" with the number in r7 (EABI).
 */
    .syntax unified
    .arm
    .text

    .global _start
    .type   _start, %function
_start:
    mov     fp, #0
    mov     lr, #0
    bic     sp, sp, #7          /* AAPCS: 8-byte aligned stack at calls */
    bl      main
    bl      exit
    .size   _start, . - _start

    .global TgtWrite
    .type   TgtWrite, %function
TgtWrite:                       /* int TgtWrite (int fd, const void* p, size_t n) */
    push    {r7, lr}
    mov     r7, #4
    svc     #0
    pop     {r7, pc}
    .size   TgtWrite, . - TgtWrite

    .global TgtExit
    .type   TgtExit, %function
TgtExit:                        /* void TgtExit (int code) */
    mov     r7, #248
    svc     #0
    mov     r7, #1
    svc     #0
1:  b       1b
    .size   TgtExit, . - TgtExit

    .section .note.GNU-stack, "", %progbits
