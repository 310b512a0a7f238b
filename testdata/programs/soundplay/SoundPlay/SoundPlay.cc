//
// SoundPlay.cc
//
// Plays a WAV file (16 kHz, 16-bit, mono PCM) on the speaker: the file
// comes from the design data (DESIGNDB.CFG keyword SNDPLAY_WAV), or from a
// fixed path when the keyword is missing. The samples go out in 32 ms
// buffers (1024 bytes), two in flight; the speaker asserts ready when it
// has played one, and writes the frame number at which it started into
// OSoundInfo.frameNumber, which is printed.
//

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SoundPlay.h"

SoundPlay::SoundPlay() : speakerID(oprimitiveID_UNDEF), wavID(odesigndataID_UNDEF),
                         wavData(0), pcm(0), pcmSize(0), pcmSent(0),
                         rate(0), bits(0), channels(0), numSent(0), numDone(0),
                         running(false)
{
    for (int i = 0; i < NUM_SOUND_VECTOR; i++) {
        region[i] = 0;
        sentIndex[i] = -1;
    }
}

OStatus
SoundPlay::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    LoadWAV();
    OpenSpeaker();
    NewSoundVectorData();

    return oSUCCESS;
}

OStatus
SoundPlay::DoStart(const OSystemEvent& event)
{
    running = (pcm != 0);

    if (running && subject[sbjSpeaker]->IsReady()) {
        if (SetNextBuffer()) SetNextBuffer();
        subject[sbjSpeaker]->NotifyObservers();
    }

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
SoundPlay::DoStop(const OSystemEvent& event)
{
    running = false;

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
SoundPlay::DoDestroy(const OSystemEvent& event)
{
    if (wavID != odesigndataID_UNDEF) OPENR::DeleteDesignData(wavID);
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

bool
SoundPlay::LoadWAV()
{
    byte*  data;
    size_t size;
    OStatus result = OPENR::FindDesignData(WAV_KEYWORD, &wavID, &data, &size);
    if (result == oSUCCESS) {
        OSYSPRINT(("SoundPlay : design data %s, %d bytes\n", WAV_KEYWORD, (int)size));
    } else {
        wavID = odesigndataID_UNDEF;
        FILE* fp = fopen(WAV_FALLBACK, "rb");
        if (fp == 0) {
            OSYSLOG1((osyslogERROR, "SoundPlay : no %s and no %s", WAV_KEYWORD, WAV_FALLBACK));
            return false;
        }
        fseek(fp, 0, SEEK_END);
        size = (size_t)ftell(fp);
        fseek(fp, 0, SEEK_SET);
        data = (byte*)malloc(size);
        size = fread(data, 1, size, fp);
        fclose(fp);
        OSYSPRINT(("SoundPlay : file %s, %d bytes\n", WAV_FALLBACK, (int)size));
    }
    wavData = data;
    return ParseWAV(data, size);
}

static longword
LE32(const byte* p)
{
    return (longword)p[0] | ((longword)p[1] << 8) | ((longword)p[2] << 16) | ((longword)p[3] << 24);
}

static word
LE16(const byte* p)
{
    return (word)(p[0] | (p[1] << 8));
}

bool
SoundPlay::ParseWAV(byte* data, size_t size)
{
    if (size < 12 || memcmp(data, "RIFF", 4) != 0 || memcmp(data + 8, "WAVE", 4) != 0) {
        OSYSLOG1((osyslogERROR, "SoundPlay : not a RIFF WAVE file"));
        return false;
    }
    size_t pos = 12;
    while (pos + 8 <= size) {
        longword chunkSize = LE32(data + pos + 4);
        const byte* chunk = data + pos + 8;
        if (memcmp(data + pos, "fmt ", 4) == 0 && chunkSize >= 16) {
            channels = LE16(chunk + 2);
            rate     = (word)LE32(chunk + 4);
            bits     = LE16(chunk + 14);
        } else if (memcmp(data + pos, "data", 4) == 0) {
            pcm = data + pos + 8;
            pcmSize = chunkSize;
            if (pcm + pcmSize > data + size) pcmSize = size - (pos + 8);
        }
        pos += 8 + chunkSize + (chunkSize & 1);
    }
    if (pcm == 0 || rate != 16000 || bits != 16 || channels != 1) {
        OSYSLOG1((osyslogERROR, "SoundPlay : need 16 kHz 16-bit mono PCM"));
        pcm = 0;
        return false;
    }
    OSYSPRINT(("SoundPlay : %d Hz %d bit %d ch, %d bytes of PCM\n",
               (int)rate, (int)bits, (int)channels, (int)pcmSize));
    return true;
}

void
SoundPlay::OpenSpeaker()
{
    OStatus result = OPENR::OpenPrimitive(SPEAKER_LOCATOR, &speakerID);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "SoundPlay : OpenPrimitive(%s) FAILED %d", SPEAKER_LOCATOR, result));
        return;
    }

    //
    // Mute while the amplifier is powered up, then set the volume and the
    // sound type, then unmute.
    //
    OStatus mute = OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_MUTE_ON, 0, 0, 0, 0);
    OStatus power = OPENR::SetMotorPower(opowerON);

    OPrimitiveControl_SpeakerVolume volume(ospkvol10dB);
    OStatus vol = OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_SET_VOLUME,
                                          &volume, sizeof(volume), 0, 0);

    OPrimitiveControl_SpeakerSoundType soundType(ospksndMONO16K16B);
    OStatus type = OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_SET_SOUND_TYPE,
                                           &soundType, sizeof(soundType), 0, 0);

    OStatus unmute = OPENR::ControlPrimitive(speakerID, oprmreqSPEAKER_MUTE_OFF, 0, 0, 0, 0);

    OSYSPRINT(("SoundPlay : mute %d power %d volume %d type %d unmute %d\n",
               (int)mute, (int)power, (int)vol, (int)type, (int)unmute));
}

void
SoundPlay::NewSoundVectorData()
{
    MemoryRegionID    soundVecDataID;
    OSoundVectorData* soundVecData;

    for (int i = 0; i < NUM_SOUND_VECTOR; i++) {
        OStatus result = OPENR::NewSoundVectorData(1, SOUND_BUFFER_SIZE,
                                                   &soundVecDataID, &soundVecData);
        if (result != oSUCCESS) {
            OSYSLOG1((osyslogERROR, "SoundPlay : NewSoundVectorData() FAILED %d", result));
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

void
SoundPlay::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert() || !running) return;

    //
    // Regions the speaker has released: report when their buffer started.
    //
    for (int i = 0; i < NUM_SOUND_VECTOR; i++) {
        if (sentIndex[i] >= 0 && region[i]->NumberOfReference() == 1) {
            OSoundVectorData* v = (OSoundVectorData*)region[i]->Base();
            OSYSPRINT(("SoundPlay : buffer %d played from frame %u\n",
                       sentIndex[i], (unsigned int)v->GetInfo(0)->frameNumber));
            sentIndex[i] = -1;
            numDone++;
        }
    }

    if (SetNextBuffer()) {
        subject[sbjSpeaker]->NotifyObservers();
    } else if (numDone == numSent) {
        running = false;
        OSYSPRINT(("SoundPlay : done, %d buffers\n", numSent));
    }
}

bool
SoundPlay::SetNextBuffer()
{
    if (pcmSent >= pcmSize) return false;

    int index = FindFreeRegion();
    if (index < 0) return false;

    OSoundVectorData* soundVecData = (OSoundVectorData*)region[index]->Base();
    byte* dst = soundVecData->GetData(0);
    size_t n = pcmSize - pcmSent;
    if (n > SOUND_BUFFER_SIZE) n = SOUND_BUFFER_SIZE;
    memcpy(dst, pcm + pcmSent, n);
    if (n < SOUND_BUFFER_SIZE) memset(dst + n, 0, SOUND_BUFFER_SIZE - n);   // zero-pad the last one
    pcmSent += n;

    sentIndex[index] = numSent++;
    subject[sbjSpeaker]->SetData(region[index]);
    return true;
}

int
SoundPlay::FindFreeRegion()
{
    for (int i = 0; i < NUM_SOUND_VECTOR; i++) {
        if (region[i] != 0 && sentIndex[i] < 0 && region[i]->NumberOfReference() == 1) return i;
    }
    return -1;
}
