// mcoop.cc - the MCOOP kernel calls of MCOOP.h (object-model 3) on top of the runtime's
// host table (openr_host.h).
//
// Every object links its own copy of this archive and runs single-threaded, so the
// per-object state below (reply boxes, read-only regions) needs no locking.
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include <map>
#include <vector>

#include <MCOOP.h>

#include "openr_host.h"

namespace {

// Reply boxes of SendWithRBox: the host has no asynchronous reply, so SendWithRBox
// performs the call at once and parks the answer here until Receive asks for it.
struct RBoxTable {
    longword next;
    std::map<longword, std::vector<char> > answers;
    RBoxTable() : next(0) {}
};

RBoxTable& rboxes()
{
    static RBoxTable t;
    return t;
}

// Regions created with MEMPROTINFO_R: the page-aligned part handed out is protected
// (a write faults, as the TLB modification exception does on the robot) until deleted.
struct ProtectedRegion {
    void*  page;
    size_t len;
};

std::map<MemoryRegionID, ProtectedRegion>& protectedRegions()
{
    static std::map<MemoryRegionID, ProtectedRegion> m;
    return m;
}

size_t pageSize()
{
    long p = sysconf(_SC_PAGESIZE);
    return p > 0 ? (size_t)p : 4096;
}

sError callStatus(int rc)
{
    switch (rc) {
    case 0:  return sSUCCESS;
    case -1: return sINVALIDOID;
    case -3: return sTIMEOUT;
    default: return sFAIL;
    }
}

} // namespace

extern "C" {

/* ---- message passing ---- */

sError Send(OID dest, Selector meth, void* msg, size_t size)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    return api->send(dest.GetAddress(), meth, msg, size) == 0 ? sSUCCESS : sINVALIDOID;
}

sError SendWithRBox(OID dest, Selector meth, void* msg, size_t size, RID* rbox)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    std::vector<char> answer(65536);
    size_t got = 0;
    int rc = api->call(dest.GetAddress(), meth, msg, size, &answer[0], answer.size(), &got, 0);
    if (rc == 0 && got > answer.size()) {
        // Too small a buffer: the host tells the full size; there is no second chance to
        // read it, so keep what was copied.
        got = answer.size();
    }
    if (rc != 0) return callStatus(rc);
    answer.resize(got);
    RBoxTable& t = rboxes();
    longword id = ++t.next;
    if (id == TID_UNDEF) id = ++t.next;
    t.answers[id] = answer;
    if (rbox != 0) {
        rbox->SetMailer(OID(api->self_oid()));
        rbox->SetValue(id);
    }
    return sSUCCESS;
}

sError Receive(RID rbox, void* msg, size_t size, size_t* received, RelativeTime* timeout)
{
    (void)timeout;
    RBoxTable& t = rboxes();
    std::map<longword, std::vector<char> >::iterator it = t.answers.find(rbox.GetValue());
    if (it == t.answers.end()) return sINVALIDARG;
    size_t n = it->second.size() < size ? it->second.size() : size;
    if (msg != 0 && n > 0) memcpy(msg, &it->second[0], n);
    if (received != 0) *received = it->second.size();
    t.answers.erase(it);
    return sSUCCESS;
}

sError Call(OID dest, Selector meth, void* msg, size_t size, void* reply, size_t replySize)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    size_t got = 0;
    return callStatus(api->call(dest.GetAddress(), meth, msg, size, reply, replySize, &got, 0));
}

sError Reply(void* msg, size_t size)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    return api->reply(msg, size) == 0 ? sSUCCESS : sFAIL;
}

sError Delegate(OID dest, Selector meth, void* msg, size_t size)
{
    (void)dest; (void)meth; (void)msg; (void)size;
    return sNOTSUPPORTED;
}

sError CleanRBox(RID rbox)
{
    rboxes().answers.erase(rbox.GetValue());
    return sSUCCESS;
}

/* Return and Exit live in prologue.cc (always linked). */

/* ---- time and events ---- */

sError GetSystemTime(SystemTime* time)
{
    if (time == 0) return sINVALIDARG;
    const openr_host_api* api = openr_host();
    unsigned int sec = 0, usec = 0;
    if (api != 0) api->system_time(&sec, &usec);
    time->seconds = sec;
    time->useconds = usec;
    return sSUCCESS;
}

sError SetReplyEvent(RID rbox, OID dest, Selector meth, void* msg, size_t size, EventID* event)
{
    (void)rbox; (void)dest; (void)meth; (void)msg; (void)size; (void)event;
    return sNOTSUPPORTED;
}

sError SetTimeEvent(TimeEventInfo* info, OID dest, Selector meth, void* msg, size_t size,
                    EventID* event)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    if (info == 0) return sINVALIDARG;
    unsigned int after = info->relativeTime.sec * 1000U + info->relativeTime.msec;
    unsigned int period = info->periodicTime.sec * 1000U + info->periodicTime.msec;
    unsigned int id = api->set_timer(dest.GetAddress(), meth, msg, size, after, period);
    if (id == 0) return sFAIL;
    if (event != 0) event->SetValue(id);
    return sSUCCESS;
}

sError CancelEvent(EventID event)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    return api->cancel_timer(event.GetValue()) == 0 ? sSUCCESS : sINVALIDARG;
}

/* ---- resources ---- */

sError SetResourceValue(sResource resource, slongword value)
{
    (void)resource; (void)value;
    return sNOTSUPPORTED;
}

sError GetResourceValue(sResource resource, slongword* current, slongword* max, slongword* min)
{
    (void)resource; (void)current; (void)max; (void)min;
    return sNOTSUPPORTED;
}

/* ---- private memory ---- */

sError NewRegion(size_t size, void** base)
{
    if (base == 0) return sINVALIDARG;
    *base = malloc(size > 0 ? size : 1);
    return *base != 0 ? sSUCCESS : sNOMEMORY;
}

// Accepts any malloc() pointer (TinyFTPD frees malloc'ed memory with DeleteRegion).
sError DeleteRegion(void* base)
{
    free(base);
    return sSUCCESS;
}

/* ---- objects ---- */

sError New(OID cls, OID* object)
{
    (void)cls; (void)object;
    return sNOTSUPPORTED;
}

sError Delete(void)
{
    return sNOTSUPPORTED;
}

sError Load(const char* name, OID* object)
{
    (void)name; (void)object;
    return sNOTSUPPORTED;
}

sError LoadAndExecMAV(const char* name, longword arg1, longword arg2, longword arg3,
                      size_t stackSize, size_t heapSize)
{
    (void)name; (void)arg1; (void)arg2; (void)arg3; (void)stackSize; (void)heapSize;
    return sNOTSUPPORTED;
}

sError Unload(OID object)
{
    (void)object;
    return sNOTSUPPORTED;
}

sError WhoAmI(OID* self)
{
    if (self == 0) return sINVALIDARG;
    const openr_host_api* api = openr_host();
    if (api == 0) {
        self->MakeInvalid();
        return sFAIL;
    }
    self->SetAddress(api->self_oid());
    return sSUCCESS;
}

/* ---- name registry (the host registry only knows services) ---- */

sError Find(const char* name, OID* object)
{
    (void)name; (void)object;
    return sNOTSUPPORTED;
}

sError FindSelector(const char* name, Selector* selector)
{
    (void)name; (void)selector;
    return sNOTSUPPORTED;
}

sError Register(OID object, const char* name)
{
    (void)object; (void)name;
    return sNOTSUPPORTED;
}

sError Unregister(const char* name)
{
    (void)name;
    return sNOTSUPPORTED;
}

sError SetEntryTable(size_t numOfEntries, EntryTable* table)
{
    (void)numOfEntries; (void)table;
    return sNOTSUPPORTED;
}

/* ---- shared memory ---- */

sError NewSharedMemoryRegion(size_t size, MemoryProtectionInfo prot, MemoryRegionID* memID,
                             void** base)
{
    if (memID == 0 || base == 0 || prot == MEMPROTINFO_INVALID) return sINVALIDARG;
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    if (prot == MEMPROTINFO_R) {
        // Room for a page-aligned block of whole pages that can be write-protected.
        size_t page = pageSize();
        size_t len = (size + page - 1) / page * page;
        if (len == 0) len = page;
        unsigned int id = 0;
        char* raw = static_cast<char*>(api->shm_alloc(len + page, &id));
        if (raw == 0) return sNOMEMORY;
        char* aligned = reinterpret_cast<char*>(
            (reinterpret_cast<unsigned long>(raw) + page - 1) / page * page);
        if (mprotect(aligned, len, PROT_READ) != 0) {
            api->shm_unref(id);
            return sFAIL;
        }
        ProtectedRegion r = { aligned, len };
        protectedRegions()[id] = r;
        *memID = id;
        *base = aligned;
        return sSUCCESS;
    }
    unsigned int id = 0;
    void* p = api->shm_alloc(size, &id);
    if (p == 0) return sNOMEMORY;
    *memID = id;
    *base = p;
    return sSUCCESS;
}

sError DeleteSharedMemoryRegion(MemoryRegionID memID)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return sFAIL;
    if (api->shm_base(memID, 0) == 0) return sINVALIDARG;
    std::map<MemoryRegionID, ProtectedRegion>::iterator it = protectedRegions().find(memID);
    if (it != protectedRegions().end()) {
        mprotect(it->second.page, it->second.len, PROT_READ | PROT_WRITE);
        protectedRegions().erase(it);
    }
    api->shm_unref(memID);
    return sSUCCESS;
}

sError AllowToAttachMemoryRegion(MemoryRegionID memID, MemoryProtectionInfo prot, OID object,
                                 bool allow)
{
    (void)prot; (void)object; (void)allow;
    const openr_host_api* api = openr_host();
    if (api == 0 || api->shm_base(memID, 0) == 0) return sINVALIDARG;
    return sSUCCESS;   // one address space: every object can see every region
}

sError AttachMemoryRegion(MemoryRegionID memID, MemoryProtectionInfo prot, void** base)
{
    (void)prot;
    const openr_host_api* api = openr_host();
    if (api == 0 || base == 0) return sINVALIDARG;
    void* p = api->shm_base(memID, 0);
    if (p == 0) return sINVALIDARG;
    *base = p;
    return sSUCCESS;
}

sError DetachMemoryRegion(MemoryRegionID memID)
{
    const openr_host_api* api = openr_host();
    if (api == 0 || api->shm_base(memID, 0) == 0) return sINVALIDARG;
    return sSUCCESS;
}

sError ChangeProtectionMemoryRegion(MemoryRegionID memID, MemoryProtectionInfo prot)
{
    (void)memID; (void)prot;
    return sNOTSUPPORTED;
}

sError GrowMemoryRegion(MemoryRegionID memID, size_t size)
{
    (void)memID; (void)size;
    return sNOTSUPPORTED;
}

sError ShrinkMemoryRegion(MemoryRegionID memID, size_t size)
{
    (void)memID; (void)size;
    return sNOTSUPPORTED;
}

sError GetPageSize(size_t* size)
{
    if (size == 0) return sINVALIDARG;
    *size = pageSize();
    return sSUCCESS;
}

sError GetFreeMemorySize(size_t* size)
{
    if (size == 0) return sINVALIDARG;
    long pages = sysconf(_SC_AVPHYS_PAGES);
    *size = pages > 0 ? (size_t)pages * pageSize() : 0;
    return sSUCCESS;
}

/* ---- misc ---- */

sError Wait(longword nanosec)
{
    const openr_host_api* api = openr_host();
    if (api != 0) {
        api->sleep_ns(nanosec);
    } else {
        struct timespec ts;
        ts.tv_sec = nanosec / 1000000000U;
        ts.tv_nsec = nanosec % 1000000000U;
        while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
        }
    }
    return sSUCCESS;
}

} // extern "C"
