//
// MotionList.cc
//
// Builds a small motion table with the STL in DoStart and prints it.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "MotionList.h"

MotionList::MotionList()
{
}

OStatus
MotionList::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    motions.push_back("sit");
    motions.push_back("stand");
    motions.push_back("walk");
    duration["sit"]   = 800;
    duration["stand"] = 1200;
    duration["walk"]  = 400;
    return oSUCCESS;
}

OStatus
MotionList::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    string line;
    int total = 0;
    for (vector<string>::iterator it = motions.begin(); it != motions.end(); ++it) {
        if (!line.empty()) line += " ";
        line += *it;
        total += duration[*it];
    }
    OSYSPRINT(("MotionList : %d motions: %s\n", (int)motions.size(), line.c_str()));
    OSYSPRINT(("MotionList : total %d ms\n", total));
    return oSUCCESS;
}

OStatus
MotionList::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    OSYSPRINT(("MotionList : stopped\n"));
    return oSUCCESS;
}

OStatus
MotionList::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
MotionList::Ready(const OReadyEvent& event)
{
}

void
MotionList::NotifyResult(const ONotifyEvent& event)
{
    observer[event.ObsIndex()]->AssertReady();
}
