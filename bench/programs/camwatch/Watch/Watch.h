//
// Watch: takes every camera image and sensor vector (a robot program's data load,
// for the "how many robots in real time" benchmark) and counts them.
//
#ifndef Watch_h_DEFINED
#define Watch_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Watch : public OObject {
public:
    Watch() : images(0), sensors(0), luma(0), readPixels(true) {}
    virtual ~Watch() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit (const OSystemEvent& event);
    virtual OStatus DoStart(const OSystemEvent& event);
    virtual OStatus DoStop (const OSystemEvent& event);

    void NotifyImage(const ONotifyEvent& event);
    void NotifySensor(const ONotifyEvent& event);

private:
    int images;
    int sensors;
    unsigned long luma;
    bool readPixels;  // false when the stick has /MS/NOPIXEL
};

#endif
