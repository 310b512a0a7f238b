//
// PowerMonitor.cc
//
// PowerMonitor only talks to the system, never to other objects, so its
// dummy services are not even registered: DoInit does not use the
// NEW_ALL_SUBJECT_AND_OBSERVER / REGISTER_ALL_ENTRY macros.
//
// In DoStart it asks to be told about every change of the robot and
// battery status bits. The system then sends an OPowerStatusMessage to
// our extra entry Extra_Entry[entryUpdatePowerStatus] (entry.h).
//

#include <OPENR/OPENRAPI.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "PowerMonitor.h"
#include "entry.h"

PowerMonitor::PowerMonitor() : observing(false)
{
}

OStatus
PowerMonitor::DoInit(const OSystemEvent& event)
{
    OSYSDEBUG(("PowerMonitor::DoInit()\n"));
    return oSUCCESS;
}

OStatus
PowerMonitor::DoStart(const OSystemEvent& event)
{
    OSYSDEBUG(("PowerMonitor::DoStart()\n"));

    // This robot's clock keeps Japan time (UTC+9): the power status reports it too.
    OPENR::SetTimeDifference(9);

    OPowerStatus currentStatus;
    OStatus result = OPENR::GetPowerStatus(&currentStatus);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "PowerMonitor::DoStart()",
                  "OPENR::GetPowerStatus() FAILED", result));
    } else {
        PrintPowerStatus("PowerMonitor::DoStart()", currentStatus);
    }

    //
    // Observe every robot status bit and every battery status bit,
    // but not the capacity, temperature, time difference or volume.
    //
    OPowerStatus observationStatus;
    observationStatus.Set(orsbALL,
                          obsbALL,
                          opsoREMAINING_CAPACITY_NOT_NOTIFY,
                          opsoTEMPERATURE_NOT_NOTIFY,
                          opsoTIME_DIF_NOT_NOTIFY,
                          opsoVOLUME_NOT_NOTIFY);

    OServiceEntry entry(myOID_, Extra_Entry[entryUpdatePowerStatus]);
    result = OPENR::ObservePowerStatus(observationStatus, entry);
    if (result != oSUCCESS) {
        OSYSLOG1((osyslogERROR, "%s : %s %d",
                  "PowerMonitor::DoStart()",
                  "OPENR::ObservePowerStatus() FAILED", result));
        return oFAIL;
    }
    observing = true;

    return oSUCCESS;
}

OStatus
PowerMonitor::DoStop(const OSystemEvent& event)
{
    OSYSDEBUG(("PowerMonitor::DoStop()\n"));

    if (observing) {
        OServiceEntry entry(myOID_, Extra_Entry[entryUpdatePowerStatus]);
        OPENR::UnobservePowerStatus(entry);
        observing = false;
    }
    return oSUCCESS;
}

OStatus
PowerMonitor::DoDestroy(const OSystemEvent& event)
{
    OSYSDEBUG(("PowerMonitor::DoDestroy()\n"));
    return oSUCCESS;
}

void
PowerMonitor::UpdatePowerStatus(void* msg)
{
    OPowerStatusMessage* statusMsg = (OPowerStatusMessage*)msg;
    OPowerStatus& status = statusMsg->powerStatus;

    PrintPowerStatus("PowerMonitor::UpdatePowerStatus()", status);

    if (status.robotStatus & orsbPAUSE) {
        OSYSPRINT(("PowerMonitor : pause switch pressed, shutting down\n"));
    } else if (status.robotStatus & orsbBATTERY_CAPACITY_LOW) {
        OSYSPRINT(("PowerMonitor : battery low, shutting down\n"));
    } else {
        return;
    }

    OServiceEntry entry(myOID_, Extra_Entry[entryUpdatePowerStatus]);
    OPENR::UnobservePowerStatus(entry);
    observing = false;

    OPENR::SetMotorPower(opowerOFF);

    // Boot again when the pause switch is pressed.
    OBootCondition bootCond(obcbPAUSE_SW);
    OPENR::Shutdown(bootCond);
}

void
PowerMonitor::PrintPowerStatus(const char* who, const OPowerStatus& status)
{
    OSYSPRINT(("%s robotStatus 0x%08x batteryStatus 0x%04x capacity %d%% timeDif %d\n",
               who,
               (unsigned int)status.robotStatus,
               (unsigned int)status.batteryStatus,
               (int)status.remainingCapacity,
               (int)status.timeDif));

    OSYSPRINT(("    pause %s, motor power %s, battery %s%s\n",
               (status.robotStatus & orsbPAUSE)              ? "ON" : "OFF",
               (status.robotStatus & orsbMOTOR_POWER)        ? "ON" : "OFF",
               (status.robotStatus & orsbBATTERY_CONNECTED)  ? "connected" : "not connected",
               (status.robotStatus & orsbBATTERY_CAPACITY_LOW) ? " (LOW)" : ""));
}
