/*
 * strstream.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_strstream_h
#define _OPENR_COMPAT_strstream_h

#include <iostream.h>

/* <strstream> is deprecated: silence its warning */
#ifdef __DEPRECATED
#undef __DEPRECATED
#include <backward/backward_warning.h>
#define __DEPRECATED 1
#endif
#include <strstream>

using std::strstreambuf;
using std::istrstream;
using std::ostrstream;
using std::strstream;

#endif /* _OPENR_COMPAT_strstream_h */
