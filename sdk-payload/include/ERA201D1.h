/*
 * ERA201D1.h - information about the ERA-201D1 wireless-LAN card
 * (network-api 10). Each call fills the whole message and returns its
 * status (ETHER_UNSUPPORTED when there is no wireless driver).
 * Implemented by the runtime library (-lERA201D1).
 */
#ifndef _ERA201D1_h_DEFINED
#define _ERA201D1_h_DEFINED

#include <EtherDriverMsg.h>
#include <WLANDriverMsg.h>

extern "C" {
EtherStatus ERA201D1_GetMACAddress(EtherDriverGetMACAddressMsg* msg);
EtherStatus ERA201D1_GetEtherStatistics(EtherDriverGetStatisticsMsg* msg);
EtherStatus ERA201D1_GetWLANSettings(EtherDriverGetWLANSettingsMsg* msg);
EtherStatus ERA201D1_GetWLANStatistics(EtherDriverGetWLANStatisticsMsg* msg);
}

#endif /* _ERA201D1_h_DEFINED */
