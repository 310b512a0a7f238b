/*
 * OPENR/SharedMemoryAllocator.h - front end choosing between the unit and
 * the normal shared-memory allocators. Implemented by the runtime library.
 */
#ifndef _SharedMemoryAllocator_h_DEFINED
#define _SharedMemoryAllocator_h_DEFINED

#include <OPENR/ShmUnitAllocator.h>
#include <OPENR/ShmNormalAllocator.h>

class SharedMemoryAllocator {
public:
    /* Allocates `size` usable bytes of shared memory. */
    static ShmHdr* Allocate(size_t size);
    static OStatus Deallocate(ShmHdr* hdr);
};

#endif /* _SharedMemoryAllocator_h_DEFINED */
