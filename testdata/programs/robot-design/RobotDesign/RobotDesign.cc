//
// RobotDesign.cc
//
// Asks the system which robot we are running on, then loads the data
// file that DESIGNDB.CFG lists for this design under "SAMPLE_DATA".
// The same binary runs on every design; only the data differ.
//

#include <string.h>
#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "RobotDesign.h"

RobotDesign::RobotDesign()
{
}

OStatus
RobotDesign::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("RobotDesign::DoInit()\n"));

    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    return oSUCCESS;
}

OStatus
RobotDesign::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("RobotDesign::DoStart()\n"));

    char design[orobotdesignNAME_MAX + 1];
    OStatus result = OPENR::GetRobotDesign(design);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "RobotDesign::DoStart()",
                  "OPENR::GetRobotDesign() FAILED", result));
        return oFAIL;
    }
    OSYSPRINT(("OPENR::GetRobotDesign() : %s\n", design));

    if (strcmp(design, "ERS-7") == 0) {
        OSYSDEBUG(("  -> ERS-7 code path\n"));
    } else if (strcmp(design, "ERS-210") == 0 || strcmp(design, "ERS-220") == 0) {
        OSYSDEBUG(("  -> ERS-200 series code path\n"));
    } else {
        OSYSLOG1((osyslogERROR, "UNKNOWN ROBOT DESIGN : %s", design));
    }

    PrintDesignData("SAMPLE_DATA");

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
RobotDesign::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("RobotDesign::DoStop()\n"));

    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;

    return oSUCCESS;
}

OStatus
RobotDesign::DoDestroy(const OSystemEvent& event)
{
    OSYSDEBUG(("RobotDesign::DoDestroy()\n"));
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
RobotDesign::PrintDesignData(const char* keyword)
{
    ODesignDataID id;
    byte*         data;
    size_t        size;

    OStatus result = OPENR::FindDesignData(keyword, &id, &data, &size);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %s %d",
                  "RobotDesign::PrintDesignData()",
                  "OPENR::FindDesignData() FAILED", keyword, result));
        return;
    }

    OSYSDEBUG(("FindDesignData(%s) : %d bytes\n", keyword, (int)size));

    //
    // The data are not NUL-terminated: copy and terminate them ourselves
    // (and drop a trailing newline).
    //
    char text[256];
    size_t n = (size < sizeof(text) - 1) ? size : sizeof(text) - 1;
    memcpy(text, data, n);
    text[n] = '\0';
    while (n > 0 && (text[n - 1] == '\n' || text[n - 1] == '\r')) {
        text[--n] = '\0';
    }
    OSYSPRINT(("%s : %s\n", keyword, text));

    OPENR::DeleteDesignData(id);
}
