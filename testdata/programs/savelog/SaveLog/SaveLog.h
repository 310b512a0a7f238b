//
// SaveLog.h
//

#ifndef SaveLog_h_DEFINED
#define SaveLog_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class SaveLog : public OObject {
public:
    SaveLog();
    virtual ~SaveLog() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void SaveLines();
    void ShowWlanDefaults();
    void ListStick();
};

#endif // SaveLog_h_DEFINED
