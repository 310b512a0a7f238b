//
// Producer.h
//
#ifndef Producer_h_DEFINED
#define Producer_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int NUM_UNITS = 8;

class Producer : public OObject {
public:
    Producer();
    virtual ~Producer() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

private:
    RCRegion* region[NUM_UNITS];
};

#endif // Producer_h_DEFINED
