// VirtualRobotComm.h - the OVirtualRobotComm system object: the OPEN-R side of the
// runtime's virtual robot.  It speaks the ordinary subject/observer protocol with user
// objects; the robot itself (queues, timing, joints, sensors) is the runtime's.
#ifndef VirtualRobotComm_h_DEFINED
#define VirtualRobotComm_h_DEFINED

#include <map>

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class VirtualRobotComm : public OObject {
public:
    VirtualRobotComm() {}
    virtual ~VirtualRobotComm() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    // Effector: command vectors from user subjects.
    void NotifyEffector(const ONotifyEvent& event);
    // Runtime events: a vector finished playing, or new sensor/camera data.
    void Event(void* msg);

private:
    // vr_submit token -> the received region it stands for.
    std::map<unsigned long long, RCRegion*> playing_;
};

#endif
