//
// NTP.cc
//
// Sets the robot's clock from an (S)NTP server: the server's name is the
// first line of NTP.CFG; one 48-byte client request goes to UDP port 123,
// the transmit time of the answer becomes the robot's time.
//

#include <stdio.h>
#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OCalendarTime.h>
#include <OPENR/core_macro.h>
#include "NTP.h"
#include "entry.h"

OStatus
NTP::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

byte*
NTP::NewBuffer(antSharedBuffer& buffer)
{
    antEnvCreateSharedBufferMsg bufferMsg(NTP_BUFFER_SIZE);
    bufferMsg.Call(ipstackRef, sizeof(bufferMsg));
    if (bufferMsg.error != ANT_SUCCESS) return 0;
    buffer = bufferMsg.buffer;
    buffer.Map();
    return (byte*)buffer.GetAddress();
}

OStatus
NTP::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    ipstackRef = antStackRef("IPStack");
    sendData = NewBuffer(sendBuffer);
    recvData = NewBuffer(recvBuffer);
    if (sendData == 0 || recvData == 0) return oFAIL;

    char name[MAXDNAME];
    FILE* fp = fopen(NTP_CONF_FILE, "r");
    if (fp == 0) {
        OSYSPRINT(("NTP : can't open %s\n", NTP_CONF_FILE));
        return oFAIL;
    }
    if (fgets(name, sizeof(name) - 1, fp) == 0) name[0] = '\0';
    fclose(fp);
    name[strcspn(name, "\r\n")] = '\0';
    if (name[0] != '\0' && name[strlen(name) - 1] != '.') strcat(name, ".");

    antEnvCreateEndpointMsg dnsCreateMsg(EndpointType_DNS, 16 * 1024);
    dnsCreateMsg.Call(ipstackRef, sizeof(dnsCreateMsg));
    if (dnsCreateMsg.error != ANT_SUCCESS) return oFAIL;
    dnsEndpoint = dnsCreateMsg.moduleRef;

    OSYSPRINT(("NTP : looking up %s\n", name));
    DNSEndpointGetHostByNameMsg byNameMsg(dnsEndpoint, name);
    byNameMsg.continuation = (void*)0;
    byNameMsg.Send(ipstackRef, myOID_, Extra_Entry[entryGetHostByNameCont], sizeof(byNameMsg));
    return oSUCCESS;
}

OStatus
NTP::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
NTP::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
NTP::GetHostByNameCont(ANTENVMSG msg)
{
    DNSEndpointGetHostByNameMsg* byNameMsg = (DNSEndpointGetHostByNameMsg*)antEnvMsg::Receive(msg);
    int len = strlen(byNameMsg->name);
    if (len > 0 && byNameMsg->name[len - 1] == '.') byNameMsg->name[len - 1] = '\0';

    if (byNameMsg->error == DNS_SUCCESS && byNameMsg->n_address > 0) {
        server = byNameMsg->host_address;
    } else {
        server = IPAddress(byNameMsg->name);   // maybe a dotted literal
        if (server == IP_ADDR_ANY) {
            OSYSPRINT(("NTP : %s Non-existent host\n", byNameMsg->name));
            return;
        }
    }

    antEnvCreateEndpointMsg udpCreateMsg(EndpointType_UDP, 256);
    udpCreateMsg.Call(ipstackRef, sizeof(udpCreateMsg));
    if (udpCreateMsg.error != ANT_SUCCESS) return;
    udpEndpoint = udpCreateMsg.moduleRef;

    UDPEndpointBindMsg bindMsg(udpEndpoint, IP_ADDR_ANY, IP_PORT_ANY);
    bindMsg.Call(ipstackRef, sizeof(antEnvCreateEndpointMsg));   // sic: the size is not used
    if (bindMsg.error != UDP_SUCCESS) {
        OSYSPRINT(("NTP : bind error %d\n", bindMsg.error));
        return;
    }

    memset(sendData, 0, NTP_PACKET_SIZE);
    sendData[0] = 0x0b;   // LI 0, version 1, mode 3 (client)
    char addr[16];
    OSYSPRINT(("NTP : asking %s\n", server.GetAsString(addr)));
    UDPEndpointSendMsg sendMsg(udpEndpoint, server, NTP_PORT, sendData, NTP_PACKET_SIZE);
    sendMsg.continuation = (void*)0;
    sendMsg.Send(ipstackRef, myOID_, Extra_Entry[entrySendCont], sizeof(sendMsg));
}

void
NTP::SendCont(ANTENVMSG msg)
{
    UDPEndpointSendMsg* sendMsg = (UDPEndpointSendMsg*)antEnvMsg::Receive(msg);
    if (sendMsg->error != UDP_SUCCESS) {
        OSYSPRINT(("NTP : send error %d\n", sendMsg->error));
        return;
    }
    UDPEndpointReceiveMsg receiveMsg(udpEndpoint, recvData, NTP_PACKET_SIZE);
    receiveMsg.continuation = (void*)0;
    receiveMsg.Send(ipstackRef, myOID_, Extra_Entry[entryReceiveCont], sizeof(receiveMsg));
}

void
NTP::ReceiveCont(ANTENVMSG msg)
{
    UDPEndpointReceiveMsg* receiveMsg = (UDPEndpointReceiveMsg*)antEnvMsg::Receive(msg);
    if (receiveMsg->error != UDP_SUCCESS || receiveMsg->size < NTP_PACKET_SIZE) {
        OSYSPRINT(("NTP : receive error %d (%d bytes)\n", receiveMsg->error, receiveMsg->size));
        return;
    }
    // transmit timestamp, seconds: bytes 40..43, big-endian
    longword* data = (longword*)recvData;
    byte* t = (byte*)&data[10];
    longword seconds = ((longword)t[0] << 24) | ((longword)t[1] << 16) |
                       ((longword)t[2] << 8) | (longword)t[3];

    sbyte timeDif = 0;
    OPENR::GetTimeDifference(&timeDif);
    OTime time((time_t)(seconds - NTP_TO_2000), timeDif);
    OPENR::SetTime(time);

    OTime now;
    OPENR::GetTime(&now);
    OCalendarTime calendar(now);
    char text[64];
    OSYSPRINT(("NTP : clock set to %s\n", calendar.RFC2822(text)));
}
