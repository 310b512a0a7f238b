/*
 * queue.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_queue_h
#define _OPENR_COMPAT_queue_h

#include <vector.h>
#include <deque.h>
#include <queue>

using std::queue;
using std::priority_queue;

#endif /* _OPENR_COMPAT_queue_h */
