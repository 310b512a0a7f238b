//
// PIDGains.h
//

#ifndef PIDGains_h_DEFINED
#define PIDGains_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_LEG_JOINTS     = 12;
const int NUM_COMMAND_VECTOR = 2;
const int FIRST_RIGHT_JOINT  = 6;       // right legs: gains disabled again

static const char* const LEG_JOINT_LOCATOR[NUM_LEG_JOINTS] = {
    "PRM:/r2/c1-Joint2:21", "PRM:/r2/c1/c2-Joint2:22", "PRM:/r2/c1/c2/c3-Joint2:23",
    "PRM:/r3/c1-Joint2:31", "PRM:/r3/c1/c2-Joint2:32", "PRM:/r3/c1/c2/c3-Joint2:33",
    "PRM:/r4/c1-Joint2:41", "PRM:/r4/c1/c2-Joint2:42", "PRM:/r4/c1/c2/c3-Joint2:43",
    "PRM:/r5/c1-Joint2:51", "PRM:/r5/c1/c2-Joint2:52", "PRM:/r5/c1/c2/c3-Joint2:53"
};

static const char* const LEG_JOINT_NAME[NUM_LEG_JOINTS] = {
    "LF-J1", "LF-J2", "LF-J3", "LR-J1", "LR-J2", "LR-J3",
    "RF-J1", "RF-J2", "RF-J3", "RR-J1", "RR-J2", "RR-J3"
};

// Standard leg gains of the ERS-7 (Model Information), per joint kind.
const word STD_PGAIN[3] = { 0x1c, 0x14, 0x1c };
const word STD_IGAIN[3] = { 0x08, 0x04, 0x08 };
const word STD_DGAIN[3] = { 0x01, 0x01, 0x01 };
const word PSHIFT = 0x0e, ISHIFT = 0x02, DSHIFT = 0x0f;

// A deliberately different set for the left front J1.
const word ODD_PGAIN = 0x0c, ODD_IGAIN = 0x02, ODD_DGAIN = 0x08;

// Where the legs are sent (degrees J1, J2, J3, same for every leg).
static const double TARGET_POSTURE[3] = { 0.0, 10.0, 60.0 };

const int MOVE_FRAMES = 128;    // 1 s from the current posture to the target
const int HOLD_FRAMES = 64;     // then hold it for 0.5 s

class PIDGains : public OObject {
public:
    PIDGains();
    virtual ~PIDGains() {}

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
    void ExerciseGains();
    void PrintGain(int joint);

    void SendFirstVectors();
    bool SetNextVector();
    int  FindFreeRegion();

    bool         running;
    bool         primed;
    bool         done;
    int          frameCount;
    OPrimitiveID jointID[NUM_LEG_JOINTS];
    double       start[NUM_LEG_JOINTS];     // degrees
    RCRegion*    region[NUM_COMMAND_VECTOR];
};

#endif // PIDGains_h_DEFINED
