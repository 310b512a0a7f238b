/*
 * MCOOP/antEnvMsg.h - ANT messages on top of the MCOOP kernel calls
 * (network-api 1.2). Reached through -I.../OPEN_R/include/MCOOP.
 */
#ifndef _antEnvMsg_h_DEFINED
#define _antEnvMsg_h_DEFINED

#include <MCOOP.h>

/* type of the argument of an ANT continuation entry */
#ifndef ANTENVMSG
#define ANTENVMSG void*
#endif

#include <antEnvInternalMsg.h>

#endif /* _antEnvMsg_h_DEFINED */
