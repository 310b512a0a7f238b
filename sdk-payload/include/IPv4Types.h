/*
 * IPv4Types.h - generic IPv4 error codes (network-api 7). Unused by samples.
 */
#ifndef _IPv4Types_h_DEFINED
#define _IPv4Types_h_DEFINED

#include <antTypes.h>
#include <IPAddress.h>

enum IPv4Error {
    IPV4_SUCCESS              = 0,
    IPV4_FAIL                 = 1,
    IPV4_NOMEMORY             = 2,
    IPV4_ADDRESSINUSE         = 3,
    IPV4_ADDRESSERROR         = 4,
    IPV4_INVALID_REQUEST      = 5,
    IPV4_CONNECTION_CLOSED    = 6,
    IPV4_CONNECTION_BUSY      = 7,
    IPV4_CONNECTION_RESET     = 8,
    IPV4_CONNECTION_TIMEOUT   = 9,
    IPV4_NETWORK_UNREACHABLE  = 10,
    IPV4_HOST_UNREACHABLE     = 11,
    IPV4_PROTOCOL_UNREACHABLE = 12,
    IPV4_PORT_UNREACHABLE     = 13,
    IPV4_MESSAGE_TOO_LONG     = 14,
    IPV4_TIME_EXCEEDED        = 15,
    IPV4_TTL_EXCEEDED         = 16
};

/* prints the enumerator's name; runtime library */
std::ostream& operator<<(std::ostream& os, IPv4Error error);

#endif /* _IPv4Types_h_DEFINED */
