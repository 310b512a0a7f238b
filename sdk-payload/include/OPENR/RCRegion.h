/*
 * OPENR/RCRegion.h - reference-counted handle to a block of shared memory
 * (object-model 4.1). Regions are created with `new` and released only with
 * RemoveReference(); destructor, copy constructor and assignment are private.
 * Non-inline members are implemented by the runtime library.
 */
#ifndef _RCRegion_h_DEFINED
#define _RCRegion_h_DEFINED

#include <iostream>
#include <OPENR/SharedMemoryHeader.h>
#include <OPENR/SharedMemoryAllocator.h>
#include <OPENR/StackAllocator.h>

#define OBJCOMM_VERSION_21
#define OBJCOMM_VERSION_22

typedef unsigned int offset_t;
typedef SharedMemoryAllocator SHMAllocator;

class RCRegion {
public:
    enum RegionType {
        SELF_ALLOCATED = 0,   /* owns its memory */
        REFERENCE_V20  = 1,   /* wraps memory obtained elsewhere */
        REFERENCE_V10  = 2,
        UNDEF          = 3
    };

    RCRegion();
    explicit RCRegion(size_t size);
    RCRegion(MemoryRegionID memID, offset_t offset, void* base = NULL, size_t size = 0);

    void AddReference();
    void RemoveReference();
    int  NumberOfReference() const;

    char*          Base() const { return base_; }
    size_t         Size() const { return size_; }
    MemoryRegionID MemID() const { return memID_; }
    offset_t       Offset() const { return offset_; }
    RegionType     GetType() const { return type_; }
    void           SetSize(size_t size) { size_ = size; }

    static void* operator new(size_t size);
    static void  operator delete(void* p, size_t size);

private:
    ~RCRegion();
    RCRegion(const RCRegion&);
    RCRegion& operator=(const RCRegion&);

    volatile int   refCount_;
    RegionType     type_;
    MemoryRegionID memID_;
    offset_t       offset_;
    char*          base_;
    size_t         size_;
    bool           hostRef_;   /* holds a reference on the host region memID_ */
};

typedef RCRegion RCRegionBase;

#endif /* _RCRegion_h_DEFINED */
