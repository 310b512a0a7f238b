/*
 * SystemTime.h - kernel time (seconds + microseconds since boot).
 */
#ifndef _SystemTime_h_DEFINED
#define _SystemTime_h_DEFINED

#include <Types.h>

#define SYSTEMTIME_INVALID_USECONDS 0xffffffffU

#ifdef __cplusplus

struct SystemTime {
    longword seconds;
    longword useconds;

    SystemTime() : seconds(0), useconds(0) {}
    SystemTime(longword sec, longword usec) : seconds(sec), useconds(usec) {}

    bool IsValid() const { return useconds < 1000000U; }
    void MakeInvalid() { seconds = 0; useconds = SYSTEMTIME_INVALID_USECONDS; }

    bool operator<(const SystemTime& t) const {
        return seconds < t.seconds || (seconds == t.seconds && useconds < t.useconds);
    }
    bool operator==(const SystemTime& t) const {
        return seconds == t.seconds && useconds == t.useconds;
    }
    SystemTime operator+(const SystemTime& t) const {
        SystemTime r(seconds + t.seconds, useconds + t.useconds);
        if (r.useconds >= 1000000U) { r.useconds -= 1000000U; r.seconds++; }
        return r;
    }
    SystemTime operator-(const SystemTime& t) const {
        SystemTime r(seconds - t.seconds, 0);
        if (useconds >= t.useconds) {
            r.useconds = useconds - t.useconds;
        } else {
            r.useconds = useconds + 1000000U - t.useconds;
            r.seconds--;
        }
        return r;
    }
};

#else

typedef struct SystemTime {
    longword seconds;
    longword useconds;
} SystemTime;

#endif

#endif /* _SystemTime_h_DEFINED */
