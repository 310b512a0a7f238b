//
// SampleObserver.cc  (shared by SampleObserver1, 2 and 3)
//
// SampleObserver3 is connected to two subjects. After a notification we
// assert ready only to the subject that sent it (event.SenderID()), so
// each subject gets exactly one ASSERT READY per string it sent.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SampleObserver.h"

SampleObserver::SampleObserver()
{
    const char* svc = observerService[obsReceiveString];
    int i;
    for (i = 0; i < (int)sizeof(myName) - 1 && svc[i] != '.' && svc[i] != '\0'; i++) {
        myName[i] = svc[i];
    }
    myName[i] = '\0';
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
    ASSERT_READY_TO_ALL_OBSERVER;   // to every connected subject
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
    for (int i = 0; i < event.NumOfData(); i++) {
        const char* text = (const char*)event.Data(i);
        OSYSPRINT(("%s::Notify() %s\n", myName, text));
    }
    observer[event.ObsIndex()]->AssertReady(event.SenderID());
}
