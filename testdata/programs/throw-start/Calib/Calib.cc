//
// Calib.cc
//
// Loads joint offsets in DoStart and, in the style of C++ code of the time,
// reports a missing file by throwing: std::runtime_error when CALIB.DAT is
// absent, a CalibError (not derived from std::exception) when a value is
// malformed. Nobody catches either: on the robot the object died. The host
// runtime reports the exception and stops the run with a non-zero status.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "Calib.h"

static const char* const CALIB_FILE = "/MS/OPEN-R/MW/DATA/P/CALIB.DAT";

struct CalibError {
    int line;
};

Calib::Calib()
{
    offset[0] = offset[1] = offset[2] = 0.0;
}

OStatus
Calib::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

void
Calib::LoadCalibration()
{
    FILE* fp = fopen(CALIB_FILE, "r");
    if (fp == 0) throw std::runtime_error("calibration file missing");
    char line[64];
    for (int i = 0; i < 3; i++) {
        if (fgets(line, sizeof(line), fp) == 0 || sscanf(line, "%lf", &offset[i]) != 1) {
            fclose(fp);
            CalibError e;
            e.line = i + 1;
            throw e;
        }
    }
    fclose(fp);
}

OStatus
Calib::DoStart(const OSystemEvent& event)
{
    OSYSPRINT(("Calib : loading %s\n", CALIB_FILE));
    LoadCalibration();
    OSYSPRINT(("Calib : offsets %.1f %.1f %.1f\n", offset[0], offset[1], offset[2]));
    return oSUCCESS;
}

OStatus
Calib::DoStop(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus
Calib::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
