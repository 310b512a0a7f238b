//
// SampleObserver.cc
//
// Prints every string it receives and then asserts "ready" again, which
// both returns the shared memory of the string to the subject and
// tells the subject that we can take the next one.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SampleObserver.h"

SampleObserver::SampleObserver()
{
}

OStatus
SampleObserver::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
SampleObserver::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;   // the first ASSERT READY goes out here
    return oSUCCESS;
}

OStatus
SampleObserver::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SampleObserver::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
SampleObserver::Notify(const ONotifyEvent& event)
{
    const char* text = (const char*)event.Data(0);
    OSYSPRINT(("SampleObserver::Notify() %s\n", text));
    observer[event.ObsIndex()]->AssertReady();
}
