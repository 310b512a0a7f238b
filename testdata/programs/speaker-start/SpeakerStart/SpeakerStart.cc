//
// SpeakerStart.cc
//
// Plays 8 buffers of a 500 Hz square wave. Like the SDK's sound samples it
// primes the speaker with both of its buffers in DoStart, counting on the
// speaker's ASSERT-READY, which the system sends when it connects the
// speaker to us -- before any DoStart. After that, each ASSERT-READY means
// the speaker has played (and released) one buffer, which is refilled.
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SpeakerStart.h"

SpeakerStart::SpeakerStart() : speakerID(oprimitiveID_UNDEF),
                               numSent(0), numPlayed(0), running(false)
{
    for (int i = 0; i < NUM_SOUND_VECTOR; i++) region[i] = 0;
}

OStatus
SpeakerStart::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OpenSpeaker();
    NewSoundVectorData();

    return oSUCCESS;
}

OStatus
SpeakerStart::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    if (!subject[sbjSpeaker]->IsReady()) {
        OSYSLOG1((osyslogERROR, "SpeakerStart : the speaker is not ready in DoStart"));
        return oFAIL;
    }

    running = true;
    SendBuffer(0);
    SendBuffer(1);
    subject[sbjSpeaker]->NotifyObservers();
    OSYSPRINT(("SpeakerStart : primed %d buffers\n", numSent));

    return oSUCCESS;
}

OStatus
SpeakerStart::DoStop(const OSystemEvent& event)
{
    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
SpeakerStart::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
SpeakerStart::Ready(const OReadyEvent& event)
{
    // The speaker's ASSERT-READY at connection arrives before DoStart.
    if (!event.IsAssert() || !running) return;

    numPlayed++;
    if (numSent < NUM_BUFFERS) {
        int index = FindFreeRegion();
        if (index < 0) {
            OSYSLOG1((osyslogERROR, "SpeakerStart : ready, but no buffer came back"));
            return;
        }
        SendBuffer(index);
        subject[sbjSpeaker]->NotifyObservers();
    } else if (numPlayed == numSent) {
        running = false;
        OSYSPRINT(("SpeakerStart : done, %d buffers\n", numPlayed));
    }
}

void
SpeakerStart::OpenSpeaker()
{
    OStatus result = OPENR::OpenPrimitive(SPEAKER_LOCATOR, &speakerID);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "SpeakerStart : OpenPrimitive(%s) FAILED %d", SPEAKER_LOCATOR, result));
        return;
    }

    OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_MUTE_ON, 0, 0, 0, 0);
    OPENR::SetMotorPower(opowerON);

    OPrimitiveControl_SpeakerVolume volume(ospkvol10dB);
    OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_SET_VOLUME, &volume, sizeof(volume), 0, 0);

    OPrimitiveControl_SpeakerSoundType soundType(ospksndMONO16K16B);
    OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_SET_SOUND_TYPE, &soundType, sizeof(soundType), 0, 0);

    OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_MUTE_OFF, 0, 0, 0, 0);
}

void
SpeakerStart::NewSoundVectorData()
{
    MemoryRegionID    soundVecDataID;
    OSoundVectorData* soundVecData;

    for (int i = 0; i < NUM_SOUND_VECTOR; i++) {
        OStatus result = OPENR::NewSoundVectorData(1, SOUND_BUFFER_SIZE,
                                                   &soundVecDataID, &soundVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "SpeakerStart : NewSoundVectorData() FAILED %d", result));
            continue;
        }

        soundVecData->SetNumData(1);
        OSoundInfo* info = soundVecData->GetInfo(0);
        info->Set(odataSOUND_VECTOR, speakerID, SOUND_BUFFER_SIZE);
        info->format        = osoundformatPCM;
        info->channel       = osoundchannelMONO;
        info->samplingRate  = 16000;
        info->bitsPerSample = 16;

        region[i] = new RCRegion(soundVecData->vectorInfo.memRegionID,
                                 soundVecData->vectorInfo.offset,
                                 (void*)soundVecData,
                                 soundVecData->vectorInfo.totalSize);
    }
}

// Fills region[index] with the next 32 ms of the square wave and queues it.
bool
SpeakerStart::SendBuffer(int index)
{
    if (region[index] == 0) return false;

    OSoundVectorData* soundVecData = (OSoundVectorData*)region[index]->Base();
    short* pcm = (short*)soundVecData->GetData(0);
    int n = SOUND_BUFFER_SIZE / sizeof(short);
    for (int i = 0; i < n; i++) {
        int sample = numSent * n + i;
        pcm[i] = ((sample / TONE_HALF_PERIOD) % 2 == 0) ? TONE_LEVEL : -TONE_LEVEL;
    }

    numSent++;
    subject[sbjSpeaker]->SetData(region[index]);
    return true;
}

int
SpeakerStart::FindFreeRegion()
{
    for (int i = 0; i < NUM_SOUND_VECTOR; i++) {
        if (region[i] != 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}
