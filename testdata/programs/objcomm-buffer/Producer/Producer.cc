//
// Producer.cc -- fills a 10-entry subject queue faster than its observer drains it.
//
#include <OPENR/OSyslog.h>
#include <OPENR/RCRegion.h>
#include <OPENR/core_macro.h>
#include "Producer.h"

Producer::Producer()
{
    for (int i = 0; i < NUM_UNITS; i++) region[i] = 0;
}

OStatus
Producer::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    // Only allowed before the first connection: 10 entries = 5 one-region units.
    subject[sbjCount]->SetBufferSize(10);
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Producer::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    for (int i = 0; i < NUM_UNITS; i++) {
        region[i] = new RCRegion(sizeof(int));
        *(int*)region[i]->Base() = i + 1;
        OStatus status = subject[sbjCount]->SetData(region[i]);
        subject[sbjCount]->NotifyObservers();
        OSYSPRINT(("Producer : SetData #%d status %d\n", i + 1, (int)status));
    }
    return oSUCCESS;
}

OStatus
Producer::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Producer::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Producer::Ready(const OReadyEvent& event)
{
    if (!event.IsAssert()) return;

    char line[128];
    int n = 0;
    for (int i = 0; i < NUM_UNITS; i++) {
        if (region[i] != 0)
            n += sprintf(line + n, " %d", region[i]->NumberOfReference());
    }
    OSYSPRINT(("Producer : Ready ASSERT references%s\n", line));
}
