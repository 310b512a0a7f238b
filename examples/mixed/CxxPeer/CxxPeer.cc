//
// CxxPeer.cc - sends three strings to whoever observes CxxPeer.SendString (the Rust
// object), one per ASSERT READY, and prints what arrives at CxxPeer.ReceiveString.
//

#include <stdio.h>
#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "CxxPeer.h"

CxxPeer::CxxPeer() : sent(0)
{
}

OStatus
CxxPeer::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
CxxPeer::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
CxxPeer::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
CxxPeer::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
CxxPeer::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert() || sent >= 3) return;
    sent++;
    char text[64];
    snprintf(text, sizeof(text), "hello %d from C++", sent);
    subject[sbjSendString]->SetData(text, strlen(text) + 1);
    subject[sbjSendString]->NotifyObservers();
}

void
CxxPeer::Notify(const ONotifyEvent& event)
{
    const char* text = (const char*)event.Data(0);
    OSYSPRINT(("CxxPeer::Notify() %s\n", text));
    observer[event.ObsIndex()]->AssertReady();
}
