// Memory.cc - observer bookkeeping (DataManager, MemoryMapAgent) and the shared-memory
// allocators behind RCRegion/OShmPtr (object-model 4.1).
#include <OPENR/DataManager.h>
#include <OPENR/MemoryMapAgent.h>
#include <OPENR/SharedMemoryAllocator.h>
#include <OPENR/ShmNormalAllocator.h>
#include <OPENR/ShmUnitAllocator.h>

#include "openr_host.h"

/* ---- DataManager ---- */

DataManager::DataManager()
{
}

DataManager::~DataManager()
{
    Clear();
}

OStatus DataManager::Add(const SubjectID& subject, RCRegion* local, RCRegion* source)
{
    Record r;
    r.subject = subject;
    r.local = local;
    r.source = source;
    records_.push_back(r);
    return oSUCCESS;
}

int DataManager::Collect(const SubjectID& subject, RCRegion** sources, int max)
{
    int n = 0;
    std::list<Record>::iterator it = records_.begin();
    while (it != records_.end() && n < max) {
        if (it->subject == subject) {
            sources[n++] = it->source;
            if (it->local != 0) it->local->RemoveReference();
            it = records_.erase(it);
        } else {
            ++it;
        }
    }
    return n;
}

SubjectID DataManager::FindSender(RCRegion* local) const
{
    for (std::list<Record>::const_iterator it = records_.begin(); it != records_.end(); ++it) {
        if (it->local == local) return it->subject;
    }
    return SubjectID();
}

bool DataManager::CollectOne(RCRegion* local, SubjectID* subject, RCRegion** source)
{
    for (std::list<Record>::iterator it = records_.begin(); it != records_.end(); ++it) {
        if (it->local != local) continue;
        *subject = it->subject;
        *source = it->source;
        if (it->local != 0) it->local->RemoveReference();
        records_.erase(it);
        return true;
    }
    return false;
}

void DataManager::Clear()
{
    for (std::list<Record>::iterator it = records_.begin(); it != records_.end(); ++it) {
        if (it->local != 0) it->local->RemoveReference();
    }
    records_.clear();
}

/* ---- MemoryMapAgent ---- */

void* MemoryMapAgent::Attach(MemoryRegionID memID)
{
    const openr_host_api* api = openr_host();
    return api != 0 ? api->shm_base(memID, 0) : 0;
}

OStatus MemoryMapAgent::Detach(MemoryRegionID memID)
{
    attached_.erase(memID);
    return oSUCCESS;
}

void* MemoryMapAgent::Find(MemoryRegionID memID) const
{
    const openr_host_api* api = openr_host();
    return api != 0 ? api->shm_base(memID, 0) : 0;
}

void MemoryMapAgent::DetachAll()
{
    attached_.clear();
}

/* ---- allocators ---- */

namespace {

ShmHdr* newBlock(size_t size)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return 0;
    unsigned int id = 0;
    void* base = api->shm_alloc(size, &id);
    if (base == 0) return 0;
    ShmHdr* h = new ShmHdr;
    h->memID = id;
    h->offset = 0;
    h->size = size;
    h->base = base;
    return h;
}

void freeBlock(ShmHdr* h)
{
    if (h == 0) return;
    const openr_host_api* api = openr_host();
    if (api != 0) api->shm_unref(h->memID);
    delete h;
}

} // namespace

ShmHdr* SharedMemoryAllocator::Allocate(size_t size)
{
    return newBlock(size);
}

OStatus SharedMemoryAllocator::Deallocate(ShmHdr* hdr)
{
    if (hdr == 0) return oINVALID_ARG;
    freeBlock(hdr);
    return oSUCCESS;
}

ShmNormalAllocator::ShmNormalAllocator()
{
}

ShmNormalAllocator::~ShmNormalAllocator()
{
    for (std::list<ShmHdr*>::iterator it = blocks_.begin(); it != blocks_.end(); ++it) {
        freeBlock(*it);
    }
}

ShmHdr* ShmNormalAllocator::Allocate(size_t size)
{
    ShmHdr* h = newBlock(size);
    if (h != 0) blocks_.push_back(h);
    return h;
}

OStatus ShmNormalAllocator::Deallocate(ShmHdr* hdr)
{
    for (std::list<ShmHdr*>::iterator it = blocks_.begin(); it != blocks_.end(); ++it) {
        if (*it == hdr) {
            blocks_.erase(it);
            freeBlock(hdr);
            return oSUCCESS;
        }
    }
    return oINVALID_ARG;
}

ShmUnitAllocator::ShmUnitAllocator(size_t unitSize) : unitSize_(unitSize)
{
}

ShmUnitAllocator::~ShmUnitAllocator()
{
    for (std::list<ShmHdr*>::iterator it = freeUnits_.begin(); it != freeUnits_.end(); ++it) {
        freeBlock(*it);
    }
    for (std::list<ShmHdr*>::iterator it = usedUnits_.begin(); it != usedUnits_.end(); ++it) {
        freeBlock(*it);
    }
}

ShmHdr* ShmUnitAllocator::Allocate()
{
    ShmHdr* h;
    if (!freeUnits_.empty()) {
        h = freeUnits_.front();
        freeUnits_.pop_front();
    } else {
        h = newBlock(unitSize_);
        if (h == 0) return 0;
    }
    usedUnits_.push_back(h);
    return h;
}

OStatus ShmUnitAllocator::Deallocate(ShmHdr* hdr)
{
    for (std::list<ShmHdr*>::iterator it = usedUnits_.begin(); it != usedUnits_.end(); ++it) {
        if (*it == hdr) {
            usedUnits_.erase(it);
            freeUnits_.push_back(hdr);
            return oSUCCESS;
        }
    }
    return oINVALID_ARG;
}
