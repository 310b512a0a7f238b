/*
 * UDPEndpointMsg.h - messages of UDP endpoints (network-api 4).
 * NOTE: the error and operation numbering differs from TCP.
 */
#ifndef _UDPEndpointMsg_h_DEFINED
#define _UDPEndpointMsg_h_DEFINED

#include <MCOOP/antEnvMsg.h>
#include <IPAddress.h>

enum UDPEndpointError {
    UDP_SUCCESS              = 0,
    UDP_FAIL                 = 1,
    UDP_CONNECTION_CLOSED    = 2,
    UDP_CONNECTION_BUSY      = 3,
    UDP_ADDRESSINUSE         = 4,
    UDP_ADDRESSERROR         = 5,
    UDP_PORT_UNREACHABLE     = 6,
    UDP_PROTOCOL_UNREACHABLE = 7,
    UDP_HOST_UNREACHABLE     = 8,
    UDP_NETWORK_UNREACHABLE  = 9,
    UDP_MESSAGE_TOO_LONG     = 10,
    UDP_TTL_EXCEEDED         = 11,
    UDP_TIME_EXCEEDED        = 12,
    UDP_BUFFER_INVALID       = 13,
    UDP_OPERATION_INVALID    = 14,
    UDP_OPERATION_UNKNOWN    = 15,
    UDP_WOULDBLOCK           = 16
};

enum UDPEndpointOperation {
    UDPEndpoint_Bind             = 0,
    UDPEndpoint_Connect          = 1,
    UDPEndpoint_Send             = 2,
    UDPEndpoint_Receive          = 3,
    UDPEndpoint_Close            = 4,
#ifdef USE_MULTICAST
    UDPEndpoint_SetMulticastLoop = 5,
    UDPEndpoint_SetMulticastTTL  = 6,
    UDPEndpoint_AddMembership    = 7,
    UDPEndpoint_DropMembership   = 8,
#endif
    UDPEndpoint_SetBlockingMode  = 9,
    UDPEndpoint_ReadyForRead     = 10,
    UDPEndpoint_ReadyForWrite    = 11,
    UDPEndpoint_Address          = 12,
    UDPEndpoint_ResetConnect     = 13
};

/* debug printer: the enumerator's name; runtime library */
std::ostream& operator<<(std::ostream& os, UDPEndpointError error);

struct UDPEndpointBaseMsg : public antEnvMsg {
    UDPEndpointError error;

    UDPEndpointBaseMsg() : antEnvMsg(), error(UDP_FAIL) {}
    UDPEndpointBaseMsg(const antModuleRef& module, UDPEndpointOperation op)
        : antEnvMsg(module, op), error(UDP_FAIL) {}

    antError Reply(UDPEndpointError e) { error = e; return antEnvMsg::Reply(); }
};

struct UDPEndpointBindMsg : public UDPEndpointBaseMsg {
    IPAddress address;   /* in/out */
    Port      port;      /* in/out */

    UDPEndpointBindMsg(const antModuleRef& module, IPAddress addr, Port p)
        : UDPEndpointBaseMsg(module, UDPEndpoint_Bind), address(addr), port(p) {}
};

struct UDPEndpointConnectMsg : public UDPEndpointBaseMsg {
    IPAddress address;
    Port      port;

    UDPEndpointConnectMsg(const antModuleRef& module, IPAddress addr, Port p)
        : UDPEndpointBaseMsg(module, UDPEndpoint_Connect), address(addr), port(p) {}
};

struct UDPEndpointSendMsg : public UDPEndpointBaseMsg {
    IPAddress address;
    Port      port;
    byte*     buffer;   /* inside a shared buffer */
    int       size;

    UDPEndpointSendMsg(const antModuleRef& module, byte* buf, int sz)
        : UDPEndpointBaseMsg(module, UDPEndpoint_Send),
          address(IP_ADDR_ANY), port(IP_PORT_ANY), buffer(buf), size(sz) {}
    UDPEndpointSendMsg(const antModuleRef& module, IPAddress addr, Port p,
                       byte* buf, int sz)
        : UDPEndpointBaseMsg(module, UDPEndpoint_Send),
          address(addr), port(p), buffer(buf), size(sz) {}
};

struct UDPEndpointReceiveMsg : public UDPEndpointBaseMsg {
    IPAddress address;   /* out: sender */
    Port      port;      /* out: sender */
    byte*     buffer;    /* inside a shared buffer */
    int       size;      /* in/out */

    UDPEndpointReceiveMsg(const antModuleRef& module, byte* buf, int sz)
        : UDPEndpointBaseMsg(module, UDPEndpoint_Receive),
          address(), port(0), buffer(buf), size(sz) {}
};

struct UDPEndpointCloseMsg : public UDPEndpointBaseMsg {
    bool linger;
    int  lingerTime;

    UDPEndpointCloseMsg(const antModuleRef& module, bool lng = false, int lngTime = 0)
        : UDPEndpointBaseMsg(module, UDPEndpoint_Close), linger(lng), lingerTime(lngTime) {}
};

#ifdef USE_MULTICAST
struct UDPEndpointSetMulticastLoopMsg : public UDPEndpointBaseMsg {
    Boolean enable;

    UDPEndpointSetMulticastLoopMsg(const antModuleRef& module, Boolean en)
        : UDPEndpointBaseMsg(module, UDPEndpoint_SetMulticastLoop), enable(en) {}
};

struct UDPEndpointSetMulticastTTLMsg : public UDPEndpointBaseMsg {
    byte ttl;

    UDPEndpointSetMulticastTTLMsg(const antModuleRef& module, byte t)
        : UDPEndpointBaseMsg(module, UDPEndpoint_SetMulticastTTL), ttl(t) {}
};

struct UDPEndpointAddMembershipMsg : public UDPEndpointBaseMsg {
    IPAddress multiaddr;
    IPAddress interface;

    UDPEndpointAddMembershipMsg(const antModuleRef& module, IPAddress m, IPAddress i)
        : UDPEndpointBaseMsg(module, UDPEndpoint_AddMembership), multiaddr(m), interface(i) {}
};

struct UDPEndpointDropMembershipMsg : public UDPEndpointBaseMsg {
    IPAddress multiaddr;
    IPAddress interface;

    UDPEndpointDropMembershipMsg(const antModuleRef& module, IPAddress m, IPAddress i)
        : UDPEndpointBaseMsg(module, UDPEndpoint_DropMembership), multiaddr(m), interface(i) {}
};
#endif /* USE_MULTICAST */

struct UDPEndpointSetBlockingModeMsg : public UDPEndpointBaseMsg {
    bool blocking;

    UDPEndpointSetBlockingModeMsg(const antModuleRef& module, bool blk)
        : UDPEndpointBaseMsg(module, UDPEndpoint_SetBlockingMode), blocking(blk) {}
};

struct UDPEndpointReadyForReadMsg : public UDPEndpointBaseMsg {
    boolean ready;   /* out */

    UDPEndpointReadyForReadMsg(const antModuleRef& module)
        : UDPEndpointBaseMsg(module, UDPEndpoint_ReadyForRead), ready(FALSE) {}
};

struct UDPEndpointReadyForWriteMsg : public UDPEndpointBaseMsg {
    boolean ready;   /* out */

    UDPEndpointReadyForWriteMsg(const antModuleRef& module)
        : UDPEndpointBaseMsg(module, UDPEndpoint_ReadyForWrite), ready(FALSE) {}
};

struct UDPEndpointAddressMsg : public UDPEndpointBaseMsg {
    IPAddress lAddress;
    Port      lPort;
    IPAddress fAddress;
    Port      fPort;

    UDPEndpointAddressMsg(const antModuleRef& module)
        : UDPEndpointBaseMsg(module, UDPEndpoint_Address),
          lAddress(), lPort(0), fAddress(), fPort(0) {}
};

struct UDPEndpointResetConnectMsg : public UDPEndpointBaseMsg {
    UDPEndpointResetConnectMsg(const antModuleRef& module)
        : UDPEndpointBaseMsg(module, UDPEndpoint_ResetConnect) {}
};

#endif /* _UDPEndpointMsg_h_DEFINED */
