// OPower.cc - non-inline members of OPowerStatus (robot-api 9.2).
#include <stdio.h>

#include <OPENR/OPower.h>

#include "openr_host.h"

namespace {

void consoleWrite(const char* text, int len)
{
    if (len <= 0) return;
    const openr_host_api* api = openr_host();
    if (api != 0) {
        api->console_write(text, (size_t)len);
    } else {
        fwrite(text, 1, (size_t)len, stdout);
        fflush(stdout);
    }
}

} // namespace

void OPowerStatus::Print() const
{
    char buf[256];
    int n = snprintf(buf, sizeof(buf),
                     "robotStatus %08x batteryStatus %04x remainingCapacity %d%% "
                     "temperature %d.%d K voltage %d mV current %d mA\n",
                     (unsigned int)robotStatus, (unsigned int)batteryStatus,
                     (int)remainingCapacity, temperature / 10, temperature % 10, (int)voltage,
                     (int)current);
    consoleWrite(buf, n < (int)sizeof(buf) ? n : (int)sizeof(buf) - 1);
}

void OPowerStatus::PrintDetail() const
{
    static const char* const robotBits[] = {
        "PAUSE", "MOTOR_POWER", "VIBRATION_DETECT", "EX_PORT_CONNECTED", "STATION_CONNECTED",
        "EX_POWER_CONNECTED", "BATTERY_CONNECTED", "BATTERY_CHARGING",
        "BATTERY_CAPACITY_FULL", "BATTERY_CAPACITY_LOW", "BATTERY_OVER_CURRENT",
        "BATTERY_OVER_TEMP_DISCHARGING", "BATTERY_OVER_TEMP_CHARGING",
        "BATTERY_ERROR_OF_CHARGING", "ERROR_OF_PLUNGER", "OPEN_R_POWER_GOOD", "ERROR_OF_FAN",
        "DATA_STREAM_FROM_STATION", "REGISTER_UPDATED_BY_STATION", "RTC_ERROR", "RTC_OVERFLOW",
        "RTC_RESET", "RTC_SET", "SPECIAL_MODE", "BMN_DEBUG_MODE", "CHARGER_STATUS", "PLUNGER",
        "SUSPENDED", "SPECIAL_DATA_READ_REQ"
    };
    static const char* const batteryBits[] = {
        0, 0, 0, 0, "FULLY_DISCHARGED", "FULLY_CHARGED", "DISCHARGING", "INITIALIZED",
        "REMAINING_TIME_ALARM", "REMAINING_CAPACITY_ALARM", "RESERVED0",
        "TERMINATED_DISCHARGING_ALARM", "OVER_TEMP_ALARM", "RESERVED1",
        "TERMINATED_CHARGING_ALARM", "OVER_CHARGED_ALARM"
    };
    char buf[1536];
    int n = snprintf(buf, sizeof(buf), "robotStatus    : %08x\n", (unsigned int)robotStatus);
    for (int i = 0; i < 29 && n < (int)sizeof(buf); i++) {
        if (robotStatus & (1U << i)) {
            n += snprintf(buf + n, sizeof(buf) - n, "    orsb%s\n", robotBits[i]);
        }
    }
    if (n < (int)sizeof(buf)) {
        n += snprintf(buf + n, sizeof(buf) - n, "batteryStatus  : %04x (error code %d)\n",
                      (unsigned int)batteryStatus, batteryStatus & 0x000f);
    }
    for (int i = 4; i < 16 && n < (int)sizeof(buf); i++) {
        if (batteryStatus & (1U << i)) {
            n += snprintf(buf + n, sizeof(buf) - n, "    obsb%s\n", batteryBits[i]);
        }
    }
    if (n < (int)sizeof(buf)) {
        n += snprintf(buf + n, sizeof(buf) - n,
                      "remainingCapacity    : %d %%\n"
                      "temperature          : %d.%d K\n"
                      "fullyChargedCapacity : %d mAh\n"
                      "voltage              : %d mV\n"
                      "current              : %d mA\n"
                      "timeDif              : %d\n"
                      "volume               : %d\n",
                      (int)remainingCapacity, temperature / 10, temperature % 10,
                      (int)fullyChargedCapacity, (int)voltage, (int)current, (int)timeDif,
                      (int)volume);
    }
    consoleWrite(buf, n < (int)sizeof(buf) ? n : (int)sizeof(buf) - 1);
}
