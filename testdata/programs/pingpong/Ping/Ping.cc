//
// Ping.cc
//
// Sends the ball (a counter) to Pong each time Pong asserts ready, and
// Pong asserts ready as soon as it has the ball: the two objects are
// never idle. Every 25000 exchanges Ping prints the system time, which
// goes on advancing while they play, as on the robot.
//

#include <MCOOP.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Ping.h"

Ping::Ping() : exchanges(0)
{
}

OStatus
Ping::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
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
    OSYSPRINT(("Ping : %u exchanges\n", (unsigned int)exchanges));
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

    exchanges++;
    if (exchanges % REPORT_EVERY == 0) {
        SystemTime now;
        GetSystemTime(&now);
        OSYSPRINT(("Ping : %u exchanges, %u ms\n", (unsigned int)exchanges,
                   (unsigned int)(now.seconds * 1000 + now.useconds / 1000)));
    }
    subject[sbjBall]->SetData(&exchanges, sizeof(exchanges));
    subject[sbjBall]->NotifyObservers();
}
