//
// OldCode.h
//

#ifndef OldCode_h_DEFINED
#define OldCode_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class OldCode : public OObject {
public:
    OldCode();
    virtual ~OldCode() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void ReadConfig();

    int samples[8];
    int numSamples;
};

#endif // OldCode_h_DEFINED
