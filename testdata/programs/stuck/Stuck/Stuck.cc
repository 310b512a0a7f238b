//
// Stuck.cc
//
// An object that never returns from one of its life-cycle functions: it
// spins in the one named in STUCK.TXT ("DoInit", "DoStart" or "DoStop"),
// as a program waiting for a flag nobody sets does. The system must go on
// (and report it) without it.
//

#include <stdio.h>
#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Stuck.h"

Stuck::Stuck()
{
    hangIn[0] = '\0';
}

OStatus
Stuck::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    ReadConfig();
    Spin("DoInit");
    return oSUCCESS;
}

OStatus
Stuck::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    OSYSPRINT(("Stuck : started\n"));
    Spin("DoStart");
    return oSUCCESS;
}

OStatus
Stuck::DoStop(const OSystemEvent& event)
{
    Spin("DoStop");
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Stuck::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Stuck::ReadConfig()
{
    FILE* fp = fopen(STUCK_CONFIG, "r");
    if (fp == 0) {
        OSYSLOG1((osyslogERROR, "Stuck : cannot open %s", STUCK_CONFIG));
        return;
    }
    if (fscanf(fp, "%15s", hangIn) != 1) hangIn[0] = '\0';
    fclose(fp);
}

void
Stuck::Spin(const char* where)
{
    if (strcmp(hangIn, where) != 0) return;

    OSYSPRINT(("Stuck : spinning in %s\n", where));
    volatile int waiting = 1;
    while (waiting) {
        // nobody ever clears it
    }
}
