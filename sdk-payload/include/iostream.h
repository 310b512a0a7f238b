/*
 * iostream.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_iostream_h
#define _OPENR_COMPAT_iostream_h

#include <iostream>

using std::iostream;
using std::ostream;
using std::istream;
using std::ios;
using std::ios_base;
using std::streambuf;
using std::streamsize;
using std::cout;
using std::cin;
using std::cerr;
using std::clog;
using std::ws;
using std::endl;
using std::ends;
using std::flush;
using std::dec;
using std::hex;
using std::oct;

#endif /* _OPENR_COMPAT_iostream_h */
