//
// NetErrors.h
//

#ifndef NetErrors_h_DEFINED
#define NetErrors_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <TCPEndpointMsg.h>
#include <UDPEndpointMsg.h>
#include <DNSEndpointMsg.h>
#include "def.h"

const char* const NETERRORS_CONF = "/MS/OPEN-R/MW/CONF/NETERR.CFG";

class NetErrors : public OObject {
public:
    NetErrors() {}
    virtual ~NetErrors() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void ReceiveCont(void* msg);

private:
    void Check(const char* what, int got);
    antModuleRef NewEndpoint(int protocol);
    byte* NewBuffer(int size);
    void TCPChecks(Port resetPort, Port closedPort);
    void UDPChecks(Port udpPort);
    void DNSChecks();

    antStackRef ipstackRef;
};

#endif // NetErrors_h_DEFINED
