/*
 * EtherTypes.h - types of the wireless-LAN / Ethernet driver API
 * (network-api 10).
 */
#ifndef _EtherTypes_h_DEFINED
#define _EtherTypes_h_DEFINED

#include <OID.h>
#include <Types.h>
#include <string.h>
#include <stdio.h>
#include <iostream>

enum EtherStatus {
    ETHER_OK               = 0,
    ETHER_UNSUPPORTED      = 1,
    ETHER_NO_MEMORY        = 2,
    ETHER_INVALID_PROTOCOL = 3,
    ETHER_INVALID_ADDRESS  = 4,
    ETHER_INVALID_PORT     = 5,
    ETHER_INVALID_ATTR     = 6,
    ETHER_NO_CLIENT_ENTRY  = 7,
    ETHER_INVALID_HANDLE   = 8,
    ETHER_RCV_IDLE         = 9,
    ETHER_RCV_BUSY         = 10,
    ETHER_NO_ADDRESS_ENTRY = 11,
    ETHER_NO_DEVICE        = 12
};

/* debug names of EtherStatus values */
inline const char* EtherStatusString(EtherStatus status)
{
    static const char* const names[] = {
        "ETHER_OK", "ETHER_UNSUPPORTED", "ETHER_NO_MEMORY",
        "ETHER_INVALID_PROTOCOL", "ETHER_INVALID_ADDRESS", "ETHER_INVALID_PORT",
        "ETHER_INVALID_ATTR", "ETHER_NO_CLIENT_ENTRY", "ETHER_INVALID_HANDLE",
        "ETHER_RCV_IDLE", "ETHER_RCV_BUSY", "ETHER_NO_ADDRESS_ENTRY", "ETHER_NO_DEVICE"
    };
    int i = (int)status;
    return (i >= 0 && i <= 12) ? names[i] : "ETHER_UNKNOWN_STATUS";
}

#define ETHER_WLAN_ESSID_MAX        32
#define ETHER_WLAN_STATIONNAME_MAX  32
#define ETHER_WLAN_ENC_MAX          5
#define ETHER_WLAN_ENC_128_MAX      13

union EtherMACAddress {
    uint8 octet[6];
    struct Opt {
        uint16 w1;
        uint16 w2;
        uint16 w3;
    } opt;

    EtherMACAddress() { opt.w1 = 0; opt.w2 = 0; opt.w3 = 0; }
    EtherMACAddress(const EtherMACAddress& a) { opt = a.opt; }
    EtherMACAddress(const byte* a) { memcpy(octet, a, 6); }
    EtherMACAddress(byte b0, byte b1, byte b2, byte b3, byte b4, byte b5) {
        octet[0] = b0; octet[1] = b1; octet[2] = b2;
        octet[3] = b3; octet[4] = b4; octet[5] = b5;
    }
    EtherMACAddress& operator=(const EtherMACAddress& a) { opt = a.opt; return *this; }

    bool operator==(const EtherMACAddress& a) const {
        return opt.w1 == a.opt.w1 && opt.w2 == a.opt.w2 && opt.w3 == a.opt.w3;
    }
    bool IsBroadcast() const {
        return opt.w1 == 0xffff && opt.w2 == 0xffff && opt.w3 == 0xffff;
    }
    bool IsMulticast() const { return (octet[0] & 0x01) != 0; }
    void ToByte(byte* dst) const { memcpy(dst, octet, 6); }
};

/* prints "aa:bb:cc:dd:ee:ff" */
inline std::ostream& operator<<(std::ostream& os, const EtherMACAddress& a)
{
    char buf[18];
    sprintf(buf, "%02x:%02x:%02x:%02x:%02x:%02x", a.octet[0], a.octet[1],
            a.octet[2], a.octet[3], a.octet[4], a.octet[5]);
    return os << buf;
}

struct EtherStatistics {
    uint32 carrierSenseErrorCount;
    uint32 lateCollisionCount;
    uint32 excessiveCollisionCount;
    uint32 singleCollisionCount;
    uint32 multipleCollisionCount;
    uint32 deferredCount;
    uint32 alignmentErrorCount;
    uint32 fcsErrorCount;
    uint32 frameTooLongCount;
};

struct EtherWLANStatistics {
    uint8  link;     /* percent of maximum */
    uint8  signal;   /* percent of maximum */
    uint8  noise;    /* percent of maximum */
    uint32 invalidIDCount;
    uint32 invalidEncCount;
    uint32 invalidMiscCount;
};

/* The robot's enumerator spellings are only partly documented; both
   plausible spellings are provided for mode and encryption. */
enum EtherWLANMode {
    ETHER_WLAN_MODE_ADHOC = 0,
    ETHER_WLAN_MODE_AP    = 1,
    ETHER_WLAN_ADHOC      = 0,
    ETHER_WLAN_AP         = 1
};

enum EtherWLANEncryption {
    ETHER_WLAN_ENCRYPTION_OFF = 0,
    ETHER_WLAN_ENCRYPTION_WEP = 1,
    ETHER_WLAN_ENC_OFF        = 0,
    ETHER_WLAN_ENC_WEP        = 1
};

enum EtherWLANRate {
    ETHER_WLAN_RATE_1MB   = 0,
    ETHER_WLAN_RATE_2MB   = 1,
    ETHER_WLAN_RATE_5_5MB = 2,
    ETHER_WLAN_RATE_11MB  = 3,
    ETHER_WLAN_RATE_AUTO  = 4
};

enum EtherWLANSensitivity {
    ETHER_WLAN_DENSITY_LOW  = 0,
    ETHER_WLAN_DENSITY_MED  = 1,
    ETHER_WLAN_DENSITY_HIGH = 2
};

#endif /* _EtherTypes_h_DEFINED */
