//
// BlinkingHeadLED.cc
//
// Blinks the six LED2 lights of the head (head lights, mode indicator,
// wireless-LAN light) in an 8-step pattern: each step lasts 512 ms.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "BlinkingHeadLED.h"

BlinkingHeadLED::BlinkingHeadLED() : running(false), primed(false), numVectors(0)
{
    for (int i = 0; i < NUM_HEAD_LED; i++) primitiveID[i] = oprimitiveID_UNDEF;
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) region[i] = 0;
}

OStatus
BlinkingHeadLED::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingHeadLED::DoInit()\n"));

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
                  "BlinkingHeadLED::DoInit()",
                  "OPENR::SetMotorPower() FAILED", result));
    }

    return oSUCCESS;
}

OStatus
BlinkingHeadLED::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingHeadLED::DoStart()\n"));

    running = true;
    OSYSPRINT(("BlinkingHeadLED : %d LEDs, %d steps of %d frames per vector\n",
               NUM_HEAD_LED, HEAD_LED_STEPS, (int)HEAD_LED_PERIOD));

    if (subject[sbjBlink]->IsReady()) SendFirstVectors();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BlinkingHeadLED::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("BlinkingHeadLED::DoStop()\n"));

    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
BlinkingHeadLED::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
BlinkingHeadLED::Ready(const OReadyEvent& event)
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
BlinkingHeadLED::SendFirstVectors()
{
    primed = true;
    if (SetNextVector()) SetNextVector();
    subject[sbjBlink]->NotifyObservers();
}

void
BlinkingHeadLED::OpenPrimitives()
{
    for (int i = 0; i < NUM_HEAD_LED; i++) {
        OStatus result = OPENR::OpenPrimitive(HEAD_LED_LOCATOR[i], &primitiveID[i]);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                      "BlinkingHeadLED::OpenPrimitives()",
                      "OPENR::OpenPrimitive() FAILED", HEAD_LED_LOCATOR[i], result));
        }
    }
}

void
BlinkingHeadLED::NewCommandVectorData()
{
    OStatus result;
    MemoryRegionID      cmdVecDataID;
    OCommandVectorData* cmdVecData;

    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {

        result = OPENR::NewCommandVectorData(NUM_HEAD_LED,
                                             &cmdVecDataID, &cmdVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "%s : %s %d",
                      "BlinkingHeadLED::NewCommandVectorData()",
                      "OPENR::NewCommandVectorData() FAILED", result));
            continue;
        }

        region[i] = new RCRegion(cmdVecData->vectorInfo.memRegionID,
                                 cmdVecData->vectorInfo.offset,
                                 (void*)cmdVecData,
                                 cmdVecData->vectorInfo.totalSize);

        cmdVecData->SetNumData(NUM_HEAD_LED);

        for (int j = 0; j < NUM_HEAD_LED; j++) {
            OCommandInfo* info = cmdVecData->GetInfo(j);
            info->Set(odataLED_COMMAND2, primitiveID[j], HEAD_LED_STEPS);
        }
    }
}

bool
BlinkingHeadLED::SetNextVector()
{
    int index = FindFreeRegion();
    if (index < 0) {
        OSYSLOG1((osyslogWARNING, "BlinkingHeadLED : no free command vector"));
        return false;
    }

    OCommandVectorData* cmdVecData = (OCommandVectorData*)region[index]->Base();
    FillVector(cmdVecData, numVectors);
    numVectors++;

    subject[sbjBlink]->SetData(region[index]);
    return true;
}

int
BlinkingHeadLED::FindFreeRegion()
{
    for (int i = 0; i < NUM_COMMAND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}

//
// Step k of the pattern is a 3-bit counter:
//   l1 (head colour)  on when bit 0 is set   -> toggles every step
//   l2 (head white)   on when bit 0 is clear
//   l3 (red)          bit 0
//   l4 (green)        bit 1                  -> toggles every 2 steps
//   l5 (blue)         bit 2                  -> toggles every 4 steps
//   l6 (wireless)     on when bit 2 is clear
//
void
BlinkingHeadLED::FillVector(OCommandVectorData* cmdVecData, int vectorIndex)
{
    for (int j = 0; j < NUM_HEAD_LED; j++) {
        OCommandData* data = cmdVecData->GetData(j);
        OLEDCommandValue2* led = (OLEDCommandValue2*)data->value;
        for (int k = 0; k < HEAD_LED_STEPS; k++) {
            bool on;
            switch (j) {
            case 0:  on = (k & 1) != 0; break;
            case 1:  on = (k & 1) == 0; break;
            case 2:  on = (k & 1) != 0; break;
            case 3:  on = (k & 2) != 0; break;
            case 4:  on = (k & 4) != 0; break;
            default: on = (k & 4) == 0; break;
            }
            led[k].led    = on ? oledON : oledOFF;
            led[k].period = HEAD_LED_PERIOD;
        }
    }
}
