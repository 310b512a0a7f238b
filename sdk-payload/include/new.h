/*
 * new.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_new_h
#define _OPENR_COMPAT_new_h

#include <new>

using std::bad_alloc;
using std::nothrow_t;
using std::nothrow;
using std::new_handler;
using std::set_new_handler;

#endif /* _OPENR_COMPAT_new_h */
