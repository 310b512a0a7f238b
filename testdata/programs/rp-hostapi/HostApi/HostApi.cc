//
// HostApi.cc
//
// Calls two OPEN-R functions at start: one every object may call
// (GetRobotDesign) and one the Installation Guide lists as not
// available to Remote Processing host objects (NewSoundVectorData).
// On the robot both succeed; on the host the second returns oFAIL.
// Then it looks for the IPStack, which host objects do not have either
// (the ANT network library: host programs use the PC's sockets).
//

#include <OPENR/OSyslog.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/core_macro.h>
#include <antEnvBaseMsg.h>
#include "HostApi.h"

HostApi::HostApi()
{
}

OStatus
HostApi::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
HostApi::DoStart(const OSystemEvent& event)
{
    char design[orobotdesignNAME_MAX + 1];
    OStatus st = OPENR::GetRobotDesign(design);
    OSYSPRINT(("HostApi: GetRobotDesign %s (%s)\n",
               st == oSUCCESS ? "ok" : "failed", st == oSUCCESS ? design : "-"));

    MemoryRegionID    soundID;
    OSoundVectorData* soundVec;
    st = OPENR::NewSoundVectorData(1, 256, &soundID, &soundVec);
    OSYSPRINT(("HostApi: NewSoundVectorData %s\n",
               st == oSUCCESS ? "ok" : (st == oFAIL ? "oFAIL" : "other error")));
    if (st == oSUCCESS) OPENR::DeleteSoundVectorData(soundID);

    antStackRef ipstack("IPStack");
    OSYSPRINT(("HostApi: IPStack %s\n", ipstack.IsValid() ? "found" : "not found"));
    return oSUCCESS;
}

OStatus
HostApi::DoStop(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus
HostApi::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
