/*
 * OPENR/SharedMemoryHeader.h - bookkeeping header of a shared-memory block
 * handed out by the object-communication allocators.
 */
#ifndef _SharedMemoryHeader_h_DEFINED
#define _SharedMemoryHeader_h_DEFINED

#include <MCOOP.h>
#include <OPENR/ODataFormats.h>

struct SharedMemoryHeader {
    MemoryRegionID memID;    /* region holding the block */
    size_t         offset;   /* offset of the block in the region */
    size_t         size;     /* usable bytes after the header */
    void*          base;     /* base address of the region */
};

typedef SharedMemoryHeader ShmHdr;

#endif /* _SharedMemoryHeader_h_DEFINED */
