/*
 * OPENR/ObserverInfo.h - obsolete header name.
 */
#ifndef _ObserverInfo_h_DEFINED
#define _ObserverInfo_h_DEFINED

#warning "OPENR/ObserverInfo.h is obsolete: include <OPENR/OObserverInfo.h> instead"
#include <OPENR/OObserverInfo.h>

#endif /* _ObserverInfo_h_DEFINED */
