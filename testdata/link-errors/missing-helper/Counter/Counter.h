//
// Counter.h
//

#ifndef Counter_h_DEFINED
#define Counter_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

//
// Meant to live in CounterUtil.cc, which was never written.
//
int missing_helper(int step);

class Counter : public OObject {
public:
    Counter();
    virtual ~Counter() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    int count;
};

#endif // Counter_h_DEFINED
