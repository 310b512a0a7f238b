/*
 * antSharedBuffer.h - shared buffers of the ANT networking toolkit.
 */
#ifndef _antSharedBuffer_h_DEFINED
#define _antSharedBuffer_h_DEFINED

#include <antTypes.h>
#include <antSharedBufferDef.h>
#include <antSharedBufferFunc.h>

#endif /* _antSharedBuffer_h_DEFINED */
