//
// Stuck.h
//

#ifndef Stuck_h_DEFINED
#define Stuck_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

static const char* const STUCK_CONFIG = "/MS/OPEN-R/MW/DATA/P/STUCK.TXT";

class Stuck : public OObject {
public:
    Stuck();
    virtual ~Stuck() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void ReadConfig();
    void Spin(const char* where);

    char hangIn[16];    // "DoInit", "DoStart" or "DoStop"
};

#endif // Stuck_h_DEFINED
