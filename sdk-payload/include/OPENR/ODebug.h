/*
 * OPENR/ODebug.h - printf-based debug macros (object-model 4.2).
 * Define OPENR_NO_DEBUG before including to switch OPENR_DEBUG off.
 */
#ifndef _ODebug_h_DEFINED
#define _ODebug_h_DEFINED

#include <stdio.h>

#ifdef OPENR_NO_DEBUG
#undef OPENR_DEBUG
#endif

/* ::printf in C++: a member called printf cannot capture the macros */
#ifdef __cplusplus
#define OPENR_DEBUG_PRINTF ::printf
#else
#define OPENR_DEBUG_PRINTF printf
#endif

#define PRINTF(x) (OPENR_DEBUG_PRINTF x)

#ifdef OPENR_DEBUG
#define ODEBUG(x)       (x)
#define DPRINTF(x)      (OPENR_DEBUG_PRINTF x)
#define DPRINTF2(c, x)  ((c) ? (void)(OPENR_DEBUG_PRINTF x) : (void)0)
#else
#define ODEBUG(x)
#define DPRINTF(x)
#define DPRINTF2(c, x)
#endif

#endif /* _ODebug_h_DEFINED */
