/*
 * fstream.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_fstream_h
#define _OPENR_COMPAT_fstream_h

#include <iostream.h>
#include <fstream>

using std::filebuf;
using std::ifstream;
using std::ofstream;
using std::fstream;
using std::streampos;
using std::streamoff;

#endif /* _OPENR_COMPAT_fstream_h */
