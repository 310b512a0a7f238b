//
// SampleSubject.cc
//
// The observer asserts "ready" when it can accept data. We count
// those ASSERT READY events and send one string on the first and one
// on the second; after that we only print the event.
//

#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SampleSubject.h"

SampleSubject::SampleSubject() : readyCount(0)
{
}

OStatus
SampleSubject::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
SampleSubject::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SampleSubject::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SampleSubject::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
SampleSubject::Ready(const OReadyEvent& event)
{
    if (event.IsAssert()) {
        OSYSPRINT(("SampleSubject::Ready() : ASSERT READY\n"));
        readyCount++;
        if (readyCount == 1) {
            SendString("!!! Hello world !!!");
        } else if (readyCount == 2) {
            SendString("!!! Hello world again !!!");
        }
    } else if (event.IsDeassert()) {
        OSYSPRINT(("SampleSubject::Ready() : DEASSERT READY\n"));
    }
}

void
SampleSubject::SendString(const char* str)
{
    //
    // SetData(buf, size) copies the bytes into a new shared memory
    // region, so the string (including its '\0') may live on the stack.
    //
    subject[sbjSendString]->SetData(str, strlen(str) + 1);
    subject[sbjSendString]->NotifyObservers();
}
