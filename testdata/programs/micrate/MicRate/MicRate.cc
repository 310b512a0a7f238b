//
// MicRate.cc
//
// Measures how much sound the microphones deliver per second of robot time.
// Each OSoundVectorData block ends at info->frameNumber; the blocks after the
// first one cover (frame - firstFrame) * 8 ms of sound.  Whatever the design,
// 16 kHz 16-bit stereo is 64000 bytes per second.  The raw samples go to
// /MS/MIC.RAW so they can be compared with what was played into the mic.
//

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "MicRate.h"

MicRate::MicRate() : buffer(0), recorded(0), measured(0), numBlocks(0),
                     firstFrame(0), done(false)
{
}

OStatus
MicRate::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    buffer = (byte*)malloc(RECORD_SIZE);
    return oSUCCESS;
}

OStatus
MicRate::DoStart(const OSystemEvent& event)
{
    char design[32];
    OPENR::GetRobotDesign(design);
    OSYSPRINT(("MicRate : measuring the microphones of %s\n", design));
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
MicRate::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
MicRate::DoDestroy(const OSystemEvent& event)
{
    free(buffer);
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
MicRate::Notify(const ONotifyEvent& event)
{
    OSoundVectorData* soundVec = (OSoundVectorData*)event.Data(0);
    OSoundInfo* info = soundVec->GetInfo(0);
    unsigned int frame = (unsigned int)info->frameNumber;

    if (numBlocks == 0) {
        firstFrame = frame;
        OSYSPRINT(("MicRate : block size %d\n", (int)info->dataSize));
    } else if (!done) {
        measured += info->dataSize;
    }
    numBlocks++;

    size_t n = info->dataSize;
    if (n > RECORD_SIZE - recorded) n = RECORD_SIZE - recorded;
    memcpy(buffer + recorded, soundVec->GetData(0), n);
    recorded += n;

    if (!done && frame - firstFrame >= (unsigned int)MEASURE_FRAMES) {
        done = true;
        Report(frame - firstFrame);
    }
    observer[event.ObsIndex()]->AssertReady(event.SenderID());
}

void
MicRate::Report(unsigned int frames)
{
    unsigned int ms = frames * 8;
    OSYSPRINT(("MicRate : %d bytes in %u ms of sound: %d bytes/s\n",
               (int)measured, ms, (int)(measured * 1000 / ms)));
    FILE* fp = fopen(RAW_PATH, "wb");
    if (fp == 0) {
        OSYSLOG1((osyslogERROR, "MicRate : cannot open %s", RAW_PATH));
        return;
    }
    fwrite(buffer, 1, recorded, fp);
    fclose(fp);
}
