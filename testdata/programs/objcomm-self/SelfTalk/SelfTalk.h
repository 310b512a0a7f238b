//
// SelfTalk.h
//

#ifndef SelfTalk_h_DEFINED
#define SelfTalk_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class SelfTalk : public OObject {
public:
    SelfTalk();
    virtual ~SelfTalk() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);
    void Notify(const ONotifyEvent& event);
    void TimerFired(void* msg);

private:
    void CheckTime();
    void CheckKernel();

    int readyCount;
};

#endif // SelfTalk_h_DEFINED
