//
// SpeakerStart.h
//

#ifndef SpeakerStart_h_DEFINED
#define SpeakerStart_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ODataFormats.h>
#include "def.h"

static const char* const SPEAKER_LOCATOR = "PRM:/s1-Speaker:S1";

const int    NUM_SOUND_VECTOR  = 2;
const int    NUM_BUFFERS       = 8;         // 8 x 32 ms of tone
const size_t SOUND_BUFFER_SIZE = 1024;      // 32 ms of 16 kHz 16-bit mono
const int    TONE_HALF_PERIOD  = 16;        // samples: a 500 Hz square wave
const short  TONE_LEVEL        = 8000;

class SpeakerStart : public OObject {
public:
    SpeakerStart();
    virtual ~SpeakerStart() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

private:
    void OpenSpeaker();
    void NewSoundVectorData();
    bool SendBuffer(int index);
    int  FindFreeRegion();

    OPrimitiveID speakerID;
    int          numSent;
    int          numPlayed;
    bool         running;
    RCRegion*    region[NUM_SOUND_VECTOR];
};

#endif // SpeakerStart_h_DEFINED
