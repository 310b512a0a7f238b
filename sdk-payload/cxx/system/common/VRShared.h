// VRShared.h - what every system object of the virtual robot does with the runtime:
// hand received vectors to it, give each back when it is done, and publish the data it
// produces.  Inline, because each system object links its own copy.
#ifndef VRShared_h_DEFINED
#define VRShared_h_DEFINED

#include <map>

#include <OPENR/OObserver.h>
#include <OPENR/OSubject.h>

#include "openr_host.h"

typedef std::map<unsigned long long, RCRegion*> VRPlaying;

// Every data item of a notification goes to the runtime's `service`; the region stays
// with us (and the subject) until the runtime reports it done.
inline void vrSubmit(OObserver* obs, const ONotifyEvent& event, int service, VRPlaying* playing)
{
    const openr_host_api* api = openr_host();
    SubjectID sender = event.SenderID().GetSubjectID();
    for (int i = 0; i < event.NumOfData(); i++) {
        RCRegion* r = event.RCData(i);
        if (r == 0) continue;
        unsigned long long token = 0;
        unsigned int st = api->vr_submit(service, sender.GetOID().GetAddress(), sender.GetSelector(),
                                         r->Base(), r->Size(), &token);
        if (st == oSUCCESS) {
            (*playing)[token] = r;
        } else {
            obs->AssertReadyFor(r);   // malformed: not played, given back at once
        }
    }
}

// The runtime finished a vector: release it first, then ASSERT-READY (robot-api 8.2.3).
inline void vrDone(OObserver* obs, unsigned long long token, VRPlaying* playing)
{
    VRPlaying::iterator it = playing->find(token);
    if (it == playing->end()) return;
    obs->AssertReadyFor(it->second);
    playing->erase(it);
}

// A subject was just connected to `obs` (it is the last of its subjects): the effector and
// the speaker are ready for it from the connection on, before any Start (robot-api 8.2.3).
inline void vrConnected(OObserver* obs)
{
    SubjectConstIterator newest = obs->end();
    if (newest == obs->begin()) return;
    --newest;
    obs->AssertReady(newest->GetSubjectID());
}

// A vector the runtime made (with one reference that the event owns) goes to observers.
inline void vrPublish(OSubject* sbj, unsigned int memID, unsigned int size)
{
    const openr_host_api* api = openr_host();
    void* base = api->shm_base(memID, 0);
    if (base == 0) return;
    RCRegion* r = new RCRegion(memID, 0, base, size);   // takes its own reference
    api->shm_unref(memID);                               // the event's one
    sbj->SetData(r);
    sbj->NotifyObservers();
    r->RemoveReference();   // observers' queues keep what they still need
}

#endif
