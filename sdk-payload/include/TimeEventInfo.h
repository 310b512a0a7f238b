/*
 * TimeEventInfo.h - parameters of SetTimeEvent(): first expiry and period
 * (periodicTime zero = one-shot).
 */
#ifndef _TimeEventInfo_h_DEFINED
#define _TimeEventInfo_h_DEFINED

#include <Types.h>
#include <Time_a.h>

#ifdef __cplusplus

struct TimeEventInfo {
    enum EventType { Periodic, NonPeriodic };

    RelativeTime relativeTime;
    RelativeTime periodicTime;

    TimeEventInfo() : relativeTime(), periodicTime() {}
    TimeEventInfo(const RelativeTime& rel, const RelativeTime& per)
        : relativeTime(rel), periodicTime(per) {}

    EventType GetType() const {
        return (periodicTime.sec == 0 && periodicTime.msec == 0) ? NonPeriodic : Periodic;
    }
};

struct TimeEventInfoWithRelativeTime : public TimeEventInfo {
    TimeEventInfoWithRelativeTime() : TimeEventInfo() {}
    TimeEventInfoWithRelativeTime(const RelativeTime& rel, const RelativeTime& per)
        : TimeEventInfo(rel, per) {}

    void Set(const RelativeTime& rel, const RelativeTime& per) {
        relativeTime = rel;
        periodicTime = per;
    }
    void Set(const RelativeTime& rel) {
        relativeTime = rel;
        periodicTime = RelativeTime(0, 0);
    }
};

#else

typedef struct TimeEventInfo {
    RelativeTime relativeTime;
    RelativeTime periodicTime;
} TimeEventInfo;

#endif

#endif /* _TimeEventInfo_h_DEFINED */
