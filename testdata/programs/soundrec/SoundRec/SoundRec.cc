//
// SoundRec.cc
//
// Records one second from the microphones (OVirtualRobotAudioComm.Mic:
// 16 kHz, 16-bit, 2 channels, a block every 16 ms on the ERS-7) and saves
// it as /MS/RECORD.WAV. It stops asserting ready once the buffer is full.
//

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SoundRec.h"

SoundRec::SoundRec() : micID(oprimitiveID_UNDEF), buffer(0), recorded(0), numBlocks(0),
                       rate(0), bits(0), channels(0)
{
}

OStatus
SoundRec::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OStatus result = OPENR::OpenPrimitive(MIC_LOCATOR, &micID);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "SoundRec : OpenPrimitive(%s) FAILED %d", MIC_LOCATOR, result));
    }
    buffer = (byte*)malloc(RECORD_SIZE);
    return oSUCCESS;
}

OStatus
SoundRec::DoStart(const OSystemEvent& event)
{
    OSYSPRINT(("SoundRec : recording %d bytes\n", (int)RECORD_SIZE));
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SoundRec::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SoundRec::DoDestroy(const OSystemEvent& event)
{
    free(buffer);
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
SoundRec::Notify(const ONotifyEvent& event)
{
    OSoundVectorData* soundVec = (OSoundVectorData*)event.Data(0);
    OSoundInfo* info = soundVec->GetInfo(0);

    if (numBlocks < NUM_PRINTED_BLOCKS) {
        OSYSPRINT(("SoundRec : block %d frame %u rate %d bits %d ch %d size %d id %s\n",
                   numBlocks, (unsigned int)info->frameNumber, (int)info->samplingRate,
                   (int)info->bitsPerSample, (int)info->channel, (int)info->dataSize,
                   info->primitiveID == micID ? "mic" : "OTHER"));
    }
    if (numBlocks == 0) {
        rate = info->samplingRate;
        bits = info->bitsPerSample;
        channels = info->channel;
    }
    numBlocks++;

    size_t n = info->dataSize;
    if (n > RECORD_SIZE - recorded) n = RECORD_SIZE - recorded;
    memcpy(buffer + recorded, soundVec->GetData(0), n);
    recorded += n;

    if (recorded < RECORD_SIZE) {
        observer[event.ObsIndex()]->AssertReady(event.SenderID());
    } else {
        SaveWAV();
    }
}

static void
PutLE(FILE* fp, longword value, int bytes)
{
    for (int i = 0; i < bytes; i++) fputc((int)((value >> (8 * i)) & 0xff), fp);
}

void
SoundRec::SaveWAV()
{
    FILE* fp = fopen(WAV_PATH, "wb");
    if (fp == 0) {
        OSYSLOG1((osyslogERROR, "SoundRec : cannot open %s", WAV_PATH));
        return;
    }
    word blockAlign = (word)(channels * bits / 8);
    fwrite("RIFF", 1, 4, fp);
    PutLE(fp, 36 + recorded, 4);
    fwrite("WAVEfmt ", 1, 8, fp);
    PutLE(fp, 16, 4);
    PutLE(fp, 1, 2);                        // PCM
    PutLE(fp, channels, 2);
    PutLE(fp, rate, 4);
    PutLE(fp, (longword)rate * blockAlign, 4);
    PutLE(fp, blockAlign, 2);
    PutLE(fp, bits, 2);
    fwrite("data", 1, 4, fp);
    PutLE(fp, recorded, 4);
    fwrite(buffer, 1, recorded, fp);
    fclose(fp);

    OSYSPRINT(("SoundRec : saved %s, %d bytes in %d blocks\n", WAV_PATH, (int)recorded, numBlocks));
}
