// OCalendarTime.cc - broken-down robot time (object-model 4.3, robot-api 9.6).
//
// The fields hold LOCAL time (clock + timeDif hours); the epoch is 2000-01-01 00:00:00
// UTC, a Saturday.  timeDif_ == otimeTIME_DIF_UNDEF counts as 0 hours.
#include <stdio.h>

#include <OPENR/OCalendarTime.h>

namespace {

const char* const kDayName[7] = { "Sun", "Mon", "Tue", "Wed", "Thu", "Fri", "Sat" };
const char* const kMonthName[12] = { "Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                     "Jul", "Aug", "Sep", "Oct", "Nov", "Dec" };
const long kDay = 86400L;

int daysInMonth(int year, int month)
{
    static const int days[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
    if (month == 2 && LeapYear(year)) return 29;
    return days[month - 1];
}

int daysInYear(int year)
{
    return LeapYear(year) ? 366 : 365;
}

int hoursOf(sbyte timeDif)
{
    return timeDif == otimeTIME_DIF_UNDEF ? 0 : (int)timeDif;
}

// Days since 2000-01-01 of the given date (year >= 2000).
long daysSinceEpoch(int year, int month, int day)
{
    long days = 0;
    for (int y = otimeSTART_YEAR; y < year; y++) days += daysInYear(y);
    for (int m = 1; m < month; m++) days += daysInMonth(year, m);
    return days + day - 1;
}

int dayOfWeek(long days)
{
    return (int)((ocldtSTART_DAY_OF_THE_WEEK + days) % 7);
}

} // namespace

OCalendarTime::OCalendarTime()
    : year_(0), month_(1), day_(1), hour_(0), min_(0), sec_(0),
      dow_(ocldtSTART_DAY_OF_THE_WEEK), timeDif_(0)
{
}

OCalendarTime::OCalendarTime(time_t clock, sbyte timeDif)
    : year_(0), month_(1), day_(1), hour_(0), min_(0), sec_(0),
      dow_(ocldtSTART_DAY_OF_THE_WEEK), timeDif_(0)
{
    SetTime(clock, timeDif);
}

OCalendarTime::OCalendarTime(const OTime& time)
    : year_(0), month_(1), day_(1), hour_(0), min_(0), sec_(0),
      dow_(ocldtSTART_DAY_OF_THE_WEEK), timeDif_(0)
{
    SetTime(time);
}

OCalendarTime::OCalendarTime(const OCalendarTime& t)
    : year_(t.year_), month_(t.month_), day_(t.day_), hour_(t.hour_), min_(t.min_),
      sec_(t.sec_), dow_(t.dow_), timeDif_(t.timeDif_)
{
}

OCalendarTime& OCalendarTime::operator=(const OCalendarTime& t)
{
    year_ = t.year_;
    month_ = t.month_;
    day_ = t.day_;
    hour_ = t.hour_;
    min_ = t.min_;
    sec_ = t.sec_;
    dow_ = t.dow_;
    timeDif_ = t.timeDif_;
    return *this;
}

static time_t clockOf(const OCalendarTime& t)
{
    time_t clock = 0;
    sbyte dif = 0;
    t.GetTime(&clock, &dif);
    return clock;
}

bool OCalendarTime::operator<(const OCalendarTime& t) const { return clockOf(*this) < clockOf(t); }
bool OCalendarTime::operator<=(const OCalendarTime& t) const { return clockOf(*this) <= clockOf(t); }
bool OCalendarTime::operator>(const OCalendarTime& t) const { return clockOf(*this) > clockOf(t); }
bool OCalendarTime::operator>=(const OCalendarTime& t) const { return clockOf(*this) >= clockOf(t); }
bool OCalendarTime::operator==(const OCalendarTime& t) const { return clockOf(*this) == clockOf(t); }

OStatus OCalendarTime::SetTime(time_t clock, sbyte timeDif)
{
    if (timeDif != otimeTIME_DIF_UNDEF && (timeDif < -12 || timeDif > 12)) return oINVALID_ARG;
    long long local = (long long)clock + hoursOf(timeDif) * 3600LL;
    if (local < 0) return oOUT_OF_RANGE;
    long days = (long)(local / kDay);
    long rest = (long)(local % kDay);
    int weekday = dayOfWeek(days);
    int year = otimeSTART_YEAR;
    while (days >= daysInYear(year)) {
        days -= daysInYear(year);
        year++;
    }
    if (year - otimeSTART_YEAR > 255) return oOUT_OF_RANGE;
    int month = 1;
    while (days >= daysInMonth(year, month)) {
        days -= daysInMonth(year, month);
        month++;
    }
    year_ = (byte)(year - otimeSTART_YEAR);
    month_ = (byte)month;
    day_ = (byte)(days + 1);
    hour_ = (byte)(rest / 3600);
    min_ = (byte)(rest / 60 % 60);
    sec_ = (byte)(rest % 60);
    dow_ = (byte)weekday;
    timeDif_ = timeDif;
    return oSUCCESS;
}

OStatus OCalendarTime::SetTime(const OTime& time)
{
    return SetTime(time.GetClock(), time.GetTimeDif());
}

OStatus OCalendarTime::GetTime(time_t* clock, sbyte* timeDif) const
{
    if (!ProperDate()) return oINVALID_ARG;
    long days = daysSinceEpoch(otimeSTART_YEAR + year_, month_, day_);
    long long local = (long long)days * kDay + hour_ * 3600L + min_ * 60L + sec_;
    if (clock != 0) *clock = (time_t)(local - hoursOf(timeDif_) * 3600LL);
    if (timeDif != 0) *timeDif = timeDif_;
    return oSUCCESS;
}

OStatus OCalendarTime::GetTime(OTime* time) const
{
    if (time == 0) return oINVALID_ARG;
    time_t clock = 0;
    sbyte dif = 0;
    OStatus st = GetTime(&clock, &dif);
    if (st != oSUCCESS) return st;
    time->Set(clock, dif);
    return oSUCCESS;
}

bool OCalendarTime::ProperDate() const
{
    if (month_ < 1 || month_ > 12) return false;
    if (day_ < 1 || day_ > daysInMonth(otimeSTART_YEAR + year_, month_)) return false;
    if (hour_ > 23 || min_ > 59 || sec_ > 59) return false;
    if (timeDif_ != otimeTIME_DIF_UNDEF && (timeDif_ < -12 || timeDif_ > 12)) return false;
    return true;
}

void OCalendarTime::CorrectDayOfTheWeek()
{
    if (month_ < 1 || month_ > 12 || day_ < 1) return;
    dow_ = (byte)dayOfWeek(daysSinceEpoch(otimeSTART_YEAR + year_, month_, day_));
}

void OCalendarTime::Print() const
{
    char buf[64];
    fputs(Sprint(buf), stdout);
}

char* OCalendarTime::Sprint(char* buf) const
{
    if (buf == 0) return 0;
    int m = (month_ >= 1 && month_ <= 12) ? month_ - 1 : 0;
    sprintf(buf, "%s %s %02d %02d:%02d:%02d %d\n", kDayName[dow_ % 7], kMonthName[m], day_,
            hour_, min_, sec_, otimeSTART_YEAR + year_);
    return buf;
}

char* OCalendarTime::RFC2822(char* buf) const
{
    if (buf == 0) return 0;
    int m = (month_ >= 1 && month_ <= 12) ? month_ - 1 : 0;
    int dif = hoursOf(timeDif_);
    sprintf(buf, "%s, %d %s %04d %02d:%02d:%02d %c%02d00", kDayName[dow_ % 7], day_,
            kMonthName[m], otimeSTART_YEAR + year_, hour_, min_, sec_, dif < 0 ? '-' : '+',
            dif < 0 ? -dif : dif);
    return buf;
}
