// IPAddress.cc - the out-of-line members of IPAddress (network-api 8.1) and the
// debug printers of the Internet library.
#include <stdio.h>
#include <string.h>
#include <IPAddress.h>
#include <IPv4Types.h>
#include <UDPEndpointMsg.h>

IPAddress::IPAddress(const char* s) : address(0)
{
    if (s == 0) return;
    uint32 parts[4] = {0, 0, 0, 0};
    int dots = 0;
    for (const char* p = s; *p != '\0'; p++) {
        if (*p >= '0' && *p <= '9') {
            parts[dots] = parts[dots] * 10 + (uint32)(*p - '0');
        } else if (*p == '.') {
            if (++dots > 3) return;   // a fourth dot: not an address
        } else {
            break;                    // any other character ends the number
        }
    }
    if (dots != 3) return;
    address = (parts[0] << 24) | (parts[1] << 16) | (parts[2] << 8) | parts[3];
}

char* IPAddress::intToAscii(char* buf, int value, bool first) const
{
    if (!first) *buf++ = '.';
    return buf + sprintf(buf, "%d", value & 0xff);
}

char* IPAddress::GetAsString(char* buf) const
{
    // At most 16 bytes ("255.255.255.255" + NUL): callers pass exactly 16.
    char* p = intToAscii(buf, (int)(address >> 24), true);
    p = intToAscii(p, (int)(address >> 16), false);
    p = intToAscii(p, (int)(address >> 8), false);
    intToAscii(p, (int)address, false);
    return buf;
}

OSTREAM& IPAddress::print(OSTREAM& os) const
{
    char buf[16];
    return os << "[" << GetAsString(buf) << "]";
}

static const char* const udp_error_names[] = {
    "UDP_SUCCESS", "UDP_FAIL", "UDP_CONNECTION_CLOSED", "UDP_CONNECTION_BUSY",
    "UDP_ADDRESSINUSE", "UDP_ADDRESSERROR", "UDP_PORT_UNREACHABLE",
    "UDP_PROTOCOL_UNREACHABLE", "UDP_HOST_UNREACHABLE", "UDP_NETWORK_UNREACHABLE",
    "UDP_MESSAGE_TOO_LONG", "UDP_TTL_EXCEEDED", "UDP_TIME_EXCEEDED", "UDP_BUFFER_INVALID",
    "UDP_OPERATION_INVALID", "UDP_OPERATION_UNKNOWN", "UDP_WOULDBLOCK",
};

std::ostream& operator<<(std::ostream& os, UDPEndpointError error)
{
    int i = (int)error;
    if (i < 0 || i > 16) return os << "UDP_UNKNOWN_ERROR(" << i << ")";
    return os << udp_error_names[i];
}

static const char* const ipv4_error_names[] = {
    "IPV4_SUCCESS", "IPV4_FAIL", "IPV4_NOMEMORY", "IPV4_ADDRESSINUSE", "IPV4_ADDRESSERROR",
    "IPV4_INVALID_REQUEST", "IPV4_CONNECTION_CLOSED", "IPV4_CONNECTION_BUSY",
    "IPV4_CONNECTION_RESET", "IPV4_CONNECTION_TIMEOUT", "IPV4_NETWORK_UNREACHABLE",
    "IPV4_HOST_UNREACHABLE", "IPV4_PROTOCOL_UNREACHABLE", "IPV4_PORT_UNREACHABLE",
    "IPV4_MESSAGE_TOO_LONG", "IPV4_TIME_EXCEEDED", "IPV4_TTL_EXCEEDED",
};

std::ostream& operator<<(std::ostream& os, IPv4Error error)
{
    int i = (int)error;
    if (i < 0 || i > 16) return os << "IPV4_UNKNOWN_ERROR(" << i << ")";
    return os << ipv4_error_names[i];
}
