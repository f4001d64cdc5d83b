/* stdio.h of the freestanding target C library (examples_c/target/libc):
 * formatted output to the Linux standard output of qemu-armeb. */
#ifndef COP_TARGET_STDIO_H
#define COP_TARGET_STDIO_H
#include <stdarg.h>
#include <stddef.h>

typedef struct TgtFile FILE;
extern FILE* const stdout;
extern FILE* const stderr;
#define EOF (-1)

int printf (const char* pszFormat_p, ...) __attribute__((format(printf, 1, 2)));
int fprintf (FILE* pFile_p, const char* pszFormat_p, ...) __attribute__((format(printf, 2, 3)));
int sprintf (char* pszOut_p, const char* pszFormat_p, ...) __attribute__((format(printf, 2, 3)));
int snprintf (char* pszOut_p, size_t uSize_p, const char* pszFormat_p, ...) __attribute__((format(printf, 3, 4)));
int vprintf (const char* pszFormat_p, va_list Args_p);
int vfprintf (FILE* pFile_p, const char* pszFormat_p, va_list Args_p);
int vsnprintf (char* pszOut_p, size_t uSize_p, const char* pszFormat_p, va_list Args_p);
int puts (const char* psz_p);
int putchar (int c_p);
int fputs (const char* psz_p, FILE* pFile_p);
int fflush (FILE* pFile_p);
#endif
