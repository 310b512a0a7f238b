//
// Watch.cc
//
#include <OPENR/OSyslog.h>
#include <OPENR/OFbkImage.h>
#include <OPENR/core_macro.h>
#include <stdio.h>
#include "Watch.h"

OStatus Watch::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    // A stick with /MS/NOPIXEL: take each image and read none of it (the benchmark's
    // share of an image that is the runtime's, not this program's loop).
    FILE* f = fopen("/MS/NOPIXEL", "r");
    if (f) {
        readPixels = false;
        fclose(f);
    }
    return oSUCCESS;
}

OStatus Watch::DoStart(const OSystemEvent& event)
{
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus Watch::DoStop(const OSystemEvent& event)
{
    OSYSPRINT(("BENCH watch images=%d sensors=%d\n", images, sensors));
    return oSUCCESS;
}

void Watch::NotifyImage(const ONotifyEvent& event)
{
    // Touch every Y pixel of layer H, as an image-processing object would.
    OFbkImageVectorData* v = (OFbkImageVectorData*)event.Data(0);
    OFbkImage y(v->GetInfo(ofbkimageLAYER_H), v->GetData(ofbkimageLAYER_H), ofbkimageBAND_Y);
    if (readPixels)
        for (int j = 0; j < y.Height() - 1; j++)
            for (int i = 0; i < y.Width(); i++) luma += y.Pixel(i, j);
    images++;
    observer[event.ObsIndex()]->AssertReady();
}

void Watch::NotifySensor(const ONotifyEvent& event)
{
    sensors++;
    observer[event.ObsIndex()]->AssertReady();
}
