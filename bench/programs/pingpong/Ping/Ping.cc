//
// Ping.cc
//
#include <OPENR/OSyslog.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/core_macro.h>
#include <time.h>
#include <stdlib.h>
#include <algorithm>
#include "Ping.h"

// Round trips timed after WARMUP untimed ones.
static const int WARMUP  = 1000;
static const int SAMPLES = 20000;

static long long now_ns()
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

Ping::Ping() : count(0), last(0), first(0), rtt(0)
{
}

OStatus
Ping::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    rtt = (long long*)malloc(sizeof(long long) * SAMPLES);
    return oSUCCESS;
}

OStatus
Ping::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Ping::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Ping::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Ping::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert()) return;

    long long t = now_ns();
    int n = count - WARMUP;
    if (n == 0) first = t;
    if (n > 0 && n <= SAMPLES) rtt[n - 1] = t - last;
    last = t;
    if (n == SAMPLES) {
        Report();
        OPENR::Shutdown(OBootCondition());
        return;
    }
    count++;
    subject[sbjBall]->SetData(&count, sizeof(count));
    subject[sbjBall]->NotifyObservers();
}

void
Ping::Report()
{
    std::sort(rtt, rtt + SAMPLES);
    double secs = (double)(last - first) / 1e9;
    OSYSPRINT(("BENCH pingpong round_trips=%d p50_ns=%lld p99_ns=%lld msgs_per_sec=%.0f\n",
               SAMPLES, rtt[SAMPLES / 2], rtt[SAMPLES * 99 / 100],
               2.0 * SAMPLES / secs));
}
