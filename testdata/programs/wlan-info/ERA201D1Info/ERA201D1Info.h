//
// ERA201D1Info.h
//

#ifndef ERA201D1Info_h_DEFINED
#define ERA201D1Info_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <ERA201D1.h>
#include "def.h"

class ERA201D1Info : public OObject {
public:
    ERA201D1Info() {}
    virtual ~ERA201D1Info() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void PrintMACAddress();
    void PrintEtherStatistics();
    void PrintWLANSettings();
    void PrintWLANStatistics();
    void PrintEtherIP();
};

#endif // ERA201D1Info_h_DEFINED
