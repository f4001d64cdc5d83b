/* string.h of the freestanding target C library (examples_c/target/libc). */
#ifndef COP_TARGET_STRING_H
#define COP_TARGET_STRING_H
#include <stddef.h>
void* memcpy (void* pDst_p, const void* pSrc_p, size_t uLen_p);
void* memmove (void* pDst_p, const void* pSrc_p, size_t uLen_p);
void* memset (void* pDst_p, int iValue_p, size_t uLen_p);
int memcmp (const void* pA_p, const void* pB_p, size_t uLen_p);
size_t strlen (const char* psz_p);
int strcmp (const char* pszA_p, const char* pszB_p);
int strncmp (const char* pszA_p, const char* pszB_p, size_t uLen_p);
char* strcpy (char* pszDst_p, const char* pszSrc_p);
char* strchr (const char* psz_p, int c_p);
#endif
