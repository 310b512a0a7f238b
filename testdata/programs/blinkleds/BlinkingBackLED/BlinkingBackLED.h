//
// BlinkingBackLED.h
//
// Blinks the six back lights (LED3): the colour lights and the white
// lights take turns, 256 ms each.
//

#ifndef BlinkingBackLED_h_DEFINED
#define BlinkingBackLED_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_BACK_LED = 6;
const int NUM_COMMAND_VECTOR = 2;

static const char* const BACK_LED_LOCATOR[NUM_BACK_LED] = {
    "PRM:/lu-LED3:lu",
    "PRM:/lv-LED3:lv",
    "PRM:/lw-LED3:lw",
    "PRM:/lx-LED3:lx",
    "PRM:/ly-LED3:ly",
    "PRM:/lz-LED3:lz"
};

// Two values per vector, 32 frames (256 ms) each: one vector lasts 512 ms.
const int  BACK_LED_VALUES = 2;
const word BACK_LED_PERIOD = 32;
const sword BACK_LED_ON    = 255;
const sword BACK_LED_OFF   = 0;

class BlinkingBackLED : public OObject {
public:
    BlinkingBackLED();
    virtual ~BlinkingBackLED() {}

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
    OPrimitiveID primitiveID[NUM_BACK_LED];
    RCRegion*    region[NUM_COMMAND_VECTOR];
};

#endif // BlinkingBackLED_h_DEFINED
