/*
 * hash_set.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_hash_set_h
#define _OPENR_COMPAT_hash_set_h

/* <ext/hash_set> is deprecated: silence its warning */
#ifndef _GLIBCXX_PERMIT_BACKWARD_HASH
#define _GLIBCXX_PERMIT_BACKWARD_HASH
#endif
#include <ext/hash_set>

using __gnu_cxx::hash;
using __gnu_cxx::hash_set;
using __gnu_cxx::hash_multiset;

#endif /* _OPENR_COMPAT_hash_set_h */
