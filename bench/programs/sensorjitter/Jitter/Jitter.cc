//
// Jitter.cc
//
#include <OPENR/OSyslog.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/core_macro.h>
#include <time.h>
#include <algorithm>
#include "Jitter.h"

static const int SAMPLES = 1000;   // 32 s of sensor vectors

static long long now_ns()
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000000000LL + ts.tv_nsec;
}

OStatus Jitter::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus Jitter::DoStart(const OSystemEvent& event)
{
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

void Jitter::Notify(const ONotifyEvent& event)
{
    long long t = now_ns();
    if (last != 0 && count < SAMPLES) {
        long long d = (t - last) - 32000000LL;
        dev[count++] = d < 0 ? -d : d;
        if (count == SAMPLES) {
            std::sort(dev, dev + SAMPLES);
            OSYSPRINT(("BENCH jitter samples=%d p50_ns=%lld p99_ns=%lld max_ns=%lld\n",
                       SAMPLES, dev[SAMPLES / 2], dev[SAMPLES * 99 / 100], dev[SAMPLES - 1]));
            OPENR::Shutdown(OBootCondition());
        }
    }
    last = t;
    observer[event.ObsIndex()]->AssertReady();
}
