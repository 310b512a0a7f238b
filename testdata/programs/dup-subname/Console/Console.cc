//
// Console.cc
//
// Uses both observer indices: obsStdin (from stubgen2) and obsStdinLine (the
// name the Makefile's sed step gives the second "Stdin" service).
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Console.h"

Console::Console()
{
}

OStatus
Console::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Console::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    OSYSPRINT(("Console : obsStdin = %d (%s)\n", obsStdin, observerService[obsStdin]));
    OSYSPRINT(("Console : obsStdinLine = %d (%s)\n", obsStdinLine, observerService[obsStdinLine]));
    OSYSPRINT(("Console : %d observers, %d basic entries\n", numOfObserver, (int)numOfBasicEntries));
    return oSUCCESS;
}

OStatus
Console::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Console::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Console::NotifyChar(const ONotifyEvent& event)
{
    observer[obsStdin]->AssertReady();
}

void
Console::NotifyLine(const ONotifyEvent& event)
{
    observer[obsStdinLine]->AssertReady();
}
