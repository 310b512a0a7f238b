/*
 * OPENR/OMemoryLocator.h - (region, offset, size) triple naming a block of
 * shared memory. Legacy; kept because other headers refer to it.
 */
#ifndef _OMemoryLocator_h_DEFINED
#define _OMemoryLocator_h_DEFINED

#include <iostream>
#include <MCOOP.h>
#include <OID.h>

class OMemoryLocator {
public:
    OMemoryLocator() : memID_(0), offset_(0), size_(0) {}
    OMemoryLocator(MemoryRegionID memID, size_t offset, size_t size)
        : memID_(memID), offset_(offset), size_(size) {}

    void Set(MemoryRegionID memID, size_t offset, size_t size) {
        memID_ = memID;
        offset_ = offset;
        size_ = size;
    }
    MemoryRegionID MemID() const { return memID_; }
    size_t         Offset() const { return offset_; }
    size_t         Size() const { return size_; }

private:
    MemoryRegionID memID_;
    size_t         offset_;
    size_t         size_;
};

std::ostream& operator<<(std::ostream& os, const OMemoryLocator& locator);

#endif /* _OMemoryLocator_h_DEFINED */
