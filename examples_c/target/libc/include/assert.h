/* assert.h of the freestanding target C library (examples_c/target/libc). */
#ifndef COP_TARGET_ASSERT_H
#define COP_TARGET_ASSERT_H
void TgtAssertFailed (const char* pszExpr_p, const char* pszFile_p, int iLine_p) __attribute__((noreturn));
#define assert(e) ((e) ? (void) 0 : TgtAssertFailed(#e, __FILE__, __LINE__))
#endif
