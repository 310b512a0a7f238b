//
// MicRate.h
//

#ifndef MicRate_h_DEFINED
#define MicRate_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ODataFormats.h>
#include "def.h"

static const char* const RAW_PATH = "/MS/MIC.RAW";

// Measure over 4 s of sound: a whole number of blocks on every design
// (250 blocks of 16 ms on the ERS-7, 125 of 32 ms on the ERS-210/220).
const int    MEASURE_FRAMES = 500;       // 8 ms frames
const size_t RECORD_SIZE    = 300000;    // more than 4 s of 16 kHz 16-bit stereo

class MicRate : public OObject {
public:
    MicRate();
    virtual ~MicRate() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    void Report(unsigned int frames);

    byte*        buffer;
    size_t       recorded;    // bytes of every block, for MIC.RAW
    size_t       measured;    // bytes of the blocks after the first one
    int          numBlocks;
    unsigned int firstFrame;
    bool         done;
};

#endif // MicRate_h_DEFINED
