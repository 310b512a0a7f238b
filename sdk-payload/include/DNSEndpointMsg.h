/*
 * DNSEndpointMsg.h - messages of DNS endpoints (network-api 5).
 * Names are copied with a bounded 100-byte copy (MAXDNAME).
 */
#ifndef _DNSEndpointMsg_h_DEFINED
#define _DNSEndpointMsg_h_DEFINED

#include <DNSEndpointErr.h>
#include <antEnvBaseMsg.h>
#include <IPAddress.h>
#include <string.h>

#define MAXNS                      3
#define MAXDNAME                   100
#define DNSENDPOINT_OPERATION_NUM  9

enum DNSEndpointOperation {
    DNSEndpoint_SetServerAddresses   = 0,
    DNSEndpoint_GetServerAddresses   = 1,
    DNSEndpoint_SetDefaultDomainName = 2,
    DNSEndpoint_GetDefaultDomainName = 3,
    DNSEndpoint_GetHostByName        = 4,
    DNSEndpoint_GetHostByAddr        = 5,
    DNSEndpoint_GetAddress           = 6,
    DNSEndpoint_GetAlias             = 7,
    DNSEndpoint_Close                = 8
};

struct DNSEndpointBaseMsg : public antEnvMsg {
    DNSEndpointError error;

    DNSEndpointBaseMsg() : antEnvMsg(), error(DNS_FAIL) {}
    DNSEndpointBaseMsg(const antModuleRef& module, DNSEndpointOperation op)
        : antEnvMsg(module, op), error(DNS_FAIL) {}
    DNSEndpointBaseMsg(const DNSEndpointBaseMsg& m) : antEnvMsg(m), error(m.error) {}

    antError Reply(DNSEndpointError e) { error = e; return antEnvMsg::Reply(); }
};

struct DNSEndpointSetServerAddressesMsg : public DNSEndpointBaseMsg {
    int32     nscount;
    IPAddress addrList[MAXNS];

    DNSEndpointSetServerAddressesMsg(const antModuleRef& module, int32 n, IPAddress* list)
        : DNSEndpointBaseMsg(module, DNSEndpoint_SetServerAddresses), nscount(n) {
        for (int32 i = 0; i < n; i++) addrList[i] = list[i];
    }
    /* as on the robot, the base part is not copied */
    DNSEndpointSetServerAddressesMsg(const DNSEndpointSetServerAddressesMsg& m)
        : DNSEndpointBaseMsg(), nscount(m.nscount) {
        for (int i = 0; i < MAXNS; i++) addrList[i] = m.addrList[i];
    }
};

struct DNSEndpointGetServerAddressesMsg : public DNSEndpointBaseMsg {
    int32     nscount;           /* out */
    IPAddress addrList[MAXNS];   /* out */

    DNSEndpointGetServerAddressesMsg(const antModuleRef& module)
        : DNSEndpointBaseMsg(module, DNSEndpoint_GetServerAddresses) {}
    /* as on the robot, the base part is not copied */
    DNSEndpointGetServerAddressesMsg(const DNSEndpointGetServerAddressesMsg& m)
        : DNSEndpointBaseMsg(), nscount(m.nscount) {
        for (int i = 0; i < MAXNS; i++) addrList[i] = m.addrList[i];
    }
};

struct DNSEndpointSetDefaultDomainNameMsg : public DNSEndpointBaseMsg {
    char name[MAXDNAME];

    DNSEndpointSetDefaultDomainNameMsg(const antModuleRef& module, const char* n)
        : DNSEndpointBaseMsg(module, DNSEndpoint_SetDefaultDomainName) {
        strncpy(name, n, MAXDNAME);
    }
    DNSEndpointSetDefaultDomainNameMsg(const DNSEndpointSetDefaultDomainNameMsg& m)
        : DNSEndpointBaseMsg(m) {
        strncpy(name, m.name, MAXDNAME);
    }
};

struct DNSEndpointGetDefaultDomainNameMsg : public DNSEndpointBaseMsg {
    char name[MAXDNAME];   /* out */

    DNSEndpointGetDefaultDomainNameMsg(const antModuleRef& module)
        : DNSEndpointBaseMsg(module, DNSEndpoint_GetDefaultDomainName) {
        name[0] = '\0';
    }
    DNSEndpointGetDefaultDomainNameMsg(const DNSEndpointGetDefaultDomainNameMsg& m)
        : DNSEndpointBaseMsg(m) {
        strncpy(name, m.name, MAXDNAME);
    }
};

struct DNSEndpointGetHostByNameMsg : public DNSEndpointBaseMsg {
    char      name[MAXDNAME];   /* in/out */
    IPAddress server_address;   /* out */
    IPAddress host_address;     /* out */
    int       n_address;        /* out */
    int       n_alias;          /* out */

    DNSEndpointGetHostByNameMsg(const antModuleRef& module, const char* n)
        : DNSEndpointBaseMsg(module, DNSEndpoint_GetHostByName),
          server_address(), host_address() {
        strncpy(name, n, MAXDNAME);
    }
    DNSEndpointGetHostByNameMsg(const DNSEndpointGetHostByNameMsg& m)
        : DNSEndpointBaseMsg(m), server_address(m.server_address),
          host_address(m.host_address), n_address(m.n_address), n_alias(m.n_alias) {
        strncpy(name, m.name, MAXDNAME);
    }
};

struct DNSEndpointGetHostByAddrMsg : public DNSEndpointBaseMsg {
    char      name[MAXDNAME];   /* out */
    IPAddress server_address;   /* out */
    IPAddress host_address;     /* in/out */
    int       n_address;        /* out */
    int       n_alias;          /* out */

    DNSEndpointGetHostByAddrMsg(const antModuleRef& module, IPAddress address)
        : DNSEndpointBaseMsg(module, DNSEndpoint_GetHostByAddr),
          server_address(), host_address(address) {
        name[0] = '\0';
    }
    DNSEndpointGetHostByAddrMsg(const DNSEndpointGetHostByAddrMsg& m)
        : DNSEndpointBaseMsg(m), server_address(m.server_address),
          host_address(m.host_address), n_address(m.n_address), n_alias(m.n_alias) {
        strncpy(name, m.name, MAXDNAME);
    }
};

struct DNSEndpointGetAddressMsg : public DNSEndpointBaseMsg {
    int       index;     /* in */
    IPAddress address;   /* out */

    DNSEndpointGetAddressMsg(const antModuleRef& module, int idx)
        : DNSEndpointBaseMsg(module, DNSEndpoint_GetAddress), index(idx), address() {}
    DNSEndpointGetAddressMsg(const DNSEndpointGetAddressMsg& m)
        : DNSEndpointBaseMsg(m), index(m.index), address(m.address) {}
};

struct DNSEndpointGetAliasMsg : public DNSEndpointBaseMsg {
    int  index;            /* in */
    char name[MAXDNAME];   /* out */

    DNSEndpointGetAliasMsg(const antModuleRef& module, int idx)
        : DNSEndpointBaseMsg(module, DNSEndpoint_GetAlias), index(idx) {
        name[0] = '\0';
    }
    DNSEndpointGetAliasMsg(const DNSEndpointGetAliasMsg& m)
        : DNSEndpointBaseMsg(m), index(m.index) {
        strncpy(name, m.name, MAXDNAME);
    }
};

struct DNSEndpointCloseMsg : public DNSEndpointBaseMsg {
    DNSEndpointCloseMsg(const antModuleRef& module)
        : DNSEndpointBaseMsg(module, DNSEndpoint_Close) {}
    DNSEndpointCloseMsg(const DNSEndpointCloseMsg& m) : DNSEndpointBaseMsg(m) {}
};

#endif /* _DNSEndpointMsg_h_DEFINED */
