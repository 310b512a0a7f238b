//
// Pong.h
//

#ifndef Pong_h_DEFINED
#define Pong_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Pong : public OObject {
public:
    Pong() {}
    virtual ~Pong() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Notify(const ONotifyEvent& event);
};

#endif // Pong_h_DEFINED
