//
// MovingLegs.h
//

#ifndef MovingLegs_h_DEFINED
#define MovingLegs_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

enum MovingLegsState {
    MLS_IDLE,
    MLS_ADJUSTING,      // from the current posture to the base posture
    MLS_SWINGING,       // swinging the legs back and forth
    MLS_DONE            // holding the base posture, nothing more to send
};

const int NUM_LEG_JOINTS     = 12;
const int NUM_COMMAND_VECTOR = 4;

// Leg joints of the ERS-7: left front, left rear, right front, right rear;
// J1 (rotator), J2 (abductor), J3 (knee) for each leg.
static const char* const LEG_JOINT_LOCATOR[NUM_LEG_JOINTS] = {
    "PRM:/r2/c1-Joint2:21",       // left front  J1
    "PRM:/r2/c1/c2-Joint2:22",    // left front  J2
    "PRM:/r2/c1/c2/c3-Joint2:23", // left front  J3
    "PRM:/r3/c1-Joint2:31",       // left rear   J1
    "PRM:/r3/c1/c2-Joint2:32",    // left rear   J2
    "PRM:/r3/c1/c2/c3-Joint2:33", // left rear   J3
    "PRM:/r4/c1-Joint2:41",       // right front J1
    "PRM:/r4/c1/c2-Joint2:42",    // right front J2
    "PRM:/r4/c1/c2/c3-Joint2:43", // right front J3
    "PRM:/r5/c1-Joint2:51",       // right rear  J1
    "PRM:/r5/c1/c2-Joint2:52",    // right rear  J2
    "PRM:/r5/c1/c2/c3-Joint2:53"  // right rear  J3
};

// Base posture in degrees (J1, J2, J3 of each leg).
static const double BASE_POSTURE[NUM_LEG_JOINTS] = {
     30.0, 10.0,  30.0,     // left front
    -30.0, 10.0,  30.0,     // left rear
     30.0, 10.0,  30.0,     // right front
    -30.0, 10.0,  30.0      // right rear
};

// Weak leg gains for the ERS-7 (PGAIN, IGAIN, DGAIN per joint kind).
const word LEG_J1_PGAIN = 0x10, LEG_J1_IGAIN = 0x04, LEG_J1_DGAIN = 0x01;
const word LEG_J2_PGAIN = 0x0a, LEG_J2_IGAIN = 0x04, LEG_J2_DGAIN = 0x01;
const word LEG_J3_PGAIN = 0x10, LEG_J3_IGAIN = 0x04, LEG_J3_DGAIN = 0x01;
const word PSHIFT = 0x0e, ISHIFT = 0x02, DSHIFT = 0x0f;

const int ADJUST_FRAMES  = 128;    // 128 x 8 ms = 1 s
const int SWING_PERIOD   = 128;    // one swing = 1 s
const int NUM_SWINGS     = 4;
const double SWING_AMPLITUDE = 20.0;   // degrees, J1 only

class MovingLegs : public OObject {
public:
    MovingLegs();
    virtual ~MovingLegs() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

private:
    void OpenPrimitives();
    void NewCommandVectorData();
    void SetJointGain();
    void ReadStartPosture();

    void SendFirstVectors();
    bool SetNextVector();           // false when the motion is over
    int  FindFreeRegion();
    double JointAngle(int joint, int frame);   // degrees

    MovingLegsState movingLegsState;
    bool            primed;         // first two vectors sent?
    int             frameCount;     // frames put into vectors so far

    OPrimitiveID    jointID[NUM_LEG_JOINTS];
    double          startPosture[NUM_LEG_JOINTS];   // degrees
    RCRegion*       region[NUM_COMMAND_VECTOR];
};

#endif // MovingLegs_h_DEFINED
