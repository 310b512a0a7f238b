// ERA201D1.cc - the wireless-LAN card information API (network-api 10) for a host
// robot: deterministic values derived from the robot's WLANCONF/WLANDFLT settings.
// As on the robot, the whole caller struct is overwritten, so callers need not
// initialise anything; without the runtime the card is "unsupported".
#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>
#include <ERA201D1.h>
#include "openr_net.h"

namespace {

// Own lookup (not libantMCOOP's openr_net): the archives are linked in a fixed order.
const openr_net_api* era_net()
{
    static const openr_net_api* api =
        static_cast<const openr_net_api*>(dlsym(RTLD_DEFAULT, "openr_runtime_net_v1"));
    return openr_net_accept(api);
}

bool config(const char* key, char* out, size_t cap)
{
    const openr_net_api* net = era_net();
    return net != 0 && net->config_value(key, out, cap) == 0;
}

int config_int(const char* key, int dflt)
{
    char buf[64];
    return config(key, buf, sizeof(buf)) ? atoi(buf) : dflt;
}

}  // namespace

extern "C" EtherStatus ERA201D1_GetMACAddress(EtherDriverGetMACAddressMsg* msg)
{
    const openr_net_api* net = era_net();
    if (net == 0 || msg == 0) return ETHER_UNSUPPORTED;
    unsigned int n = net->robot_number();
    // A locally administered address derived from the robot's number.
    msg->port = 0;
    msg->address = EtherMACAddress(0x02, 0x00, 0x00, 0x00, (byte)(n >> 8), (byte)(n & 0xff));
    msg->status = ETHER_OK;
    return ETHER_OK;
}

extern "C" EtherStatus ERA201D1_GetEtherStatistics(EtherDriverGetStatisticsMsg* msg)
{
    if (era_net() == 0 || msg == 0) return ETHER_UNSUPPORTED;
    msg->port = 0;
    memset(&msg->statistics, 0, sizeof(msg->statistics));
    msg->status = ETHER_OK;
    return ETHER_OK;
}

extern "C" EtherStatus ERA201D1_GetWLANSettings(EtherDriverGetWLANSettingsMsg* msg)
{
    if (era_net() == 0 || msg == 0) return ETHER_UNSUPPORTED;
    char buf[64];
    msg->port = 0;
    msg->mode = config_int("APMODE", 2) == 0 ? ETHER_WLAN_MODE_ADHOC : ETHER_WLAN_MODE_AP;
    memset(msg->essid, 0, sizeof(msg->essid));
    if (config("ESSID", buf, sizeof(buf))) strncpy(msg->essid, buf, ETHER_WLAN_ESSID_MAX);
    memset(msg->stationName, 0, sizeof(msg->stationName));
    if (config("HOSTNAME", buf, sizeof(buf))) strncpy(msg->stationName, buf, ETHER_WLAN_STATIONNAME_MAX);
    msg->channel = (uint32)config_int("CHANNEL", 3);
    msg->encryption = config_int("WEPENABLE", 0) == 1 ? ETHER_WLAN_ENCRYPTION_WEP : ETHER_WLAN_ENCRYPTION_OFF;
    msg->rate = ETHER_WLAN_RATE_11MB;
    msg->rts = 2347;
    msg->fragmentation = 2346;
    msg->sensitivity = ETHER_WLAN_DENSITY_LOW;
    msg->status = ETHER_OK;
    return ETHER_OK;
}

extern "C" EtherStatus ERA201D1_GetWLANStatistics(EtherDriverGetWLANStatisticsMsg* msg)
{
    if (era_net() == 0 || msg == 0) return ETHER_UNSUPPORTED;
    msg->port = 0;
    msg->statistics.link = 100;
    msg->statistics.signal = 100;
    msg->statistics.noise = 0;
    msg->statistics.invalidIDCount = 0;
    msg->statistics.invalidEncCount = 0;
    msg->statistics.invalidMiscCount = 0;
    msg->status = ETHER_OK;
    return ETHER_OK;
}
