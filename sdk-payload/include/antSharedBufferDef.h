/*
 * antSharedBufferDef.h - class antSharedBuffer (network-api 1.9): memory
 * shared between an object and the IP stack. Copied by value; Map()/UnMap()
 * are implemented by the runtime library.
 */
#ifndef _antSharedBufferDef_h_DEFINED
#define _antSharedBufferDef_h_DEFINED

#include <Types.h>
#include <antTypes.h>

class antSharedBuffer {
public:
    antSharedBuffer() : region(0), base(0), size(0), cookie(0) {}

    antError Map();
    antError UnMap();

    inline void*  GetAddress();
    inline uint32 GetSize();

    /* host side (runtime) initialisation */
    void HostSet(MemoryRegionID r, void* b, uint32 s, void* c) {
        region = r; base = b; size = s; cookie = c;
    }
    MemoryRegionID HostRegion() const { return region; }
    void*          HostCookie() const { return cookie; }

private:
    MemoryRegionID region;
    void*          base;
    uint32         size;
    void*          cookie;
};

#endif /* _antSharedBufferDef_h_DEFINED */
