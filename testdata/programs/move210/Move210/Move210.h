//
// Move210.h
//
// Moves the legs, head and tail of an ERS-210 and lights its eye
// lights, mode indicator and tail lights.
//

#ifndef Move210_h_DEFINED
#define Move210_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

enum Move210State {
    M2_IDLE,
    M2_ADJUSTING,       // from the current posture to the base posture
    M2_SWINGING,        // swinging the left front leg and the tail
    M2_DONE             // holding the base posture, nothing more to send
};

const int NUM_JOINTS         = 17;
const int NUM_LEDS           = 9;
const int NUM_COMMAND_VECTOR = 4;

// ERS-210 joints (MI210 2.1). The joint names repeat (every leg has a j1),
// so a joint is known by its whole locator.
static const char* const JOINT_LOCATOR[NUM_JOINTS] = {
    "PRM:/r2/c1-Joint2:j1",         //  0 left front  J1
    "PRM:/r2/c1/c2-Joint2:j2",      //  1 left front  J2
    "PRM:/r2/c1/c2/c3-Joint2:j3",   //  2 left front  J3
    "PRM:/r3/c1-Joint2:j1",         //  3 left rear   J1
    "PRM:/r3/c1/c2-Joint2:j2",      //  4 left rear   J2
    "PRM:/r3/c1/c2/c3-Joint2:j3",   //  5 left rear   J3
    "PRM:/r4/c1-Joint2:j1",         //  6 right front J1
    "PRM:/r4/c1/c2-Joint2:j2",      //  7 right front J2
    "PRM:/r4/c1/c2/c3-Joint2:j3",   //  8 right front J3
    "PRM:/r5/c1-Joint2:j1",         //  9 right rear  J1
    "PRM:/r5/c1/c2-Joint2:j2",      // 10 right rear  J2
    "PRM:/r5/c1/c2/c3-Joint2:j3",   // 11 right rear  J3
    "PRM:/r1/c1-Joint2:j1",         // 12 head tilt
    "PRM:/r1/c1/c2-Joint2:j2",      // 13 head pan
    "PRM:/r1/c1/c2/c3-Joint2:j3",   // 14 head roll
    "PRM:/r6/c1-Joint2:j1",         // 15 tail pan
    "PRM:/r6/c2-Joint2:j2"          // 16 tail tilt
};

const int LF_J1     = 0;
const int TAIL_PAN  = 15;

static const char* const LED_LOCATOR[NUM_LEDS] = {
    "PRM:/r1/c1/c2/c3/l1-LED2:l1",  // 0 eye light lower left
    "PRM:/r1/c1/c2/c3/l2-LED2:l2",  // 1 eye light middle left
    "PRM:/r1/c1/c2/c3/l3-LED2:l3",  // 2 eye light upper left
    "PRM:/r1/c1/c2/c3/l4-LED2:l4",  // 3 eye light lower right
    "PRM:/r1/c1/c2/c3/l5-LED2:l5",  // 4 eye light middle right
    "PRM:/r1/c1/c2/c3/l6-LED2:l6",  // 5 eye light upper right
    "PRM:/r1/c1/c2/c3/l7-LED2:l7",  // 6 mode indicator
    "PRM:/r6/l1-LED2:l1",           // 7 tail light blue
    "PRM:/r6/l2-LED2:l2"            // 8 tail light orange
};

const int MODE_LED      = 6;
const int TAIL_BLUE     = 7;
const int TAIL_ORANGE   = 8;

// Base posture in degrees, in JOINT_LOCATOR order.
static const double BASE_POSTURE[NUM_JOINTS] = {
     30.0, 10.0,  40.0,     // left front
    -30.0, 10.0,  40.0,     // left rear
     30.0, 10.0,  40.0,     // right front
    -30.0, 10.0,  40.0,     // right rear
    -20.0, 30.0,  10.0,     // head tilt, pan, roll
      0.0, 10.0             // tail pan, tilt
};

// Standard ERS-210 gains (MI210 2.2): P, I, D per joint, in JOINT_LOCATOR order.
static const word GAIN[NUM_JOINTS][3] = {
    { 0x16, 0x04, 0x08 }, { 0x14, 0x04, 0x06 }, { 0x23, 0x04, 0x05 },
    { 0x16, 0x04, 0x08 }, { 0x14, 0x04, 0x06 }, { 0x23, 0x04, 0x05 },
    { 0x16, 0x04, 0x08 }, { 0x14, 0x04, 0x06 }, { 0x23, 0x04, 0x05 },
    { 0x16, 0x04, 0x08 }, { 0x14, 0x04, 0x06 }, { 0x23, 0x04, 0x05 },
    { 0x0a, 0x08, 0x0c }, { 0x0d, 0x08, 0x0b }, { 0x0a, 0x08, 0x0c },
    { 0x0a, 0x00, 0x18 }, { 0x07, 0x00, 0x11 }
};
const word PSHIFT = 0x0e, ISHIFT = 0x02, DSHIFT = 0x0f;

const int ADJUST_FRAMES  = 128;    // 128 x 8 ms = 1 s
const int SWING_PERIOD   = 128;    // one swing = 1 s
const int NUM_SWINGS     = 4;
const double LEG_SWING   = 20.0;   // degrees, left front J1
const double TAIL_SWING  = 15.0;   // degrees, tail pan

class Move210 : public OObject {
public:
    Move210();
    virtual ~Move210() {}

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
    double JointAngle(int joint, int frame);    // degrees
    bool LedOn(int led, int vectorIndex);

    Move210State    state;
    bool            primed;         // first two vectors sent?
    int             frameCount;     // frames put into vectors so far

    OPrimitiveID    jointID[NUM_JOINTS];
    OPrimitiveID    ledID[NUM_LEDS];
    double          startPosture[NUM_JOINTS];   // degrees
    RCRegion*       region[NUM_COMMAND_VECTOR];
};

#endif // Move210_h_DEFINED
