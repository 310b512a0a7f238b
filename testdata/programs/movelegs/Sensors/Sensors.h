//
// Sensors.h
//

#ifndef Sensors_h_DEFINED
#define Sensors_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_WATCHED_JOINTS = 3;

// The left front leg of an ERS-7.
static const char* const WATCHED_JOINT_LOCATOR[NUM_WATCHED_JOINTS] = {
    "PRM:/r2/c1-Joint2:21",
    "PRM:/r2/c1/c2-Joint2:22",
    "PRM:/r2/c1/c2/c3-Joint2:23"
};

const int PRINT_EVERY = 8;      // sensor vectors arrive every 32 ms: 256 ms
const int MAX_PRINTS  = 24;

class Sensors : public OObject {
public:
    Sensors();
    virtual ~Sensors() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    void FindSensorIndices(OSensorFrameVectorData* sensorVec);

    OPrimitiveID jointID[NUM_WATCHED_JOINTS];
    int          sensorIndex[NUM_WATCHED_JOINTS];   // -1: not found yet
    bool         initSensorIndex;
    int          numNotify;
    int          numPrints;
};

#endif // Sensors_h_DEFINED
