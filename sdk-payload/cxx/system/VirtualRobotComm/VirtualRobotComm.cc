// VirtualRobotComm.cc
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>

#include "system/common/VRShared.h"
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
    // The effector asserted ready to each subject at its connection (vrConnected).
    ENABLE_ALL_SUBJECT;
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
    vrSubmit(observer[obsEffector], event, OPENR_VR_EFFECTOR, &playing_);
}

void
VirtualRobotComm::Event(void* msg)
{
    const openr_vr_event* ev = static_cast<const openr_vr_event*>(msg);
    if (ev->kind == OPENR_VR_CONNECTED) {
        vrConnected(observer[obsEffector]);
    } else if (ev->kind == OPENR_VR_DONE) {
        vrDone(observer[obsEffector], ev->token, &playing_);
    } else if (ev->kind == OPENR_VR_DATA) {
        vrPublish(subject[ev->service == OPENR_VR_IMAGE ? sbjFbkImageSensor : sbjSensor], ev->mem_id, ev->size);
    }
}
