//
// SampleSubject.h
//

#ifndef SampleSubject_h_DEFINED
#define SampleSubject_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class SampleSubject : public OObject {
public:
    SampleSubject();
    virtual ~SampleSubject() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    // Ready function of "SampleSubject.SendString.char.S" (see stub.cfg)
    void Ready(const OReadyEvent& event);

private:
    void SendString(const char* str);

    int readyCount;     // number of ASSERT READY received so far
};

#endif // SampleSubject_h_DEFINED
