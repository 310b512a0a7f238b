/*
 * TCPEndpointMsg.h - messages of TCP endpoints (network-api 3).
 * Field names and order follow the robot; the constructors take the
 * endpoint as `const antModuleRef&` (the robot's was non-const).
 */
#ifndef _TCPEndpointMsg_h_DEFINED
#define _TCPEndpointMsg_h_DEFINED

#include <MCOOP/antEnvMsg.h>
#include <IPAddress.h>

enum TCPEndpointError {
    TCP_SUCCESS              = 0,
    TCP_FAIL                 = 1,
    TCP_CONNECTION_CLOSED    = 2,
    TCP_CONNECTION_RESET     = 3,
    TCP_CONNECTION_TIMEOUT   = 4,
    TCP_CONNECTION_BUSY      = 5,
    TCP_ADDRESSINUSE         = 6,
    TCP_ADDRESSERROR         = 7,
    TCP_PORT_UNREACHABLE     = 8,
    TCP_PROTOCOL_UNREACHABLE = 9,
    TCP_HOST_UNREACHABLE     = 10,
    TCP_NETWORK_UNREACHABLE  = 11,
    TCP_MESSAGE_TOO_LONG     = 12,
    TCP_TTL_EXCEEDED         = 13,
    TCP_TIME_EXCEEDED        = 14,
    TCP_WOULDBLOCK           = 15,
    TCP_BUFFER_INVALID       = 16,
    TCP_OPERATION_INVALID    = 17,
    TCP_OPERATION_UNKNOWN    = 18
};

enum TCPEndpointOperation {
    TCPEndpoint_Bind            = 1,
    TCPEndpoint_Listen          = 2,
    TCPEndpoint_Connect         = 3,
    TCPEndpoint_Send            = 4,
    TCPEndpoint_Receive         = 5,
    TCPEndpoint_Close           = 6,
    TCPEndpoint_SetBlockingMode = 7,
    TCPEndpoint_ReadyForRead    = 8,
    TCPEndpoint_ReadyForWrite   = 9,
    TCPEndpoint_BacklogListen   = 10,
    TCPEndpoint_Accept          = 11,
    TCPEndpoint_BacklogQueues   = 12,
    TCPEndpoint_Address         = 13
};

struct TCPEndpointBaseMsg : public antEnvMsg {
    TCPEndpointError error;

    TCPEndpointBaseMsg() : antEnvMsg(), error(TCP_FAIL) {}
    TCPEndpointBaseMsg(const antModuleRef& module, TCPEndpointOperation op)
        : antEnvMsg(module, op), error(TCP_FAIL) {}

    antError Reply(TCPEndpointError e) { error = e; return antEnvMsg::Reply(); }
};

struct TCPEndpointBindMsg : public TCPEndpointBaseMsg {
    IPAddress lAddress;   /* in/out */
    Port      lPort;      /* in/out */

    TCPEndpointBindMsg(const antModuleRef& module, IPAddress lAddr, Port lP)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Bind), lAddress(lAddr), lPort(lP) {}
};

struct TCPEndpointListenMsg : public TCPEndpointBaseMsg {
    IPAddress lAddress;   /* out */
    Port      lPort;      /* in */
    IPAddress fAddress;   /* out */
    Port      fPort;      /* out */

    TCPEndpointListenMsg(const antModuleRef& module,
                         IPAddress lAddr = 0, Port lP = 0,
                         IPAddress fAddr = 0, Port fP = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Listen),
          lAddress(lAddr), lPort(lP), fAddress(fAddr), fPort(fP) {}
};

struct TCPEndpointConnectMsg : public TCPEndpointBaseMsg {
    IPAddress lAddress;
    Port      lPort;
    IPAddress fAddress;   /* in */
    Port      fPort;      /* in */

    TCPEndpointConnectMsg(const antModuleRef& module, IPAddress lAddr, Port lP,
                          IPAddress fAddr, Port fP)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Connect),
          lAddress(lAddr), lPort(lP), fAddress(fAddr), fPort(fP) {}
};

struct TCPEndpointSendMsg : public TCPEndpointBaseMsg {
    byte* buffer;   /* inside a shared buffer */
    int   size;
    int16 queueNr;

    TCPEndpointSendMsg(const antModuleRef& module, byte* buf, int sz, int16 q = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Send), buffer(buf), size(sz), queueNr(q) {}
};

struct TCPEndpointReceiveMsg : public TCPEndpointBaseMsg {
    byte* buffer;    /* inside a shared buffer */
    int   sizeMin;   /* in/out: out = bytes received */
    int   sizeMax;   /* in/out */
    int16 queueNr;

    TCPEndpointReceiveMsg(const antModuleRef& module, byte* buf, int szMin, int szMax,
                          int16 q = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Receive),
          buffer(buf), sizeMin(szMin), sizeMax(szMax), queueNr(q) {}
};

struct TCPEndpointCloseMsg : public TCPEndpointBaseMsg {
    bool  abort;
    bool  linger;
    int   lingerTime;
    int16 queueNr;

    TCPEndpointCloseMsg(const antModuleRef& module, bool lng = false, int lngTime = 0,
                        bool abrt = false, int16 q = -100)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Close),
          abort(abrt), linger(lng), lingerTime(lngTime), queueNr(q) {}
};

struct TCPEndpointSetBlockingModeMsg : public TCPEndpointBaseMsg {
    bool  blocking;
    int16 queueNr;

    TCPEndpointSetBlockingModeMsg(const antModuleRef& module, bool blk, int16 q = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_SetBlockingMode), blocking(blk), queueNr(q) {}
};

struct TCPEndpointReadyForReadMsg : public TCPEndpointBaseMsg {
    boolean ready;   /* out */
    int16   queueNr;

    TCPEndpointReadyForReadMsg(const antModuleRef& module, int16 q = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_ReadyForRead), ready(FALSE), queueNr(q) {}
};

struct TCPEndpointReadyForWriteMsg : public TCPEndpointBaseMsg {
    boolean ready;   /* out */
    int16   queueNr;

    TCPEndpointReadyForWriteMsg(const antModuleRef& module, int16 q = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_ReadyForWrite), ready(FALSE), queueNr(q) {}
};

struct TCPEndpointBacklogListenMsg : public TCPEndpointBaseMsg {
    IPAddress lAddress;
    Port      lPort;
    IPAddress fAddress;
    Port      fPort;

    TCPEndpointBacklogListenMsg(const antModuleRef& module,
                                IPAddress lAddr = 0, Port lP = 0,
                                IPAddress fAddr = 0, Port fP = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_BacklogListen),
          lAddress(lAddr), lPort(lP), fAddress(fAddr), fPort(fP) {}
};

struct TCPEndpointAcceptMsg : public TCPEndpointBaseMsg {
    IPAddress lAddress;
    Port      lPort;
    IPAddress fAddress;
    Port      fPort;
    int16     queueNr;

    TCPEndpointAcceptMsg(const antModuleRef& module)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Accept),
          lAddress(), lPort(0), fAddress(), fPort(0), queueNr(0) {}
};

struct TCPEndpointBacklogQueueMsg : public TCPEndpointBaseMsg {
    int16 backlog;

    TCPEndpointBacklogQueueMsg(const antModuleRef& module, int16 bl)
        : TCPEndpointBaseMsg(module, TCPEndpoint_BacklogQueues), backlog(bl) {}
};

struct TCPEndpointAddressMsg : public TCPEndpointBaseMsg {
    int16     queueNr;
    IPAddress lAddress;
    Port      lPort;
    IPAddress fAddress;
    Port      fPort;

    TCPEndpointAddressMsg(const antModuleRef& module, int16 q = 0)
        : TCPEndpointBaseMsg(module, TCPEndpoint_Address),
          queueNr(q), lAddress(), lPort(0), fAddress(), fPort(0) {}
};

#endif /* _TCPEndpointMsg_h_DEFINED */
