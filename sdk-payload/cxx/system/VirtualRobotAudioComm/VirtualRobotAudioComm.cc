// VirtualRobotAudioComm.cc
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>

#include "system/common/VRShared.h"
#include "VirtualRobotAudioComm.h"

OStatus
VirtualRobotAudioComm::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    const openr_host_api* api = openr_host();
    if (api == 0) return oFAIL;
    api->vr_attach(OPENR_VR_SPEAKER, Extra_Entry[entryEvent]);
    api->vr_attach(OPENR_VR_MIC, Extra_Entry[entryEvent]);
    return oSUCCESS;
}

OStatus
VirtualRobotAudioComm::DoStart(const OSystemEvent& event)
{
    // The speaker asserted ready to each subject at its connection (vrConnected).
    ENABLE_ALL_SUBJECT;
    return oSUCCESS;
}

OStatus
VirtualRobotAudioComm::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    return oSUCCESS;
}

OStatus
VirtualRobotAudioComm::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
VirtualRobotAudioComm::NotifySpeaker(const ONotifyEvent& event)
{
    vrSubmit(observer[obsSpeaker], event, OPENR_VR_SPEAKER, &playing_);
}

void
VirtualRobotAudioComm::Event(void* msg)
{
    const openr_vr_event* ev = static_cast<const openr_vr_event*>(msg);
    if (ev->kind == OPENR_VR_CONNECTED) {
        vrConnected(observer[obsSpeaker]);
    } else if (ev->kind == OPENR_VR_DONE) {
        vrDone(observer[obsSpeaker], ev->token, &playing_);
    } else if (ev->kind == OPENR_VR_DATA) {
        vrPublish(subject[sbjMic], ev->mem_id, ev->size);
    }
}
