/*
 * IPAddress.h - IPv4 address (network-api 8.1). The value is a host-order
 * integer whose most significant byte is the first dotted octet
 * (10.0.1.100 = 0x0A000164). All constructors are implicit on purpose.
 * Out-of-line members are implemented by the runtime library.
 */
#ifndef _IPAddress_h_DEFINED
#define _IPAddress_h_DEFINED

#include <antTypes.h>
#include <antIOStream.h>
#include <Internet.h>

typedef uint16 Port;   /* host byte order */

#define IP_PORT_ANY 0

struct IPAddress {
public:
    IPAddress() : address(0) {}
    IPAddress(uint32 a) : address(a) {}
    IPAddress(int a) : address((uint32)a) {}
    IPAddress(byte b1, byte b2, byte b3, byte b4)
        : address(((uint32)b1 << 24) | ((uint32)b2 << 16) | ((uint32)b3 << 8) | (uint32)b4) {}
    IPAddress(const char* dotted);   /* dotted decimal only; 0 when malformed */

    boolean operator==(const IPAddress& a) const { return address == a.address; }
    boolean operator!=(const IPAddress& a) const { return address != a.address; }
    boolean operator<(const IPAddress& a) const { return address < a.address; }
    boolean operator<(uint32 a) const { return address < a; }
    IPAddress operator&(const IPAddress& a) const { return IPAddress(address & a.address); }
    IPAddress operator^(const IPAddress& a) const { return IPAddress(address ^ a.address); }

    boolean InMulticast() const { return (address >> 28) == 0xe; }
    boolean InBroadcast() const { return address == 0xffffffffU; }
    boolean InLoop() const { return (address >> 24) == 127; }
    boolean AllHostsGroup() const { return address == 0xe0000001U; }

    uint32 Address() const { return address; }

    /* writes "a.b.c.d" (at most 16 bytes including the NUL), returns buf */
    char*    GetAsString(char* buf) const;
    /* prints "[a.b.c.d]" */
    OSTREAM& print(OSTREAM& os) const;

private:
    char* intToAscii(char* buf, int value, bool first = true) const;

    uint32 address;
};

inline OSTREAM& operator<<(OSTREAM& os, const IPAddress& a)
{
    return a.print(os);
}

/* Sony's library exports these two constants; the host defines them in the
   header (internal linkage) so that programs need no library symbol. */
const IPAddress IP_ADDR_ANY((uint32)0);                /* 0.0.0.0 */
const IPAddress IP_ADDR_BROADCAST((uint32)0xffffffffU); /* 255.255.255.255 */

#endif /* _IPAddress_h_DEFINED */
