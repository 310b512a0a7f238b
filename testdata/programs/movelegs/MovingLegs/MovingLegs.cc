//
// MovingLegs.cc
//
// Moves the twelve leg joints of an ERS-7.
//
// Joint commands are sent as OCommandVectorData in shared memory
// regions. One vector holds ocommandMAX_FRAMES (16) target angles per
// joint, one per 8 ms frame, so one vector lasts 128 ms. The effector
// (OVirtualRobotComm) asserts "ready" each time it has finished playing
// a vector; we keep it busy by sending two vectors at the start and one
// more on every ASSERT READY.
//

#include <math.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "MovingLegs.h"

MovingLegs::MovingLegs() : movingLegsState(MLS_IDLE), primed(false), frameCount(0)
{
    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        jointID[i] = oprimitiveID_UNDEF;
        startPosture[i] = 0.0;
    }
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
MovingLegs::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingLegs::DoInit()\n"));

    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenPrimitives();
    NewCommandVectorData();

    OStatus result = OPENR::SetMotorPower(opowerON);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "MovingLegs::DoInit()",
                  "OPENR::SetMotorPower() FAILED", result));
    }

    return oSUCCESS;
}

OStatus
MovingLegs::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingLegs::DoStart()\n"));

    SetJointGain();
    ReadStartPosture();

    movingLegsState = MLS_ADJUSTING;
    OSYSPRINT(("MovingLegs : adjusting to the base posture\n"));

    //
    // The effector may have asserted ready when we were connected; if
    // not, the first vectors are sent from Ready().
    //
    if (subject[sbjMove]->IsReady()) {
        SendFirstVectors();
    }

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
MovingLegs::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingLegs::DoStop()\n"));

    movingLegsState = MLS_IDLE;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
MovingLegs::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
MovingLegs::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert()) return;
    if (movingLegsState == MLS_IDLE || movingLegsState == MLS_DONE) return;

    if (!primed) {
        SendFirstVectors();
        return;
    }

    if (SetNextVector()) {
        subject[sbjMove]->NotifyObservers();
    }
}

void
MovingLegs::SendFirstVectors()
{
    //
    // Two vectors in one notification: the effector plays the second
    // right after the first, so there is no gap while we wait for the
    // next ASSERT READY.
    //
    primed = true;
    bool ok = SetNextVector();
    if (ok) SetNextVector();
    subject[sbjMove]->NotifyObservers();
}

void
MovingLegs::OpenPrimitives()
{
    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(LEG_JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "MovingLegs::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", LEG_JOINT_LOCATOR[i], result));
        }
    }
}

void
MovingLegs::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {

        result = OPENR::NewCommandVectorData(NUM_LEG_JOINTS,
                                             &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "MovingLegs::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_LEG_JOINTS);

        for (int j = 0; j < NUM_LEG_JOINTS; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataJOINT_COMMAND2, jointID[j], ocommandMAX_FRAMES);
        }
    }
}

void
MovingLegs::SetJointGain()
{
    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        OPENR::EnableJointGain(jointID[i]);
        switch (i % 3) {
        case 0:
            OPENR::SetJointGain(jointID[i], LEG_J1_PGAIN, LEG_J1_IGAIN, LEG_J1_DGAIN,
                                PSHIFT, ISHIFT, DSHIFT);
            break;
        case 1:
            OPENR::SetJointGain(jointID[i], LEG_J2_PGAIN, LEG_J2_IGAIN, LEG_J2_DGAIN,
                                PSHIFT, ISHIFT, DSHIFT);
            break;
        default:
            OPENR::SetJointGain(jointID[i], LEG_J3_PGAIN, LEG_J3_IGAIN, LEG_J3_DGAIN,
                                PSHIFT, ISHIFT, DSHIFT);
            break;
        }
    }
}

void
MovingLegs::ReadStartPosture()
{
    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        OJointValue current;
        if (OPENR::GetJointValue(jointID[i], &current) == oSUCCESS) {
            startPosture[i] = degrees(current.value / 1000000.0);
        } else {
            startPosture[i] = BASE_POSTURE[i];
        }
    }
}

//
// Target angle (degrees) of a joint at a given frame of the motion.
//
double
MovingLegs::JointAngle(int joint, int frame)
{
    if (frame < ADJUST_FRAMES) {
        double t = (double)(frame + 1) / ADJUST_FRAMES;
        return startPosture[joint] + (BASE_POSTURE[joint] - startPosture[joint]) * t;
    }

    double angle = BASE_POSTURE[joint];
    if (joint % 3 == 0) {
        // J1: left legs and right legs swing in opposite phase.
        double phase = 2.0 * M_PI * (frame - ADJUST_FRAMES) / SWING_PERIOD;
        double sign  = (joint < 6) ? 1.0 : -1.0;
        angle += sign * SWING_AMPLITUDE * sin(phase);
    }
    return angle;
}

//
// Fill a free region with the next 16 frames and queue it.
// Returns false when there is nothing more to send.
//
bool
MovingLegs::SetNextVector()
{
    const int lastFrame = ADJUST_FRAMES + NUM_SWINGS * SWING_PERIOD;

    if (frameCount >= lastFrame) {
        if (movingLegsState != MLS_DONE) {
            movingLegsState = MLS_DONE;
            OSYSPRINT(("MovingLegs : done, holding the base posture\n"));
        }
        return false;
    }

    int index = FindFreeRegion();
    if (index < 0) {
        OSYSLOG1((osyslogWARNING, "MovingLegs : no free command vector"));
        return false;
    }

    if (frameCount >= ADJUST_FRAMES && movingLegsState == MLS_ADJUSTING) {
        movingLegsState = MLS_SWINGING;
        OSYSPRINT(("MovingLegs : swinging %d times\n", NUM_SWINGS));
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    for (int j = 0; j < NUM_LEG_JOINTS; j++) {
        OCommandData* data = cmdVecData->GetData(j);
        OJointCommandValue2* jval = (OJointCommandValue2*)data->value;
        for (int f = 0; f < ocommandMAX_FRAMES; f++) {
            jval[f].value = oradians(JointAngle(j, frameCount + f));
        }
    }
    frameCount += ocommandMAX_FRAMES;

    subject[sbjMove]->SetData(region[index]);
    return true;
}

//
// A region is free again when only we hold it (reference count 1):
// the effector releases it once the vector has been played.
//
int
MovingLegs::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}
