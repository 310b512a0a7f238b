/*
 * OPENR/OCalendarTime.h - broken-down robot time (robot-api 9.6,
 * object-model 4.3). Conversions are implemented by the runtime library.
 */
#ifndef _OCalendarTime_h_DEFINED
#define _OCalendarTime_h_DEFINED

#include <OPENR/OStatus.h>
#include <OPENR/OTime.h>

const byte ocldtdowSUNDAY    = 0;
const byte ocldtdowMONDAY    = 1;
const byte ocldtdowTUESDAY   = 2;
const byte ocldtdowWEDNESDAY = 3;
const byte ocldtdowTHURSDAY  = 4;
const byte ocldtdowFRIDAY    = 5;
const byte ocldtdowSATURDAY  = 6;
const byte ocldtSTART_DAY_OF_THE_WEEK = ocldtdowSATURDAY;   /* 2000-01-01 */

inline bool LeapYear(int year)
{
    return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

class OCalendarTime {
public:
    OCalendarTime();
    OCalendarTime(time_t clock, sbyte timeDif);
    OCalendarTime(const OTime& time);
    OCalendarTime(const OCalendarTime& t);
    OCalendarTime& operator=(const OCalendarTime& t);

    bool operator< (const OCalendarTime& t) const;
    bool operator<=(const OCalendarTime& t) const;
    bool operator> (const OCalendarTime& t) const;
    bool operator>=(const OCalendarTime& t) const;
    bool operator==(const OCalendarTime& t) const;

    OStatus SetTime(time_t clock, sbyte timeDif);
    OStatus SetTime(const OTime& time);
    OStatus GetTime(time_t* clock, sbyte* timeDif) const;
    OStatus GetTime(OTime* time) const;

    bool  ProperDate() const;
    void  CorrectDayOfTheWeek();
    void  Print() const;
    char* Sprint(char* buf) const;     /* "Sat Jan 01 00:00:00 2000\n" */
    char* RFC2822(char* buf) const;    /* "Sat, 1 Jan 2000 00:00:00 +0900" */

    byte  year_;     /* years since 2000 */
    byte  month_;    /* 1..12 */
    byte  day_;      /* 1..31 */
    byte  hour_;
    byte  min_;
    byte  sec_;
    byte  dow_;      /* 0 = Sunday */
    sbyte timeDif_;  /* hours from UTC */
};

#endif /* _OCalendarTime_h_DEFINED */
