//
// SelfTalk.cc
//
// A subject talking to an observer of the same object (self connection),
// plus a few kernel calls and the calendar-time formats.
//

#include <string.h>
#include <OPENR/OSyslog.h>
#include <OPENR/OCalendarTime.h>
#include <OPENR/core_macro.h>
#include "SelfTalk.h"
#include "entry.h"

SelfTalk::SelfTalk() : readyCount(0)
{
}

OStatus
SelfTalk::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
SelfTalk::DoStart(const OSystemEvent& event)
{
    CheckTime();
    CheckKernel();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SelfTalk::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
SelfTalk::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
SelfTalk::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert()) return;
    OSYSPRINT(("SelfTalk : Ready ASSERT (IsReady %d)\n", subject[sbjText]->IsReady()));
    readyCount++;
    if (readyCount <= 2) {
        char text[32];
        sprintf(text, "self #%d", readyCount);
        subject[sbjText]->SetData(text, strlen(text) + 1);
        subject[sbjText]->NotifyObservers();
    }
}

void
SelfTalk::Notify(const ONotifyEvent& event)
{
    OSYSPRINT(("SelfTalk : Notify %s (NumOfData %d)\n",
               (const char*)event.Data(0), event.NumOfData()));
    observer[event.ObsIndex()]->AssertReady(event.SenderID());
}

void
SelfTalk::TimerFired(void* msg)
{
    OSYSPRINT(("SelfTalk : timer fired (%s)\n", (const char*)msg));
}

void
SelfTalk::CheckTime()
{
    char buf[64];
    OCalendarTime t0(0, 9);
    OSYSPRINT(("SelfTalk : RFC2822 %s\n", t0.RFC2822(buf)));

    OCalendarTime t1(366 * 24 * 3600, 0);   // 2000 is a leap year
    OSYSPRINT(("SelfTalk : Sprint %s", t1.Sprint(buf)));

    OCalendarTime t2(123456789, -5);
    OTime back;
    t2.GetTime(&back);
    OSYSPRINT(("SelfTalk : round trip %s\n",
               back.GetClock() == 123456789 && back.GetTimeDif() == -5 ? "ok" : "FAILED"));

    char longText[400];
    memset(longText, 'x', sizeof(longText) - 1);
    longText[sizeof(longText) - 1] = '\0';
    OSYSLOG1((osyslogERROR, "%s", longText));
}

void
SelfTalk::CheckKernel()
{
    SystemTime before, after;
    GetSystemTime(&before);
    Wait(50000000);   // 50 ms
    GetSystemTime(&after);
    SystemTime d = after - before;
    OSYSPRINT(("SelfTalk : Wait %s\n",
               d.seconds > 0 || d.useconds >= 50000 ? "ok" : "FAILED"));

    MemoryRegionID memID;
    void* base;
    sError e1 = NewSharedMemoryRegion(1000, MEMPROTINFO_RW, &memID, &base);
    if (e1 == sSUCCESS) memset(base, 0x5a, 1000);
    sError e2 = DeleteSharedMemoryRegion(memID);
    OSYSPRINT(("SelfTalk : shared memory %s\n",
               e1 == sSUCCESS && e2 == sSUCCESS ? "ok" : "FAILED"));

    static char note[] = "after 100 ms";
    TimeEventInfo info(RelativeTime(0, 100), RelativeTime(0, 0));
    EventID id;
    sError e3 = SetTimeEvent(&info, myOID_, Extra_Entry[entryTimerFired],
                             note, sizeof(note), &id);
    if (e3 != sSUCCESS) OSYSPRINT(("SelfTalk : SetTimeEvent FAILED %d\n", (int)e3));
}
