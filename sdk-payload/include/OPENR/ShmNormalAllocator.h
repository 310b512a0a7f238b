/*
 * OPENR/ShmNormalAllocator.h - allocator of arbitrary-size shared-memory
 * blocks (one region per block). Implemented by the runtime library.
 */
#ifndef _ShmNormalAllocator_h_DEFINED
#define _ShmNormalAllocator_h_DEFINED

#include <list>
#include <OPENR/SharedMemoryHeader.h>

class ShmNormalAllocator {
public:
    ShmNormalAllocator();
    ~ShmNormalAllocator();

    ShmHdr* Allocate(size_t size);
    OStatus Deallocate(ShmHdr* hdr);

private:
    ShmNormalAllocator(const ShmNormalAllocator&);
    ShmNormalAllocator& operator=(const ShmNormalAllocator&);

    std::list<ShmHdr*> blocks_;
};

#endif /* _ShmNormalAllocator_h_DEFINED */
