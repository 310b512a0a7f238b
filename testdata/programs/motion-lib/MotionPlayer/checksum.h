/*
 * checksum.h : C helpers, usable from C and C++
 */

#ifndef checksum_h_DEFINED
#define checksum_h_DEFINED

#include <Types.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Sum of n 32-bit words, wrapping around at 2^32. */
longword mtn_checksum(const slongword* words, longword n);

/* Micro-radians to whole degrees, rounded to the nearest degree. */
int mtn_udeg(slongword urad);

#ifdef __cplusplus
}
#endif

#endif /* checksum_h_DEFINED */
