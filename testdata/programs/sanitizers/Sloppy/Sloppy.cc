//
// Sloppy.cc
//
// Two bugs of the kind that "worked on the PC": DoInit adds one to a sensor
// count that is already INT_MAX (signed overflow: undefined behaviour), and
// DoStart writes the terminating NUL of an 8-character name one byte past
// the 8 bytes it allocated. Without a sanitizer both pass unnoticed; built
// with `cargo openr build --sanitize undefined` or `--sanitize address`,
// `cargo openr run` reports each at its line.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Sloppy.h"

static volatile int sensorCount = 2147483647;   // INT_MAX, as read from a bad config

OStatus
Sloppy::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    int next = sensorCount;
    next = next + 1;                              // the signed overflow
    OSYSPRINT(("Sloppy : next sensor %d\n", next));
    return oSUCCESS;
}

OStatus
Sloppy::DoStart(const OSystemEvent& event)
{
    char* name = (char*)malloc(8);
    strcpy(name, "ERS-7M3");                      // 7 characters and the NUL: fits
    name[8] = '\0';                               // one past the end: the overrun
    OSYSPRINT(("Sloppy : robot %s\n", name));
    free(name);
    return oSUCCESS;
}

OStatus
Sloppy::DoStop(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus
Sloppy::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
