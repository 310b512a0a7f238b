//
// ImageSave.cc
//
// Observes the camera (OVirtualRobotComm.FbkImageSensor): prints the
// layout of the four layers of the first image and the frame numbers of
// the first images, and saves layer H of a few images as 24-bit BMP files
// on the memory stick (/MS/IMG0.BMP, ...), converting Y/Cr/Cb to RGB.
//

#include <stdio.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OFbkImage.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "ImageSave.h"

ImageSave::ImageSave() : cameraID(oprimitiveID_UNDEF), numImages(0), numSaved(0)
{
}

OStatus
ImageSave::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    OStatus result = OPENR::OpenPrimitive(CAMERA_LOCATOR, &cameraID);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "ImageSave::DoInit()", "OPENR::OpenPrimitive() FAILED", result));
    }
    return oSUCCESS;
}

OStatus
ImageSave::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
ImageSave::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
ImageSave::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
ImageSave::Notify(const ONotifyEvent& event)
{
    OFbkImageVectorData* imageVec = (OFbkImageVectorData*)event.Data(0);
    OFbkImageInfo* info = imageVec->GetInfo(ofbkimageLAYER_H);

    if (numImages == 0) PrintLayers(imageVec);

    if (numImages < NUM_PRINTED_IMAGES) {
        OFbkImage yImage(info, imageVec->GetData(ofbkimageLAYER_H), ofbkimageBAND_Y);
        OSYSPRINT(("ImageSave : image %d frame %u field %d\n", numImages,
                   (unsigned int)info->frameNumber, yImage.FieldCounter()));
    }

    if (numSaved < NUM_SAVED_IMAGES && numImages % SAVE_EVERY == 0) {
        char path[32];
        sprintf(path, "/MS/IMG%d.BMP", numSaved);
        if (SaveBMP(path, imageVec, ofbkimageLAYER_H)) {
            OSYSPRINT(("ImageSave : saved %s frame %u\n", path,
                       (unsigned int)info->frameNumber));
            numSaved++;
        }
    }
    numImages++;

    observer[event.ObsIndex()]->AssertReady(event.SenderID());
}

void
ImageSave::PrintLayers(OFbkImageVectorData* imageVec)
{
    static const char* const name[4] = { "H", "M", "L", "C" };

    OSYSPRINT(("ImageSave : %d layers, camera ID %s\n", (int)imageVec->vectorInfo.numData,
               imageVec->GetInfo(0)->primitiveID == cameraID ? "matches" : "DIFFERS"));
    for (int l = 0; l < (int)imageVec->vectorInfo.numData && l < 4; l++) {
        OFbkImageInfo* info = imageVec->GetInfo(l);
        OFbkImageBand band = (l == ofbkimageLAYER_C) ? ofbkimageBAND_CDT : ofbkimageBAND_Y;
        OFbkImage image(info, imageVec->GetData(l), band);
        OSYSPRINT(("ImageSave : layer %s type %d %dx%d skip %d size %d\n", name[l],
                   (int)info->type, image.Width(), image.Height(), image.Skip(),
                   (int)info->dataSize));
    }
}

static void
PutLE(FILE* fp, longword value, int bytes)
{
    for (int i = 0; i < bytes; i++) fputc((int)((value >> (8 * i)) & 0xff), fp);
}

static byte
Clip(double v)
{
    if (v < 0.0) return 0;
    if (v > 255.0) return 255;
    return (byte)(v + 0.5);
}

//
// 24-bit BMP, bottom-up rows of B, G, R padded to 4 bytes.
//
bool
ImageSave::SaveBMP(const char* path, OFbkImageVectorData* imageVec, OFbkImageLayer layer)
{
    OFbkImageInfo* info = imageVec->GetInfo(layer);
    byte* data = imageVec->GetData(layer);
    OFbkImage yImage (info, data, ofbkimageBAND_Y);
    OFbkImage crImage(info, data, ofbkimageBAND_Cr);
    OFbkImage cbImage(info, data, ofbkimageBAND_Cb);
    if (!yImage.IsValid() || !crImage.IsValid() || !cbImage.IsValid()) return false;

    int width  = yImage.Width();
    int height = yImage.Height();
    int rowSize = (width * 3 + 3) & ~3;
    longword imageSize = (longword)(rowSize * height);

    FILE* fp = fopen(path, "wb");
    if (fp == 0) {
        OSYSLOG1((osyslogERROR, "ImageSave : cannot open %s", path));
        return false;
    }

    // BITMAPFILEHEADER
    fputc('B', fp); fputc('M', fp);
    PutLE(fp, 54 + imageSize, 4);
    PutLE(fp, 0, 4);
    PutLE(fp, 54, 4);
    // BITMAPINFOHEADER
    PutLE(fp, 40, 4);
    PutLE(fp, (longword)width, 4);
    PutLE(fp, (longword)height, 4);
    PutLE(fp, 1, 2);
    PutLE(fp, 24, 2);
    PutLE(fp, 0, 4);
    PutLE(fp, imageSize, 4);
    PutLE(fp, 2835, 4);
    PutLE(fp, 2835, 4);
    PutLE(fp, 0, 4);
    PutLE(fp, 0, 4);

    for (int y = height - 1; y >= 0; y--) {
        int x;
        for (x = 0; x < width; x++) {
            double Y  = yImage.Pixel(x, y);
            double Cr = crImage.Pixel(x, y) - 128.0;
            double Cb = cbImage.Pixel(x, y) - 128.0;
            double R  = Y + 2.0 * Cr * 255.0 / 256.0;
            double B  = Y + 2.0 * Cb * 255.0 / 256.0;
            double G  = Y - 0.51 * (R - Y) - 0.19 * (B - Y);
            fputc(Clip(B), fp);
            fputc(Clip(G), fp);
            fputc(Clip(R), fp);
        }
        for (x = width * 3; x < rowSize; x++) fputc(0, fp);
    }
    fclose(fp);
    return true;
}
