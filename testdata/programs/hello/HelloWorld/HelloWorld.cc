//
// HelloWorld.cc
//
// Prints a greeting when the object is started and says good-bye when
// the robot shuts down.
//
//   OSYSPRINT(( ... ))  : always printed, exactly as formatted.
//   OSYSLOG1(( prio, ... )) : printed with an "[oid:...,prio:N]" prefix.
//   OSYSDEBUG(( ... ))  : printed only when compiled with -DOPENR_DEBUG.
//

#include <OPENR/OSyslog.h>
#include "HelloWorld.h"

HelloWorld::HelloWorld()
{
}

OStatus
HelloWorld::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("HelloWorld::DoInit()\n"));
    return oSUCCESS;
}

OStatus
HelloWorld::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("HelloWorld::DoStart()\n"));
    OSYSPRINT(("!!! Hello World !!!\n"));
    return oSUCCESS;
}

OStatus
HelloWorld::DoStop(const OSystemEvent& event)
{
    OSYSLOG1((osyslogERROR, "Bye Bye ..."));
    return oSUCCESS;
}

OStatus
HelloWorld::DoDestroy(const OSystemEvent& event)
{
    OSYSDEBUG(("HelloWorld::DoDestroy()\n"));
    return oSUCCESS;
}
