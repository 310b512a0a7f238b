//
// HelloWorld.cc  (stubgen version)
//
// Same greeting as the hand-written version; the difference is that
// DoInit/DoStart/DoStop/DoDestroy use the standard macros of
// core_macro.h to manage the (dummy) subject and observer.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "HelloWorld.h"

HelloWorld::HelloWorld()
{
}

OStatus
HelloWorld::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("HelloWorld::DoInit()\n"));

    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    return oSUCCESS;
}

OStatus
HelloWorld::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("HelloWorld::DoStart()\n"));
    OSYSPRINT(("!!! Hello World !!!\n"));

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
HelloWorld::DoStop(const OSystemEvent& event)
{
    OSYSLOG1((osyslogERROR, "Bye Bye ..."));

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
HelloWorld::DoDestroy(const OSystemEvent& event)
{
    OSYSDEBUG(("HelloWorld::DoDestroy()\n"));

    DELETE_ALL_SUBJECT_AND_OBSERVER;

    return oSUCCESS;
}
