/*
 * MCOOP/ant.h - umbrella header of the OPEN-R networking toolkit (ANT).
 */
#ifndef _ant_h_DEFINED
#define _ant_h_DEFINED

#include <antTypes.h>
#include <MCOOP/antEnvMsg.h>
#include <antSharedBuffer.h>
#include <antModuleRef.h>

#endif /* _ant_h_DEFINED */
