/*
 * deque.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_deque_h
#define _OPENR_COMPAT_deque_h

#include <deque>

using std::deque;

#endif /* _OPENR_COMPAT_deque_h */
