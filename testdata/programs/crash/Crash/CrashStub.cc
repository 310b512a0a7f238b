//
// CrashStub.cc : hand-written stub (same shape as HelloWorldStub.cc)
//

#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <apsys.h>
#include "Crash.h"

Crash Self;

extern "C" void
InitStub(OReasonMessage* reasonMsg)
{
    OSystemEvent event(reasonMsg->reason,
                       reasonMsg->param, reasonMsg->paramSize);
    Self.Init(event);
    Return();
}

extern "C" void
StartStub(OReasonMessage* reasonMsg)
{
    OSystemEvent event(reasonMsg->reason,
                       reasonMsg->param, reasonMsg->paramSize);
    Self.Start(event);
    Return();
}

extern "C" void
StopStub(OReasonMessage* reasonMsg)
{
    OSystemEvent event(reasonMsg->reason,
                       reasonMsg->param, reasonMsg->paramSize);
    Self.Stop(event);
    Return();
}

extern "C" void
DestroyStub(OReasonMessage* reasonMsg)
{
    OSystemEvent event(reasonMsg->reason,
                       reasonMsg->param, reasonMsg->paramSize);
    Self.Destroy(event);
    Return();
}

GEN_ENTRY(InitEntry,     InitStub);
GEN_ENTRY(StartEntry,    StartStub);
GEN_ENTRY(StopEntry,     StopStub);
GEN_ENTRY(DestroyEntry,  DestroyStub);
GEN_ENTRY(PrologueEntry, Prologue);

ObjectEntry ObjectEntryTable[] = {
    {oentryINIT,    (Entry)InitEntry    },
    {oentrySTART,   (Entry)StartEntry   },
    {oentrySTOP,    (Entry)StopEntry    },
    {oentryDESTROY, (Entry)DestroyEntry },
    {UNDEF,         (Entry)ENTRY_UNDEF  }
};
