//
// SensorKey.h
//

#ifndef SensorKey_h_DEFINED
#define SensorKey_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

//
// Every sensor of the ERS-7, grouped as they are printed.
//
const int NUM_JOINTS   = 18;
const int NUM_SWITCHES = 6;     // chin, 4 paws, wireless-LAN switch
const int NUM_TOUCH    = 4;     // head, back rear, back middle, back front
const int NUM_ACCEL    = 3;
const int NUM_PSD      = 3;     // head near, head far, chest
const int NUM_SENSORS  = NUM_JOINTS + NUM_SWITCHES + NUM_TOUCH + NUM_ACCEL + NUM_PSD;

static const char* const SENSOR_LOCATOR[NUM_SENSORS] = {
    // joints: head, LF, LR, RF, RR, tail
    "PRM:/r1/c1-Joint2:11",
    "PRM:/r1/c1/c2-Joint2:12",
    "PRM:/r1/c1/c2/c3-Joint2:13",
    "PRM:/r1/c1/c2/c3/c4-Joint2:14",
    "PRM:/r2/c1-Joint2:21", "PRM:/r2/c1/c2-Joint2:22", "PRM:/r2/c1/c2/c3-Joint2:23",
    "PRM:/r3/c1-Joint2:31", "PRM:/r3/c1/c2-Joint2:32", "PRM:/r3/c1/c2/c3-Joint2:33",
    "PRM:/r4/c1-Joint2:41", "PRM:/r4/c1/c2-Joint2:42", "PRM:/r4/c1/c2/c3-Joint2:43",
    "PRM:/r5/c1-Joint2:51", "PRM:/r5/c1/c2-Joint2:52", "PRM:/r5/c1/c2/c3-Joint2:53",
    "PRM:/r6/c1-Joint2:61",
    "PRM:/r6/c2-Joint2:62",
    // switches
    "PRM:/r1/c1/c2/c3/c4/s5-Sensor:s5",
    "PRM:/r2/c1/c2/c3/c4-Sensor:24",
    "PRM:/r3/c1/c2/c3/c4-Sensor:34",
    "PRM:/r4/c1/c2/c3/c4-Sensor:44",
    "PRM:/r5/c1/c2/c3/c4-Sensor:54",
    "PRM:/b1-Sensor:b1",
    // touch
    "PRM:/r1/c1/c2/c3/t1-Sensor:t1",
    "PRM:/t2-Sensor:t2",
    "PRM:/t3-Sensor:t3",
    "PRM:/t4-Sensor:t4",
    // accelerometer: front-back, right-left, up-down
    "PRM:/a1-Sensor:a1",
    "PRM:/a2-Sensor:a2",
    "PRM:/a3-Sensor:a3",
    // distance
    "PRM:/r1/c1/c2/c3/p1-Sensor:p1",
    "PRM:/r1/c1/c2/c3/p2-Sensor:p2",
    "PRM:/p1-Sensor:p1"
};

// Short names printed for the joints (the number of the locator).
static const char* const JOINT_NAME[NUM_JOINTS] = {
    "11", "12", "13", "14",
    "21", "22", "23", "31", "32", "33",
    "41", "42", "43", "51", "52", "53",
    "61", "62"
};

class SensorKey : public OObject {
public:
    SensorKey();
    virtual ~SensorKey() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    void InitSensorIndex(OSensorFrameVectorData* sensorVec);
    void PrintSensorVector(OSensorFrameVectorData* sensorVec);
    void PrintFrame(OSensorFrameVectorData* sensorVec, int frame);
    bool WaitReturnKey();

    OPrimitiveID sensorID[NUM_SENSORS];
    int          sensorIndex[NUM_SENSORS];
    bool         initSensorIndex;
    bool         stdinClosed;
    int          numPrinted;
};

#endif // SensorKey_h_DEFINED
