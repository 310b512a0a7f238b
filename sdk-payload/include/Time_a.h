/*
 * Time_a.h - relative time (seconds + milliseconds) for kernel timers.
 */
#ifndef _Time_a_h_DEFINED
#define _Time_a_h_DEFINED

#include <Types.h>
#include <SystemTime.h>

#ifdef __cplusplus

struct RelativeTime {
    longword sec;
    longword msec;

    RelativeTime() : sec(0), msec(0) {}
    RelativeTime(longword s, longword ms) : sec(s), msec(ms) {}

    bool operator==(const RelativeTime& t) const { return sec == t.sec && msec == t.msec; }
    bool operator!=(const RelativeTime& t) const { return !(*this == t); }
};

inline RelativeTime ConvertToRelativeTime(const SystemTime& t)
{
    return RelativeTime(t.seconds, t.useconds / 1000U);
}

inline SystemTime ConvertToSystemTime(const RelativeTime& t)
{
    return SystemTime(t.sec + t.msec / 1000U, (t.msec % 1000U) * 1000U);
}

#else

typedef struct RelativeTime {
    longword sec;
    longword msec;
} RelativeTime;

#endif

#endif /* _Time_a_h_DEFINED */
