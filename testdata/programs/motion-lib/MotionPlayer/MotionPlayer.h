//
// MotionPlayer.h
//

#ifndef MotionPlayer_h_DEFINED
#define MotionPlayer_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"
#include "MTNFile.h"

class MotionPlayer : public OObject {
public:
    MotionPlayer();
    virtual ~MotionPlayer() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void PrintMotion();

    MTNFile motion;
};

#endif // MotionPlayer_h_DEFINED
