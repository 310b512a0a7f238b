// VirtualRobotComm.cc
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>

#include "openr_host.h"
#include "VirtualRobotComm.h"

OStatus
VirtualRobotComm::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    const openr_host_api* api = openr_host();
    if (api == 0) return oFAIL;
    api->vr_attach(OPENR_VR_EFFECTOR, Extra_Entry[entryEvent]);
    api->vr_attach(OPENR_VR_SENSOR, Extra_Entry[entryEvent]);
    api->vr_attach(OPENR_VR_IMAGE, Extra_Entry[entryEvent]);
    return oSUCCESS;
}

OStatus
VirtualRobotComm::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    // The effector is ready for every subject connected to it (robot-api 8.2.3).
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
VirtualRobotComm::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    return oSUCCESS;
}

OStatus
VirtualRobotComm::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
VirtualRobotComm::NotifyEffector(const ONotifyEvent& event)
{
    const openr_host_api* api = openr_host();
    SubjectID sender = event.SenderID().GetSubjectID();
    for (int i = 0; i < event.NumOfData(); i++) {
        RCRegion* r = event.RCData(i);
        if (r == 0) continue;
        unsigned long long token = 0;
        unsigned int st = api->vr_submit(OPENR_VR_EFFECTOR, sender.GetOID().GetAddress(),
                                         sender.GetSelector(), r->Base(), r->Size(), &token);
        if (st == oSUCCESS) {
            playing_[token] = r;
        } else {
            // A malformed vector is not played: give it back at once.
            observer[obsEffector]->AssertReadyFor(r);
        }
    }
}

void
VirtualRobotComm::Event(void* msg)
{
    const openr_vr_event* ev = static_cast<const openr_vr_event*>(msg);
    if (ev->kind == OPENR_VR_DONE) {
        std::map<unsigned long long, RCRegion*>::iterator it = playing_.find(ev->token);
        if (it == playing_.end()) return;
        // Release first, then ASSERT-READY: the sender reuses a region as soon as its
        // count is back to 1 (robot-api 8.2.3).
        observer[obsEffector]->AssertReadyFor(it->second);
        playing_.erase(it);
    } else if (ev->kind == OPENR_VR_DATA) {
        Publish(ev->service == OPENR_VR_IMAGE ? sbjFbkImageSensor : sbjSensor, ev->mem_id, ev->size);
    }
}

void
VirtualRobotComm::Publish(int sbj, unsigned int memID, unsigned int size)
{
    const openr_host_api* api = openr_host();
    void* base = api->shm_base(memID, 0);
    if (base == 0) return;
    RCRegion* r = new RCRegion(memID, 0, base, size);   // takes its own reference
    api->shm_unref(memID);                               // the event's one
    subject[sbj]->SetData(r);
    subject[sbj]->NotifyObservers();
    r->RemoveReference();   // observers' queues keep what they still need
}
