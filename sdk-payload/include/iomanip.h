/*
 * iomanip.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_iomanip_h
#define _OPENR_COMPAT_iomanip_h

#include <iostream.h>
#include <iomanip>

using std::setw;
using std::setfill;
using std::setprecision;
using std::setbase;
using std::setiosflags;
using std::resetiosflags;

#endif /* _OPENR_COMPAT_iomanip_h */
