/*
 * Types.h - basic scalar types of the OPEN-R SDK (host re-implementation).
 *
 * Written from the cargo-openr specification (object-model 2.2, robot-api 1).
 * Host ABI: LP64 Linux; every "long" of the robot is mapped to a 32-bit int
 * type so that byte/word/longword keep the robot's 8/16/32-bit sizes.
 * Usable from C and C++.
 */
#ifndef _Types_h_DEFINED
#define _Types_h_DEFINED

/* size_t, NULL and ptrdiff_t come from the system; never redefine them. */
#include <stddef.h>
#include <sys/types.h>

/*
 * Programs written for gcc 3.3 used printf/malloc/strcpy/isdigit/sin/stricmp ...
 * without including the C headers: make the robot's C library surface (newlib's)
 * visible through every OPEN-R header.
 */
#include <openr_newlib.h>

#ifndef __cplusplus
#include <stdbool.h>
#endif

#if defined(__cplusplus) && __cplusplus >= 201402L
/* gets() disappeared from <stdio.h> in C++14 mode; old code still calls it. */
extern "C" char* gets(char*);
#endif

typedef unsigned char   byte;
typedef unsigned short  word;
typedef unsigned int    longword;      /* exactly 32 bits on the host */
typedef char            sbyte;
typedef short           sword;
typedef int             slongword;     /* exactly 32 bits on the host */

typedef signed char     int8;
typedef unsigned char   uint8;
typedef short           int16;
typedef unsigned short  uint16;
typedef int             int32;
typedef unsigned int    uint32;
typedef long long       int64;
typedef unsigned long long uint64;

typedef byte*           pbyte;
typedef word*           pword;
typedef longword*       plongword;
typedef longword        magicword;

#ifndef __u_char_defined
typedef unsigned char   u_char;
typedef unsigned short  u_short;
typedef unsigned int    u_int;
typedef unsigned long   u_long;
#define __u_char_defined
#endif

#ifdef __cplusplus
typedef bool            Boolean;
#else
typedef _Bool           Boolean;
#endif

typedef slongword       sError;
typedef longword        Selector;

#ifdef __cplusplus
const Selector UNDEF = 0xffffffff;
typedef void (*Entry)(...);
#else
#define UNDEF ((Selector)0xffffffffU)
typedef void (*Entry)();
#endif

typedef unsigned int    MemoryRegionID;
typedef unsigned int    SharedMemoryRegionID;

typedef enum {
    MEMPROTINFO_INVALID = 0,
    MEMPROTINFO_R       = 1,
    MEMPROTINFO_RW      = 2
} MemoryProtectionInfo;

#ifndef NULL
#ifdef __cplusplus
#define NULL 0
#else
#define NULL ((void*)0)
#endif
#endif

/* Sony: TRUE = !NULL, FALSE = NULL; same values, without NULL-to-int warnings. */
#ifndef TRUE
#define TRUE  1
#endif
#ifndef FALSE
#define FALSE 0
#endif

/* Compile-time check usable in C and C++98 (negative array size on failure). */
#define OPENR_STATIC_CHECK(cond, name) \
    typedef char openr_static_check_##name[(cond) ? 1 : -1]

OPENR_STATIC_CHECK(sizeof(byte) == 1, byte_is_8bit);
OPENR_STATIC_CHECK(sizeof(word) == 2, word_is_16bit);
OPENR_STATIC_CHECK(sizeof(longword) == 4, longword_is_32bit);
OPENR_STATIC_CHECK(sizeof(slongword) == 4, slongword_is_32bit);
OPENR_STATIC_CHECK(sizeof(int32) == 4, int32_is_32bit);

#endif /* _Types_h_DEFINED */
