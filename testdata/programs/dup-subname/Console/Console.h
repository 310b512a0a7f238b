//
// Console.h
//

#ifndef Console_h_DEFINED
#define Console_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Console : public OObject {
public:
    Console();
    virtual ~Console() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void NotifyChar(const ONotifyEvent& event);
    void NotifyLine(const ONotifyEvent& event);
};

#endif // Console_h_DEFINED
