/*
 * antIOStream.h - stream types used by the ANT debug printers.
 */
#ifndef _antIOStream_h_DEFINED
#define _antIOStream_h_DEFINED

#include <iostream>

typedef std::ostream OSTREAM;
typedef std::istream ISTREAM;

#endif /* _antIOStream_h_DEFINED */
