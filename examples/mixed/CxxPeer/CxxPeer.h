//
// CxxPeer.h - the C++ half of the mixed example.
//

#ifndef CxxPeer_h_DEFINED
#define CxxPeer_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class CxxPeer : public OObject {
public:
    CxxPeer();
    virtual ~CxxPeer() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    // Ready function of "CxxPeer.SendString.char.S"
    void Ready(const OReadyEvent& event);
    // Notify function of "CxxPeer.ReceiveString.char.O"
    void Notify(const ONotifyEvent& event);

private:
    int sent;
};

#endif // CxxPeer_h_DEFINED
