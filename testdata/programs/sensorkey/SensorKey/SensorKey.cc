//
// SensorKey.cc
//
// Prints the sensor frames of the robot. Compiled with -DWAIT_RETURN_KEY
// it waits for the RETURN key before each vector it prints (on the
// robot: the wireless console); without it, it prints every vector.
//
// One line per group and frame, each starting with the frame number:
//   SensorKey : frame F joint 11 -25.000 12 0.000 ...   (degrees)
//   SensorKey : frame F switch chin 0 paw 1 1 1 1 wlan 0 touch 0 0 0 0
//   SensorKey : frame F accel 0.000 0.000 9.807 psd 500.000 1500.000 900.000
// (accelerations in m/s^2, distances in mm.)
//

#include <stdio.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SensorKey.h"

SensorKey::SensorKey() : initSensorIndex(false), stdinClosed(false), numPrinted(0)
{
    for (int i = 0; i < NUM_SENSORS; i++) {
        sensorID[i]    = oprimitiveID_UNDEF;
        sensorIndex[i] = -1;
    }
}

OStatus
SensorKey::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    for (int i = 0; i < NUM_SENSORS; i++) {
        OStatus result = OPENR::OpenPrimitive(SENSOR_LOCATOR[i], &sensorID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "SensorKey::DoInit()",
                      "OPENR::OpenPrimitive() FAILED", SENSOR_LOCATOR[i], result));
        }
    }
    return oSUCCESS;
}

OStatus
SensorKey::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SensorKey::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SensorKey::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
SensorKey::Notify(const ONotifyEvent& event)
{
    OSensorFrameVectorData* sensorVec = (OSensorFrameVectorData*)event.Data(0);

    if (initSensorIndex == false) {
        InitSensorIndex(sensorVec);
        initSensorIndex = true;
    }

#ifdef WAIT_RETURN_KEY
    if (WaitReturnKey()) {
        PrintSensorVector(sensorVec);
    }
#else
    PrintSensorVector(sensorVec);
#endif

    observer[event.ObsIndex()]->AssertReady();
}

//
// Blocks this object until a line has been typed. At the end of the
// input it stops printing (once it has said so).
//
bool
SensorKey::WaitReturnKey()
{
    if (stdinClosed) return false;

    OSYSPRINT(("SensorKey : hit RETURN key\n"));
    int c;
    while ((c = getchar()) != '\n') {
        if (c == EOF) {
            stdinClosed = true;
            OSYSPRINT(("SensorKey : end of input, %d vectors printed\n", numPrinted));
            return false;
        }
    }
    return true;
}

void
SensorKey::InitSensorIndex(OSensorFrameVectorData* sensorVec)
{
    int found = 0;
    for (int i = 0; i < NUM_SENSORS; i++) {
        for (int j = 0; j < (int)sensorVec->vectorInfo.numData; j++) {
            if (sensorVec->GetInfo(j)->primitiveID == sensorID[i]) {
                sensorIndex[i] = j;
                found++;
                break;
            }
        }
    }
    OSYSPRINT(("SensorKey : %d entries, %d of %d sensors found\n",
               (int)sensorVec->vectorInfo.numData, found, NUM_SENSORS));
}

void
SensorKey::PrintSensorVector(OSensorFrameVectorData* sensorVec)
{
    numPrinted++;
    int numFrames = (int)sensorVec->GetInfo(0)->numFrames;
    OSYSPRINT(("SensorKey : vector %d first frame %u frames %d\n", numPrinted,
               (unsigned int)sensorVec->GetInfo(0)->frameNumber, numFrames));
    for (int f = 0; f < numFrames; f++) PrintFrame(sensorVec, f);
}

void
SensorKey::PrintFrame(OSensorFrameVectorData* sensorVec, int frame)
{
    char line[240];
    char* p;
    int s;
    unsigned int frameNumber = 0;

    for (s = 0; s < NUM_SENSORS; s++) {
        if (sensorIndex[s] >= 0) {
            frameNumber = sensorVec->GetInfo(sensorIndex[s])->frameNumber + frame;
            break;
        }
    }

    //
    // joints, in degrees (three lines: head, legs, tail)
    //
    int groups[4] = { 0, 4, 16, NUM_JOINTS };
    for (int g = 0; g < 3; g++) {
        p = line;
        p += sprintf(p, "SensorKey : frame %u joint", frameNumber);
        for (s = groups[g]; s < groups[g + 1]; s++) {
            if (sensorIndex[s] < 0) continue;
            OSensorFrameData* data = sensorVec->GetData(sensorIndex[s]);
            OJointValue* jval = (OJointValue*)&data->frame[frame];
            p += sprintf(p, " %s %.3f", JOINT_NAME[s], degrees(jval->value / 1000000.0));
        }
        OSYSPRINT(("%s\n", line));
    }

    //
    // switches and touch sensors
    //
    int value[NUM_SENSORS];
    for (s = NUM_JOINTS; s < NUM_SENSORS; s++) {
        value[s] = 0;
        if (sensorIndex[s] < 0) continue;
        OSensorFrameData* data = sensorVec->GetData(sensorIndex[s]);
        OSensorValue* sval = (OSensorValue*)&data->frame[frame];
        value[s] = (int)sval->value;
    }
    s = NUM_JOINTS;
    OSYSPRINT(("SensorKey : frame %u switch chin %d paw %d %d %d %d wlan %d touch %d %d %d %d\n",
               frameNumber, value[s], value[s + 1], value[s + 2], value[s + 3],
               value[s + 4], value[s + 5], value[s + 6], value[s + 7],
               value[s + 8], value[s + 9]));

    //
    // accelerometer (um/s^2 -> m/s^2) and distance sensors (um -> mm)
    //
    s = NUM_JOINTS + NUM_SWITCHES + NUM_TOUCH;
    OSYSPRINT(("SensorKey : frame %u accel %.3f %.3f %.3f psd %.3f %.3f %.3f\n",
               frameNumber,
               value[s] / 1000000.0, value[s + 1] / 1000000.0, value[s + 2] / 1000000.0,
               value[s + 3] / 1000.0, value[s + 4] / 1000.0, value[s + 5] / 1000.0));
}
