/*
 * ICMPProtocol.h - ICMP message types and header (for raw IP endpoints).
 * The type macros have the same names and values as glibc's
 * <netinet/ip_icmp.h>, so either header may come first.
 */
#ifndef _ICMPProtocol_h_DEFINED
#define _ICMPProtocol_h_DEFINED

#include <antTypes.h>

#ifndef ICMP_ECHOREPLY
#define ICMP_ECHOREPLY      0
#endif
#ifndef ICMP_UNREACH
#define ICMP_UNREACH        3
#endif
#ifndef ICMP_SOURCEQUENCH
#define ICMP_SOURCEQUENCH   4
#endif
#ifndef ICMP_REDIRECT
#define ICMP_REDIRECT       5
#endif
#ifndef ICMP_ECHO
#define ICMP_ECHO           8
#endif
#ifndef ICMP_TIMXCEED
#define ICMP_TIMXCEED       11
#endif
#ifndef ICMP_PARAMPROB
#define ICMP_PARAMPROB      12
#endif
#ifndef ICMP_TSTAMP
#define ICMP_TSTAMP         13
#endif
#ifndef ICMP_TSTAMPREPLY
#define ICMP_TSTAMPREPLY    14
#endif

struct ICMPHeader {
    byte   type;
    byte   code;
    uint16 checksum;   /* network byte order */
};

#endif /* _ICMPProtocol_h_DEFINED */
