//
// Escape.h
//

#ifndef Escape_h_DEFINED
#define Escape_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Escape : public OObject {
public:
    Escape();
    virtual ~Escape() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    bool ReadConfig();
    void ThroughLinks();
    void ThroughHostPaths();
    void FromOwnThread();
    void StillWorks();

    char stick[256];     // the stick's host directory (ESCAPE.CFG line 1)
    char outside[256];   // a host directory outside it (ESCAPE.CFG line 2)
};

#endif // Escape_h_DEFINED
