//
// BadCommands.cc
//
// Sends command vectors a careless program might send, to see that the
// robot survives them and keeps its joints in range:
//   * targets beyond the software limits of the head, mouth and tail;
//   * neck tilt2 below the limit that depends on neck tilt1;
//   * a slot whose primitive ID is oprimitiveID_UNDEF (its OpenPrimitive
//     failed and the program did not check);
//   * a JOINT_COMMAND2 slot addressed to an ear (a Joint4);
//   * a slot counted in numData but never Set().
// Each vector lasts 16 frames; the program counts the ASSERT READYs.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OUnits.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "BadCommands.h"

BadCommands::BadCommands() : running(false), primed(false), done(false),
                             numSent(0), numReady(0),
                             badID(oprimitiveID_UNDEF), earID(oprimitiveID_UNDEF)
{
    for (int i = 0; i < NUM_JOINTS; i++) jointID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
BadCommands::DoInit(const OSystemEvent& event)
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
BadCommands::DoStart(const OSystemEvent& event)
{
    SetJointGain();

    running = true;
    if (subject[sbjMove]->IsReady()) SendFirstVectors();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BadCommands::DoStop(const OSystemEvent& event)
{
    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BadCommands::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
BadCommands::OpenPrimitives()
{
    for (int i = 0; i < NUM_JOINTS; i++) {
        OStatus result = OPENR::OpenPrimitive(JOINT_LOCATOR[i], &jointID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "BadCommands::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", JOINT_LOCATOR[i], result));
        }
    }

    OStatus result = OPENR::OpenPrimitive(BAD_LOCATOR, &badID);
    OSYSPRINT(("BadCommands : OpenPrimitive %s status %d id 0x%08x\n",
               BAD_LOCATOR, (int)result, (unsigned int)badID));

    OPENR::OpenPrimitive(EAR_LOCATOR, &earID);
}

void
BadCommands::NewCommandVectorData()
{
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        OStatus result = OPENR::NewCommandVectorData(NUM_SLOTS, &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "BadCommands::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_SLOTS);
        for (int j = 0; j < NUM_JOINTS; j++) {
            cmdVecData->GetInfo(j)->Set(odataJOINT_COMMAND2, jointID[j], ocommandMAX_FRAMES);
        }
        cmdVecData->GetInfo(SLOT_BAD_ID)->Set(odataJOINT_COMMAND2, badID, ocommandMAX_FRAMES);
        cmdVecData->GetInfo(SLOT_EAR)->Set(odataJOINT_COMMAND2, earID, ocommandMAX_FRAMES);
        // SLOT_UNSET: left as NewCommandVectorData() initialised it.
    }
}

void
BadCommands::SetJointGain()
{
    OPENR::EnableJointGain(jointID[0]);
    OPENR::SetJointGain(jointID[0], 0x0a, 0x04, 0x02, 0x0e, 0x02, 0x0f);
    OPENR::EnableJointGain(jointID[1]);
    OPENR::SetJointGain(jointID[1], 0x08, 0x02, 0x04, 0x0e, 0x02, 0x0f);
    OPENR::EnableJointGain(jointID[2]);
    OPENR::SetJointGain(jointID[2], 0x08, 0x04, 0x02, 0x0e, 0x02, 0x0f);
    OPENR::EnableJointGain(jointID[3]);
    OPENR::SetJointGain(jointID[3], 0x08, 0x00, 0x04, 0x0e, 0x02, 0x0f);
    OPENR::EnableJointGain(jointID[4]);
    OPENR::SetJointGain(jointID[4], 0x0a, 0x04, 0x04, 0x0e, 0x02, 0x0f);
}

void
BadCommands::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert() || !running || done) return;

    if (!primed) {
        SendFirstVectors();
        return;
    }

    numReady++;
    if (SetNextVector()) {
        subject[sbjMove]->NotifyObservers();
    } else if (numReady == numSent) {
        done = true;
        OSYSPRINT(("BadCommands : done, %d vectors sent, %d ready\n", numSent, numReady));
    }
}

void
BadCommands::SendFirstVectors()
{
    primed = true;
    if (SetNextVector()) SetNextVector();
    subject[sbjMove]->NotifyObservers();
}

bool
BadCommands::SetNextVector()
{
    if (numSent >= NUM_PHASES * VECTORS_PER_PHASE) return false;

    int index = FindFreeRegion();
    if (index < 0) return false;

    int phase = numSent / VECTORS_PER_PHASE;
    if (numSent % VECTORS_PER_PHASE == 0) {
        OSYSPRINT(("BadCommands : phase %s\n", PHASE_NAME[phase]));
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    for (int j = 0; j < NUM_SLOTS; j++) {
        if (j == SLOT_UNSET) continue;
        OJointCommandValue2* jval = (OJointCommandValue2*)cmdVecData->GetData(j)->value;
        for (int f = 0; f < ocommandMAX_FRAMES; f++) {
            if (j < NUM_JOINTS) {
                jval[f].value = oradians(PHASE_TARGET[phase][j]);
            } else if (j == SLOT_BAD_ID) {
                jval[f].value = oradians(170.0);
            } else {
                jval[f].value = 0;
            }
        }
    }
    numSent++;

    subject[sbjMove]->SetData(region[index]);
    return true;
}

int
BadCommands::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}
