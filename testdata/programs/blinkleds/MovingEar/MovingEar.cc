//
// MovingEar.cc
//
// Flicks the ears (Joint4 plungers) in turn: one ear goes to STATE1 for
// 128 ms, then both rest for the remaining 1.92 s of the vector.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "MovingEar.h"

MovingEar::MovingEar() : running(false), primed(false), numVectors(0)
{
    for (int i = 0; i < NUM_EAR; i++) primitiveID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
MovingEar::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingEar::DoInit()\n"));

    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenPrimitives();
    NewCommandVectorData();

    //
    // LEDs and ear plungers are powered through the motor power.
    //
    OStatus result = OPENR::SetMotorPower(opowerON);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "MovingEar::DoInit()",
                  "OPENR::SetMotorPower() FAILED", result));
    }

    return oSUCCESS;
}

OStatus
MovingEar::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingEar::DoStart()\n"));

    running = true;
    OSYSPRINT(("MovingEar : ears take turns, one flick per %d frames\n",
               EAR_VALUES * (int)EAR_PERIOD));

    if (subject[sbjMove]->IsReady()) SendFirstVectors();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
MovingEar::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingEar::DoStop()\n"));

    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
MovingEar::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
MovingEar::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert() || !running) return;

    if (!primed) {
        SendFirstVectors();
        return;
    }

    if (SetNextVector()) subject[sbjMove]->NotifyObservers();
}

//
// Two vectors in the first notification, then one more each time the
// effector reports that one has been played: the pattern runs without
// gaps.
//
void
MovingEar::SendFirstVectors()
{
    primed = true;
    if (SetNextVector()) SetNextVector();
    subject[sbjMove]->NotifyObservers();
}

void
MovingEar::OpenPrimitives()
{
    for (int i = 0; i < NUM_EAR; i++) {
        OStatus result = OPENR::OpenPrimitive(EAR_LOCATOR[i], &primitiveID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "MovingEar::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", EAR_LOCATOR[i], result));
        }
    }
}

void
MovingEar::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {

        result = OPENR::NewCommandVectorData(NUM_EAR,
                                             &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "MovingEar::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_EAR);

        for (int j = 0; j < NUM_EAR; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataJOINT_COMMAND4, primitiveID[j], EAR_VALUES);
        }
    }
}

bool
MovingEar::SetNextVector()
{
    int index = FindFreeRegion();
    if (index < 0) {
        OSYSLOG1((osyslogWARNING, "MovingEar : no free command vector"));
        return false;
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    FillVector(cmdVecData, numVectors);
    numVectors++;

    subject[sbjMove]->SetData(region[index]);
    return true;
}

int
MovingEar::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}

//
// Even vectors flick the left ear, odd vectors the right one. Keeping a
// plunger in STATE1 for long can damage the robot: only one value of 16.
//
void
MovingEar::FillVector(OCommandVectorData* cmdVecData, int vectorIndex)
{
    int flicking = vectorIndex % 2;     // 0: left, 1: right

    for (int j = 0; j < NUM_EAR; j++) {
        OCommandData* data = cmdVecData->GetData(j);
        OJointCommandValue4* ear = (OJointCommandValue4*)data->value;
        for (int k = 0; k < EAR_VALUES; k++) {
            ear[k].value  = (j == flicking && k == 0) ? ojoint4_STATE1 : ojoint4_STATE0;
            ear[k].period = EAR_PERIOD;
        }
    }
}
