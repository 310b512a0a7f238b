/*
 * WLANDriverMsg.h - wireless-LAN messages of the Ethernet driver
 * (network-api 10).
 */
#ifndef _WLANDriverMsg_h_DEFINED
#define _WLANDriverMsg_h_DEFINED

#include <Types.h>
#include <EtherTypes.h>

struct EtherDriverGetWLANSettingsMsg {
    uint32               port;
    EtherWLANMode        mode;
    char                 essid[ETHER_WLAN_ESSID_MAX + 1];
    char                 stationName[ETHER_WLAN_STATIONNAME_MAX + 1];
    uint32               channel;
    EtherWLANEncryption  encryption;
    EtherWLANRate        rate;
    uint32               rts;
    uint32               fragmentation;
    EtherWLANSensitivity sensitivity;
    EtherStatus          status;
};

struct EtherDriverGetWLANStatisticsMsg {
    uint32              port;
    EtherWLANStatistics statistics;
    EtherStatus         status;
};

/* setters (no ERA201D1_* wrapper exists; unused by samples) */
struct EtherDriverSetWLANModeMsg {
    uint32 port; EtherWLANMode mode; EtherStatus status;
};
struct EtherDriverSetWLANESSIDMsg {
    uint32 port; char essid[ETHER_WLAN_ESSID_MAX + 1]; EtherStatus status;
};
struct EtherDriverSetWLANStationNameMsg {
    uint32 port; char stationName[ETHER_WLAN_STATIONNAME_MAX + 1]; EtherStatus status;
};
struct EtherDriverSetWLANChannelMsg {
    uint32 port; uint32 channel; EtherStatus status;
};
struct EtherDriverSetWLANEncryptionMsg {
    uint32 port; EtherWLANEncryption encryption; uint32 keyIndex;
    char key[ETHER_WLAN_ENC_MAX]; EtherStatus status;
};
struct EtherDriverSetWLANEncryption128Msg {
    uint32 port; EtherWLANEncryption encryption; uint32 keyIndex;
    char key[ETHER_WLAN_ENC_128_MAX]; EtherStatus status;
};
struct EtherDriverSetWLANRateMsg {
    uint32 port; EtherWLANRate rate; EtherStatus status;
};
struct EtherDriverSetWLANMediumReservationMsg {
    uint32 port; uint32 rts; EtherStatus status;
};
struct EtherDriverSetWLANFragmentationMsg {
    uint32 port; uint32 fragmentation; EtherStatus status;
};
struct EtherDriverSetWLANSensitivityMsg {
    uint32 port; EtherWLANSensitivity sensitivity; EtherStatus status;
};

#endif /* _WLANDriverMsg_h_DEFINED */
