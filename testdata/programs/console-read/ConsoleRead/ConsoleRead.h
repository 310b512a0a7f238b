//
// ConsoleRead.h
//

#ifndef ConsoleRead_h_DEFINED
#define ConsoleRead_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class ConsoleRead : public OObject {
public:
    ConsoleRead() {}
    virtual ~ConsoleRead() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void GetsLoop();
    void CinLoop();
};

#endif // ConsoleRead_h_DEFINED
