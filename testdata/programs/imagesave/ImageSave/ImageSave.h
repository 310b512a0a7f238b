//
// ImageSave.h
//

#ifndef ImageSave_h_DEFINED
#define ImageSave_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ODataFormats.h>
#include "def.h"

static const char* const CAMERA_LOCATOR = "PRM:/r1/c1/c2/c3/i1-FbkImageSensor:F1";

const int NUM_PRINTED_IMAGES = 10;  // frame numbers of the first 10 images
const int SAVE_EVERY         = 15;  // one picture every 15 images (0.5 s)
const int NUM_SAVED_IMAGES   = 3;   // /MS/IMG0.BMP .. /MS/IMG2.BMP

class ImageSave : public OObject {
public:
    ImageSave();
    virtual ~ImageSave() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    void PrintLayers(OFbkImageVectorData* imageVec);
    bool SaveBMP(const char* path, OFbkImageVectorData* imageVec, OFbkImageLayer layer);

    OPrimitiveID cameraID;
    int          numImages;
    int          numSaved;
};

#endif // ImageSave_h_DEFINED
