//
// LegSwing.cc
//
// The control loop of a Remote Processing program: it runs on the PC, the
// leg it moves is the robot's. Every OPENR:: call below goes to the robot
// through the gateway's proxy; the command vectors travel to the robot's
// effector through the gateway, and the sensor frames come back the same way.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "LegSwing.h"

LegSwing::LegSwing() : vectorCount(0), sensorCount(0)
{
    for (int i = 0; i < NUM_JOINTS; i++) jointID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
LegSwing::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenPrimitives();
    NewCommandVectorData();
    SetJointGain();

    OStatus result = OPENR::SetMotorPower(opowerON);
    OSYSPRINT(("LegSwing : motor power on, OStatus %d\n", (int)result));

    return oSUCCESS;
}

OStatus
LegSwing::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
LegSwing::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
LegSwing::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
LegSwing::OpenPrimitives()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d", "LegSwing::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", JOINT_LOCATOR[i], result));
        }
    }
    OSYSPRINT(("LegSwing : opened %s as primitive %d\n",
               JOINT_LOCATOR[0], (int)jointID[0]));
}

void
LegSwing::SetJointGain()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OPENR::EnableJointGain(jointID[i]);
        OPENR::SetJointGain(jointID[i], 0x10, 0x04, 0x01, 0x0e, 0x02, 0x0f);
    }
}

void
LegSwing::NewCommandVectorData()
{
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        OStatus result = OPENR::NewCommandVectorData(NUM_JOINTS, &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d", "LegSwing::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }
        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);
        cmdVecData->SetNumData(NUM_JOINTS);
        for (int j = 0; j < NUM_JOINTS; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataJOINT_COMMAND2, jointID[j], ocommandMAX_FRAMES);
        }
    }
}

int
LegSwing::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}

//
// J1 ramps from 0 to SWING_MAX degrees and back; J2 and J3 hold 10 and 30.
//
void
LegSwing::SendVector()
{
    int index = FindFreeRegion();
    if (index < 0) return;

    int step = vectorCount % (2 * SWING_VECTORS);
    if (step > SWING_VECTORS) step = 2 * SWING_VECTORS - step;
    double j1 = SWING_MAX * step / SWING_VECTORS;
    double angle[NUM_JOINTS] = { j1, 10.0, 30.0 };

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    for (int j = 0; j < NUM_JOINTS; j++) {
        OJointCommandValue2* jval = (OJointCommandValue2*)cmdVecData->GetData(j)->value;
        for (int f = 0; f < ocommandMAX_FRAMES; f++) {
            jval[f].value = oradians(angle[j]);
        }
    }
    vectorCount++;
    subject[sbjMove]->SetData(region[index]);
    subject[sbjMove]->NotifyObservers();
}

void
LegSwing::Ready(const OReadyEvent& event)
{
    if (event.IsAssert()) SendVector();
}

void
LegSwing::NotifySensor(const ONotifyEvent& event)
{
    OSensorFrameVectorData* sensor = (OSensorFrameVectorData*)event.Data(0);
    if (++sensorCount % REPORT_EVERY == 0) {
        OJointValue current;
        OStatus result = OPENR::GetJointValue(jointID[0], &current);
        if (result == oSUCCESS) {
            OSYSPRINT(("LegSwing : robot frame %d, right front J1 %d deg\n",
                       (int)sensor->GetInfo(0)->frameNumber,
                       (int)degrees(current.value / 1000000.0)));
        } else {
            OSYSPRINT(("LegSwing : GetJointValue() failed, OStatus %d\n", (int)result));
        }
    }
    observer[event.ObsIndex()]->AssertReady();
}
