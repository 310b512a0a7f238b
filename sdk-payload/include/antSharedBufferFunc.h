/*
 * antSharedBufferFunc.h - inline members of antSharedBuffer.
 */
#ifndef _antSharedBufferFunc_h_DEFINED
#define _antSharedBufferFunc_h_DEFINED

#include <antSharedBufferDef.h>

inline void* antSharedBuffer::GetAddress()
{
    return base;
}

inline uint32 antSharedBuffer::GetSize()
{
    return size;
}

#endif /* _antSharedBufferFunc_h_DEFINED */
