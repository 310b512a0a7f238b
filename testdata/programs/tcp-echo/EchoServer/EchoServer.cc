//
// EchoServer.cc
//
// A TCP echo server on port 54321. Every chunk a client sends comes back
// unchanged. One connection at a time: Listen -> Receive -> Send -> Receive
// ... until the client goes away, then Close and Listen on a new endpoint.
//

#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "EchoServer.h"
#include "entry.h"

EchoServer::EchoServer() : stopping(false)
{
    for (int i = 0; i < ECHOSERVER_CONNECTION_MAX; i++) {
        connection[i].state = CONNECTION_CLOSED;
        connection[i].sendData = 0;
        connection[i].recvData = 0;
        connection[i].sendSize = 0;
    }
}

OStatus
EchoServer::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
EchoServer::DoStart(const OSystemEvent& event)
{
    ipstackRef = antStackRef("IPStack");

    for (int index = 0; index < ECHOSERVER_CONNECTION_MAX; index++) {
        if (InitBuffers(index) != oSUCCESS) return oFAIL;
        Listen(index);
    }

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
EchoServer::DoStop(const OSystemEvent& event)
{
    stopping = true;
    for (int index = 0; index < ECHOSERVER_CONNECTION_MAX; index++) {
        if (connection[index].state != CONNECTION_CLOSED &&
            connection[index].state != CONNECTION_CLOSING) Close(index);
    }

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
EchoServer::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

OStatus
EchoServer::InitBuffers(int index)
{
    EchoConnection* c = &connection[index];

    antEnvCreateSharedBufferMsg sendBufferMsg(ECHOSERVER_BUFFER_SIZE);
    sendBufferMsg.Call(ipstackRef, sizeof(sendBufferMsg));
    if (sendBufferMsg.error != ANT_SUCCESS) {
        OSYSLOG1((osyslogERROR, "EchoServer : can't allocate a send buffer (%d)",
                  sendBufferMsg.error));
        return oFAIL;
    }
    c->sendBuffer = sendBufferMsg.buffer;
    c->sendBuffer.Map();
    c->sendData = (byte*)c->sendBuffer.GetAddress();

    antEnvCreateSharedBufferMsg recvBufferMsg(ECHOSERVER_BUFFER_SIZE);
    recvBufferMsg.Call(ipstackRef, sizeof(recvBufferMsg));
    if (recvBufferMsg.error != ANT_SUCCESS) {
        OSYSLOG1((osyslogERROR, "EchoServer : can't allocate a receive buffer (%d)",
                  recvBufferMsg.error));
        return oFAIL;
    }
    c->recvBuffer = recvBufferMsg.buffer;
    c->recvBuffer.Map();
    c->recvData = (byte*)c->recvBuffer.GetAddress();
    return oSUCCESS;
}

OStatus
EchoServer::Listen(int index)
{
    EchoConnection* c = &connection[index];

    antEnvCreateEndpointMsg tcpCreateMsg(EndpointType_TCP, ECHOSERVER_BUFFER_SIZE * 2);
    tcpCreateMsg.Call(ipstackRef, sizeof(tcpCreateMsg));
    if (tcpCreateMsg.error != ANT_SUCCESS) {
        OSYSLOG1((osyslogERROR, "EchoServer : can't create an endpoint (%d)",
                  tcpCreateMsg.error));
        return oFAIL;
    }
    c->endpoint = tcpCreateMsg.moduleRef;

    TCPEndpointListenMsg listenMsg(c->endpoint, IP_ADDR_ANY, ECHOSERVER_PORT);
    listenMsg.continuation = (void*)index;
    listenMsg.Send(ipstackRef, myOID_, Extra_Entry[entryListenCont], sizeof(listenMsg));
    c->state = CONNECTION_LISTENING;

    OSYSPRINT(("EchoServer : listening on port %d\n", ECHOSERVER_PORT));
    return oSUCCESS;
}

void
EchoServer::ListenCont(ANTENVMSG msg)
{
    TCPEndpointListenMsg* listenMsg = (TCPEndpointListenMsg*)antEnvMsg::Receive(msg);
    int index = (int)listenMsg->continuation;
    if (connection[index].state != CONNECTION_LISTENING) return;

    if (listenMsg->error != TCP_SUCCESS) {
        OSYSPRINT(("EchoServer : listen error %d\n", listenMsg->error));
        Close(index);
        return;
    }

    char addr[16];
    OSYSPRINT(("EchoServer : connection from %s:%d\n",
               listenMsg->fAddress.GetAsString(addr), (int)listenMsg->fPort));
    connection[index].state = CONNECTION_CONNECTED;
    Receive(index);
}

OStatus
EchoServer::Receive(int index)
{
    EchoConnection* c = &connection[index];
    TCPEndpointReceiveMsg receiveMsg(c->endpoint, c->recvData, 1, ECHOSERVER_BUFFER_SIZE);
    receiveMsg.continuation = (void*)index;
    receiveMsg.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveCont], sizeof(receiveMsg));
    c->state = CONNECTION_RECEIVING;
    return oSUCCESS;
}

void
EchoServer::ReceiveCont(ANTENVMSG msg)
{
    TCPEndpointReceiveMsg* receiveMsg = (TCPEndpointReceiveMsg*)antEnvMsg::Receive(msg);
    int index = (int)receiveMsg->continuation;
    EchoConnection* c = &connection[index];
    if (c->state == CONNECTION_CLOSED || c->state == CONNECTION_CLOSING) return;

    if (receiveMsg->error != TCP_SUCCESS) {
        if (receiveMsg->error == TCP_CONNECTION_CLOSED) {
            OSYSPRINT(("EchoServer : peer closed the connection\n"));
        } else {
            OSYSPRINT(("EchoServer : receive error %d\n", receiveMsg->error));
        }
        Close(index);
        return;
    }

    c->sendSize = receiveMsg->sizeMin;
    memcpy(c->sendData, c->recvData, c->sendSize);

    int len = c->sendSize;
    while (len > 0 && (c->sendData[len - 1] == '\0' || c->sendData[len - 1] == '\n' ||
                       c->sendData[len - 1] == '\r')) len--;
    OSYSPRINT(("EchoServer : received %d bytes : %.*s\n", c->sendSize, len,
               (const char*)c->sendData));
    Send(index);
}

OStatus
EchoServer::Send(int index)
{
    EchoConnection* c = &connection[index];
    TCPEndpointSendMsg sendMsg(c->endpoint, c->sendData, c->sendSize);
    sendMsg.continuation = (void*)index;
    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendCont], sizeof(sendMsg));
    c->state = CONNECTION_SENDING;
    return oSUCCESS;
}

void
EchoServer::SendCont(ANTENVMSG msg)
{
    TCPEndpointSendMsg* sendMsg = (TCPEndpointSendMsg*)antEnvMsg::Receive(msg);
    int index = (int)sendMsg->continuation;
    if (connection[index].state == CONNECTION_CLOSED ||
        connection[index].state == CONNECTION_CLOSING) return;

    if (sendMsg->error != TCP_SUCCESS) {
        OSYSPRINT(("EchoServer : send error %d\n", sendMsg->error));
        Close(index);
        return;
    }
    Receive(index);
}

OStatus
EchoServer::Close(int index)
{
    EchoConnection* c = &connection[index];
    TCPEndpointCloseMsg closeMsg(c->endpoint);
    closeMsg.continuation = (void*)index;
    closeMsg.Send(ipstackRef, myOID_, Extra_Entry[entryCloseCont], sizeof(closeMsg));
    c->state = CONNECTION_CLOSING;
    return oSUCCESS;
}

void
EchoServer::CloseCont(ANTENVMSG msg)
{
    TCPEndpointCloseMsg* closeMsg = (TCPEndpointCloseMsg*)antEnvMsg::Receive(msg);
    int index = (int)closeMsg->continuation;
    if (connection[index].state == CONNECTION_CLOSED) return;

    OSYSPRINT(("EchoServer : connection closed (%d)\n", closeMsg->error));
    connection[index].state = CONNECTION_CLOSED;
    if (!stopping) Listen(index);
}
