//
// Ping.h
//

#ifndef Ping_h_DEFINED
#define Ping_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const longword REPORT_EVERY = 25000;    // exchanges between two time reports

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
    longword exchanges;
};

#endif // Ping_h_DEFINED
