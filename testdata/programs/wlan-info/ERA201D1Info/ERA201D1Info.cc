//
// ERA201D1Info.cc
//
// Prints what the wireless-LAN card reports: MAC address, Ethernet and
// WLAN statistics, WLAN settings, and the robot's IP address from the
// IPStack's registry.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "ERA201D1Info.h"

OStatus
ERA201D1Info::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
ERA201D1Info::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    PrintMACAddress();
    PrintEtherStatistics();
    PrintWLANSettings();
    PrintWLANStatistics();
    PrintEtherIP();
    return oSUCCESS;
}

OStatus
ERA201D1Info::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
ERA201D1Info::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
ERA201D1Info::PrintMACAddress()
{
    EtherDriverGetMACAddressMsg msg;
    if (ERA201D1_GetMACAddress(&msg) != ETHER_OK) return;
    OSYSPRINT(("[MAC Address] %02x:%02x:%02x:%02x:%02x:%02x\n",
               msg.address.octet[0], msg.address.octet[1], msg.address.octet[2],
               msg.address.octet[3], msg.address.octet[4], msg.address.octet[5]));
}

void
ERA201D1Info::PrintEtherStatistics()
{
    EtherDriverGetStatisticsMsg msg;
    if (ERA201D1_GetEtherStatistics(&msg) != ETHER_OK) return;
    OSYSPRINT(("[Ether Statistics]\n"));
    OSYSPRINT(("  carrierSenseErrorCount  : %u\n", msg.statistics.carrierSenseErrorCount));
    OSYSPRINT(("  lateCollisionCount      : %u\n", msg.statistics.lateCollisionCount));
    OSYSPRINT(("  excessiveCollisionCount : %u\n", msg.statistics.excessiveCollisionCount));
    OSYSPRINT(("  singleCollisionCount    : %u\n", msg.statistics.singleCollisionCount));
    OSYSPRINT(("  multipleCollisionCount  : %u\n", msg.statistics.multipleCollisionCount));
    OSYSPRINT(("  deferredCount           : %u\n", msg.statistics.deferredCount));
    OSYSPRINT(("  alignmentErrorCount     : %u\n", msg.statistics.alignmentErrorCount));
    OSYSPRINT(("  fcsErrorCount           : %u\n", msg.statistics.fcsErrorCount));
    OSYSPRINT(("  frameTooLongCount       : %u\n", msg.statistics.frameTooLongCount));
}

static const char*
RateString(EtherWLANRate rate)
{
    switch (rate) {
    case ETHER_WLAN_RATE_1MB:   return "1MB";
    case ETHER_WLAN_RATE_2MB:   return "2MB";
    case ETHER_WLAN_RATE_5_5MB: return "5_5MB";
    case ETHER_WLAN_RATE_11MB:  return "11MB";
    default:                    return "invalid value";
    }
}

void
ERA201D1Info::PrintWLANSettings()
{
    EtherDriverGetWLANSettingsMsg msg;
    if (ERA201D1_GetWLANSettings(&msg) != ETHER_OK) return;
    OSYSPRINT(("[WLAN Settings]\n"));
    OSYSPRINT(("  port          : %u\n", msg.port));
    OSYSPRINT(("  mode          : %s\n", msg.mode == ETHER_WLAN_MODE_AP ? "AP" :
               msg.mode == ETHER_WLAN_MODE_ADHOC ? "ADHOC" : "invalid value"));
    OSYSPRINT(("  essid         : %s\n", msg.essid));
    OSYSPRINT(("  stationName   : %s\n", msg.stationName));
    OSYSPRINT(("  channel       : %u\n", msg.channel));
    OSYSPRINT(("  encryption    : %s\n", msg.encryption == ETHER_WLAN_ENCRYPTION_WEP ? "WEP" : "OFF"));
    OSYSPRINT(("  rate          : %s\n", RateString(msg.rate)));
    OSYSPRINT(("  rts           : %u\n", msg.rts));
    OSYSPRINT(("  fragmentation : %u\n", msg.fragmentation));
    OSYSPRINT(("  sensitivity   : %s\n", msg.sensitivity == ETHER_WLAN_DENSITY_LOW ? "LOW" :
               msg.sensitivity == ETHER_WLAN_DENSITY_MED ? "MED" : "HIGH"));
}

void
ERA201D1Info::PrintWLANStatistics()
{
    EtherDriverGetWLANStatisticsMsg msg;
    if (ERA201D1_GetWLANStatistics(&msg) != ETHER_OK) return;
    OSYSPRINT(("[WLAN Statistics]\n"));
    OSYSPRINT(("  link             : %u\n", msg.statistics.link));
    OSYSPRINT(("  signal           : %u\n", msg.statistics.signal));
    OSYSPRINT(("  noise            : %u\n", msg.statistics.noise));
    OSYSPRINT(("  invalidIDCount   : %u\n", msg.statistics.invalidIDCount));
    OSYSPRINT(("  invalidEncCount  : %u\n", msg.statistics.invalidEncCount));
    OSYSPRINT(("  invalidMiscCount : %u\n", msg.statistics.invalidMiscCount));
}

void
ERA201D1Info::PrintEtherIP()
{
    antStackRef ipstackRef("IPStack");
    antEnvInitGetParamMsg getParamMsg("ETHER_IP");
    getParamMsg.Call(ipstackRef, sizeof(getParamMsg));
    if (getParamMsg.error == ANT_SUCCESS && getParamMsg.paramType == antEnv_InitParam_String) {
        OSYSPRINT(("[ETHER_IP] %s\n", getParamMsg.value.str));
    }
}
