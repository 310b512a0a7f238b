/*
 * multimap.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_multimap_h
#define _OPENR_COMPAT_multimap_h

#include <map>

using std::multimap;

#endif /* _OPENR_COMPAT_multimap_h */
