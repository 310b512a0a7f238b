/*
 * DNSEndpointErr.h - error codes of DNS endpoints (network-api 5.1).
 */
#ifndef _DNSEndpointErr_h_DEFINED
#define _DNSEndpointErr_h_DEFINED

enum DNSEndpointError {
    DNS_SUCCESS,              /*  0 */
    DNS_FAIL,                 /*  1 */
    DNS_HOST_NOT_FOUND,       /*  2 */
    DNS_TRY_AGAIN,            /*  3 */
    DNS_NO_RECOVERY,          /*  4 */
    DNS_NO_DATA,              /*  5 */
    DNS_CONNECTION_CLOSED,    /*  6 */
    DNS_CONNECTION_BUSY,      /*  7 */
    DNS_INDEX_INVALID,        /*  8 */
    DNS_BUFFER_INVALID,       /*  9 */
    DNS_OPERATION_INVALID,    /* 10 */
    DNS_OPERATION_UNKNOWN     /* 11 */
};

#endif /* _DNSEndpointErr_h_DEFINED */
