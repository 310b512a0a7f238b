//
// Counter.cc
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Counter.h"

Counter::Counter() : count(0)
{
}

OStatus
Counter::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Counter::DoStart(const OSystemEvent& event)
{
    for (int i = 0; i < 3; i++) {
        count += missing_helper(i);
    }
    OSYSPRINT(("Counter : count = %d\n", count));

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Counter::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Counter::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
