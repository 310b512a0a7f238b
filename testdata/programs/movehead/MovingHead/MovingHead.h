//
// MovingHead.h
//

#ifndef MovingHead_h_DEFINED
#define MovingHead_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

enum MovingHeadState {
    MHS_IDLE,
    MHS_START,          // first vector: hold the current angles
    MHS_ADJUSTING,      // from the current posture to the first posture
    MHS_MOVING,         // between postures, mouth open on the way
    MHS_HOLDING,        // holding a posture, mouth closed
    MHS_DONE
};

const int NUM_HEAD_JOINTS    = 4;       // tilt1, pan, tilt2, mouth
const int NUM_COMMAND_VECTOR = 2;
const int NUM_POSTURES       = 4;

static const char* const HEAD_JOINT_LOCATOR[NUM_HEAD_JOINTS] = {
    "PRM:/r1/c1-Joint2:11",         // neck tilt1
    "PRM:/r1/c1/c2-Joint2:12",      // neck pan
    "PRM:/r1/c1/c2/c3-Joint2:13",   // neck tilt2
    "PRM:/r1/c1/c2/c3/c4-Joint2:14" // mouth
};

static const char* const HEAD_JOINT_NAME[NUM_HEAD_JOINTS] = {
    "TILT1", "PAN", "TILT2", "MOUTH"
};

// Postures in degrees: tilt1, pan, tilt2, mouth (closed).
static const double POSTURE[NUM_POSTURES][NUM_HEAD_JOINTS] = {
    { -10.0,   0.0, 20.0, -3.0 },   // looking ahead
    { -20.0,  60.0, 30.0, -3.0 },   // to the left
    { -30.0,   0.0, 10.0, -3.0 },   // down
    { -20.0, -60.0, 30.0, -3.0 }    // to the right
};

// Head gains of the ERS-7 (standard = weak for the head).
const word TILT1_PGAIN = 0x0a, TILT1_IGAIN = 0x04, TILT1_DGAIN = 0x02;
const word PAN_PGAIN   = 0x08, PAN_IGAIN   = 0x02, PAN_DGAIN   = 0x04;
const word TILT2_PGAIN = 0x08, TILT2_IGAIN = 0x04, TILT2_DGAIN = 0x02;
const word MOUTH_PGAIN = 0x08, MOUTH_IGAIN = 0x00, MOUTH_DGAIN = 0x04;
const word PSHIFT = 0x0e, ISHIFT = 0x02, DSHIFT = 0x0f;

class MovingHead : public OObject {
public:
    MovingHead();
    virtual ~MovingHead() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

    //
    // Motion timing, in command vectors of 16 frames (128 ms).
    //
    static const double MOUTH_OPEN     = -30.0;   // degrees, on the way
    static const double ADJUST_VECTORS = 8.0;     // 1.024 s
    static const double MOVE_VECTORS   = 6.0;     // 0.768 s
    static const double HOLD_VECTORS   = 3.0;     // 0.384 s
    static const int    NUM_CYCLES     = 1;

private:
    void OpenPrimitives();
    void NewCommandVectorData();
    void SetJointGain();
    void ReadCurrentPosture();

    void SendFirstVectors();
    bool SetNextVector();
    int  FindFreeRegion();
    void NextState();
    double Target(int joint, int frame);    // degrees, frame in the state

    MovingHeadState movingHeadState;
    bool            primed;
    int             stateVector;    // vectors sent in this state
    int             posture;        // posture we move to / hold
    int             numPostures;    // postures reached so far

    OPrimitiveID    jointID[NUM_HEAD_JOINTS];
    double          current[NUM_HEAD_JOINTS];   // degrees
    double          from[NUM_HEAD_JOINTS];      // start of the move
    RCRegion*       region[NUM_COMMAND_VECTOR];
};

#endif // MovingHead_h_DEFINED
