//
// DNSLookUp.h
//

#ifndef DNSLookUp_h_DEFINED
#define DNSLookUp_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <DNSEndpointMsg.h>
#include "def.h"

class DNSLookUp : public OObject {
public:
    DNSLookUp() {}
    virtual ~DNSLookUp() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void GetDefaultServerByAddrCont(ANTENVMSG msg);
    void GetHostByNameCont(ANTENVMSG msg);

private:
    void Prompt();

    antStackRef  ipstackRef;
    antModuleRef endpoint;
};

#endif // DNSLookUp_h_DEFINED
