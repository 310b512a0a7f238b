//
// UDPEcho.h
//

#ifndef UDPEcho_h_DEFINED
#define UDPEcho_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <UDPEndpointMsg.h>
#include "def.h"

const int  UDPECHO_BUFFER_SIZE = 512;
const Port UDPECHO_PORT        = 54330;

enum UDPEchoState {
    UDPECHO_CLOSED,
    UDPECHO_RECEIVING,
    UDPECHO_SENDING,
    UDPECHO_CLOSING
};

class UDPEcho : public OObject {
public:
    UDPEcho();
    virtual ~UDPEcho() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    // continuations (Extra entries, see stub.cfg)
    void SendCont   (ANTENVMSG msg);
    void ReceiveCont(ANTENVMSG msg);
    void CloseCont  (ANTENVMSG msg);

private:
    OStatus CreateBuffers();
    OStatus Open();
    OStatus Receive();
    OStatus Send();
    OStatus Close();

    antStackRef     ipstackRef;
    antModuleRef    endpoint;
    UDPEchoState    state;
    bool            stopping;

    antSharedBuffer sendBuffer;
    byte*           sendData;
    antSharedBuffer recvBuffer;
    byte*           recvData;

    IPAddress       peerAddress;
    Port            peerPort;
    int             peerSize;
};

#endif // UDPEcho_h_DEFINED
