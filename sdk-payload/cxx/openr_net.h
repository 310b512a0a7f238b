/*
 * openr_net.h - the private ABI between the ANT libraries an object links
 * (libantMCOOP, libInternet, libERA201D1) and the runtime's IPStack emulation
 * (sdk-runtime/src/net).  Not an OPEN-R header: programs never include it.
 *
 * The runtime exports `openr_runtime_net_v1`; the archives find it with
 * dlsym(RTLD_DEFAULT).  The C++ side knows the layouts of the ANT messages,
 * the runtime does not: antEnvMsg::Send/Call decode the message into a flat
 * `openr_net_request`, hand the runtime a copy of the whole message (`blob`,
 * exactly sizeof(real type), never msgSize) and an `encode` function that
 * writes an `openr_net_result` into such a copy.  The runtime completes the
 * operation (at once or later, on its own thread), calls `encode` on its copy
 * and delivers it: to (reply_oid, reply_selector) as an ordinary message for
 * Send, or back into `blob` for Call.  Plain C types only.
 */
#ifndef OPENR_NET_H
#define OPENR_NET_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OPENR_NET_ABI_VERSION 1

/* The OID antStackRef("IPStack") yields (no real object has it). */
#define OPENR_NET_IPSTACK_OID 0x8000000cUL

/* openr_net_request.proto */
#define OPENR_NET_ENV  0    /* selector External, module 0: -1 create endpoint, -2/-3 buffers */
#define OPENR_NET_INIT 100  /* selector Initialize: -1 SetParam, -2 Start, -3 GetParam */
#define OPENR_NET_TCP  1    /* EndpointType_TCP */
#define OPENR_NET_UDP  2    /* EndpointType_UDP */
#define OPENR_NET_DNS  4    /* EndpointType_DNS */

#define OPENR_NET_NAME_MAX 100

struct openr_net_request {
    int proto;                 /* OPENR_NET_* */
    int op;                    /* dstOperation */
    unsigned int endpoint;     /* dstModule's index (0 for ENV / INIT) */
    /* generic inputs; which are meaningful depends on (proto, op) */
    unsigned int addr;         /* IPAddress value (UDP address, TCP fAddress) */
    unsigned int port;         /* UDP port, TCP fPort */
    unsigned int laddr;        /* TCP lAddress */
    unsigned int lport;        /* TCP lPort */
    void* buffer;              /* payload in a shared buffer */
    int size;                  /* TCP/UDP send size, UDP receive size, TCP sizeMax */
    int size_min;              /* TCP receive sizeMin */
    int flags;                 /* TCP close: 1 abort, 2 linger; UDP/TCP blocking */
    int linger_time;
    int value;                 /* create endpoint: protocol; shared buffer: size;
                                  DNS index / nscount; registry int32 */
    int value2;                /* create endpoint: poolSize; registry param type */
    unsigned int region;       /* destroy shared buffer: its region id */
    void* region_base;
    unsigned int addr_list[3]; /* DNS server list */
    char name[OPENR_NET_NAME_MAX + 1]; /* DNS name, registry key */
    char str[OPENR_NET_NAME_MAX + 1];  /* registry string value */
};

struct openr_net_result {
    int proto, op;             /* copied from the request */
    int error;                 /* in the protocol's own numbering */
    unsigned int laddr, lport, faddr, fport;  /* TCP/UDP addresses (robot view) */
    int size;                  /* bytes received (TCP sizeMin = sizeMax, UDP size) */
    int ready;
    void* module;              /* new endpoint: module pointer and index */
    unsigned int endpoint;
    unsigned int region;       /* new shared buffer */
    void* base;
    unsigned int buf_size;
    /* DNS */
    char name[OPENR_NET_NAME_MAX + 1];
    int name_valid;            /* write `name` only when set */
    unsigned int server_address, host_address;
    int host_valid;            /* write host_address only when set */
    int n_address, n_alias;
    int nscount;
    unsigned int addr_list[3];
    /* registry */
    int param_type;
    int i32;
    char str[33];
};

typedef void (*openr_net_encode_fn)(void* blob, const struct openr_net_result* result);

struct openr_net_api {
    unsigned int abi_version;  /* OPENR_NET_ABI_VERSION */
    unsigned int size;         /* sizeof(struct openr_net_api) of the runtime */

    /* Protocol of an endpoint (OPENR_NET_TCP/UDP/DNS), or -1 if unknown/closed. */
    int (*endpoint_protocol)(unsigned int endpoint);
    /* Submits one request.  `sync` != 0 (Call): blocks the calling object until the
     * operation completes, then encodes into `blob`.  Otherwise (Send): copies
     * `blob_size` bytes of `blob` at once and later delivers the encoded copy to
     * (reply_oid, reply_selector).  Returns 0, or -1 when the request cannot be
     * accepted (no runtime). */
    int (*submit)(const struct openr_net_request* req, void* blob, size_t blob_size,
                  openr_net_encode_fn encode, void* reply_oid, unsigned int reply_selector,
                  int sync);
    /* The robot's wireless configuration (WLANCONF.TXT, else WLANDFLT.TXT, else the
     * shipped defaults): copies the value of `key` into `out`; 0, or -1 if unknown. */
    int (*config_value)(const char* key, char* out, size_t cap);
    /* The robot's number (0 for the first robot; the port offset by default): used
     * for its MAC address. */
    unsigned int (*robot_number)(void);
};

/* Found with dlsym; NULL outside cargo-openr. */
const struct openr_net_api* openr_net(void);

/* `api` if it is a table this library can use (its ABI version, at least its size: a
 * runtime older than the library has fewer entries), else NULL. Both network libraries
 * (antMCOOP, ERA201D1) look the table up themselves and check it with this. */
static inline const struct openr_net_api* openr_net_accept(const struct openr_net_api* api)
{
    if (api != 0 && (api->abi_version != OPENR_NET_ABI_VERSION || api->size < sizeof(struct openr_net_api))) return 0;
    return api;
}

#ifdef __cplusplus
}
#endif

#endif /* OPENR_NET_H */
