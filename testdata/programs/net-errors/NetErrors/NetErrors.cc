//
// NetErrors.cc
//
// Feeds the IPStack bad input and prints the error code of each answer:
// "NetErrors : <check> = <code>". Everything is synchronous (Call).
// NETERR.CFG holds three ports: a TCP server that resets the connection
// after reading 5 bytes, a TCP port nobody listens on, and a UDP port.
//

#include <stdio.h>
#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "NetErrors.h"

OStatus
NetErrors::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    ipstackRef = antStackRef("IPStack");
    return oSUCCESS;
}

OStatus
NetErrors::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    int resetPort = 0, closedPort = 0, udpPort = 0;
    FILE* fp = fopen(NETERRORS_CONF, "r");
    if (fp == 0 || fscanf(fp, "%d %d %d", &resetPort, &closedPort, &udpPort) != 3) {
        OSYSPRINT(("NetErrors : can't read %s\n", NETERRORS_CONF));
        if (fp != 0) fclose(fp);
        return oFAIL;
    }
    fclose(fp);

    antEnvCreateEndpointMsg pop3Msg(EndpointType_POP3, 1024);
    pop3Msg.Call(ipstackRef, sizeof(pop3Msg));
    Check("create-pop3", pop3Msg.error);

    TCPChecks((Port)resetPort, (Port)closedPort);
    UDPChecks((Port)udpPort);
    DNSChecks();
    OSYSPRINT(("NetErrors : done\n"));
    return oSUCCESS;
}

OStatus
NetErrors::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
NetErrors::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
NetErrors::ReceiveCont(void* msg)
{
    UDPEndpointReceiveMsg* receiveMsg = (UDPEndpointReceiveMsg*)msg;
    Check("udp-pending-receive", receiveMsg->error);
}

void
NetErrors::Check(const char* what, int got)
{
    OSYSPRINT(("NetErrors : %s = %d\n", what, got));
}

antModuleRef
NetErrors::NewEndpoint(int protocol)
{
    antEnvCreateEndpointMsg createMsg(protocol, 2048);
    createMsg.Call(ipstackRef, sizeof(createMsg));
    if (createMsg.error != ANT_SUCCESS) Check("create-endpoint", createMsg.error);
    return createMsg.moduleRef;
}

byte*
NetErrors::NewBuffer(int size)
{
    antEnvCreateSharedBufferMsg bufferMsg(size);
    bufferMsg.Call(ipstackRef, sizeof(bufferMsg));
    if (bufferMsg.error != ANT_SUCCESS) {
        Check("create-buffer", bufferMsg.error);
        return 0;
    }
    antSharedBuffer buffer = bufferMsg.buffer;
    buffer.Map();
    return (byte*)buffer.GetAddress();
}

void
NetErrors::TCPChecks(Port resetPort, Port closedPort)
{
    byte* data = NewBuffer(4096);
    byte local[16];
    antModuleRef ep = NewEndpoint(EndpointType_TCP);

    TCPEndpointSendMsg early(ep, data, 5);
    early.Call(ipstackRef, sizeof(early));
    Check("send-unconnected", early.error);

    TCPEndpointConnectMsg connectMsg(ep, IP_ADDR_ANY, IP_PORT_ANY, "127.0.0.1", resetPort);
    connectMsg.Call(ipstackRef, sizeof(connectMsg));
    Check("connect", connectMsg.error);

    TCPEndpointListenMsg again(ep, IP_ADDR_ANY, 54400);
    again.Call(ipstackRef, sizeof(again));
    Check("listen-connected", again.error);

    TCPEndpointSendMsg oversized(ep, data, 4097);
    oversized.Call(ipstackRef, sizeof(oversized));
    Check("send-oversized", oversized.error);

    TCPEndpointSendMsg empty(ep, data, 0);
    empty.Call(ipstackRef, sizeof(empty));
    Check("send-empty", empty.error);

    TCPEndpointSendMsg outside(ep, local, 5);
    outside.Call(ipstackRef, sizeof(outside));
    Check("send-outside", outside.error);

    TCPEndpointBaseMsg unknown(ep, (TCPEndpointOperation)99);
    unknown.Call(ipstackRef, sizeof(unknown));
    Check("tcp-unknown-op", unknown.error);

    memcpy(data, "hello", 5);
    TCPEndpointSendMsg hello(ep, data, 5);
    hello.Call(ipstackRef, sizeof(hello));
    Check("send", hello.error);

    // the peer resets the connection after reading "hello"
    TCPEndpointReceiveMsg receiveMsg(ep, data, 1, 4096);
    receiveMsg.Call(ipstackRef, sizeof(receiveMsg));
    Check("receive-reset", receiveMsg.error);

    TCPEndpointCloseMsg closeMsg(ep);
    closeMsg.Call(ipstackRef, sizeof(closeMsg));
    Check("close", closeMsg.error);

    TCPEndpointSendMsg late(ep, data, 5);
    late.Call(ipstackRef, sizeof(late));
    Check("send-closed", late.error);

    TCPEndpointReceiveMsg lateReceive(ep, data, 1, 4096);
    lateReceive.Call(ipstackRef, sizeof(lateReceive));
    Check("receive-closed", lateReceive.error);

    TCPEndpointCloseMsg closeAgain(ep);
    closeAgain.Call(ipstackRef, sizeof(closeAgain));
    Check("close-closed", closeAgain.error);

    antModuleRef ep2 = NewEndpoint(EndpointType_TCP);
    TCPEndpointConnectMsg refused(ep2, IP_ADDR_ANY, IP_PORT_ANY, "127.0.0.1", closedPort);
    refused.Call(ipstackRef, sizeof(refused));
    Check("connect-refused", refused.error);

    // the reset server's port is taken by the test itself
    TCPEndpointListenMsg inUse(ep2, IP_ADDR_ANY, resetPort);
    inUse.Call(ipstackRef, sizeof(inUse));
    Check("listen-inuse", inUse.error);

    TCPEndpointCloseMsg close2(ep2, false, 0, true);
    close2.Call(ipstackRef, sizeof(close2));
    Check("abort", close2.error);
}

void
NetErrors::UDPChecks(Port udpPort)
{
    byte* big = NewBuffer(70000);
    antModuleRef ep = NewEndpoint(EndpointType_UDP);

    UDPEndpointSendMsg unbound(ep, "127.0.0.1", udpPort, big, 10);
    unbound.Call(ipstackRef, sizeof(unbound));
    Check("udp-send-unbound", unbound.error);

    UDPEndpointBindMsg bindMsg(ep, IP_ADDR_ANY, IP_PORT_ANY);
    bindMsg.Call(ipstackRef, sizeof(bindMsg));
    Check("udp-bind", bindMsg.error);

    antModuleRef ep2 = NewEndpoint(EndpointType_UDP);
    UDPEndpointBindMsg clash(ep2, IP_ADDR_ANY, bindMsg.port);
    clash.Call(ipstackRef, sizeof(clash));
    Check("udp-addressinuse", clash.error);

    UDPEndpointSendMsg oversized(ep, "127.0.0.1", udpPort, big, 69000);
    oversized.Call(ipstackRef, sizeof(oversized));
    Check("udp-oversized", oversized.error);

    byte local[16];
    UDPEndpointSendMsg outside(ep, "127.0.0.1", udpPort, local, 10);
    outside.Call(ipstackRef, sizeof(outside));
    Check("udp-send-outside", outside.error);

    UDPEndpointBaseMsg unknown(ep, (UDPEndpointOperation)99);
    unknown.Call(ipstackRef, sizeof(unknown));
    Check("udp-unknown-op", unknown.error);

    memcpy(big, "datagram", 8);
    UDPEndpointSendMsg sendMsg(ep, "127.0.0.1", udpPort, big, 8);
    sendMsg.Call(ipstackRef, sizeof(sendMsg));
    Check("udp-send", sendMsg.error);

    // a buffer destroyed while a Receive into it is pending: the IPStack refuses,
    // because the pending Receive still writes into it
    antEnvCreateSharedBufferMsg pendingBuffer(1024);
    pendingBuffer.Call(ipstackRef, sizeof(pendingBuffer));
    pendingBuffer.buffer.Map();
    UDPEndpointReceiveMsg pending(ep, (byte*)pendingBuffer.buffer.GetAddress(), 1024);
    pending.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveCont], sizeof(pending));
    antEnvDestroySharedBufferMsg destroyPending(pendingBuffer.buffer);
    destroyPending.Call(ipstackRef, sizeof(destroyPending));
    Check("destroy-pending-buffer", destroyPending.error);

    UDPEndpointCloseMsg closeMsg(ep);
    closeMsg.Call(ipstackRef, sizeof(closeMsg));
    Check("udp-close", closeMsg.error);

    // once the Receive has ended, the buffer can go
    antEnvDestroySharedBufferMsg destroyLater(pendingBuffer.buffer);
    destroyLater.Call(ipstackRef, sizeof(destroyLater));
    Check("destroy-buffer-after-close", destroyLater.error);

    UDPEndpointSendMsg late(ep, "127.0.0.1", udpPort, big, 8);
    late.Call(ipstackRef, sizeof(late));
    Check("udp-send-closed", late.error);
}

void
NetErrors::DNSChecks()
{
    antModuleRef ep = NewEndpoint(EndpointType_DNS);

    DNSEndpointGetAddressMsg before(ep, 0);
    before.Call(ipstackRef, sizeof(before));
    Check("dns-address-before-lookup", before.error);

    DNSEndpointGetHostByNameMsg lookup(ep, "localhost.");
    lookup.Call(ipstackRef, sizeof(lookup));
    Check("dns-lookup", lookup.error);

    DNSEndpointGetAliasMsg alias(ep, 99);
    alias.Call(ipstackRef, sizeof(alias));
    Check("dns-alias-99", alias.error);

    DNSEndpointGetHostByNameMsg missing(ep, "no-such-host.invalid.");
    missing.Call(ipstackRef, sizeof(missing));
    OSYSPRINT(("NetErrors : dns-missing n_address = %d, name = %s\n",
               missing.n_address, missing.name));

    DNSEndpointCloseMsg closeMsg(ep);
    closeMsg.Call(ipstackRef, sizeof(closeMsg));
    Check("dns-close", closeMsg.error);

    DNSEndpointGetHostByNameMsg late(ep, "localhost.");
    late.Call(ipstackRef, sizeof(late));
    Check("dns-lookup-closed", late.error);
}
