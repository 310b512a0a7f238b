//
// Sloppy.h
//

#ifndef Sloppy_h_DEFINED
#define Sloppy_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Sloppy : public OObject {
public:
    Sloppy() {}
    virtual ~Sloppy() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);
};

#endif // Sloppy_h_DEFINED
