/*
 * R4000/FixedPtr.h - build a pointer value from a fixed 32-bit address
 * (used for well-known object identifiers). Host version: the 32-bit value is
 * zero-extended into a pointer-sized integer first.
 */
#ifndef _FixedPtr_h_DEFINED
#define _FixedPtr_h_DEFINED

#define OPENR_FIXED_PTR(addr) ((void*)(unsigned long)(unsigned int)(addr))

#endif /* _FixedPtr_h_DEFINED */
