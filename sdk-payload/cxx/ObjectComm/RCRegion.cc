// RCRegion.cc - reference-counted shared memory (object-model 4.1).
//
// RCRegion(size) owns a host region (shm_alloc).  A wrapping RCRegion(memID, ...) takes
// a host reference on memID when it names a host region, so the memory outlives the
// subject's own handle while an observer-side handle is alive; both drop their host
// reference when their count reaches 0.
#include <pthread.h>
#include <stdlib.h>

#include <new>
#include <vector>

#include <OPENR/RCRegion.h>

#include "openr_host.h"

namespace {

// Handles come from a pool whose slots are never returned to the C library, so a stale
// handle still reads a count of 0 (ONotifyEvent::RCData relies on it, as on the robot).
const size_t kChunk = 20;
pthread_mutex_t poolLock = PTHREAD_MUTEX_INITIALIZER;

std::vector<void*>& freeSlots()
{
    static std::vector<void*>* v = new std::vector<void*>();
    return *v;
}

} // namespace

void* RCRegion::operator new(size_t size)
{
    if (size != sizeof(RCRegion)) {
        void* p = malloc(size);
        if (p == 0) throw std::bad_alloc();
        return p;
    }
    pthread_mutex_lock(&poolLock);
    std::vector<void*>& slots = freeSlots();
    if (slots.empty()) {
        char* chunk = static_cast<char*>(malloc(sizeof(RCRegion) * kChunk));
        if (chunk == 0) {
            pthread_mutex_unlock(&poolLock);
            throw std::bad_alloc();
        }
        for (size_t i = kChunk; i > 0; i--) slots.push_back(chunk + sizeof(RCRegion) * (i - 1));
    }
    void* p = slots.back();
    slots.pop_back();
    pthread_mutex_unlock(&poolLock);
    return p;
}

void RCRegion::operator delete(void* p, size_t size)
{
    if (p == 0) return;
    if (size != sizeof(RCRegion)) {
        free(p);
        return;
    }
    pthread_mutex_lock(&poolLock);
    freeSlots().push_back(p);
    pthread_mutex_unlock(&poolLock);
}

RCRegion::RCRegion()
    : refCount_(0), type_(UNDEF), memID_(0), offset_(0), base_(0), size_(0), hostRef_(false)
{
}

RCRegion::RCRegion(size_t size)
    : refCount_(1), type_(SELF_ALLOCATED), memID_(0), offset_(0), base_(0), size_(0),
      hostRef_(false)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return;
    unsigned int id = 0;
    void* p = api->shm_alloc(size, &id);
    if (p == 0) return;
    memID_ = id;
    base_ = static_cast<char*>(p);
    size_ = size;
    hostRef_ = true;
}

RCRegion::RCRegion(MemoryRegionID memID, offset_t offset, void* base, size_t size)
    : refCount_(1), type_(REFERENCE_V20), memID_(memID), offset_(offset),
      base_(static_cast<char*>(base)), size_(size), hostRef_(false)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return;
    size_t total = 0;
    char* region = static_cast<char*>(api->shm_base(memID, &total));
    if (region == 0) return;   // not a host region: plain wrapper
    api->shm_ref(memID);
    hostRef_ = true;
    if (base_ == 0) {
        base_ = region + offset;
        if (size_ == 0 && offset <= total) size_ = total - offset;
    }
}

RCRegion::~RCRegion()
{
    if (hostRef_) {
        const openr_host_api* api = openr_host();
        if (api != 0) api->shm_unref(memID_);
        hostRef_ = false;
    }
    type_ = UNDEF;
}

void RCRegion::AddReference()
{
    __sync_add_and_fetch(&refCount_, 1);
}

void RCRegion::RemoveReference()
{
    int left = __sync_sub_and_fetch(&refCount_, 1);
    if (left == 0) delete this;
}

int RCRegion::NumberOfReference() const
{
    return refCount_;
}
