/*
 * HWAddress.h - 48-bit hardware (MAC) address. Header-only.
 */
#ifndef _HWAddress_h_DEFINED
#define _HWAddress_h_DEFINED

#include <string.h>
#include <stdio.h>
#include <antTypes.h>
#include <antIOStream.h>

struct HWAddress {
    byte address[6];

    HWAddress() { memset(address, 0, sizeof(address)); }
    HWAddress(const byte* a) { memcpy(address, a, sizeof(address)); }
    HWAddress(byte b0, byte b1, byte b2, byte b3, byte b4, byte b5) {
        address[0] = b0; address[1] = b1; address[2] = b2;
        address[3] = b3; address[4] = b4; address[5] = b5;
    }

    bool operator==(const HWAddress& h) const {
        return memcmp(address, h.address, sizeof(address)) == 0;
    }
    bool operator!=(const HWAddress& h) const { return !(*this == h); }

    bool IsBroadcast() const {
        for (int i = 0; i < 6; i++) if (address[i] != 0xff) return false;
        return true;
    }
    bool IsMulticast() const { return (address[0] & 0x01) != 0; }

    /* "aa:bb:cc:dd:ee:ff" (18 bytes with the NUL) */
    char* GetAsString(char* buf) const {
        sprintf(buf, "%02x:%02x:%02x:%02x:%02x:%02x", address[0], address[1],
                address[2], address[3], address[4], address[5]);
        return buf;
    }
};

inline OSTREAM& operator<<(OSTREAM& os, const HWAddress& h)
{
    char buf[18];
    return os << h.GetAsString(buf);
}

#endif /* _HWAddress_h_DEFINED */
