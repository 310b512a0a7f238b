//
// Probe.cc
//
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include <time.h>
#include "Probe.h"

OStatus Probe::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus Probe::DoStart(const OSystemEvent& event)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    OSYSPRINT(("BENCH coldstart start_ns=%lld\n", (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec));
    return oSUCCESS;
}
