/*
 * OPENR/MemoryMapAgent.h - table of shared-memory regions attached by an
 * object (used by OObserver). Implemented by the runtime library.
 */
#ifndef _MemoryMapAgent_h_DEFINED
#define _MemoryMapAgent_h_DEFINED

#include <Types.h>
#include <map>
#include <OPENR/OPENR.h>

class MemoryMapAgent {
public:
    void*   Attach(MemoryRegionID memID);          /* map once, return base */
    OStatus Detach(MemoryRegionID memID);
    void*   Find(MemoryRegionID memID) const;      /* NULL if not attached */
    void    DetachAll();

private:
    /* Host: one address space, so a region needs no mapping; every lookup asks the
       runtime's region table (no cache, so retired regions leave nothing behind). */
    std::map<MemoryRegionID, void*> attached_;   /* regions attached explicitly */
};

#endif /* _MemoryMapAgent_h_DEFINED */
