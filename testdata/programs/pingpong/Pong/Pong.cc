//
// Pong.cc
//
// Gives the ball straight back: asserting ready returns the region and
// asks Ping for the next one.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Pong.h"

OStatus
Pong::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Pong::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Pong::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Pong::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Pong::Notify(const ONotifyEvent& event)
{
    observer[event.ObsIndex()]->AssertReady();
}
