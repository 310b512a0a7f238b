//
// BlinkingHeadLED.h
//
// Blinks the six LED2 lights of the head (head lights, mode indicator,
// wireless-LAN light) in an 8-step pattern: each step lasts 512 ms.
//

#ifndef BlinkingHeadLED_h_DEFINED
#define BlinkingHeadLED_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_HEAD_LED = 6;
const int NUM_COMMAND_VECTOR = 2;

static const char* const HEAD_LED_LOCATOR[NUM_HEAD_LED] = {
    "PRM:/r1/c1/c2/c3/l1-LED2:l1",
    "PRM:/r1/c1/c2/c3/l2-LED2:l2",
    "PRM:/r1/c1/c2/c3/l3-LED2:l3",
    "PRM:/r1/c1/c2/c3/l4-LED2:l4",
    "PRM:/r1/c1/c2/c3/l5-LED2:l5",
    "PRM:/r1/c1/c2/c3/l6-LED2:l6"
};

// One vector holds 8 steps; each step holds its value for 64 frames
// (64 x 8 ms = 512 ms), so one vector lasts 4.096 s.
const int  HEAD_LED_STEPS  = 8;
const word HEAD_LED_PERIOD = 64;

class BlinkingHeadLED : public OObject {
public:
    BlinkingHeadLED();
    virtual ~BlinkingHeadLED() {}

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
    void SendFirstVectors();
    bool SetNextVector();
    int  FindFreeRegion();
    void FillVector(OCommandVectorData* cmdVecData, int vectorIndex);

    bool         running;
    bool         primed;
    int          numVectors;    // vectors filled so far
    OPrimitiveID primitiveID[NUM_HEAD_LED];
    RCRegion*    region[NUM_COMMAND_VECTOR];
};

#endif // BlinkingHeadLED_h_DEFINED
