//
// LegSwing.h
//

#ifndef LegSwing_h_DEFINED
#define LegSwing_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_COMMAND_VECTOR = 2;
const int REPORT_EVERY       = 16;     // sensor frames between two reports
const int SWING_VECTORS      = 16;     // vectors per half swing (16 x 4 frames)
const double SWING_MAX       = 40.0;   // degrees

// The right front leg of the ERS-7: J1 swings, J2 and J3 hold.
const int NUM_JOINTS = 3;
static const char* const JOINT_LOCATOR[NUM_JOINTS] = {
    "PRM:/r4/c1-Joint2:41",
    "PRM:/r4/c1/c2-Joint2:42",
    "PRM:/r4/c1/c2/c3-Joint2:43"
};

class LegSwing : public OObject {
public:
    LegSwing();
    virtual ~LegSwing() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);
    void NotifySensor(const ONotifyEvent& event);

private:
    void OpenPrimitives();
    void NewCommandVectorData();
    void SetJointGain();
    int  FindFreeRegion();
    void SendVector();

    OPrimitiveID jointID[NUM_JOINTS];
    RCRegion*    region[NUM_COMMAND_VECTOR];
    int          vectorCount;
    int          sensorCount;
};

#endif // LegSwing_h_DEFINED
