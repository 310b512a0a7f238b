//
// PIDGains.cc
//
// Exercises the joint-gain calls of the OPENR API on the legs and prints
// what they return: gains before EnableJointGain, the standard ERS-7 leg
// gains (and one deliberately different set) after it, and zeros again
// once DisableJointGain has been called on the right legs. Then it sends
// every leg to the same posture: only the legs whose gains are on move.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "PIDGains.h"

PIDGains::PIDGains() : running(false), primed(false), done(false), frameCount(0)
{
    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        jointID[i] = oprimitiveID_UNDEF;
        start[i]   = 0.0;
    }
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
PIDGains::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenPrimitives();
    NewCommandVectorData();
    OPENR::SetMotorPower(opowerON);

    return oSUCCESS;
}

OStatus
PIDGains::DoStart(const OSystemEvent& event)
{
    ExerciseGains();

    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        OJointValue current;
        OPENR::GetJointValue(jointID[i], &current);
        start[i] = degrees(current.value / 1000000.0);
    }

    running = true;
    if (subject[sbjMove]->IsReady()) SendFirstVectors();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
PIDGains::DoStop(const OSystemEvent& event)
{
    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
PIDGains::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
PIDGains::OpenPrimitives()
{
    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(LEG_JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "PIDGains::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", LEG_JOINT_LOCATOR[i], result));
        }
    }
}

void
PIDGains::NewCommandVectorData()
{
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        OStatus result = OPENR::NewCommandVectorData(NUM_LEG_JOINTS,
                                                     &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "PIDGains::NewCommandVectorData()",
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

//
// One line per GetJointGain call:
//   PIDGains : get LF-J1 status 0 gain 0x1c 0x08 0x01 0x0e 0x02 0x0f
//
void
PIDGains::PrintGain(int joint)
{
    word pg = 0xffff, ig = 0xffff, dg = 0xffff, ps = 0xffff, is = 0xffff, ds = 0xffff;
    OStatus result = OPENR::GetJointGain(jointID[joint], &pg, &ig, &dg, &ps, &is, &ds);
    OSYSPRINT(("PIDGains : get %s status %d gain 0x%02x 0x%02x 0x%02x 0x%02x 0x%02x 0x%02x\n",
               LEG_JOINT_NAME[joint], (int)result, pg, ig, dg, ps, is, ds));
}

void
PIDGains::ExerciseGains()
{
    OStatus result;

    //
    // 1. Before EnableJointGain: nothing is effective.
    //
    PrintGain(0);
    result = OPENR::SetJointGain(jointID[0], STD_PGAIN[0], STD_IGAIN[0], STD_DGAIN[0],
                                 PSHIFT, ISHIFT, DSHIFT);
    OSYSPRINT(("PIDGains : set before enable %s status %d\n", LEG_JOINT_NAME[0], (int)result));

    //
    // 2. Enable and load: standard values, a different set on LF-J1.
    //
    for (int i = 0; i < NUM_LEG_JOINTS; i++) {
        OStatus enable = OPENR::EnableJointGain(jointID[i]);
        int kind = i % 3;
        if (i == 0) {
            result = OPENR::SetJointGain(jointID[i], ODD_PGAIN, ODD_IGAIN, ODD_DGAIN,
                                         PSHIFT, ISHIFT, DSHIFT);
        } else {
            result = OPENR::SetJointGain(jointID[i], STD_PGAIN[kind], STD_IGAIN[kind],
                                         STD_DGAIN[kind], PSHIFT, ISHIFT, DSHIFT);
        }
        OSYSPRINT(("PIDGains : enable %s status %d set status %d\n",
                   LEG_JOINT_NAME[i], (int)enable, (int)result));
    }
    for (int i = 0; i < NUM_LEG_JOINTS; i++) PrintGain(i);

    //
    // 3. Disable the right legs: they go limp, their gains read as zeros.
    //
    for (int i = FIRST_RIGHT_JOINT; i < NUM_LEG_JOINTS; i++) {
        result = OPENR::DisableJointGain(jointID[i]);
        OSYSPRINT(("PIDGains : disable %s status %d\n", LEG_JOINT_NAME[i], (int)result));
    }
    for (int i = FIRST_RIGHT_JOINT; i < NUM_LEG_JOINTS; i++) PrintGain(i);
    result = OPENR::SetJointGain(jointID[FIRST_RIGHT_JOINT], STD_PGAIN[0], STD_IGAIN[0],
                                 STD_DGAIN[0], PSHIFT, ISHIFT, DSHIFT);
    OSYSPRINT(("PIDGains : set after disable %s status %d\n",
               LEG_JOINT_NAME[FIRST_RIGHT_JOINT], (int)result));

    //
    // 4. oprimitiveUNDEF (0) is a primitive *type*, not an ID.
    //
    word pg = 0xffff, ig = 0xffff, dg = 0xffff, ps = 0xffff, is = 0xffff, ds = 0xffff;
    result = OPENR::GetJointGain(oprimitiveUNDEF, &pg, &ig, &dg, &ps, &is, &ds);
    OSYSPRINT(("PIDGains : get UNDEF status %d gain 0x%02x 0x%02x 0x%02x 0x%02x 0x%02x 0x%02x\n",
               (int)result, pg, ig, dg, ps, is, ds));
    result = OPENR::EnableJointGain(oprimitiveUNDEF);
    OSYSPRINT(("PIDGains : enable UNDEF status %d\n", (int)result));
}

void
PIDGains::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert() || !running || done) return;

    if (!primed) {
        SendFirstVectors();
        return;
    }

    if (SetNextVector()) {
        subject[sbjMove]->NotifyObservers();
    } else if (!done) {
        done = true;
        OSYSPRINT(("PIDGains : done\n"));
    }
}

void
PIDGains::SendFirstVectors()
{
    primed = true;
    OSYSPRINT(("PIDGains : moving every leg to J1 %.0f J2 %.0f J3 %.0f\n",
               TARGET_POSTURE[0], TARGET_POSTURE[1], TARGET_POSTURE[2]));
    if (SetNextVector()) SetNextVector();
    subject[sbjMove]->NotifyObservers();
}

bool
PIDGains::SetNextVector()
{
    if (frameCount >= MOVE_FRAMES + HOLD_FRAMES) return false;

    int index = FindFreeRegion();
    if (index < 0) return false;

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    for (int j = 0; j < NUM_LEG_JOINTS; j++) {
        OJointCommandValue2* jval = (OJointCommandValue2*)cmdVecData->GetData(j)->value;
        double target = TARGET_POSTURE[j % 3];
        for (int f = 0; f < ocommandMAX_FRAMES; f++) {
            int frame = frameCount + f;
            double angle = target;
            if (frame < MOVE_FRAMES) {
                double t = (double)(frame + 1) / MOVE_FRAMES;
                angle = start[j] + (target - start[j]) * t;
            }
            jval[f].value = oradians(angle);
        }
    }
    frameCount += ocommandMAX_FRAMES;

    subject[sbjMove]->SetData(region[index]);
    return true;
}

int
PIDGains::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}
