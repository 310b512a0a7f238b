//
// CdtDetect.cc
//
// Loads two colour detection tables into the camera (OPENR::SetCdtVectorData):
// channel 0 detects the pink of the AIBO ball, channel 1 the green of the
// carpet. For the first images it prints, per channel, the ColorFrequency the
// image's tag carries, the number of CDT pixels with the channel's bit and
// their centre (as a ball tracker would find the ball).
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OFbkImage.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "CdtDetect.h"

CdtDetect::CdtDetect() : cameraID(oprimitiveID_UNDEF), numImages(0)
{
}

OStatus
CdtDetect::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OStatus result = OPENR::OpenPrimitive(CAMERA_LOCATOR, &cameraID);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "CdtDetect::DoInit()", "OPENR::OpenPrimitive() FAILED", result));
        return oSUCCESS;
    }
    SetCdt();
    return oSUCCESS;
}

void
CdtDetect::SetCdt()
{
    MemoryRegionID  cdtVecID;
    OCdtVectorData* cdtVec;

    OStatus result = OPENR::NewCdtVectorData(&cdtVecID, &cdtVec);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "CdtDetect::SetCdt()", "OPENR::NewCdtVectorData() FAILED", result));
        return;
    }
    cdtVec->SetNumData(2);

    OCdtInfo* pink = cdtVec->GetInfo(0);
    pink->Init(cameraID, ocdtCHANNEL0);
    OCdtInfo* green = cdtVec->GetInfo(1);
    green->Init(cameraID, ocdtCHANNEL1);
    for (int seg = 0; seg < ocdtMAX_Y_SEGMENT; seg++) {
        pink->Set(seg, PINK_CR_MAX, PINK_CR_MIN, PINK_CB_MAX, PINK_CB_MIN);
        green->Set(seg, GREEN_CR_MAX, GREEN_CR_MIN, GREEN_CB_MAX, GREEN_CB_MIN);
    }

    result = OPENR::SetCdtVectorData(cdtVecID);
    OSYSPRINT(("CdtDetect : SetCdtVectorData %s\n", result == oSUCCESS ? "oSUCCESS" : "FAILED"));
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "CdtDetect::SetCdt()", "OPENR::SetCdtVectorData() FAILED", result));
    }
    // The camera copied the tables.
    OPENR::DeleteCdtVectorData(cdtVecID);
}

OStatus
CdtDetect::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
CdtDetect::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
CdtDetect::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
CdtDetect::Notify(const ONotifyEvent& event)
{
    OFbkImageVectorData* imageVec = (OFbkImageVectorData*)event.Data(0);

    if (numImages < NUM_PRINTED_IMAGES) {
        PrintDetection(imageVec, ocdtCHANNEL0, "pink");
        PrintDetection(imageVec, ocdtCHANNEL1, "green");
    }
    numImages++;

    observer[event.ObsIndex()]->AssertReady(event.SenderID());
}

//
// "CdtDetect : image N pink ColorFrequency F pixels P centre (X,Y)": the last
// row's first 16 bytes are the tag, not pixels, so they are not counted.
//
void
CdtDetect::PrintDetection(OFbkImageVectorData* imageVec, OCdtChannel chan, const char* name)
{
    OFbkImageInfo* info = imageVec->GetInfo(ofbkimageLAYER_C);
    OFbkImage cdtImage(info, imageVec->GetData(ofbkimageLAYER_C), ofbkimageBAND_CDT);
    if (!cdtImage.IsValid()) {
        OSYSLOG1((osyslogERROR, "CdtDetect : the CDT layer is not valid"));
        return;
    }

    int width = cdtImage.Width(), height = cdtImage.Height();
    long pixels = 0, sumX = 0, sumY = 0;
    for (int y = 0; y < height; y++) {
        for (int x = (y == height - 1) ? 16 : 0; x < width; x++) {
            if (cdtImage.Pixel(x, y) & chan) {
                pixels++;
                sumX += x;
                sumY += y;
            }
        }
    }
    if (pixels == 0) {
        OSYSPRINT(("CdtDetect : image %d %s ColorFrequency %d pixels 0\n",
                   numImages, name, cdtImage.ColorFrequency(chan)));
    } else {
        OSYSPRINT(("CdtDetect : image %d %s ColorFrequency %d pixels %ld centre (%ld,%ld)\n",
                   numImages, name, cdtImage.ColorFrequency(chan), pixels,
                   sumX / pixels, sumY / pixels));
    }
}
