//
// MovingEar.h
//
// Flicks the ears (Joint4 plungers) in turn: one ear goes to STATE1 for
// 128 ms, then both rest for the remaining 1.92 s of the vector.
//

#ifndef MovingEar_h_DEFINED
#define MovingEar_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_EAR = 2;
const int NUM_COMMAND_VECTOR = 2;

static const char* const EAR_LOCATOR[NUM_EAR] = {
    "PRM:/r1/c1/c2/c3/e5-Joint4:15",    // left ear
    "PRM:/r1/c1/c2/c3/e6-Joint4:16"     // right ear
};

// 16 values of 16 frames each: one vector lasts 256 frames (2.048 s).
const int  EAR_VALUES = ocommandMAX_FRAMES;
const word EAR_PERIOD = 16;

class MovingEar : public OObject {
public:
    MovingEar();
    virtual ~MovingEar() {}

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
    OPrimitiveID primitiveID[NUM_EAR];
    RCRegion*    region[NUM_COMMAND_VECTOR];
};

#endif // MovingEar_h_DEFINED
