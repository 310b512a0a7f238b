//
// HostCalls.h
//

#ifndef HostCalls_h_DEFINED
#define HostCalls_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class HostCalls : public OObject {
public:
    HostCalls();
    virtual ~HostCalls() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    bool ReadConfig();
    void FromOwnThread();

    char outside[256];   // a host directory (HOSTCALL.CFG): nothing may appear in it
};

#endif // HostCalls_h_DEFINED
