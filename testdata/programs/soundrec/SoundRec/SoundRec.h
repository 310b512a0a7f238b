//
// SoundRec.h
//

#ifndef SoundRec_h_DEFINED
#define SoundRec_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ODataFormats.h>
#include "def.h"

static const char* const MIC_LOCATOR = "PRM:/r1/c1/c2/c3/m1-Mic:M1";
static const char* const WAV_PATH    = "/MS/RECORD.WAV";

// One second of 16 kHz, 16-bit stereo.
const size_t RECORD_SIZE = 16000 * 2 * 2;
const int    NUM_PRINTED_BLOCKS = 5;

class SoundRec : public OObject {
public:
    SoundRec();
    virtual ~SoundRec() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    void SaveWAV();

    OPrimitiveID micID;
    byte*        buffer;
    size_t       recorded;
    int          numBlocks;
    word         rate, bits, channels;
};

#endif // SoundRec_h_DEFINED
