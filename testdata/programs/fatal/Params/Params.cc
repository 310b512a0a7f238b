//
// Params.cc
//
// Reads its walking parameters in DoStart. Without them the robot must not move,
// so, as robot code of the time did, it gives up with OPENR::Fatal: the robot plays
// the memory-stick error sound and powers off. Nothing runs after that call - not
// the rest of DoStart, not DoStop, not DoDestroy.
//

#include <stdio.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Params.h"

static const char* const PARAMS_FILE = "/MS/OPEN-R/MW/DATA/P/PARAMS.TXT";

Params::Params() : numParams(0)
{
}

OStatus
Params::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
Params::DoStart(const OSystemEvent& event)
{
    FILE* fp = fopen(PARAMS_FILE, "r");
    if (fp == 0) {
        OSYSLOG1((osyslogERROR, "Params : can't open %s", PARAMS_FILE));
        OPENR::Fatal(ofatalMEMORY_STICK);
        OSYSLOG1((osyslogERROR, "Params : still running after Fatal"));
        return oFAIL;
    }
    double value;
    while (fscanf(fp, "%lf", &value) == 1) numParams++;
    fclose(fp);
    OSYSLOG1((osyslogINFO, "Params : %d parameters loaded", numParams));

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Params::DoStop(const OSystemEvent& event)
{
    OSYSLOG1((osyslogINFO, "Params : DoStop"));
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
Params::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
