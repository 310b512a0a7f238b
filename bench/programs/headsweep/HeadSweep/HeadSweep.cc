//
// HeadSweep.cc
//
// The first command vector holds the joints where they are (so nothing jumps when
// the gains come on); then each joint blends in the first second from there onto
// its sine wave and follows it until the program ends. A new vector (16 frames of
// 8 ms) goes out whenever the effector takes one, so the head never stops.
//
#include <math.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "HeadSweep.h"

static const char* const LOCATOR[NUM_SWEEP_JOINTS] = {
    "PRM:/r1/c1-Joint2:11",         // neck tilt1
    "PRM:/r1/c1/c2-Joint2:12",      // neck pan
    "PRM:/r1/c1/c2/c3-Joint2:13"    // neck tilt2
};

// Sine waves in degrees: centre, amplitude, period in 8 ms frames (coprime periods,
// so the pose keeps changing).
static const double CENTRE[NUM_SWEEP_JOINTS]    = { -15.0,  0.0, 15.0 };
static const double AMPLITUDE[NUM_SWEEP_JOINTS] = {  10.0, 60.0, 15.0 };
static const double PERIOD[NUM_SWEEP_JOINTS]    = { 641.0, 401.0, 263.0 };
static const int    BLEND_FRAMES = 125;     // 1 s

// Standard head gains of the ERS-7 (tilt1, pan, tilt2).
static const word PGAIN[NUM_SWEEP_JOINTS] = { 0x0a, 0x08, 0x08 };
static const word IGAIN[NUM_SWEEP_JOINTS] = { 0x04, 0x02, 0x04 };
static const word DGAIN[NUM_SWEEP_JOINTS] = { 0x02, 0x04, 0x02 };

HeadSweep::HeadSweep() : running(false), gainsOn(false), frames(0)
{
    for (int i = 0; i < NUM_SWEEP_JOINTS; i++) {
        jointID[i] = oprimitiveID_UNDEF;
        start[i] = CENTRE[i];
    }
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus HeadSweep::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    for (int i = 0; i < NUM_SWEEP_JOINTS; i++) {
        if (OPENR::OpenPrimitive(LOCATOR[i], &jointID[i]) != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "HeadSweep : cannot open %s", LOCATOR[i]));
        }
    }
    NewCommandVectors();
    OPENR::SetMotorPower(opowerON);
    return oSUCCESS;
}

OStatus HeadSweep::DoStart(const OSystemEvent& event)
{
    for (int i = 0; i < NUM_SWEEP_JOINTS; i++) {
        OJointValue value;
        if (OPENR::GetJointValue(jointID[i], &value) == oSUCCESS) {
            start[i] = degrees(value.value / 1000000.0);
        }
    }
    running = true;
    if (subject[sbjMove]->IsReady() && SendVector()) {
        SendVector();
        subject[sbjMove]->NotifyObservers();
    }
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus HeadSweep::DoStop(const OSystemEvent& event)
{
    running = false;
    OSYSPRINT(("BENCH headsweep frames=%d\n", frames));
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

void HeadSweep::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert() || !running) return;
    if (!gainsOn) {
        // the first vector (the current angles) is playing: gains on without a jump
        for (int i = 0; i < NUM_SWEEP_JOINTS; i++) {
            OPENR::EnableJointGain(jointID[i]);
            OPENR::SetJointGain(jointID[i], PGAIN[i], IGAIN[i], DGAIN[i], 0x0e, 0x02, 0x0f);
        }
        gainsOn = true;
    }
    if (SendVector()) subject[sbjMove]->NotifyObservers();
}

void HeadSweep::NewCommandVectors()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        MemoryRegionID id;
        OCommandVectorData* v;
        if (OPENR::NewCommandVectorData(NUM_SWEEP_JOINTS, &id, &v) != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "HeadSweep : NewCommandVectorData failed"));
            continue;
        }
        region[i] = new RCRegion(v->vectorInfo.memRegionID, v->vectorInfo.offset, (void*)v, v->vectorInfo.totalSize);
        v->SetNumData(NUM_SWEEP_JOINTS);
        for (int j = 0; j < NUM_SWEEP_JOINTS; j++) {
            v->GetInfo(j)->Set(odataJOINT_COMMAND2, jointID[j], ocommandMAX_FRAMES);
        }
    }
}

double HeadSweep::Target(int joint, int frame)
{
    if (frame < ocommandMAX_FRAMES) return start[joint];    // the first vector holds
    int f = frame - ocommandMAX_FRAMES;
    double wave = CENTRE[joint] + AMPLITUDE[joint] * sin(2.0 * M_PI * f / PERIOD[joint]);
    if (f >= BLEND_FRAMES) return wave;
    double t = (double)f / BLEND_FRAMES;
    return start[joint] + (wave - start[joint]) * t;
}

bool HeadSweep::SendVector()
{
    int index = -1;
    for (int i = 0; i < NUM_COMMAND_VECTOR && index < 0; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) index = i;
    }
    if (index < 0) return false;
    OCommandVectorData* v = (OCommandVectorData*)region[index]->Base();
    for (int j = 0; j < NUM_SWEEP_JOINTS; j++) {
        OJointCommandValue2* jval = (OJointCommandValue2*)v->GetData(j)->value;
        for (int f = 0; f < ocommandMAX_FRAMES; f++) {
            jval[f].value = oradians(Target(j, frames + f));
        }
    }
    frames += ocommandMAX_FRAMES;
    subject[sbjMove]->SetData(region[index]);
    return true;
}
