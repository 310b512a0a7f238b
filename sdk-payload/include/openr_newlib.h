/*
 * openr_newlib.h - the C library a unit including any OPEN-R header saw on the robot.
 *
 * The OPEN-R toolchain's C library was newlib, and gcc 3.3's libstdc++ (reached through
 * <iostream> in the SDK headers) pulled in <cmath>, <cstdlib>, <cctype>, <cerrno> ...
 * Code of that era calls sin/sqrt/M_PI, printf, malloc, strcpy, stricmp, strlwr ...
 * with none of the C headers included. Types.h includes this header, so every OPEN-R
 * header makes that surface visible (object-model 5.5):
 *
 *  1. the C headers themselves: <stdio.h> <stdlib.h> <string.h> <strings.h> <ctype.h>
 *     <math.h> <stdarg.h> <limits.h> <errno.h>;
 *  2. what newlib's headers declared and glibc lacks, declared here with C linkage and
 *     defined in libOPENR (one archive member per function, so a program defining one
 *     of them itself still links):
 *       string.h  strlwr strupr, strlcpy strlcat (glibc < 2.38), and newlib's macros
 *                 strcmpi stricmp (= strcasecmp), strncmpi strnicmp (= strncasecmp);
 *       stdlib.h  atoff ecvtf fcvtf gcvtf ecvtbuf fcvtbuf cfree;
 *       math.h    the M_* constants glibc does not define (M_TWOPI, M_3PI_4 ...).
 *     Everything else newlib's extensions had (strdup strndup strsep strtok_r bzero
 *     bcopy bcmp index rindex memccpy mempcpy strnlen strcasecmp strncasecmp ffs;
 *     drand48 rand_r ecvt fcvt gcvt on_exit; finite isnanf isinff finitef sincos
 *     hypot cbrt rint ...) glibc declares too: g++ defines _GNU_SOURCE.
 *     Not provided: itoa/utoa (newlib added them only in 2014), newlib's nan(void) and
 *     infinity() (they would collide with C99's nan(const char*)).
 * Usable from C and C++. Nothing here defines a MIPS marker.
 */
#ifndef _openr_newlib_h_DEFINED
#define _openr_newlib_h_DEFINED

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <limits.h>
#include <errno.h>

#ifdef __cplusplus
extern "C" {
#endif

/* newlib <string.h> */
char* strlwr(char* s);
char* strupr(char* s);

#if defined(__GLIBC__) && !__GLIBC_PREREQ(2, 38)
size_t strlcpy(char* dst, const char* src, size_t size);
size_t strlcat(char* dst, const char* src, size_t size);
#endif

/* newlib <stdlib.h> */
float atoff(const char* s);
char* ecvtf(float value, int ndigit, int* decpt, int* sign);
char* fcvtf(float value, int ndigit, int* decpt, int* sign);
char* gcvtf(float value, int ndigit, char* buf);
char* ecvtbuf(double value, int ndigit, int* decpt, int* sign, char* buf);
char* fcvtbuf(double value, int ndigit, int* decpt, int* sign, char* buf);
#if defined(__GLIBC__) && __GLIBC_PREREQ(2, 26)
void cfree(void* p);     /* glibc dropped it in 2.26 */
#endif

#ifdef __cplusplus
} /* extern "C" */
#endif

/* newlib <string.h>: the Windows names, as macros like newlib's (so a program's own
   definition of one becomes a definition of strcasecmp, as it did on the robot). */
#ifndef strcmpi
#define strcmpi strcasecmp
#endif
#ifndef stricmp
#define stricmp strcasecmp
#endif
#ifndef strncmpi
#define strncmpi strncasecmp
#endif
#ifndef strnicmp
#define strnicmp strncasecmp
#endif

/* newlib <math.h> constants that glibc lacks (glibc has M_E ... M_SQRT1_2). */
#ifndef M_TWOPI
#define M_TWOPI   (M_PI * 2.0)
#endif
#ifndef M_3PI_4
#define M_3PI_4   2.3561944901923448370E0
#endif
#ifndef M_SQRTPI
#define M_SQRTPI  1.77245385090551602792981
#endif
#ifndef M_LN2LO
#define M_LN2LO   1.9082149292705877000E-10
#endif
#ifndef M_LN2HI
#define M_LN2HI   6.9314718036912381649E-1
#endif
#ifndef M_SQRT3
#define M_SQRT3   1.73205080756887719000
#endif
#ifndef M_IVLN10
#define M_IVLN10  0.43429448190325182765   /* 1 / ln(10) */
#endif
#ifndef M_LOG2_E
#define M_LOG2_E  0.693147180559945309417  /* ln(2) */
#endif
#ifndef M_INVLN2
#define M_INVLN2  1.4426950408889633870E0  /* 1 / ln(2) */
#endif

#endif /* _openr_newlib_h_DEFINED */
