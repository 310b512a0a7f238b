/*
 * OPENR/OObserverVector.h - legacy name of OObserver.
 */
#ifndef _OObserverVector_h_DEFINED
#define _OObserverVector_h_DEFINED

#include <OPENR/OObserver.h>

typedef OObserver OObserverVector;

#endif /* _OObserverVector_h_DEFINED */
