//
// Move210.cc
//
// Moves the legs, head and tail of an ERS-210 and lights its eye
// lights, mode indicator and tail lights.
//
// One OCommandVectorData carries both: each joint slot holds
// ocommandMAX_FRAMES (16) target angles, one per 8 ms frame, and each
// LED slot one OLEDCommandValue2 held for the same 16 frames, so one
// vector lasts 128 ms. Two vectors are sent at the start and one more
// on every ASSERT READY from the effector (OVirtualRobotComm).
//

#include <math.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Move210.h"

Move210::Move210() : state(M2_IDLE), primed(false), frameCount(0)
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        jointID[i] = oprimitiveID_UNDEF;
        startPosture[i] = 0.0;
    }
    for (int i = 0; i < NUM_LEDS; i++) ledID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
Move210::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("Move210::DoInit()\n"));

    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenPrimitives();
    NewCommandVectorData();

    OStatus result = OPENR::SetMotorPower(opowerON);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "Move210::DoInit()",
                  "OPENR::SetMotorPower() FAILED", result));
    }

    return oSUCCESS;
}

OStatus
Move210::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("Move210::DoStart()\n"));

    SetJointGain();
    ReadStartPosture();

    state = M2_ADJUSTING;
    OSYSPRINT(("Move210 : adjusting to the base posture\n"));

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
Move210::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("Move210::DoStop()\n"));

    state = M2_IDLE;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
Move210::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Move210::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert()) return;
    if (state == M2_IDLE || state == M2_DONE) return;

    if (!primed) {
        SendFirstVectors();
        return;
    }

    if (SetNextVector()) {
        subject[sbjMove]->NotifyObservers();
    }
}

void
Move210::SendFirstVectors()
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
Move210::OpenPrimitives()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "Move210::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", JOINT_LOCATOR[i], result));
        }
    }
    for (int i = 0; i < NUM_LEDS; i++) {
        OStatus result = OPENR::OpenPrimitive(LED_LOCATOR[i], &ledID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "Move210::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", LED_LOCATOR[i], result));
        }
    }
}

void
Move210::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {

        result = OPENR::NewCommandVectorData(NUM_JOINTS + NUM_LEDS,
                                             &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "Move210::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_JOINTS + NUM_LEDS);

        for (int j = 0; j < NUM_JOINTS; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataJOINT_COMMAND2, jointID[j], ocommandMAX_FRAMES);
        }
        for (int k = 0; k < NUM_LEDS; k++) {
            OCommandInfo* info = cmdVecData->GetInfo(NUM_JOINTS + k);
            info->Set(odataLED_COMMAND2, ledID[k], 1);
        }
    }
}

void
Move210::SetJointGain()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OPENR::EnableJointGain(jointID[i]);
        OPENR::SetJointGain(jointID[i], GAIN[i][0], GAIN[i][1], GAIN[i][2],
                            PSHIFT, ISHIFT, DSHIFT);
    }
}

void
Move210::ReadStartPosture()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OJointValue current;
        if (OPENR::GetJointValue(jointID[i], &current) == oSUCCESS) {
            startPosture[i] = degrees(current.value / 1000000.0);
        } else {
            startPosture[i] = BASE_POSTURE[i];
        }
    }
}

//
// Target angle (degrees) of a joint at a given frame of the motion:
// a straight line to the base posture, then the left front J1 and the
// tail pan swing about it.
//
double
Move210::JointAngle(int joint, int frame)
{
    if (frame < ADJUST_FRAMES) {
        double t = (double)(frame + 1) / ADJUST_FRAMES;
        return startPosture[joint] + (BASE_POSTURE[joint] - startPosture[joint]) * t;
    }

    double angle = BASE_POSTURE[joint];
    double phase = 2.0 * M_PI * (frame - ADJUST_FRAMES) / SWING_PERIOD;
    if (joint == LF_J1)    angle += LEG_SWING * sin(phase);
    if (joint == TAIL_PAN) angle += TAIL_SWING * sin(phase);
    return angle;
}

//
// The lights of vector n: the mode indicator always, one eye light in
// turn (l1 .. l6), the blue tail light on even vectors and the orange
// one on odd ones.
//
bool
Move210::LedOn(int led, int vectorIndex)
{
    if (led == MODE_LED)    return true;
    if (led == TAIL_BLUE)   return vectorIndex % 2 == 0;
    if (led == TAIL_ORANGE) return vectorIndex % 2 == 1;
    return led == vectorIndex % 6;
}

//
// Fill a free region with the next 16 frames and queue it.
// Returns false when there is nothing more to send.
//
bool
Move210::SetNextVector()
{
    const int lastFrame = ADJUST_FRAMES + NUM_SWINGS * SWING_PERIOD;

    if (frameCount >= lastFrame) {
        if (state != M2_DONE) {
            state = M2_DONE;
            OSYSPRINT(("Move210 : done, holding the base posture\n"));
        }
        return false;
    }

    int index = FindFreeRegion();
    if (index < 0) {
        OSYSLOG1((osyslogWARNING, "Move210 : no free command vector"));
        return false;
    }

    if (frameCount >= ADJUST_FRAMES && state == M2_ADJUSTING) {
        state = M2_SWINGING;
        OSYSPRINT(("Move210 : swinging %d times\n", NUM_SWINGS));
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    for (int j = 0; j < NUM_JOINTS; j++) {
        OCommandData* data = cmdVecData->GetData(j);
        OJointCommandValue2* jval = (OJointCommandValue2*)data->value;
        for (int f = 0; f < ocommandMAX_FRAMES; f++) {
            jval[f].value = oradians(JointAngle(j, frameCount + f));
        }
    }
    int vectorIndex = frameCount / ocommandMAX_FRAMES;
    for (int k = 0; k < NUM_LEDS; k++) {
        OCommandData* data = cmdVecData->GetData(NUM_JOINTS + k);
        OLEDCommandValue2* led = (OLEDCommandValue2*)data->value;
        led[0].led    = LedOn(k, vectorIndex) ? oledON : oledOFF;
        led[0].period = ocommandMAX_FRAMES;
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
Move210::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}
