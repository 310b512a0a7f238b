//
// BlinkingFaceLED.h
//
// Ramps the 14 face lights (LED3) up and down, first on face A, then on
// face B: 16 frames per vector, 256 frames (2.048 s) per face.
//

#ifndef BlinkingFaceLED_h_DEFINED
#define BlinkingFaceLED_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_FACE_LED = 14;
const int NUM_COMMAND_VECTOR = 2;

static const char* const FACE_LED_LOCATOR[NUM_FACE_LED] = {
    "PRM:/r1/c1/c2/c3/la-LED3:la",
    "PRM:/r1/c1/c2/c3/lb-LED3:lb",
    "PRM:/r1/c1/c2/c3/lc-LED3:lc",
    "PRM:/r1/c1/c2/c3/ld-LED3:ld",
    "PRM:/r1/c1/c2/c3/le-LED3:le",
    "PRM:/r1/c1/c2/c3/lf-LED3:lf",
    "PRM:/r1/c1/c2/c3/lg-LED3:lg",
    "PRM:/r1/c1/c2/c3/lh-LED3:lh",
    "PRM:/r1/c1/c2/c3/li-LED3:li",
    "PRM:/r1/c1/c2/c3/lj-LED3:lj",
    "PRM:/r1/c1/c2/c3/lk-LED3:lk",
    "PRM:/r1/c1/c2/c3/ll-LED3:ll",
    "PRM:/r1/c1/c2/c3/lm-LED3:lm",
    "PRM:/r1/c1/c2/c3/ln-LED3:ln"
};

// 16 values of one frame each per vector (128 ms).
const int  FACE_LED_VALUES  = ocommandMAX_FRAMES;
const word FACE_LED_PERIOD  = 1;
// One face: 128 frames up (0 -> 255), 128 frames down (255 -> 0).
const int  FACE_RAMP_FRAMES = 128;
const int  FACE_FRAMES      = 2 * FACE_RAMP_FRAMES;

class BlinkingFaceLED : public OObject {
public:
    BlinkingFaceLED();
    virtual ~BlinkingFaceLED() {}

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
    OPrimitiveID primitiveID[NUM_FACE_LED];
    RCRegion*    region[NUM_COMMAND_VECTOR];
};

#endif // BlinkingFaceLED_h_DEFINED
