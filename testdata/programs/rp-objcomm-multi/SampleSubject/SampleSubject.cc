//
// SampleSubject.cc  (shared by SampleSubject1 and SampleSubject2)
//
// With several observers, one Ready event arrives per observer. We wait
// until every connected observer has asserted ready (IsAllReady) and then
// send one string to all of them at once.
//

#include <string.h>
#include <stdio.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "SampleSubject.h"

SampleSubject::SampleSubject() : numSent(0)
{
    //
    // Take our name from the first part of the service name, e.g.
    // "SampleSubject2.SendString.char.S" -> "SampleSubject2".
    //
    const char* svc = subjectService[sbjSendString];
    int i;
    for (i = 0; i < SAMPLE_NAME_MAX - 1 && svc[i] != '.' && svc[i] != '\0'; i++) {
        myName[i] = svc[i];
    }
    myName[i] = '\0';
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
    if (!event.IsAssert()) return;
    if (numSent >= SAMPLE_NUM_MESSAGES) return;

    // IsAllReady() is 0 while one of the observers has not asserted yet.
    if (subject[sbjSendString]->IsAllReady() == 0) return;

    numSent++;

    char str[64];
    sprintf(str, "!!! Hello from %s (#%d) !!!", myName, numSent);

    OSYSPRINT(("%s : send #%d to %d observer(s)\n",
               myName, numSent, subject[sbjSendString]->NumberOfObservers()));

    subject[sbjSendString]->SetData(str, strlen(str) + 1);
    subject[sbjSendString]->NotifyObservers();
}
