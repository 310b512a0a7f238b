//
// Jitter: times the arrival of sensor vectors in real time (benchmark of the frame
// clock: every 32 ms on the robot).
//
#ifndef Jitter_h_DEFINED
#define Jitter_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Jitter : public OObject {
public:
    Jitter() : count(0), last(0) {}
    virtual ~Jitter() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit (const OSystemEvent& event);
    virtual OStatus DoStart(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    int       count;
    long long last;
    long long dev[1000];
};

#endif
