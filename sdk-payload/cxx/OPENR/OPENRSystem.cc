// OPENRSystem.cc - the OPENR:: functions served by the system objects rather than by
// robot hardware: robot design and design data (object-model 4.5, robot-api 4.6/12),
// Memory Stick status, clock (robot-api 9.6) and power (robot-api 4.5, 9).
// The hardware families (primitives, data vectors, joints, sensors, sound) live
// elsewhere.
#include <string.h>

#include <OPENR/OPENRAPI.h>
#include <OPENR/OTime.h>

#include "openr_host.h"

namespace {

void toHost(const OPowerStatus& ps, openr_power_state* s)
{
    s->robot_status = ps.robotStatus;
    s->battery_status = ps.batteryStatus;
    s->remaining_capacity = ps.remainingCapacity;
    s->temperature = ps.temperature;
    s->fully_charged_capacity = ps.fullyChargedCapacity;
    s->voltage = ps.voltage;
    s->current = ps.current;
    s->time_dif = (signed char)ps.timeDif;
    s->volume = ps.volume;
}

void fromHost(const openr_power_state& s, OPowerStatus* ps)
{
    ps->robotStatus = s.robot_status;
    ps->batteryStatus = (word)s.battery_status;
    ps->remainingCapacity = (word)s.remaining_capacity;
    ps->temperature = (word)s.temperature;
    ps->fullyChargedCapacity = (word)s.fully_charged_capacity;
    ps->voltage = (word)s.voltage;
    ps->current = (sword)s.current;
    ps->timeDif = (sbyte)s.time_dif;
    ps->volume = (byte)s.volume;
}

bool validDif(int dif)
{
    return dif >= -12 && dif <= 12;
}

} // namespace

namespace OPENR {

/* ---- robot design and design data ---- */

OStatus GetRobotDesign(char* design)
{
    const openr_host_api* api = openr_host();
    if (api == 0 || design == 0) return oFAIL;
    const char* name = api->robot_design();
    if (name == 0) return oFAIL;
    strncpy(design, name, orobotdesignNAME_MAX);
    design[orobotdesignNAME_MAX] = '\0';
    return oSUCCESS;
}

OStatus FindDesignData(const char* keyword, ODesignDataID* id, byte** data, size_t* size)
{
    if (openr_rp_unavailable("FindDesignData")) return oFAIL;
    const openr_host_api* api = openr_host();
    if (api == 0) return oFAIL;
    if (keyword == 0 || id == 0 || data == 0 || size == 0) return oINVALID_ARG;
    unsigned int memID = 0;
    void* base = 0;
    size_t n = 0;
    OStatus st = api->find_design_data(keyword, &memID, &base, &n);
    if (st != oSUCCESS) return st;
    *id = memID;
    *data = static_cast<byte*>(base);
    *size = n;
    return oSUCCESS;
}

OStatus DeleteDesignData(ODesignDataID id)
{
    if (openr_rp_unavailable("DeleteDesignData")) return oFAIL;
    const openr_host_api* api = openr_host();
    if (api == 0) return oFAIL;
    return api->delete_design_data(id);
}

OStatus GetMemoryStickStatus(OMemoryStickStatus* status)
{
    if (status == 0) return oINVALID_ARG;
    // The emulated stick is a host directory the runtime may write to.
    *status = omemorystickWRITABLE;
    return oSUCCESS;
}

/* ---- time ---- */

OStatus GetTime(OTime* time)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    if (time == 0) return oINVALID_ARG;
    long long sec = 0;
    int dif = 0;
    api->get_clock(&sec, &dif);
    time->Set((time_t)sec, validDif(dif) ? (sbyte)dif : otimeTIME_DIF_UNDEF);
    return oSUCCESS;
}

// Sets the clock; the time difference too when it is a valid one (robot-api 4.5).
OStatus SetTime(const OTime& time)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    long long sec = 0;
    int dif = 0;
    api->get_clock(&sec, &dif);
    int newDif = time.GetTimeDif();
    api->set_clock((long long)time.GetClock(), validDif(newDif) ? newDif : dif);
    return oSUCCESS;
}

OStatus GetTimeDifference(sbyte* timeDifference)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    if (timeDifference == 0) return oINVALID_ARG;
    long long sec = 0;
    int dif = 0;
    api->get_clock(&sec, &dif);
    *timeDifference = validDif(dif) ? (sbyte)dif : otimeTIME_DIF_UNDEF;
    return oSUCCESS;
}

OStatus SetTimeDifference(sbyte timeDifference)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    if (!validDif(timeDifference)) return oINVALID_ARG;
    long long sec = 0;
    int dif = 0;
    api->get_clock(&sec, &dif);
    api->set_clock(sec, timeDifference);
    return oSUCCESS;
}

/* ---- power ---- */

OStatus GetPowerStatus(OPowerStatus* powerStatus)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    if (powerStatus == 0) return oINVALID_ARG;
    openr_power_state s;
    memset(&s, 0, sizeof(s));
    api->power_status(&s);
    fromHost(s, powerStatus);
    return oSUCCESS;
}

OStatus ObservePowerStatus(const OPowerStatus& notifyStatus, const OServiceEntry& entry)
{
    if (openr_rp_unavailable("ObservePowerStatus")) return oFAIL;
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    if (!entry.IsValid()) return oINVALID_ARG;
    openr_power_state filter;
    toHost(notifyStatus, &filter);
    return api->observe_power(entry.GetOID().GetAddress(), entry.GetSelector(), &filter) == 0
        ? oSUCCESS : oFAIL;
}

OStatus UnobservePowerStatus(const OServiceEntry& entry)
{
    if (openr_rp_unavailable("UnobservePowerStatus")) return oFAIL;
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    return api->observe_power(entry.GetOID().GetAddress(), entry.GetSelector(), 0) == 0
        ? oSUCCESS : oINVALID_ARG;
}

OStatus SetMotorPower(OPower power)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    api->set_motor_power(power ? 1 : 0);
    return oSUCCESS;
}

OStatus Shutdown(const OBootCondition& bootCondition)
{
    if (openr_rp_unavailable("Shutdown")) return oFAIL;
    (void)bootCondition;   // the emulator does not reboot by itself
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    api->shutdown();
    return oSUCCESS;
}

OStatus Fatal(OFatal fatal)
{
    if (openr_rp_unavailable("Fatal")) return oFAIL;
    const openr_host_api* api = openr_host();
    if (api == 0) return oNOT_FOUND;
    api->fatal(fatal);
    return oFAIL;   // not reached: the robot is off
}

// Only `bitmap` is meaningful: an emulated robot is always booted by the pause button.
OStatus GetBootCondition(OBootCondition* bootCondition)
{
    if (bootCondition == 0) return oINVALID_ARG;
    *bootCondition = OBootCondition(obcbPAUSE_SW);
    return oSUCCESS;
}

} // namespace OPENR
