//
// DNSLookUp.cc
//
// An interactive resolver on the console: shows the default server, then
// reads host names with gets() and prints their address. "shutdown" ends
// the robot. Lookups use Send() and a continuation; the prompt blocks
// inside the continuation, which only blocks this object.
//

#include <stdio.h>
#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/core_macro.h>
#include "DNSLookUp.h"
#include "entry.h"

extern "C" char* gets(char*);

OStatus
DNSLookUp::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
DNSLookUp::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    ipstackRef = antStackRef("IPStack");
    antEnvCreateEndpointMsg dnsCreateMsg(EndpointType_DNS, 16 * 1024);
    dnsCreateMsg.Call(ipstackRef, sizeof(dnsCreateMsg));
    if (dnsCreateMsg.error != ANT_SUCCESS) {
        OSYSPRINT(("DNSLookUp : can't create an endpoint (%d)\n", dnsCreateMsg.error));
        return oFAIL;
    }
    endpoint = dnsCreateMsg.moduleRef;

    DNSEndpointGetServerAddressesMsg serversMsg(endpoint);
    serversMsg.Call(ipstackRef, sizeof(serversMsg));
    if (serversMsg.error != DNS_SUCCESS) {
        OSYSPRINT(("DNSLookUp : no server list (%d)\n", serversMsg.error));
        return oFAIL;
    }

    DNSEndpointGetHostByAddrMsg byAddrMsg(endpoint, serversMsg.addrList[0]);
    byAddrMsg.Send(ipstackRef, myOID_, Extra_Entry[entryGetDefaultServerByAddrCont],
                   sizeof(byAddrMsg));
    return oSUCCESS;
}

OStatus
DNSLookUp::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
DNSLookUp::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
DNSLookUp::GetDefaultServerByAddrCont(ANTENVMSG msg)
{
    DNSEndpointGetHostByAddrMsg* byAddrMsg =
        (DNSEndpointGetHostByAddrMsg*)antEnvMsg::Receive(msg);
    char addr[16];
    if (byAddrMsg->n_address > 0) {
        OSYSPRINT(("Default Server : %s\n", byAddrMsg->name));
        OSYSPRINT(("Address        : %s\n", byAddrMsg->host_address.GetAsString(addr)));
    } else {
        OSYSPRINT(("%s Non-existent host/domain\n", byAddrMsg->host_address.GetAsString(addr)));
    }

    DNSEndpointGetDefaultDomainNameMsg domainMsg(endpoint);
    domainMsg.Call(ipstackRef, sizeof(domainMsg));
    if (domainMsg.error == DNS_SUCCESS) {
        OSYSPRINT(("Default domain : %s\n", domainMsg.name));
    }
    Prompt();
}

void
DNSLookUp::Prompt()
{
    char line[MAXDNAME];
    for (;;) {
        OSYSPRINT(("DNSLookUp> "));
        fflush(stdout);
        if (gets(line) == 0) {
            OSYSPRINT(("\nDNSLookUp : end of input\n"));
            return;
        }
        if (line[0] == '\0') continue;
        if (strcmp(line, "shutdown") == 0) {
            OSYSPRINT(("SHUTDOWN ...\n"));
            OBootCondition bootCond(obcbPAUSE_SW);
            OPENR::Shutdown(bootCond);
            return;
        }
        break;
    }
    // a name with an inner dot is fully qualified
    char* dot = strrchr(line, '.');
    if (dot != 0 && dot[1] != '\0' && strlen(line) < MAXDNAME - 1) strcat(line, ".");

    DNSEndpointGetHostByNameMsg byNameMsg(endpoint, line);
    byNameMsg.Send(ipstackRef, myOID_, Extra_Entry[entryGetHostByNameCont], sizeof(byNameMsg));
}

void
DNSLookUp::GetHostByNameCont(ANTENVMSG msg)
{
    DNSEndpointGetHostByNameMsg* byNameMsg =
        (DNSEndpointGetHostByNameMsg*)antEnvMsg::Receive(msg);
    char addr[16];
    if (byNameMsg->n_address > 0) {
        OSYSPRINT(("Name    : %s\n", byNameMsg->name));
        OSYSPRINT(("Address : %s\n", byNameMsg->host_address.GetAsString(addr)));
    } else {
        OSYSPRINT(("%s Non-existent host/domain\n", byNameMsg->name));
    }
    Prompt();
}
