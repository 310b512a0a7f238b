/*
 * Internet.h - protocol numbers and port constants (network-api 8.2).
 *
 * Sony's header defined IPPROTO_* as plain macros, which collide with the
 * enumerators of glibc's <netinet/in.h> when that header comes later. The
 * host version includes <netinet/in.h> first (so both include orders
 * compile) and only adds the names glibc lacks. Values agree with Sony's,
 * except IPPROTO_MAX, which is glibc's (Sony: 256; unused by programs).
 */
#ifndef _Internet_h_DEFINED
#define _Internet_h_DEFINED

#include <Types.h>
#include <netinet/in.h>

typedef uint16 Protocol;

/* IPPROTO_IP 0, ICMP 1, IGMP 2, TCP 6, EGP 8, PUP 12, UDP 17, IDP 22, TP 29,
   ENCAP 98, RAW 255 come from <netinet/in.h> */
#ifndef IPPROTO_GGP
#define IPPROTO_GGP 3
#endif
#ifndef IPPROTO_EON
#define IPPROTO_EON 80
#endif

/* IPPORT_RESERVED (1024) and IPPORT_USERRESERVED (5000) are enumerators of
   <netinet/in.h> with Sony's values. */

#endif /* _Internet_h_DEFINED */
