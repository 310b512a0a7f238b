//
// BlinkingBackLED.cc
//
// Blinks the six back lights (LED3): the colour lights and the white
// lights take turns, 256 ms each.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "BlinkingBackLED.h"

BlinkingBackLED::BlinkingBackLED() : running(false), primed(false), numVectors(0)
{
    for (int i = 0; i < NUM_BACK_LED; i++) primitiveID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
BlinkingBackLED::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingBackLED::DoInit()\n"));

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
                  "BlinkingBackLED::DoInit()",
                  "OPENR::SetMotorPower() FAILED", result));
    }

    return oSUCCESS;
}

OStatus
BlinkingBackLED::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingBackLED::DoStart()\n"));

    running = true;
    OSYSPRINT(("BlinkingBackLED : %d LEDs, colour and white take turns every %d frames\n",
               NUM_BACK_LED, (int)BACK_LED_PERIOD));

    if (subject[sbjBlink]->IsReady()) SendFirstVectors();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BlinkingBackLED::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingBackLED::DoStop()\n"));

    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BlinkingBackLED::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
BlinkingBackLED::Ready(const OReadyEvent& event)
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
BlinkingBackLED::SendFirstVectors()
{
    primed = true;
    if (SetNextVector()) SetNextVector();
    subject[sbjBlink]->NotifyObservers();
}

void
BlinkingBackLED::OpenPrimitives()
{
    for (int i = 0; i < NUM_BACK_LED; i++) {
        OStatus result = OPENR::OpenPrimitive(BACK_LED_LOCATOR[i], &primitiveID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "BlinkingBackLED::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", BACK_LED_LOCATOR[i], result));
        }
    }
}

void
BlinkingBackLED::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {

        result = OPENR::NewCommandVectorData(NUM_BACK_LED,
                                             &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "BlinkingBackLED::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_BACK_LED);

        for (int j = 0; j < NUM_BACK_LED; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataLED_COMMAND3, primitiveID[j], BACK_LED_VALUES);
        }
    }
}

bool
BlinkingBackLED::SetNextVector()
{
    int index = FindFreeRegion();
    if (index < 0) {
        OSYSLOG1((osyslogWARNING, "BlinkingBackLED : no free command vector"));
        return false;
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    FillVector(cmdVecData, numVectors);
    numVectors++;

    subject[sbjBlink]->SetData(region[index]);
    return true;
}

int
BlinkingBackLED::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}

//
// lu, lw, ly are the colour lights (front, middle, rear), lv, lx, lz the
// white ones. The back lights have no A/B mode: send MODE_UNDEF.
//
void
BlinkingBackLED::FillVector(OCommandVectorData* cmdVecData, int vectorIndex)
{
    for (int j = 0; j < NUM_BACK_LED; j++) {
        bool colour = (j % 2 == 0);
        OCommandData* data = cmdVecData->GetData(j);
        OLEDCommandValue3* led = (OLEDCommandValue3*)data->value;

        led[0].intensity = colour ? BACK_LED_ON : BACK_LED_OFF;
        led[0].mode      = oled3_MODE_UNDEF;
        led[0].period    = BACK_LED_PERIOD;

        led[1].intensity = colour ? BACK_LED_OFF : BACK_LED_ON;
        led[1].mode      = oled3_MODE_UNDEF;
        led[1].period    = BACK_LED_PERIOD;
    }
}
