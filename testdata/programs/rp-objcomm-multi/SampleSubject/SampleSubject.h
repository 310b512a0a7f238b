//
// SampleSubject.h  (shared by SampleSubject1 and SampleSubject2)
//
// def.h comes from the robot/ directory of the instance being built,
// so each instance sees its own service names.
//

#ifndef SampleSubject_h_DEFINED
#define SampleSubject_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

const int SAMPLE_NUM_MESSAGES = 2;   // strings sent by each subject
const int SAMPLE_NAME_MAX     = 32;

class SampleSubject : public OObject {
public:
    SampleSubject();
    virtual ~SampleSubject() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);

private:
    char myName[SAMPLE_NAME_MAX];   // "SampleSubject1" or "SampleSubject2"
    int  numSent;
};

#endif // SampleSubject_h_DEFINED
