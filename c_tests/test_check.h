/*
 * test_check.h - the checks of every C test program, in either instance
 * form of the library (COP_MAX_INSTANCES 1 or more).
 *
 * Every test is a small program: it runs its checks, prints each failing one
 * with file and line, and returns 0 when all passed (TEST_DONE). A check that
 * cannot run because the library lacks a feature returns TEST_SKIP (77,
 * reported by CTest as "Skipped" with the reason printed).
 */
#ifndef TEST_CHECK_H
#define TEST_CHECK_H

#include <stdio.h>

#include "cop.h"

#define TEST_SKIP 77

extern int iTestFailures_g;

#define CHECK(cond) \
    do { if (!(cond)) { printf("%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); iTestFailures_g++; } } while (0)

#define CHECK_EQ(actual, expected) \
    do { unsigned long long a_ = (unsigned long long) (actual), e_ = (unsigned long long) (expected); \
         if (a_ != e_) { printf("%s:%d: CHECK_EQ failed: %s = 0x%llX, expected %s = 0x%llX\n", \
                                __FILE__, __LINE__, #actual, a_, #expected, e_); iTestFailures_g++; } } while (0)

/* Return code check with the names of both codes in the message. */
#define CHECK_RET(expr, expected) \
    do { tCopKernel r_ = (tCopKernel) (expr); \
         if (r_ != (tCopKernel) (expected)) { printf("%s:%d: %s returned 0x%04X (%s), expected 0x%04X (%s)\n", \
             __FILE__, __LINE__, #expr, (unsigned) r_, TestKernelName(r_), (unsigned) (expected), \
             TestKernelName((tCopKernel) (expected))); iTestFailures_g++; } } while (0)

#define TEST_DONE(name) TestDone(name)

/* Prints the result line and returns the program's exit code. */
int         TestDone (const char* pszName_p);
/* The errordef.h name of a code ("kCopSuccessful", ...). */
const char* TestKernelName (tCopKernel Ret_p);

#endif
