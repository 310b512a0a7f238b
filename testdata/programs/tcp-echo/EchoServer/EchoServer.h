//
// EchoServer.h
//

#ifndef EchoServer_h_DEFINED
#define EchoServer_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <TCPEndpointMsg.h>
#include "def.h"

const int  ECHOSERVER_CONNECTION_MAX = 1;
const int  ECHOSERVER_BUFFER_SIZE    = 512;
const Port ECHOSERVER_PORT           = 54321;

enum EchoConnectionState {
    CONNECTION_CLOSED,
    CONNECTION_LISTENING,
    CONNECTION_CONNECTED,
    CONNECTION_SENDING,
    CONNECTION_RECEIVING,
    CONNECTION_CLOSING
};

struct EchoConnection {
    antModuleRef        endpoint;
    EchoConnectionState state;

    antSharedBuffer     sendBuffer;
    byte*               sendData;
    int                 sendSize;

    antSharedBuffer     recvBuffer;
    byte*               recvData;
};

class EchoServer : public OObject {
public:
    EchoServer();
    virtual ~EchoServer() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void ListenCont (ANTENVMSG msg);
    void SendCont   (ANTENVMSG msg);
    void ReceiveCont(ANTENVMSG msg);
    void CloseCont  (ANTENVMSG msg);

private:
    OStatus Listen (int index);
    OStatus Send   (int index);
    OStatus Receive(int index);
    OStatus Close  (int index);
    OStatus InitBuffers(int index);

    antStackRef    ipstackRef;
    EchoConnection connection[ECHOSERVER_CONNECTION_MAX];
    bool           stopping;
};

#endif // EchoServer_h_DEFINED
