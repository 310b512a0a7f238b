//
// SampleObserver.cc
//
// Keeps the length of every string it receives in a vector and prints the
// one it was told to look at -- with vector::at, which throws
// std::out_of_range for the second string (nobody catches it: the object
// dies in Notify, and the runtime says so).
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
    lengths.push_back((int)strlen(text));
    size_t look = lengths.size() == 1 ? 0 : 5;   // a bad index on the second string
    OSYSPRINT(("SampleObserver::Notify() %s (length %d)\n", text, lengths.at(look)));
    observer[event.ObsIndex()]->AssertReady();
}
