//
// MovingHead.cc
//
// Swings the head of an ERS-7 between four postures and opens the mouth
// on the way from one posture to the next. Every posture is held for a
// moment with the mouth closed.
//
// The first vector holds the joints where they are (GetJointValue), so
// nothing jumps when the gains become effective on the first ASSERT
// READY; then the head adjusts to the first posture and starts moving.
//

#include <math.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "MovingHead.h"

MovingHead::MovingHead() : movingHeadState(MHS_IDLE), primed(false),
                           stateVector(0), posture(0), numPostures(0)
{
    for (int i = 0; i < NUM_HEAD_JOINTS; i++) {
        jointID[i] = oprimitiveID_UNDEF;
        current[i] = 0.0;
        from[i]    = 0.0;
    }
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
MovingHead::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingHead::DoInit()\n"));

    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenPrimitives();
    NewCommandVectorData();

    OStatus result = OPENR::SetMotorPower(opowerON);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "MovingHead::DoInit()",
                  "OPENR::SetMotorPower() FAILED", result));
    }

    return oSUCCESS;
}

OStatus
MovingHead::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingHead::DoStart()\n"));

    ReadCurrentPosture();
    movingHeadState = MHS_START;
    stateVector = 0;

    if (subject[sbjMove]->IsReady()) SendFirstVectors();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
MovingHead::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("MovingHead::DoStop()\n"));

    movingHeadState = MHS_IDLE;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
MovingHead::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
MovingHead::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert()) return;
    if (movingHeadState == MHS_IDLE || movingHeadState == MHS_DONE) return;

    if (!primed) {
        SendFirstVectors();
        return;
    }

    //
    // The first vector (the current angles) has been played: now the
    // gains can be switched on without a jump.
    //
    static bool gainSet = false;
    if (!gainSet) {
        SetJointGain();
        gainSet = true;
    }

    if (SetNextVector()) subject[sbjMove]->NotifyObservers();
}

void
MovingHead::SendFirstVectors()
{
    primed = true;
    if (SetNextVector()) SetNextVector();
    subject[sbjMove]->NotifyObservers();
}

void
MovingHead::OpenPrimitives()
{
    for (int i = 0; i < NUM_HEAD_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(HEAD_JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "MovingHead::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", HEAD_JOINT_LOCATOR[i], result));
        }
    }
}

void
MovingHead::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {

        result = OPENR::NewCommandVectorData(NUM_HEAD_JOINTS,
                                             &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "MovingHead::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_HEAD_JOINTS);

        for (int j = 0; j < NUM_HEAD_JOINTS; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataJOINT_COMMAND2, jointID[j], ocommandMAX_FRAMES);
        }
    }
}

void
MovingHead::SetJointGain()
{
    OPENR::EnableJointGain(jointID[0]);
    OPENR::SetJointGain(jointID[0], TILT1_PGAIN, TILT1_IGAIN, TILT1_DGAIN,
                        PSHIFT, ISHIFT, DSHIFT);

    OPENR::EnableJointGain(jointID[1]);
    OPENR::SetJointGain(jointID[1], PAN_PGAIN, PAN_IGAIN, PAN_DGAIN,
                        PSHIFT, ISHIFT, DSHIFT);

    OPENR::EnableJointGain(jointID[2]);
    OPENR::SetJointGain(jointID[2], TILT2_PGAIN, TILT2_IGAIN, TILT2_DGAIN,
                        PSHIFT, ISHIFT, DSHIFT);

    OPENR::EnableJointGain(jointID[3]);
    OPENR::SetJointGain(jointID[3], MOUTH_PGAIN, MOUTH_IGAIN, MOUTH_DGAIN,
                        PSHIFT, ISHIFT, DSHIFT);

    OSYSPRINT(("MovingHead : gains on\n"));
}

void
MovingHead::ReadCurrentPosture()
{
    for (int i = 0; i < NUM_HEAD_JOINTS; i++) {
        OJointValue value;
        if (OPENR::GetJointValue(jointID[i], &value) == oSUCCESS) {
            current[i] = degrees(value.value / 1000000.0);
        } else {
            current[i] = POSTURE[0][i];
        }
    }
    OSYSPRINT(("MovingHead : starting at %s %.1f %s %.1f %s %.1f %s %.1f\n",
               HEAD_JOINT_NAME[0], current[0], HEAD_JOINT_NAME[1], current[1],
               HEAD_JOINT_NAME[2], current[2], HEAD_JOINT_NAME[3], current[3]));
}

//
// Target angle (degrees) of a joint at frame f of the current state.
//
double
MovingHead::Target(int joint, int f)
{
    double t;

    switch (movingHeadState) {
    case MHS_START:
        return current[joint];

    case MHS_ADJUSTING:
        t = (double)(f + 1) / (ADJUST_VECTORS * ocommandMAX_FRAMES);
        return current[joint] + (POSTURE[0][joint] - current[joint]) * t;

    case MHS_MOVING:
        t = (double)(f + 1) / (MOVE_VECTORS * ocommandMAX_FRAMES);
        if (joint == 3) {
            // open the mouth on the way, closed again on arrival
            double closed = POSTURE[posture][3];
            return closed + (MOUTH_OPEN - closed) * sin(M_PI * t);
        }
        return from[joint] + (POSTURE[posture][joint] - from[joint]) * t;

    default:
        return POSTURE[posture][joint];
    }
}

//
// Leaves a state when all its vectors have been filled.
//
void
MovingHead::NextState()
{
    int vectors;
    switch (movingHeadState) {
    case MHS_START:     vectors = 1; break;
    case MHS_ADJUSTING: vectors = (int)ADJUST_VECTORS; break;
    case MHS_MOVING:    vectors = (int)MOVE_VECTORS; break;
    case MHS_HOLDING:   vectors = (int)HOLD_VECTORS; break;
    default:            return;
    }
    if (stateVector < vectors) return;

    stateVector = 0;
    switch (movingHeadState) {
    case MHS_START:
        movingHeadState = MHS_ADJUSTING;
        OSYSPRINT(("MovingHead : adjusting to posture 0\n"));
        break;

    case MHS_ADJUSTING:
    case MHS_MOVING:
        movingHeadState = MHS_HOLDING;
        numPostures++;
        OSYSPRINT(("MovingHead : holding posture %d\n", posture));
        break;

    case MHS_HOLDING:
        if (numPostures > NUM_CYCLES * NUM_POSTURES) {    // back at posture 0
            movingHeadState = MHS_DONE;
            OSYSPRINT(("MovingHead : done, %d postures\n", numPostures));
            break;
        }
        for (int j = 0; j < NUM_HEAD_JOINTS; j++) from[j] = POSTURE[posture][j];
        posture = (posture + 1) % NUM_POSTURES;
        movingHeadState = MHS_MOVING;
        break;

    default:
        break;
    }
}

bool
MovingHead::SetNextVector()
{
    if (movingHeadState == MHS_DONE || movingHeadState == MHS_IDLE) return false;

    int index = FindFreeRegion();
    if (index < 0) {
        OSYSLOG1((osyslogWARNING, "MovingHead : no free command vector"));
        return false;
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    for (int j = 0; j < NUM_HEAD_JOINTS; j++) {
        OCommandData* data = cmdVecData->GetData(j);
        OJointCommandValue2* jval = (OJointCommandValue2*)data->value;
        for (int f = 0; f < ocommandMAX_FRAMES; f++) {
            jval[f].value = oradians(Target(j, stateVector * ocommandMAX_FRAMES + f));
        }
    }
    stateVector++;
    NextState();

    subject[sbjMove]->SetData(region[index]);
    return true;
}

int
MovingHead::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}
