/*
 * EndpointTypes.h - protocols of ANT endpoints (antEnvCreateEndpointMsg).
 */
#ifndef _EndpointTypes_h_DEFINED
#define _EndpointTypes_h_DEFINED

#define EndpointType_TCP           1
#define EndpointType_UDP           2
#define EndpointType_TFTP          3
#define EndpointType_DNS           4
#define EndpointType_POP3          5
#define EndpointType_SMTP          6
#define EndpointType_IP            7
#define EndpointType_MIBII         8
#define EndpointType_MIB_ETHERNET  9

#endif /* _EndpointTypes_h_DEFINED */
