//
// HeadSweep: keeps the head of an ERS-7 moving for as long as it runs (pan and both
// tilts on sine waves of different periods), so that every camera image differs from
// the one before (the camera benchmark's honest load: nothing can be reused).
//
#ifndef HeadSweep_h_DEFINED
#define HeadSweep_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_SWEEP_JOINTS   = 3;   // tilt1, pan, tilt2
const int NUM_COMMAND_VECTOR = 3;

class HeadSweep : public OObject {
public:
    HeadSweep();
    virtual ~HeadSweep() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit (const OSystemEvent& event);
    virtual OStatus DoStart(const OSystemEvent& event);
    virtual OStatus DoStop (const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

private:
    void NewCommandVectors();
    bool SendVector();     // false when every region is still in use
    double Target(int joint, int frame);    // degrees at command frame `frame`

    bool         running;
    bool         gainsOn;
    int          frames;                     // command frames sent so far
    OPrimitiveID jointID[NUM_SWEEP_JOINTS];
    double       start[NUM_SWEEP_JOINTS];    // degrees when the sweep began
    RCRegion*    region[NUM_COMMAND_VECTOR];
};

#endif // HeadSweep_h_DEFINED
