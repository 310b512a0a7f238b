/*
 * pair.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_pair_h
#define _OPENR_COMPAT_pair_h

#include <utility>

using std::pair;
using std::make_pair;

#endif /* _OPENR_COMPAT_pair_h */
