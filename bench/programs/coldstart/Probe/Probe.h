//
// Probe: prints the monotonic time at which its DoStart runs (cold-start benchmark).
//
#ifndef Probe_h_DEFINED
#define Probe_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Probe : public OObject {
public:
    Probe() {}
    virtual ~Probe() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
};

#endif // Probe_h_DEFINED
