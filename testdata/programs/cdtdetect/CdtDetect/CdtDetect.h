//
// CdtDetect.h
//

#ifndef CdtDetect_h_DEFINED
#define CdtDetect_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ODataFormats.h>
#include "def.h"

static const char* const CAMERA_LOCATOR = "PRM:/r1/c1/c2/c3/i1-FbkImageSensor:F1";

const int NUM_PRINTED_IMAGES = 5;   // the detections of the first 5 images

// Channel 0, the pink ball: Cr 150..255 and Cb 129..255 in every Y segment.
const byte PINK_CR_MAX = 255, PINK_CR_MIN = 150, PINK_CB_MAX = 255, PINK_CB_MIN = 129;
// Channel 1, the green carpet: Cr 0..110 and Cb 0..127.
const byte GREEN_CR_MAX = 110, GREEN_CR_MIN = 0, GREEN_CB_MAX = 127, GREEN_CB_MIN = 0;

class CdtDetect : public OObject {
public:
    CdtDetect();
    virtual ~CdtDetect() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    void SetCdt();
    void PrintDetection(OFbkImageVectorData* imageVec, OCdtChannel chan, const char* name);

    OPrimitiveID cameraID;
    int          numImages;
};

#endif // CdtDetect_h_DEFINED
