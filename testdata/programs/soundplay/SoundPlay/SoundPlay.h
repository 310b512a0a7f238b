//
// SoundPlay.h
//

#ifndef SoundPlay_h_DEFINED
#define SoundPlay_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ODataFormats.h>
#include "def.h"

static const char* const SPEAKER_LOCATOR = "PRM:/s1-Speaker:S1";
static const char* const WAV_KEYWORD     = "SNDPLAY_WAV";
static const char* const WAV_FALLBACK    = "/MS/OPEN-R/MW/DATA/P/TONE.WAV";

const int    NUM_SOUND_VECTOR = 2;
const size_t SOUND_BUFFER_SIZE = 1024;      // 32 ms of 16 kHz 16-bit mono

class SoundPlay : public OObject {
public:
    SoundPlay();
    virtual ~SoundPlay() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

private:
    bool LoadWAV();
    bool ParseWAV(byte* data, size_t size);
    void OpenSpeaker();
    void NewSoundVectorData();
    bool SetNextBuffer();
    int  FindFreeRegion();

    OPrimitiveID  speakerID;
    ODesignDataID wavID;
    byte*         wavData;      // design data (or a malloc'ed file)
    byte*         pcm;          // PCM samples inside wavData
    size_t        pcmSize;
    size_t        pcmSent;
    word          rate, bits, channels;
    int           numSent;
    int           numDone;
    bool          running;
    RCRegion*     region[NUM_SOUND_VECTOR];
    int           sentIndex[NUM_SOUND_VECTOR];  // buffer number in each region
};

#endif // SoundPlay_h_DEFINED
