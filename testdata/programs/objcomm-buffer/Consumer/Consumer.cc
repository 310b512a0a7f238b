//
// Consumer.cc -- a slow observer that accepts up to 20 waiting units.
//
#include <unistd.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Consumer.h"

OStatus
Consumer::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    // skip 0, min 1, max 20: sent to the subject when connecting.
    observer[obsCount]->SetBufCtrlParam(0, 1, 20);
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Consumer::DoStart(const OSystemEvent& event)
{
    ENABLE_ALL_SUBJECT;
    usleep(500000);     // busy elsewhere: the producer's queue fills meanwhile
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Consumer::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Consumer::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
Consumer::Notify(const ONotifyEvent& event)
{
    char line[128];
    int n = 0;
    for (int i = 0; i < event.NumOfData(); i++)
        n += sprintf(line + n, " %d", *(const int*)event.Data(i));
    OSYSPRINT(("Consumer : NumOfData %d NumOfNotify %d :%s\n",
               event.NumOfData(), event.NumOfNotify(), line));
    observer[event.ObsIndex()]->AssertReady();
}
