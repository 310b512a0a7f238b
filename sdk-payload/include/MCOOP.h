/*
 * MCOOP.h - the kernel (Aperios MCOOP) calls available to an object
 * (object-model section 3). All functions have C linkage; default arguments
 * exist only in C++. Implemented by the cargo-openr runtime library.
 */
#ifndef _MCOOP_h_DEFINED
#define _MCOOP_h_DEFINED

#include <Types.h>
#include <SystemError.h>
#include <SystemResource.h>
#include <OID.h>
#include <TID.h>
#include <SystemTime.h>
#include <TimeEventInfo.h>
#include <EventID.h>
#include <MCOOPError.h>
#include <MCOOPTypes.h>

#ifdef __cplusplus
#define OPENR_DEFAULT_ARG(v) = v
struct EntryTable;
extern "C" {
#else
#define OPENR_DEFAULT_ARG(v)
typedef struct EntryTable EntryTable;
#endif

/* message passing */
sError Send(OID dest, Selector meth, void* msg, size_t size);
sError SendWithRBox(OID dest, Selector meth, void* msg, size_t size, RID* rbox);
sError Receive(RID rbox,
               void* msg OPENR_DEFAULT_ARG(0),
               size_t size OPENR_DEFAULT_ARG(0),
               size_t* received OPENR_DEFAULT_ARG(NULL),
               RelativeTime* timeout OPENR_DEFAULT_ARG(NULL));
sError Call(OID dest, Selector meth, void* msg, size_t size,
            void* reply OPENR_DEFAULT_ARG(0),
            size_t replySize OPENR_DEFAULT_ARG(0));
sError Reply(void* msg OPENR_DEFAULT_ARG(0), size_t size OPENR_DEFAULT_ARG(0));
sError Delegate(OID dest, Selector meth, void* msg, size_t size);
sError CleanRBox(RID rbox);
void   Return(void* msg OPENR_DEFAULT_ARG(0), size_t size OPENR_DEFAULT_ARG(0));
void   Exit(void);
void   ExitFromPrologue(void);

/* time and events */
sError GetSystemTime(SystemTime* time);
sError SetReplyEvent(RID rbox, OID dest, Selector meth, void* msg, size_t size,
                     EventID* event);
sError SetTimeEvent(TimeEventInfo* info, OID dest, Selector meth, void* msg,
                    size_t size, EventID* event);
sError CancelEvent(EventID event);

/* resources */
sError SetResourceValue(sResource resource, slongword value);
sError GetResourceValue(sResource resource, slongword* current,
                        slongword* max OPENR_DEFAULT_ARG(NULL),
                        slongword* min OPENR_DEFAULT_ARG(NULL));

/* private memory */
sError NewRegion(size_t size, void** base);
sError DeleteRegion(void* base);

/* objects */
sError New(OID cls, OID* object);
sError Delete(void);
sError Load(const char* name, OID* object);
sError LoadAndExecMAV(const char* name, longword arg1, longword arg2,
                      longword arg3, size_t stackSize, size_t heapSize);
sError Unload(OID object);
sError WhoAmI(OID* self);

/* name registry */
sError Find(const char* name, OID* object);
sError FindSelector(const char* name, Selector* selector);
sError Register(OID object, const char* name);
sError Unregister(const char* name);
sError SetEntryTable(size_t numOfEntries, EntryTable* table);

/* shared memory */
sError NewSharedMemoryRegion(size_t size, MemoryProtectionInfo prot,
                             MemoryRegionID* memID, void** base);
sError DeleteSharedMemoryRegion(MemoryRegionID memID);
sError AllowToAttachMemoryRegion(MemoryRegionID memID, MemoryProtectionInfo prot,
                                 OID object, bool allow);
sError AttachMemoryRegion(MemoryRegionID memID, MemoryProtectionInfo prot,
                          void** base);
sError DetachMemoryRegion(MemoryRegionID memID);
sError ChangeProtectionMemoryRegion(MemoryRegionID memID, MemoryProtectionInfo prot);
sError GrowMemoryRegion(MemoryRegionID memID, size_t size);
sError ShrinkMemoryRegion(MemoryRegionID memID, size_t size);
sError GetPageSize(size_t* size);
sError GetFreeMemorySize(size_t* size);

/* misc */
sError Wait(longword nanosec);

#ifdef __cplusplus
} /* extern "C" */

/* C++ conveniences (overloads of the C functions above). */
inline sError Send(OID dest, Selector meth, void* msg, size_t size, RID* rbox)
{
    return SendWithRBox(dest, meth, msg, size, rbox);
}

inline sError Receive(RID rbox, void* msg, size_t size, RelativeTime* timeout)
{
    return Receive(rbox, msg, size, (size_t*)NULL, timeout);
}

inline sError Find(const char* name, Selector* selector)
{
    return FindSelector(name, selector);
}
#endif

#undef OPENR_DEFAULT_ARG

#endif /* _MCOOP_h_DEFINED */
