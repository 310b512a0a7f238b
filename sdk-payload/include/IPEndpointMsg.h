/*
 * IPEndpointMsg.h - messages of raw IP endpoints (network-api 6).
 * Not used by the samples; the host may refuse to create IP endpoints.
 */
#ifndef _IPEndpointMsg_h_DEFINED
#define _IPEndpointMsg_h_DEFINED

#include <MCOOP/antEnvMsg.h>
#include <IPAddress.h>
#include <Internet.h>

enum IPEndpointError {
    IP_SUCCESS           = 0,
    IP_FAIL              = 1,
    IP_INVALID_PROTOCOL  = 2,
    IP_PACKETSIZE        = 3,
    IP_CONNECTION_CLOSED = 4,
    IP_CONNECTION_BUSY   = 5,
    IP_BUFFER_INVALID    = 6,
    IP_OPERATION_INVALID = 7,
    IP_OPERATION_UNKNOWN = 8
};

enum IPPacketType {
    IP_DATA                 = 1,
    IP_NETWORK_UNREACHABLE  = 2,
    IP_HOST_UNREACHABLE     = 3,
    IP_PROTOCOL_UNREACHABLE = 4,
    IP_PORT_UNREACHABLE     = 5,
    IP_MESSAGE_TOO_LONG     = 6,
    IP_TTL_EXCEEDED         = 7,
    IP_TIME_EXCEEDED        = 8,
    IP_PACKETTYPE_MAX       = 9
};

enum IPEndpointOperation {
    IPEndpoint_Bind    = 1,
    IPEndpoint_Send    = 2,
    IPEndpoint_Receive = 3,
    IPEndpoint_Close   = 4
};

struct IPEndpointBaseMsg : public antEnvMsg {
    IPEndpointError error;

    IPEndpointBaseMsg() : antEnvMsg(), error(IP_FAIL) {}
    IPEndpointBaseMsg(const antModuleRef& module, IPEndpointOperation op)
        : antEnvMsg(module, op), error(IP_FAIL) {}
    IPEndpointBaseMsg(const IPEndpointBaseMsg& m) : antEnvMsg(m), error(m.error) {}

    antError Reply(IPEndpointError e) { error = e; return antEnvMsg::Reply(); }
};

struct IPEndpointBindMsg : public IPEndpointBaseMsg {
    Protocol protocol;

    IPEndpointBindMsg(const antModuleRef& module, Protocol p)
        : IPEndpointBaseMsg(module, IPEndpoint_Bind), protocol(p) {}
};

struct IPEndpointSendMsg : public IPEndpointBaseMsg {
    IPPacketType type;
    byte*        buffer;   /* a complete IP packet, inside a shared buffer */
    int          size;

    IPEndpointSendMsg(const antModuleRef& module, IPPacketType t, byte* buf, int sz)
        : IPEndpointBaseMsg(module, IPEndpoint_Send), type(t), buffer(buf), size(sz) {}
};

struct IPEndpointReceiveMsg : public IPEndpointBaseMsg {
    IPPacketType type;     /* out */
    byte*        buffer;
    int          size;     /* in/out */

    IPEndpointReceiveMsg(const antModuleRef& module, byte* buf, int sz)
        : IPEndpointBaseMsg(module, IPEndpoint_Receive), type(IP_DATA), buffer(buf), size(sz) {}
};

struct IPEndpointCloseMsg : public IPEndpointBaseMsg {
    IPEndpointCloseMsg(const antModuleRef& module)
        : IPEndpointBaseMsg(module, IPEndpoint_Close) {}
};

#endif /* _IPEndpointMsg_h_DEFINED */
