//
// EchoClient.h
//

#ifndef EchoClient_h_DEFINED
#define EchoClient_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <TCPEndpointMsg.h>
#include "def.h"

const int         ECHOCLIENT_BUFFER_SIZE = 512;
const char* const ECHOCLIENT_MESSAGE     = "This is a test message.\n";
const char* const ECHOSERVER_IP          = "10.0.1.2";
const int         ECHOSERVER_PORT        = 54321;

enum EchoClientState {
    CLIENT_CLOSED,
    CLIENT_CONNECTING,
    CLIENT_SENDING,
    CLIENT_RECEIVING,
    CLIENT_CLOSING
};

class EchoClient : public OObject {
public:
    EchoClient();
    virtual ~EchoClient() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void ConnectCont(ANTENVMSG msg);
    void SendCont   (ANTENVMSG msg);
    void ReceiveCont(ANTENVMSG msg);
    void CloseCont  (ANTENVMSG msg);

private:
    OStatus Send();
    OStatus Receive();
    OStatus Close();

    antStackRef     ipstackRef;
    antModuleRef    endpoint;
    EchoClientState state;
    antSharedBuffer sendBuffer;
    byte*           sendData;
    antSharedBuffer recvBuffer;
    byte*           recvData;
    int             rounds;
};

#endif // EchoClient_h_DEFINED
