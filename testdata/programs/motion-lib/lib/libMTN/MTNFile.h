//
// MTNFile.h : a very small key-frame motion file format
//
// A .MTN file is little endian and starts with an MTNHeader, followed by
// numKeyFrames records. A record is numJoints slongword angles
// (micro-radians) followed by one slongword: the number of 8 ms steps
// used to reach the next key frame.
//
// The file is read in one piece and the structs below are laid over the
// bytes, so every field must have exactly the size it has in the file:
// longword and slongword are 32 bits on OPEN-R.
//

#ifndef MTNFile_h_DEFINED
#define MTNFile_h_DEFINED

#include <Types.h>

const longword MTN_MAGIC   = 0x4e544d4f;  // "OMTN" read as a little endian longword
const longword MTN_VERSION = 1;
const int      MTN_NAME_MAX = 16;

struct MTNHeader {
    longword magic;
    longword version;
    longword numJoints;
    longword numKeyFrames;
    longword checksum;          // sum of all record words (see mtn_checksum())
    char     name[MTN_NAME_MAX]; // NUL padded
};

class MTNFile {
public:
    MTNFile();
    ~MTNFile();

    // Returns 0 on success, otherwise a negative error code.
    int  Load(const char* path);
    void Unload();

    const char* GetName()        const { return header->name; }
    int         GetNumJoints()   const { return (int)header->numJoints; }
    int         GetNumKeyFrames() const { return (int)header->numKeyFrames; }
    longword    GetChecksum()    const { return header->checksum; }

    slongword   GetAngle(int keyFrame, int joint) const;
    slongword   GetSteps(int keyFrame) const;

    // All record words, for checksumming.
    const slongword* GetRecords() const { return records; }
    longword         GetNumRecordWords() const;

private:
    byte*       buffer;
    MTNHeader*  header;
    slongword*  records;
};

//
// Linear interpolation between two key frames, as the motion agents do:
// value at step "step" (0..numSteps) of the way from "from" to "to".
//
slongword MTNInterpolate(slongword from, slongword to, int step, int numSteps);

#endif // MTNFile_h_DEFINED
