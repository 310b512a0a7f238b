/*
 * stack.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_stack_h
#define _OPENR_COMPAT_stack_h

#include <vector.h>
#include <deque.h>
#include <stack>

using std::stack;

#endif /* _OPENR_COMPAT_stack_h */
