//
// Sensors.cc
//
// Observes the sensor frames of OVirtualRobotComm. Each
// OSensorFrameVectorData holds one entry per sensor and joint of the
// robot; the entries are found by comparing their primitive IDs with
// the IDs we got from OPENR::OpenPrimitive(). Every entry carries
// several frames, the newest one last.
//

#include <stdio.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Sensors.h"

Sensors::Sensors() : initSensorIndex(false), numNotify(0), numPrints(0)
{
    for (int i = 0; i < NUM_WATCHED_JOINTS; i++) {
        jointID[i]     = oprimitiveID_UNDEF;
        sensorIndex[i] = -1;
    }
}

OStatus
Sensors::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    for (int i = 0; i < NUM_WATCHED_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(WATCHED_JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "Sensors::DoInit()",
                      "OPENR::OpenPrimitive() FAILED", WATCHED_JOINT_LOCATOR[i], result));
        }
    }
    return oSUCCESS;
}

OStatus
Sensors::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Sensors::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Sensors::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Sensors::Notify(const ONotifyEvent& event)
{
    OSensorFrameVectorData* sensorVec = (OSensorFrameVectorData*)event.Data(0);

    if (initSensorIndex == false) {
        FindSensorIndices(sensorVec);
        initSensorIndex = true;
    }

    if (numPrints < MAX_PRINTS && numNotify % PRINT_EVERY == 0) {
        numPrints++;

        //
        // Build the whole line first: one OSYSPRINT is printed in one
        // piece, even while other objects print at the same time.
        //
        char line[128];
        char* p = line;
        p += sprintf(p, "Sensors : frame");
        for (int i = 0; i < NUM_WATCHED_JOINTS; i++) {
            int idx = sensorIndex[i];
            if (idx < 0) continue;

            OSensorFrameInfo* info = sensorVec->GetInfo(idx);
            OSensorFrameData* data = sensorVec->GetData(idx);
            int newest = info->numFrames - 1;     // the last frame is the newest
            OJointValue* jval = (OJointValue*)&data->frame[newest];

            if (i == 0) p += sprintf(p, " %u LF", (unsigned int)(info->frameNumber + newest));
            p += sprintf(p, " J%d %d", i + 1, (int)degrees(jval->value / 1000000.0));
        }
        OSYSPRINT(("%s deg\n", line));
    }
    numNotify++;

    observer[event.ObsIndex()]->AssertReady();
}

void
Sensors::FindSensorIndices(OSensorFrameVectorData* sensorVec)
{
    for (int i = 0; i < NUM_WATCHED_JOINTS; i++) {
        for (int j = 0; j < (int)sensorVec->vectorInfo.numData; j++) {
            OSensorFrameInfo* info = sensorVec->GetInfo(j);
            if (info->primitiveID == jointID[i]) {
                sensorIndex[i] = j;
                break;
            }
        }
    }
    OSYSPRINT(("Sensors : %d entries per vector, LF leg at %d %d %d\n",
               (int)sensorVec->vectorInfo.numData,
               sensorIndex[0], sensorIndex[1], sensorIndex[2]));
}
