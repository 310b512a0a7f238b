//
// BlinkingFaceLED.cc
//
// Ramps the 14 face lights (LED3) up and down, first on face A, then on
// face B: 16 frames per vector, 256 frames (2.048 s) per face.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "BlinkingFaceLED.h"

BlinkingFaceLED::BlinkingFaceLED() : running(false), primed(false), numVectors(0)
{
    for (int i = 0; i < NUM_FACE_LED; i++) primitiveID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
BlinkingFaceLED::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingFaceLED::DoInit()\n"));

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
                  "BlinkingFaceLED::DoInit()",
                  "OPENR::SetMotorPower() FAILED", result));
    }

    return oSUCCESS;
}

OStatus
BlinkingFaceLED::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingFaceLED::DoStart()\n"));

    running = true;
    OSYSPRINT(("BlinkingFaceLED : %d LEDs, faces A and B alternate every %d frames\n",
               NUM_FACE_LED, FACE_FRAMES));

    if (subject[sbjBlink]->IsReady()) SendFirstVectors();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BlinkingFaceLED::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingFaceLED::DoStop()\n"));

    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BlinkingFaceLED::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
BlinkingFaceLED::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert() || !running) return;

    if (!primed) {
        SendFirstVectors();
        return;
    }

    if (SetNextVector()) subject[sbjBlink]->NotifyObservers();
}

//
// Two vectors in the first notification, then one more each time the
// effector reports that one has been played: the pattern runs without
// gaps.
//
void
BlinkingFaceLED::SendFirstVectors()
{
    primed = true;
    if (SetNextVector()) SetNextVector();
    subject[sbjBlink]->NotifyObservers();
}

void
BlinkingFaceLED::OpenPrimitives()
{
    for (int i = 0; i < NUM_FACE_LED; i++) {
        OStatus result = OPENR::OpenPrimitive(FACE_LED_LOCATOR[i], &primitiveID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "BlinkingFaceLED::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", FACE_LED_LOCATOR[i], result));
        }
    }
}

void
BlinkingFaceLED::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {

        result = OPENR::NewCommandVectorData(NUM_FACE_LED,
                                             &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "BlinkingFaceLED::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_FACE_LED);

        for (int j = 0; j < NUM_FACE_LED; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataLED_COMMAND3, primitiveID[j], FACE_LED_VALUES);
        }
    }
}

bool
BlinkingFaceLED::SetNextVector()
{
    int index = FindFreeRegion();
    if (index < 0) {
        OSYSLOG1((osyslogWARNING, "BlinkingFaceLED : no free command vector"));
        return false;
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    FillVector(cmdVecData, numVectors);
    numVectors++;

    subject[sbjBlink]->SetData(region[index]);
    return true;
}

int
BlinkingFaceLED::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}

void
BlinkingFaceLED::FillVector(OCommandVectorData* cmdVecData, int vectorIndex)
{
    for (int k = 0; k < FACE_LED_VALUES; k++) {
        int frame = vectorIndex * FACE_LED_VALUES + k;
        int f     = frame % FACE_FRAMES;
        OLED3Mode mode = ((frame / FACE_FRAMES) % 2 == 0) ? oled3_MODE_A : oled3_MODE_B;

        int intensity;
        if (f < FACE_RAMP_FRAMES) {
            intensity = f * 255 / (FACE_RAMP_FRAMES - 1);
        } else {
            intensity = (FACE_FRAMES - 1 - f) * 255 / (FACE_RAMP_FRAMES - 1);
        }

        for (int j = 0; j < NUM_FACE_LED; j++) {
            OCommandData* data = cmdVecData->GetData(j);
            OLEDCommandValue3* led = (OLEDCommandValue3*)data->value;
            led[k].intensity = (sword)intensity;
            led[k].mode      = mode;
            led[k].period    = FACE_LED_PERIOD;
        }
    }
}
