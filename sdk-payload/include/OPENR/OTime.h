/*
 * OPENR/OTime.h - robot clock value: seconds since 2000-01-01 00:00:00 UTC
 * plus the time difference to UTC in whole hours (robot-api 9.6).
 */
#ifndef _OTime_h_DEFINED
#define _OTime_h_DEFINED

#include <time.h>
#include <Types.h>
#include <OPENR/OStatus.h>

const sbyte otimeTIME_DIF_UNDEF = 0x7f;
const int   otimeSTART_YEAR     = 2000;

class OTime {
public:
    OTime() : clock_(0), timeDif_(otimeTIME_DIF_UNDEF) {}
    OTime(time_t clock, sbyte timeDif) : clock_(clock), timeDif_(timeDif) {}
    OTime(const OTime& t) : clock_(t.clock_), timeDif_(t.timeDif_) {}

    OTime& operator=(const OTime& t) {
        clock_ = t.clock_;
        timeDif_ = t.timeDif_;
        return *this;
    }

    bool operator< (const OTime& t) const { return clock_ <  t.clock_; }
    bool operator<=(const OTime& t) const { return clock_ <= t.clock_; }
    bool operator> (const OTime& t) const { return clock_ >  t.clock_; }
    bool operator>=(const OTime& t) const { return clock_ >= t.clock_; }
    bool operator==(const OTime& t) const { return clock_ == t.clock_; }

    OStatus Set(time_t clock, sbyte timeDif) {
        clock_ = clock;
        return SetTimeDif(timeDif);
    }
    OStatus SetClock(time_t clock) { clock_ = clock; return oSUCCESS; }
    OStatus SetLocalTime(time_t local) {
        clock_ = local - ValidDif() * 3600;
        return oSUCCESS;
    }
    OStatus SetTimeDif(sbyte timeDif) {
        if (timeDif != otimeTIME_DIF_UNDEF && (timeDif < -12 || timeDif > 12)) {
            return oINVALID_ARG;
        }
        timeDif_ = timeDif;
        return oSUCCESS;
    }

    time_t GetClock() const { return clock_; }
    time_t GetLocalTime() const { return clock_ + ValidDif() * 3600; }
    sbyte  GetTimeDif() const { return timeDif_; }

private:
    int ValidDif() const { return timeDif_ == otimeTIME_DIF_UNDEF ? 0 : (int)timeDif_; }

    time_t clock_;
    sbyte  timeDif_;
};

#endif /* _OTime_h_DEFINED */
