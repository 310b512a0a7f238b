// VirtualRobotAudioComm.h - the OVirtualRobotAudioComm system object: the speaker and
// the microphones of the runtime's virtual robot.
#ifndef VirtualRobotAudioComm_h_DEFINED
#define VirtualRobotAudioComm_h_DEFINED

#include <map>

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class VirtualRobotAudioComm : public OObject {
public:
    VirtualRobotAudioComm() {}
    virtual ~VirtualRobotAudioComm() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void NotifySpeaker(const ONotifyEvent& event);
    void Event(void* msg);

private:
    std::map<unsigned long long, RCRegion*> playing_;
};

#endif
