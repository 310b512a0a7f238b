/*
 * multiset.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_multiset_h
#define _OPENR_COMPAT_multiset_h

#include <set>

using std::multiset;

#endif /* _OPENR_COMPAT_multiset_h */
