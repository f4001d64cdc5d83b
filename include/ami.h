/*
 * ami.h - values of a given width at any address, in CANopen byte order
 * (little-endian, CiA 301 7.1.2), independent of the target's byte order and
 * alignment. Names and parameter types are those of the SYS TEC ami.h; the
 * functions are in the library (src/ffi/ami.rs), which is why they are
 * declared here by hand and not in the generated cop.h. NULL addresses are
 * ignored (Set) or read as 0 (Get).
 *
 * AmiSetByte / AmiGetByte are macros as in the original; AmiSetByte is a
 * braced block, so it is a statement (not usable before an `else` without
 * braces around it, as in the original).
 */
#ifndef COP_AMI_H
#define COP_AMI_H

#include "cop_types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define AmiSetByte(pAddr_p, bByteVal_p) { *(BYTE FAR*) (pAddr_p) = (BYTE) (bByteVal_p); }
#define AmiGetByte(pAddr_p) (*(BYTE FAR*) (pAddr_p))

void  PUBLIC AmiSetWord (void FAR* pAddr_p, WORD wWordVal_p);
void  PUBLIC AmiSetDword (void FAR* pAddr_p, DWORD dwDwordVal_p);
WORD  PUBLIC AmiGetWord (void FAR* pAddr_p);
DWORD PUBLIC AmiGetDword (void FAR* pAddr_p);
void  PUBLIC AmiSetDword24 (void FAR* pAddr_p, DWORD dwDwordVal_p);
DWORD PUBLIC AmiGetDword24 (void FAR* pAddr_p);

#ifdef QWORD
void  PUBLIC AmiSetQword40 (void FAR* pAddr_p, QWORD qwQwordVal_p);
QWORD PUBLIC AmiGetQword40 (void FAR* pAddr_p);
void  PUBLIC AmiSetQword48 (void FAR* pAddr_p, QWORD qwQwordVal_p);
QWORD PUBLIC AmiGetQword48 (void FAR* pAddr_p);
void  PUBLIC AmiSetQword56 (void FAR* pAddr_p, QWORD qwQwordVal_p);
QWORD PUBLIC AmiGetQword56 (void FAR* pAddr_p);
void  PUBLIC AmiSetQword64 (void FAR* pAddr_p, QWORD qwQwordVal_p);
QWORD PUBLIC AmiGetQword64 (void FAR* pAddr_p);
#endif

#ifdef __cplusplus
}
#endif

#endif /* COP_AMI_H */
