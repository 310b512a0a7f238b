// ant.cc - the user side of ANT (network-api 1.3-1.9): antStackRef, antEnvMsg::Send/Call,
// shared buffers, error names.  Messages are decoded into a flat request for the
// runtime's IPStack emulation (openr_net.h); replies are encoded back into a copy of
// the whole message struct, sized by its real type (never by msgSize, 1.6).
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <MCOOP.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <TCPEndpointMsg.h>
#include <UDPEndpointMsg.h>
#include <DNSEndpointMsg.h>
#include "openr_host.h"
#include "openr_net.h"

extern "C" const struct openr_net_api* openr_net(void)
{
    static const struct openr_net_api* api =
        static_cast<const struct openr_net_api*>(dlsym(RTLD_DEFAULT, "openr_runtime_net_v1"));
    return openr_net_accept(api);
}

boolean antEnvMsg::myOIDValid = FALSE;
OID     antEnvMsg::myOID;

// The ANT network library is not available to Remote Processing OPEN-R host objects
// (remote-processing 4): under start-rp-openr the stack is not found, and the first
// try says why. Host programs use the PC's own sockets. (libOPENR's RPHost.cc reads the
// same variable; calling it from here would break Makefiles that list -lOPENR before
// -lantMCOOP, as Sony's do, since a static archive only resolves names seen before it.)
static bool rpHostRefusesAnt()
{
    const char* v = getenv("OPENR_RP_HOST");
    if (v == 0 || strcmp(v, "1") != 0) return false;
    static int reported = 0;
    if (__sync_bool_compare_and_swap(&reported, 0, 1)) {
        fprintf(stderr, "antStackRef: the ANT network library is not available to Remote Processing "
                        "OPEN-R host objects; use the PC's own sockets\n");
    }
    return true;
}

antStackRef::antStackRef(const char* name) : oid(), disp(0)
{
    if (rpHostRefusesAnt()) return;
    if (name != 0 && strcmp(name, "IPStack") == 0 && openr_net() != 0) {
        oid = OID((void*)OPENR_NET_IPSTACK_OID);
        return;
    }
    OID found;
    if (Find(name, &found) == sSUCCESS) oid = found;
}

namespace {

void* own_oid()
{
    const openr_host_api* host = openr_host();
    return host != 0 ? host->self_oid() : (void*)0xffffffffUL;
}

void copy_name(char* dst, const char* src)
{
    strncpy(dst, src, OPENR_NET_NAME_MAX);
    dst[OPENR_NET_NAME_MAX] = '\0';
}

// Fills `req` from the message; returns the real size of its type (0 = unknown).
size_t decode(antEnvMsg* m, openr_net_request* req, const openr_net_api* net)
{
    memset(req, 0, sizeof(*req));
    req->op = m->dstOperation;
    if (m->dstSelector == (Selector)Entry_antEnv_Initialize) {
        req->proto = OPENR_NET_INIT;
        switch (m->dstOperation) {
        case antEnvInit_SetParam: {
            antEnvInitSetParamMsg* s = (antEnvInitSetParamMsg*)m;
            req->value2 = s->paramType;
            memcpy(req->name, s->key, ANTENV_KEY_LENGTH_MAX);
            if (s->paramType == antEnv_InitParam_Int32) req->value = s->value.i32;
            else memcpy(req->str, s->value.str, ANTENV_VALUE_LENGTH_MAX);
            return sizeof(antEnvInitSetParamMsg);
        }
        case antEnvInit_Start:
            return sizeof(antEnvInitStartMsg);
        case antEnvInit_GetParam: {
            antEnvInitGetParamMsg* g = (antEnvInitGetParamMsg*)m;
            memcpy(req->name, g->key, ANTENV_KEY_LENGTH_MAX);
            return sizeof(antEnvInitGetParamMsg);
        }
        }
        return 0;
    }
    if (m->dstModule == antModuleRef()) {
        req->proto = OPENR_NET_ENV;
        switch (m->dstOperation) {
        case antEnv_CreateEndpoint: {
            antEnvCreateEndpointMsg* c = (antEnvCreateEndpointMsg*)m;
            req->value = c->protocol;
            req->value2 = c->poolSize;
            return sizeof(antEnvCreateEndpointMsg);
        }
        case antEnv_CreateSharedBuffer:
            req->value = (int)((antEnvCreateSharedBufferMsg*)m)->size;
            return sizeof(antEnvCreateSharedBufferMsg);
        case antEnv_DestroySharedBuffer: {
            antEnvDestroySharedBufferMsg* d = (antEnvDestroySharedBufferMsg*)m;
            req->region = d->buffer.HostRegion();
            req->region_base = d->buffer.GetAddress();
            return sizeof(antEnvDestroySharedBufferMsg);
        }
        }
        return 0;
    }
    req->endpoint = m->dstModule.GetIndex();
    req->proto = net->endpoint_protocol(req->endpoint);
    switch (req->proto) {
    case OPENR_NET_TCP:
        switch (m->dstOperation) {
        case TCPEndpoint_Bind: {
            TCPEndpointBindMsg* b = (TCPEndpointBindMsg*)m;
            req->laddr = b->lAddress.Address();
            req->lport = b->lPort;
            return sizeof(*b);
        }
        case TCPEndpoint_Listen: {
            TCPEndpointListenMsg* l = (TCPEndpointListenMsg*)m;
            req->laddr = l->lAddress.Address();
            req->lport = l->lPort;
            return sizeof(*l);
        }
        case TCPEndpoint_Connect: {
            TCPEndpointConnectMsg* c = (TCPEndpointConnectMsg*)m;
            req->laddr = c->lAddress.Address();
            req->lport = c->lPort;
            req->addr = c->fAddress.Address();
            req->port = c->fPort;
            return sizeof(*c);
        }
        case TCPEndpoint_Send: {
            TCPEndpointSendMsg* s = (TCPEndpointSendMsg*)m;
            req->buffer = s->buffer;
            req->size = s->size;
            return sizeof(*s);
        }
        case TCPEndpoint_Receive: {
            TCPEndpointReceiveMsg* r = (TCPEndpointReceiveMsg*)m;
            req->buffer = r->buffer;
            req->size_min = r->sizeMin;
            req->size = r->sizeMax;
            return sizeof(*r);
        }
        case TCPEndpoint_Close: {
            TCPEndpointCloseMsg* c = (TCPEndpointCloseMsg*)m;
            req->flags = (c->abort ? 1 : 0) | (c->linger ? 2 : 0);
            req->linger_time = c->lingerTime;
            return sizeof(*c);
        }
        case TCPEndpoint_SetBlockingMode:
            req->flags = ((TCPEndpointSetBlockingModeMsg*)m)->blocking ? 1 : 0;
            return sizeof(TCPEndpointSetBlockingModeMsg);
        case TCPEndpoint_ReadyForRead: return sizeof(TCPEndpointReadyForReadMsg);
        case TCPEndpoint_ReadyForWrite: return sizeof(TCPEndpointReadyForWriteMsg);
        case TCPEndpoint_BacklogListen: return sizeof(TCPEndpointBacklogListenMsg);
        case TCPEndpoint_Accept: return sizeof(TCPEndpointAcceptMsg);
        case TCPEndpoint_BacklogQueues: return sizeof(TCPEndpointBacklogQueueMsg);
        case TCPEndpoint_Address: return sizeof(TCPEndpointAddressMsg);
        }
        return sizeof(TCPEndpointBaseMsg);
    case OPENR_NET_UDP:
        switch (m->dstOperation) {
        case UDPEndpoint_Bind:
        case UDPEndpoint_Connect: {
            // Bind and Connect have the same shape.
            UDPEndpointBindMsg* b = (UDPEndpointBindMsg*)m;
            req->addr = b->address.Address();
            req->port = b->port;
            return sizeof(*b);
        }
        case UDPEndpoint_Send: {
            UDPEndpointSendMsg* s = (UDPEndpointSendMsg*)m;
            req->addr = s->address.Address();
            req->port = s->port;
            req->buffer = s->buffer;
            req->size = s->size;
            return sizeof(*s);
        }
        case UDPEndpoint_Receive: {
            UDPEndpointReceiveMsg* r = (UDPEndpointReceiveMsg*)m;
            req->buffer = r->buffer;
            req->size = r->size;
            return sizeof(*r);
        }
        case UDPEndpoint_Close: {
            UDPEndpointCloseMsg* c = (UDPEndpointCloseMsg*)m;
            req->flags = c->linger ? 2 : 0;
            req->linger_time = c->lingerTime;
            return sizeof(*c);
        }
        case UDPEndpoint_SetBlockingMode:
            req->flags = ((UDPEndpointSetBlockingModeMsg*)m)->blocking ? 1 : 0;
            return sizeof(UDPEndpointSetBlockingModeMsg);
        case UDPEndpoint_ReadyForRead: return sizeof(UDPEndpointReadyForReadMsg);
        case UDPEndpoint_ReadyForWrite: return sizeof(UDPEndpointReadyForWriteMsg);
        case UDPEndpoint_Address: return sizeof(UDPEndpointAddressMsg);
        case UDPEndpoint_ResetConnect: return sizeof(UDPEndpointResetConnectMsg);
        }
        return sizeof(UDPEndpointBaseMsg);
    case OPENR_NET_DNS:
        switch (m->dstOperation) {
        case DNSEndpoint_SetServerAddresses: {
            DNSEndpointSetServerAddressesMsg* s = (DNSEndpointSetServerAddressesMsg*)m;
            req->value = s->nscount;
            for (int i = 0; i < MAXNS; i++) req->addr_list[i] = s->addrList[i].Address();
            return sizeof(*s);
        }
        case DNSEndpoint_GetServerAddresses: return sizeof(DNSEndpointGetServerAddressesMsg);
        case DNSEndpoint_SetDefaultDomainName:
            copy_name(req->name, ((DNSEndpointSetDefaultDomainNameMsg*)m)->name);
            return sizeof(DNSEndpointSetDefaultDomainNameMsg);
        case DNSEndpoint_GetDefaultDomainName: return sizeof(DNSEndpointGetDefaultDomainNameMsg);
        case DNSEndpoint_GetHostByName:
            copy_name(req->name, ((DNSEndpointGetHostByNameMsg*)m)->name);
            return sizeof(DNSEndpointGetHostByNameMsg);
        case DNSEndpoint_GetHostByAddr:
            req->addr = ((DNSEndpointGetHostByAddrMsg*)m)->host_address.Address();
            return sizeof(DNSEndpointGetHostByAddrMsg);
        case DNSEndpoint_GetAddress:
            req->value = ((DNSEndpointGetAddressMsg*)m)->index;
            return sizeof(DNSEndpointGetAddressMsg);
        case DNSEndpoint_GetAlias:
            req->value = ((DNSEndpointGetAliasMsg*)m)->index;
            return sizeof(DNSEndpointGetAliasMsg);
        case DNSEndpoint_Close: return sizeof(DNSEndpointCloseMsg);
        }
        return sizeof(DNSEndpointBaseMsg);
    }
    // An endpoint the stack never made: only the common error field is answered
    // (every protocol's base message puts `error` right after the header).
    return sizeof(TCPEndpointBaseMsg);
}

template <class T> void put_name(T* msg, const openr_net_result* r)
{
    if (r->name_valid) {
        strncpy(msg->name, r->name, MAXDNAME);
        msg->name[MAXDNAME - 1] = '\0';
    }
}

void encode(void* blob, const openr_net_result* r)
{
    antEnvMsg* m = (antEnvMsg*)blob;
    switch (r->proto) {
    case OPENR_NET_INIT:
        switch (r->op) {
        case antEnvInit_SetParam: ((antEnvInitSetParamMsg*)m)->error = (antError)r->error; break;
        case antEnvInit_Start: ((antEnvInitStartMsg*)m)->error = (antError)r->error; break;
        case antEnvInit_GetParam: {
            antEnvInitGetParamMsg* g = (antEnvInitGetParamMsg*)m;
            g->error = (antError)r->error;
            if (r->error == ANT_SUCCESS) {
                g->paramType = r->param_type;
                if (r->param_type == antEnv_InitParam_Int32) g->value.i32 = r->i32;
                else memcpy(g->value.str, r->str, ANTENV_VALUE_LENGTH_MAX);
            }
            break;
        }
        }
        return;
    case OPENR_NET_ENV:
        switch (r->op) {
        case antEnv_CreateEndpoint: {
            antEnvCreateEndpointMsg* c = (antEnvCreateEndpointMsg*)m;
            c->error = (antError)r->error;
            if (r->error == ANT_SUCCESS) c->moduleRef = antModuleRef(r->module, r->endpoint);
            break;
        }
        case antEnv_CreateSharedBuffer: {
            antEnvCreateSharedBufferMsg* c = (antEnvCreateSharedBufferMsg*)m;
            c->error = (antError)r->error;
            if (r->error == ANT_SUCCESS) c->buffer.HostSet(r->region, r->base, r->buf_size, 0);
            break;
        }
        case antEnv_DestroySharedBuffer:
            ((antEnvDestroySharedBufferMsg*)m)->error = (antError)r->error;
            break;
        }
        return;
    case OPENR_NET_TCP: {
        ((TCPEndpointBaseMsg*)m)->error = (TCPEndpointError)r->error;
        switch (r->op) {
        case TCPEndpoint_Bind: {
            TCPEndpointBindMsg* b = (TCPEndpointBindMsg*)m;
            b->lAddress = IPAddress((uint32)r->laddr);
            b->lPort = (Port)r->lport;
            break;
        }
        case TCPEndpoint_Listen:
        case TCPEndpoint_Connect: {
            // Listen and Connect have the same shape.
            TCPEndpointListenMsg* l = (TCPEndpointListenMsg*)m;
            if (r->error == TCP_SUCCESS) {
                l->lAddress = IPAddress((uint32)r->laddr);
                l->lPort = (Port)r->lport;
                l->fAddress = IPAddress((uint32)r->faddr);
                l->fPort = (Port)r->fport;
            }
            break;
        }
        case TCPEndpoint_Receive: {
            TCPEndpointReceiveMsg* rc = (TCPEndpointReceiveMsg*)m;
            rc->sizeMin = r->size;
            rc->sizeMax = r->size;
            break;
        }
        case TCPEndpoint_ReadyForRead: ((TCPEndpointReadyForReadMsg*)m)->ready = r->ready; break;
        case TCPEndpoint_ReadyForWrite: ((TCPEndpointReadyForWriteMsg*)m)->ready = r->ready; break;
        case TCPEndpoint_Address: {
            TCPEndpointAddressMsg* a = (TCPEndpointAddressMsg*)m;
            a->lAddress = IPAddress((uint32)r->laddr);
            a->lPort = (Port)r->lport;
            a->fAddress = IPAddress((uint32)r->faddr);
            a->fPort = (Port)r->fport;
            break;
        }
        }
        return;
    }
    case OPENR_NET_UDP: {
        ((UDPEndpointBaseMsg*)m)->error = (UDPEndpointError)r->error;
        switch (r->op) {
        case UDPEndpoint_Bind: {
            UDPEndpointBindMsg* b = (UDPEndpointBindMsg*)m;
            if (r->error == UDP_SUCCESS) {
                b->address = IPAddress((uint32)r->laddr);
                b->port = (Port)r->lport;
            }
            break;
        }
        case UDPEndpoint_Receive: {
            UDPEndpointReceiveMsg* rc = (UDPEndpointReceiveMsg*)m;
            if (r->error == UDP_SUCCESS) {
                rc->address = IPAddress((uint32)r->faddr);
                rc->port = (Port)r->fport;
                rc->size = r->size;
            }
            break;
        }
        case UDPEndpoint_ReadyForRead: ((UDPEndpointReadyForReadMsg*)m)->ready = r->ready; break;
        case UDPEndpoint_ReadyForWrite: ((UDPEndpointReadyForWriteMsg*)m)->ready = r->ready; break;
        case UDPEndpoint_Address: {
            UDPEndpointAddressMsg* a = (UDPEndpointAddressMsg*)m;
            a->lAddress = IPAddress((uint32)r->laddr);
            a->lPort = (Port)r->lport;
            a->fAddress = IPAddress((uint32)r->faddr);
            a->fPort = (Port)r->fport;
            break;
        }
        }
        return;
    }
    case OPENR_NET_DNS: {
        ((DNSEndpointBaseMsg*)m)->error = (DNSEndpointError)r->error;
        switch (r->op) {
        case DNSEndpoint_GetServerAddresses: {
            DNSEndpointGetServerAddressesMsg* g = (DNSEndpointGetServerAddressesMsg*)m;
            g->nscount = r->nscount;
            for (int i = 0; i < MAXNS; i++) g->addrList[i] = IPAddress((uint32)r->addr_list[i]);
            break;
        }
        case DNSEndpoint_GetDefaultDomainName:
            put_name((DNSEndpointGetDefaultDomainNameMsg*)m, r);
            break;
        case DNSEndpoint_GetHostByName:
        case DNSEndpoint_GetHostByAddr: {
            // Same shape; on failure `name` and `host_address` stay untouched (5.5).
            DNSEndpointGetHostByNameMsg* h = (DNSEndpointGetHostByNameMsg*)m;
            put_name(h, r);
            h->server_address = IPAddress((uint32)r->server_address);
            if (r->host_valid) h->host_address = IPAddress((uint32)r->host_address);
            h->n_address = r->n_address;
            h->n_alias = r->n_alias;
            break;
        }
        case DNSEndpoint_GetAddress:
            if (r->host_valid)
                ((DNSEndpointGetAddressMsg*)m)->address = IPAddress((uint32)r->host_address);
            break;
        case DNSEndpoint_GetAlias:
            put_name((DNSEndpointGetAliasMsg*)m, r);
            break;
        }
        return;
    }
    }
    // unknown endpoint: the common error field (CONNECTION_CLOSED is 2 in TCP and UDP)
    ((TCPEndpointBaseMsg*)m)->error = (TCPEndpointError)r->error;
}

antError submit(antEnvMsg* m, void* reply_oid, unsigned int selector, int sync)
{
    const openr_net_api* net = openr_net();
    if (net == 0) return ANT_FAIL;
    openr_net_request req;
    size_t size = decode(m, &req, net);
    if (size == 0) {
        // An operation code no message type has: answer with the header only.
        size = sizeof(antEnvMsg);
    }
    return net->submit(&req, m, size, encode, reply_oid, selector, sync) == 0 ? ANT_SUCCESS : ANT_FAIL;
}

bool is_ipstack(antStackRef& target)
{
    return target.get_oid().GetAddress() == (void*)OPENR_NET_IPSTACK_OID;
}

}  // namespace

antError antEnvMsg::Send(antStackRef target, const OID& senderOID, int32 selector, int size)
{
    contInfo = antEnvMsgContInfo(senderOID, (uint32)selector);
    invocationType = ANTENVMSG_SEND;
    sender = OID(own_oid());
    msgSize = size;
    if (!is_ipstack(target)) return ANT_FAIL;
    return submit(this, senderOID.GetAddress(), (unsigned int)selector, 0);
}

antError antEnvMsg::Call(antStackRef target, int size)
{
    invocationType = ANTENVMSG_CALL;
    sender = OID(own_oid());
    msgSize = size;
    if (!is_ipstack(target)) return ANT_FAIL;
    return submit(this, 0, 0, 1);
}

antError antEnvMsg::Reply()
{
    // Stack side only; user objects never serve ANT messages.
    return ANT_FAIL;
}

antError antSharedBuffer::Map()
{
    return base != 0 ? ANT_SUCCESS : ANT_FAIL;
}

antError antSharedBuffer::UnMap()
{
    return base != 0 ? ANT_SUCCESS : ANT_FAIL;
}

static const char* const ant_error_names[] = {
    "ANT_SUCCESS", "ANT_FAIL", "ANT_NOMEMORY", "ANT_INVALIDPTR", "ANT_NO_STATE_TRANSITION",
    "ANT_SDU_BADRANGE", "ANT_SDU_NOMORE_DATACELL", "ANT_SDU_NOOWNER", "ANT_SDUPOOL_ALLOCATED",
    "ANT_SDUPOOL_NOTASSIGNED", "ANT_QUEUE_EMPTY", "ANT_QUEUE_STATE", "ANT_QUEUE_CLOSED",
    "ANT_QUEUE_REJECTED", "ANT_QUEUE_BLOCKED", "ANT_INVALIDMODULEID", "ANT_TMR_TYPE_INVALID",
    "ANT_TMR_MAXNMBR_REACHED", "ANT_NOMESSAGES", "ANT_NAMING_ENTRY_EXISTS",
    "ANT_NAMING_NO_SUCH_NAME", "ANT_NAMING_NAME_INVALID", "ANT_REGISTRY_DUPLICATE_KEY",
    "ANT_REGISTRY_NO_KEY", "ANT_REGISTRY_WRONG_TYPE", "ANT_REGISTRY_INVALID_KEY",
    "ANT_REGISTRY_INVALID_VALUE", "ANT_ENDPOINT_NOFACTORY", "ANT_NOT_INITIALIZED",
    "ANT_INITIALIZING",
};

const char* antErrorString(antError error)
{
    int i = (int)error;
    if (i < 0 || i >= (int)(sizeof(ant_error_names) / sizeof(ant_error_names[0])))
        return "UNKNOWN ANT ERROR";
    return ant_error_names[i];
}

std::ostream& operator<<(std::ostream& os, antError error)
{
    return os << antErrorString(error);
}

void antModuleRef::Print(std::ostream& os) const
{
    os << "[" << (void*)module << "|" << index << "]";
}

std::ostream& operator<<(std::ostream& os, const antModuleRef& ref)
{
    ref.Print(os);
    return os;
}
