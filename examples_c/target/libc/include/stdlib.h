/* stdlib.h of the freestanding target C library (examples_c/target/libc):
 * a fixed heap for the simulated bus and dictionary builders (the stack
 * itself allocates nothing), exit and abort. */
#ifndef COP_TARGET_STDLIB_H
#define COP_TARGET_STDLIB_H
#include <stddef.h>
#define EXIT_SUCCESS 0
#define EXIT_FAILURE 1
void* malloc (size_t uSize_p);
void* calloc (size_t uCount_p, size_t uSize_p);
void free (void* p_p);
void exit (int iCode_p) __attribute__((noreturn));
void abort (void) __attribute__((noreturn));
int abs (int i_p);
#endif
