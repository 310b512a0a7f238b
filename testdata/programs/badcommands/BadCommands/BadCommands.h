//
// BadCommands.h
//

#ifndef BadCommands_h_DEFINED
#define BadCommands_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_JOINTS         = 5;   // tilt1, pan, tilt2, mouth, tail tilt
const int NUM_SLOTS          = 8;   // + a bad ID, an ear, a slot never set
const int SLOT_BAD_ID        = 5;
const int SLOT_EAR           = 6;
const int SLOT_UNSET         = 7;
const int NUM_COMMAND_VECTOR = 2;

static const char* const JOINT_LOCATOR[NUM_JOINTS] = {
    "PRM:/r1/c1-Joint2:11",
    "PRM:/r1/c1/c2-Joint2:12",
    "PRM:/r1/c1/c2/c3-Joint2:13",
    "PRM:/r1/c1/c2/c3/c4-Joint2:14",
    "PRM:/r6/c1-Joint2:61"
};

// There is no port r9: OpenPrimitive fails and leaves oprimitiveID_UNDEF.
static const char* const BAD_LOCATOR = "PRM:/r9/c1-Joint2:91";
static const char* const EAR_LOCATOR = "PRM:/r1/c1/c2/c3/e5-Joint4:15";

enum Phase {
    PHASE_RANGE,        // every joint beyond its software range
    PHASE_COMBINED,     // head lowered with tilt2 below the combined limit
    PHASE_VALID,        // everything in range again
    NUM_PHASES
};

static const char* const PHASE_NAME[NUM_PHASES] = { "range", "combined", "valid" };

// Targets in degrees per phase: tilt1, pan, tilt2, mouth, tail tilt.
static const double PHASE_TARGET[NUM_PHASES][NUM_JOINTS] = {
    {  30.0,  120.0,  60.0,  10.0,  0.0 },
    { -60.0, -120.0, -15.0, -80.0, 90.0 },
    { -10.0,    0.0,  10.0, -10.0, 30.0 }
};

const int VECTORS_PER_PHASE = 8;    // 8 x 128 ms = ~1 s

class BadCommands : public OObject {
public:
    BadCommands();
    virtual ~BadCommands() {}

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
    void SendFirstVectors();
    bool SetNextVector();
    int  FindFreeRegion();

    bool         running;
    bool         primed;
    bool         done;
    int          numSent;
    int          numReady;
    OPrimitiveID jointID[NUM_JOINTS];
    OPrimitiveID badID;
    OPrimitiveID earID;
    RCRegion*    region[NUM_COMMAND_VECTOR];
};

#endif // BadCommands_h_DEFINED
