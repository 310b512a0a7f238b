//
// RobotDesign.h
//

#ifndef RobotDesign_h_DEFINED
#define RobotDesign_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class RobotDesign : public OObject {
public:
    RobotDesign();
    virtual ~RobotDesign() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void PrintDesignData(const char* keyword);
};

#endif // RobotDesign_h_DEFINED
