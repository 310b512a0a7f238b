/*
 * OPENR/ShmUnitAllocator.h - allocator of fixed-size units carved out of
 * shared-memory regions. Implemented by the runtime library.
 */
#ifndef _ShmUnitAllocator_h_DEFINED
#define _ShmUnitAllocator_h_DEFINED

#include <list>
#include <OPENR/SharedMemoryHeader.h>
#include <OPENR/MemoryMapAgent.h>

class ShmUnitAllocator {
public:
    explicit ShmUnitAllocator(size_t unitSize = 0);
    ~ShmUnitAllocator();

    ShmHdr* Allocate();
    OStatus Deallocate(ShmHdr* hdr);
    size_t  UnitSize() const { return unitSize_; }

private:
    ShmUnitAllocator(const ShmUnitAllocator&);
    ShmUnitAllocator& operator=(const ShmUnitAllocator&);

    size_t              unitSize_;
    std::list<ShmHdr*>  freeUnits_;
    std::list<ShmHdr*>  usedUnits_;
};

#endif /* _ShmUnitAllocator_h_DEFINED */
