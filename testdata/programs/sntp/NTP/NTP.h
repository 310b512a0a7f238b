//
// NTP.h
//

#ifndef NTP_h_DEFINED
#define NTP_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <ant.h>
#include <EndpointTypes.h>
#include <UDPEndpointMsg.h>
#include <DNSEndpointMsg.h>
#include "def.h"

const int         NTP_BUFFER_SIZE = 128;
const int         NTP_PACKET_SIZE = 48;
const Port        NTP_PORT        = 123;
const char* const NTP_CONF_FILE   = "/MS/OPEN-R/MW/CONF/NTP.CFG";
/* seconds from 1900-01-01 (NTP) to 2000-01-01 (OPEN-R clock) */
const longword    NTP_TO_2000     = 3155673600U;

class NTP : public OObject {
public:
    NTP() : sendData(0), recvData(0) {}
    virtual ~NTP() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

    void GetHostByNameCont(ANTENVMSG msg);
    void SendCont(ANTENVMSG msg);
    void ReceiveCont(ANTENVMSG msg);

private:
    byte* NewBuffer(antSharedBuffer& buffer);

    antStackRef     ipstackRef;
    antModuleRef    dnsEndpoint;
    antModuleRef    udpEndpoint;
    antSharedBuffer sendBuffer;
    byte*           sendData;
    antSharedBuffer recvBuffer;
    byte*           recvData;
    IPAddress       server;
};

#endif // NTP_h_DEFINED
