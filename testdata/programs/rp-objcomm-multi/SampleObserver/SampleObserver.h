//
// SampleObserver.h  (shared by SampleObserver1, 2 and 3)
//

#ifndef SampleObserver_h_DEFINED
#define SampleObserver_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class SampleObserver : public OObject {
public:
    SampleObserver();
    virtual ~SampleObserver() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);

private:
    char myName[32];    // "SampleObserver1" .. "SampleObserver3"
};

#endif // SampleObserver_h_DEFINED
