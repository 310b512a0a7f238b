//
// EchoClient.cc
//
// Connects to the echo server at ECHOSERVER_IP:ECHOSERVER_PORT (10.0.1.2:54321,
// an address of the robot's LAN built into the program), sends
// "This is a test message.\n" with its NUL (25 bytes), waits for the echo and
// sends it again, as long as the server answers. When the server closes, the
// client closes too and stays idle; a failed connect is reported, not retried.
//

#include <stdio.h>
#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "EchoClient.h"
#include "entry.h"

EchoClient::EchoClient() : state(CLIENT_CLOSED), sendData(0), recvData(0), rounds(0)
{
}

OStatus
EchoClient::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
EchoClient::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    // The server's address on the robot's LAN, built in as in Sony's sample.
    const char* server = ECHOSERVER_IP;
    int port = ECHOSERVER_PORT;

    ipstackRef = antStackRef("IPStack");

    antEnvCreateEndpointMsg tcpCreateMsg(EndpointType_TCP, ECHOCLIENT_BUFFER_SIZE * 2);
    tcpCreateMsg.Call(ipstackRef, sizeof(tcpCreateMsg));
    if (tcpCreateMsg.error != ANT_SUCCESS) {
        OSYSPRINT(("EchoClient : can't create an endpoint (%d)\n", tcpCreateMsg.error));
        return oFAIL;
    }
    endpoint = tcpCreateMsg.moduleRef;

    antEnvCreateSharedBufferMsg sendBufferMsg(ECHOCLIENT_BUFFER_SIZE);
    sendBufferMsg.Call(ipstackRef, sizeof(sendBufferMsg));
    if (sendBufferMsg.error != ANT_SUCCESS) return oFAIL;
    sendBuffer = sendBufferMsg.buffer;
    sendBuffer.Map();
    sendData = (byte*)sendBuffer.GetAddress();

    antEnvCreateSharedBufferMsg recvBufferMsg(ECHOCLIENT_BUFFER_SIZE);
    recvBufferMsg.Call(ipstackRef, sizeof(recvBufferMsg));
    if (recvBufferMsg.error != ANT_SUCCESS) return oFAIL;
    recvBuffer = recvBufferMsg.buffer;
    recvBuffer.Map();
    recvData = (byte*)recvBuffer.GetAddress();

    IPAddress serverAddress(server);   // dotted decimal only
    char addr[16];
    OSYSPRINT(("EchoClient : connecting to %s:%d\n", serverAddress.GetAsString(addr), port));

    TCPEndpointConnectMsg connectMsg(endpoint, IP_ADDR_ANY, IP_PORT_ANY, serverAddress, (Port)port);
    connectMsg.continuation = (void*)0;
    connectMsg.Send(ipstackRef, myOID_, Extra_Entry[entryConnectCont], sizeof(connectMsg));
    state = CLIENT_CONNECTING;
    return oSUCCESS;
}

OStatus
EchoClient::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
EchoClient::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
EchoClient::ConnectCont(ANTENVMSG msg)
{
    TCPEndpointConnectMsg* connectMsg = (TCPEndpointConnectMsg*)antEnvMsg::Receive(msg);
    if (connectMsg->error != TCP_SUCCESS) {
        OSYSPRINT(("EchoClient : connect error %d\n", connectMsg->error));
        state = CLIENT_CLOSED;
        return;
    }
    char addr[16];
    OSYSPRINT(("EchoClient : connected from port %d to %s:%d\n", (int)connectMsg->lPort,
               connectMsg->fAddress.GetAsString(addr), (int)connectMsg->fPort));
    Send();
}

OStatus
EchoClient::Send()
{
    int size = strlen(ECHOCLIENT_MESSAGE) + 1;   // with the NUL, as echo_client does
    memcpy(sendData, ECHOCLIENT_MESSAGE, size);
    TCPEndpointSendMsg sendMsg(endpoint, sendData, size);
    sendMsg.continuation = (void*)0;
    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendCont], sizeof(sendMsg));
    state = CLIENT_SENDING;
    return oSUCCESS;
}

void
EchoClient::SendCont(ANTENVMSG msg)
{
    TCPEndpointSendMsg* sendMsg = (TCPEndpointSendMsg*)antEnvMsg::Receive(msg);
    if (sendMsg->error != TCP_SUCCESS) {
        OSYSPRINT(("EchoClient : send error %d\n", sendMsg->error));
        Close();
        return;
    }
    Receive();
}

OStatus
EchoClient::Receive()
{
    TCPEndpointReceiveMsg receiveMsg(endpoint, recvData, 1, ECHOCLIENT_BUFFER_SIZE);
    receiveMsg.continuation = (void*)0;
    receiveMsg.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveCont], sizeof(receiveMsg));
    state = CLIENT_RECEIVING;
    return oSUCCESS;
}

void
EchoClient::ReceiveCont(ANTENVMSG msg)
{
    TCPEndpointReceiveMsg* receiveMsg = (TCPEndpointReceiveMsg*)antEnvMsg::Receive(msg);
    if (receiveMsg->error != TCP_SUCCESS) {
        OSYSPRINT(("EchoClient : receive error %d\n", receiveMsg->error));
        Close();
        return;
    }
    int n = receiveMsg->sizeMin;
    int len = n;
    while (len > 0 && (recvData[len - 1] == '\0' || recvData[len - 1] == '\n')) len--;
    OSYSPRINT(("EchoClient : round %d : %d bytes : %.*s\n", ++rounds, n, len, (const char*)recvData));
    Send();
}

OStatus
EchoClient::Close()
{
    TCPEndpointCloseMsg closeMsg(endpoint);
    closeMsg.Send(ipstackRef, myOID_, Extra_Entry[entryCloseCont], sizeof(closeMsg));
    state = CLIENT_CLOSING;
    return oSUCCESS;
}

void
EchoClient::CloseCont(ANTENVMSG msg)
{
    OSYSPRINT(("EchoClient : closed\n"));
    state = CLIENT_CLOSED;
}
