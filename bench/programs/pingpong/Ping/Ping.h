//
// Ping: sends a small integer every time its observer is ready and times the
// notify -> ready round trip (benchmark of the object communication hot path).
//
#ifndef Ping_h_DEFINED
#define Ping_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Ping : public OObject {
public:
    Ping();
    virtual ~Ping() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

private:
    void Report();

    int        count;
    long long  last;
    long long  first;
    long long* rtt;
};

#endif // Ping_h_DEFINED
