/*
 * EtherDriverMsg.h - messages of the Ethernet driver (network-api 10).
 * Only the two used by ERA201D1.h are backed by the host runtime.
 */
#ifndef _EtherDriverMsg_h_DEFINED
#define _EtherDriverMsg_h_DEFINED

#include <Types.h>
#include <EtherTypes.h>

struct EtherDriverGetMACAddressMsg {
    uint32          port;
    EtherMACAddress address;
    EtherStatus     status;

    EtherDriverGetMACAddressMsg() : port(0), address(), status(ETHER_UNSUPPORTED) {}
};

struct EtherDriverGetStatisticsMsg {
    uint32          port;
    EtherStatistics statistics;
    EtherStatus     status;

    EtherDriverGetStatisticsMsg() : port(0), status(ETHER_UNSUPPORTED) {
        memset(&statistics, 0, sizeof(statistics));
    }
};

/* raw driver API (no host implementation, no sample uses it) */
struct EtherDriverRegisterClientMsg {
    uint32      port;
    uint16      protocol;
    OID         client;
    Selector    receiveSelector;
    uint32      handle;   /* out */
    EtherStatus status;
};

struct EtherDriverUnregisterClientMsg {
    uint32      port;
    uint32      handle;
    EtherStatus status;
};

struct EtherDriverTransmitMsg {
    uint32          port;
    uint32          handle;
    EtherMACAddress destination;
    void*           buffer;
    uint32          size;
    EtherStatus     status;
};

struct EtherDriverReceiveMsg {
    uint32          port;
    uint32          handle;
    EtherMACAddress source;
    void*           buffer;
    uint32          size;
    EtherStatus     status;
};

struct EtherDriverSetPromiscuousMsg {
    uint32      port;
    bool        enable;
    EtherStatus status;
};

struct EtherDriverAddMulticastAddressMsg {
    uint32          port;
    EtherMACAddress address;
    EtherStatus     status;
};

struct EtherDriverRemoveMulticastAddressMsg {
    uint32          port;
    EtherMACAddress address;
    EtherStatus     status;
};

struct EtherDriverSetDeviceModeMsg {
    uint32      port;
    uint32      mode;
    EtherStatus status;
};

#endif /* _EtherDriverMsg_h_DEFINED */
