//
// PowerMonitor.h
//

#ifndef PowerMonitor_h_DEFINED
#define PowerMonitor_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class PowerMonitor : public OObject {
public:
    PowerMonitor();
    virtual ~PowerMonitor() {}

    //
    // Declared because the generated stub refers to them, but never
    // created: PowerMonitor registers no service (see DoInit).
    //
    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    // Extra entry (see stub.cfg)
    void UpdatePowerStatus(void* msg);

private:
    void PrintPowerStatus(const char* who, const OPowerStatus& status);

    bool observing;
};

#endif // PowerMonitor_h_DEFINED
