/*
 * list.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_list_h
#define _OPENR_COMPAT_list_h

#include <list>

using std::list;

#endif /* _OPENR_COMPAT_list_h */
