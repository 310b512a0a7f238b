//
// MotionList.h
//
// Written the way MoNet-style headers of 2004-2006 were: the STL and
// "using namespace std" right in the class header. The generated stub
// (MotionListStub.cc) includes this header, so everything the stub expands
// after it -- GEN_ENTRY(_hookstub3, _Destroy) and friends -- sees std::
// names too (libstdc++ has its own std::_Destroy).
//

#ifndef MotionList_h_DEFINED
#define MotionList_h_DEFINED

#include <string>
#include <vector>
#include <map>
#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

using namespace std;

class MotionList : public OObject {
public:
    MotionList();
    virtual ~MotionList() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void Ready(const OReadyEvent& event);
    void NotifyResult(const ONotifyEvent& event);

private:
    vector<string>   motions;
    map<string, int> duration;   // milliseconds per motion
};

#endif // MotionList_h_DEFINED
