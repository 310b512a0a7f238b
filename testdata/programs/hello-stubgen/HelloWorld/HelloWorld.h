//
// HelloWorld.h  (stubgen version)
//

#ifndef HelloWorld_h_DEFINED
#define HelloWorld_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class HelloWorld : public OObject {
public:
    HelloWorld();
    virtual ~HelloWorld() {}

    // The generated stub uses these two arrays.
    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);
};

#endif // HelloWorld_h_DEFINED
