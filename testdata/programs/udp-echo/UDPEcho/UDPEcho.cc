//
// UDPEcho.cc
//
// A UDP echo server. All network work is done by the IPStack system
// object: we send it messages and it answers either at once (Call) or
// later, at one of our Extra entries (Send + continuation).
//
//   DoInit   : two shared buffers (Call)
//   DoStart  : create + bind a UDP endpoint (Call), then Receive (Send)
//   ReceiveCont -> Send the datagram back -> SendCont -> Receive ...
//

#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "UDPEcho.h"
#include "entry.h"

UDPEcho::UDPEcho() : state(UDPECHO_CLOSED), stopping(false),
                     sendData(0), recvData(0), peerPort(0), peerSize(0)
{
}

OStatus
UDPEcho::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    ipstackRef = antStackRef("IPStack");
    return CreateBuffers();
}

OStatus
UDPEcho::DoStart(const OSystemEvent& event)
{
    stopping = false;
    if (Open() == oSUCCESS) Receive();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
UDPEcho::DoStop(const OSystemEvent& event)
{
    stopping = true;
    if (state != UDPECHO_CLOSED) {
        // A pending receive is answered with an error; CloseCont and
        // ReceiveCont ignore it because the state is CLOSED by then.
        UDPEndpointCloseMsg closeMsg(endpoint);
        closeMsg.Call(ipstackRef, sizeof(closeMsg));
        state = UDPECHO_CLOSED;
    }

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
UDPEcho::DoDestroy(const OSystemEvent& event)
{
    sendBuffer.UnMap();
    antEnvDestroySharedBufferMsg destroySendMsg(sendBuffer);
    destroySendMsg.Call(ipstackRef, sizeof(destroySendMsg));

    recvBuffer.UnMap();
    antEnvDestroySharedBufferMsg destroyRecvMsg(recvBuffer);
    destroyRecvMsg.Call(ipstackRef, sizeof(destroyRecvMsg));

    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

OStatus
UDPEcho::CreateBuffers()
{
    // Payload must live in memory shared with the IPStack.
    //
    // Call() returns the transport status; the result of the request
    // itself is in the message's error field (only valid if the call
    // went through).
    //
    antEnvCreateSharedBufferMsg sendBufferMsg(UDPECHO_BUFFER_SIZE);
    antError result = sendBufferMsg.Call(ipstackRef, sizeof(sendBufferMsg));
    if (result == ANT_SUCCESS) result = sendBufferMsg.error;
    if (result != ANT_SUCCESS) {
        OSYSLOG1((osyslogERROR, "UDPEcho : can't allocate the send buffer (%d)",
                  result));
        return oFAIL;
    }
    sendBuffer = sendBufferMsg.buffer;
    sendBuffer.Map();
    sendData = (byte*)sendBuffer.GetAddress();

    antEnvCreateSharedBufferMsg recvBufferMsg(UDPECHO_BUFFER_SIZE);
    result = recvBufferMsg.Call(ipstackRef, sizeof(recvBufferMsg));
    if (result == ANT_SUCCESS) result = recvBufferMsg.error;
    if (result != ANT_SUCCESS) {
        OSYSLOG1((osyslogERROR, "UDPEcho : can't allocate the receive buffer (%d)",
                  result));
        return oFAIL;
    }
    recvBuffer = recvBufferMsg.buffer;
    recvBuffer.Map();
    recvData = (byte*)recvBuffer.GetAddress();

    return oSUCCESS;
}

OStatus
UDPEcho::Open()
{
    antEnvCreateEndpointMsg udpCreateMsg(EndpointType_UDP, UDPECHO_BUFFER_SIZE * 2);
    antError result = udpCreateMsg.Call(ipstackRef, sizeof(udpCreateMsg));
    if (result == ANT_SUCCESS) result = udpCreateMsg.error;
    if (result != ANT_SUCCESS) {
        OSYSLOG1((osyslogERROR, "UDPEcho : can't create an endpoint (%d)",
                  result));
        return oFAIL;
    }
    endpoint = udpCreateMsg.moduleRef;

    UDPEndpointBindMsg bindMsg(endpoint, IP_ADDR_ANY, UDPECHO_PORT);
    if (bindMsg.Call(ipstackRef, sizeof(bindMsg)) != ANT_SUCCESS ||
        bindMsg.error != UDP_SUCCESS) {
        OSYSLOG1((osyslogERROR, "UDPEcho : bind to port %d failed (%d)",
                  UDPECHO_PORT, bindMsg.error));
        return oFAIL;
    }

    OSYSPRINT(("UDPEcho : bound to UDP port %d\n", UDPECHO_PORT));
    state = UDPECHO_RECEIVING;
    return oSUCCESS;
}

OStatus
UDPEcho::Receive()
{
    UDPEndpointReceiveMsg receiveMsg(endpoint, recvData, UDPECHO_BUFFER_SIZE);
    receiveMsg.continuation = (void*)0;     // connection number, see ReceiveCont

    receiveMsg.Send(ipstackRef, myOID_,
                    Extra_Entry[entryReceiveCont], sizeof(receiveMsg));
    state = UDPECHO_RECEIVING;
    return oSUCCESS;
}

void
UDPEcho::ReceiveCont(ANTENVMSG msg)
{
    UDPEndpointReceiveMsg* receiveMsg = (UDPEndpointReceiveMsg*)antEnvMsg::Receive(msg);
    int index = (int)receiveMsg->continuation;   // always 0: one connection only

    if (state == UDPECHO_CLOSED) return;

    if (receiveMsg->error != UDP_SUCCESS) {
        OSYSLOG1((osyslogERROR, "UDPEcho : receive error %d on connection %d",
                  receiveMsg->error, index));
        Close();
        return;
    }

    peerAddress = receiveMsg->address;
    peerPort    = receiveMsg->port;
    peerSize    = receiveMsg->size;
    memcpy(sendData, receiveMsg->buffer, peerSize);

    // Print the text without its trailing newline / NUL.
    int len = peerSize;
    while (len > 0 && (sendData[len - 1] == '\0' || sendData[len - 1] == '\n' ||
                       sendData[len - 1] == '\r')) len--;

    char addr[16];
    OSYSPRINT(("UDPEcho : %d bytes from %s:%d : %.*s\n",
               peerSize, peerAddress.GetAsString(addr), (int)peerPort,
               len, (const char*)sendData));

    Send();
}

OStatus
UDPEcho::Send()
{
    UDPEndpointSendMsg sendMsg(endpoint, peerAddress, peerPort, sendData, peerSize);
    sendMsg.continuation = (void*)0;

    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendCont], sizeof(sendMsg));
    state = UDPECHO_SENDING;
    return oSUCCESS;
}

void
UDPEcho::SendCont(ANTENVMSG msg)
{
    UDPEndpointSendMsg* sendMsg = (UDPEndpointSendMsg*)antEnvMsg::Receive(msg);

    if (state == UDPECHO_CLOSED) return;

    if (sendMsg->error != UDP_SUCCESS) {
        OSYSLOG1((osyslogERROR, "UDPEcho : send error %d", sendMsg->error));
        Close();
        return;
    }
    Receive();
}

OStatus
UDPEcho::Close()
{
    UDPEndpointCloseMsg closeMsg(endpoint);
    closeMsg.Send(ipstackRef, myOID_, Extra_Entry[entryCloseCont], sizeof(closeMsg));
    state = UDPECHO_CLOSING;
    return oSUCCESS;
}

void
UDPEcho::CloseCont(ANTENVMSG msg)
{
    if (state == UDPECHO_CLOSED) return;
    state = UDPECHO_CLOSED;

    // Endpoints cannot be reused after Close: make a new one.
    if (!stopping && Open() == oSUCCESS) Receive();
}
