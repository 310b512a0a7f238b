/*
 * OPENR/OPower.h - power, battery and boot-condition types (robot-api 9).
 */
#ifndef _OPower_h_DEFINED
#define _OPower_h_DEFINED

#include <Types.h>
#include <time.h>
#include <OPENR/OTime.h>

typedef bool OPower;
const OPower opowerON  = true;
const OPower opowerOFF = false;

/* robot status bits (OPowerStatus::robotStatus) */
const longword orsbPAUSE                         = 0x00000001;
const longword orsbMOTOR_POWER                   = 0x00000002;
const longword orsbVIBRATION_DETECT              = 0x00000004;
const longword orsbEX_PORT_CONNECTED             = 0x00000008;
const longword orsbSTATION_CONNECTED             = 0x00000010;
const longword orsbEX_POWER_CONNECTED            = 0x00000020;
const longword orsbBATTERY_CONNECTED             = 0x00000040;
const longword orsbBATTERY_CHARGING              = 0x00000080;
const longword orsbBATTERY_CAPACITY_FULL         = 0x00000100;
const longword orsbBATTERY_CAPACITY_LOW          = 0x00000200;
const longword orsbBATTERY_OVER_CURRENT          = 0x00000400;
const longword orsbBATTERY_OVER_TEMP_DISCHARGING = 0x00000800;
const longword orsbBATTERY_OVER_TEMP_CHARGING    = 0x00001000;
const longword orsbBATTERY_ERROR_OF_CHARGING     = 0x00002000;
const longword orsbERROR_OF_PLUNGER              = 0x00004000;
const longword orsbOPEN_R_POWER_GOOD             = 0x00008000;
const longword orsbERROR_OF_FAN                  = 0x00010000;
const longword orsbDATA_STREAM_FROM_STATION      = 0x00020000;
const longword orsbREGISTER_UPDATED_BY_STATION   = 0x00040000;
const longword orsbRTC_ERROR                     = 0x00080000;
const longword orsbRTC_OVERFLOW                  = 0x00100000;
const longword orsbRTC_RESET                     = 0x00200000;
const longword orsbRTC_SET                       = 0x00400000;
const longword orsbSPECIAL_MODE                  = 0x00800000;
const longword orsbBMN_DEBUG_MODE                = 0x01000000;
const longword orsbCHARGER_STATUS                = 0x02000000;
const longword orsbPLUNGER                       = 0x04000000;
const longword orsbSUSPENDED                     = 0x08000000;
const longword orsbSPECIAL_DATA_READ_REQ         = 0x10000000;
const longword orsbALL                           = 0x1fffffff;

/* battery status bits (OPowerStatus::batteryStatus) */
const word obsbERROR_CODE_MASK             = 0x000f;
const word obsbFULLY_DISCHARGED            = 0x0010;
const word obsbFULLY_CHARGED               = 0x0020;
const word obsbDISCHARGING                 = 0x0040;
const word obsbINITIALIZED                 = 0x0080;
const word obsbREMAINING_TIME_ALARM        = 0x0100;
const word obsbREMAINING_CAPACITY_ALARM    = 0x0200;
const word obsbRESERVED0                   = 0x0400;
const word obsbTERMINATED_DISCHARGING_ALARM = 0x0800;
const word obsbOVER_TEMP_ALARM             = 0x1000;
const word obsbRESERVED1                   = 0x2000;
const word obsbTERMINATED_CHARGING_ALARM   = 0x4000;
const word obsbOVER_CHARGED_ALARM          = 0x8000;
const word obsbALL                         = 0xffff;

/* battery error codes (batteryStatus & obsbERROR_CODE_MASK) */
const word obsecOK                  = 0;
const word obsecBUSY                = 1;
const word obsecNOT_READY           = 2;
const word obsecUNSUPPORTED_COMMAND = 3;
const word obsecACCESS_DENIED       = 4;
const word obsecOVER_OR_UNDER_FLOW  = 5;
const word obsecBAD_SIZE            = 6;
const word obsecUNKNOWN             = 7;

/* boot condition bits (OBootCondition::bitmap) */
const word obcbBOOT_TIMER           = 0x0001;
const word obcbVIBRATION_DETECTED   = 0x0002;
const word obcbPAUSE_SW             = 0x0004;
const word obcbSTATION_CONNECTED    = 0x0008;
const word obcbSTATION_DISCONNECTED = 0x0010;
const word obcbBATTERY_CAPACITY_FULL = 0x0020;
const word obcbREQ_FROM_STATION     = 0x0040;
const word obcbALL                  = 0x007f;

/* boot time types (OBootCondition::bootTimeType) */
const longword obcbttRELATIVE = 0x00000000;
const longword obcbttABSOLUTE = 0x80000000;

/* battery-management data stream types */
const byte odstSOUND               = 0;
const byte odstLCD                 = 1;
const byte odstSTATION_WRITE       = 2;
const byte odstSTATION_READ        = 3;
const byte odstBATTERY_DEVICE_NAME = 4;
const byte odstSPECIAL_DATA        = 5;

/* observation selectors for ObservePowerStatus() */
const word  opsoREMAINING_CAPACITY_NOTIFY_EVERY_CHANGE = 0xffff;
const word  opsoREMAINING_CAPACITY_NOT_NOTIFY          = 0xfffe;
const word  opsoTEMPERATURE_NOTIFY_EVERY_CHANGE        = 0xffff;
const word  opsoTEMPERATURE_NOT_NOTIFY                 = 0xfffe;
const sbyte opsoTIME_DIF_NOTIFY_EVERY_CHANGE           = 0x7f;
const sbyte opsoTIME_DIF_NOT_NOTIFY                    = 0x7e;
const byte  opsoVOLUME_NOTIFY_EVERY_CHANGE             = 0xff;
const byte  opsoVOLUME_NOT_NOTIFY                      = 0xfe;

struct OPowerStatus {
    longword robotStatus;           /*  0 orsb... bits */
    word     batteryStatus;         /*  4 obsb... bits */
    word     remainingCapacity;     /*  6 % */
    word     temperature;           /*  8 0.1 K */
    word     fullyChargedCapacity;  /* 10 mAh */
    word     voltage;               /* 12 mV */
    sword    current;               /* 14 mA */
    sbyte    timeDif;               /* 16 hours from UTC */
    byte     volume;                /* 17 volume switch 0..3 */

    OPowerStatus()
        : robotStatus(0), batteryStatus(0), remainingCapacity(0), temperature(0),
          fullyChargedCapacity(0), voltage(0), current(0), timeDif(0), volume(0) {}

    OPowerStatus(longword rs, word bs, word rc, word tmpr, word fc,
                 word vlt, sword crnt, sbyte td, byte vlm)
        : robotStatus(rs), batteryStatus(bs), remainingCapacity(rc), temperature(tmpr),
          fullyChargedCapacity(fc), voltage(vlt), current(crnt), timeDif(td), volume(vlm) {}

    void Set(longword rs, word bs, word rc, word tp, sbyte td, byte v) {
        robotStatus = rs;
        batteryStatus = bs;
        remainingCapacity = rc;
        temperature = tp;
        fullyChargedCapacity = 0;
        voltage = 0;
        current = 0;
        timeDif = td;
        volume = v;
    }

    void Print() const;         /* runtime library */
    void PrintDetail() const;   /* runtime library */
};

OPENR_STATIC_CHECK(sizeof(OPowerStatus) == 20, OPowerStatus_20);

struct OBootCondition {
    word     bitmap;
    time_t   bootTime;
    longword bootTimeType;
    byte     vibrationLevel;

    OBootCondition()
        : bitmap(obcbALL), bootTime(10), bootTimeType(obcbttRELATIVE), vibrationLevel(4) {}
    OBootCondition(word bm)
        : bitmap(bm), bootTime(10), bootTimeType(obcbttRELATIVE), vibrationLevel(4) {}
    OBootCondition(word bm, time_t bt, longword btt)
        : bitmap(bm), bootTime(bt), bootTimeType(btt), vibrationLevel(4) {}
    OBootCondition(word bm, time_t bt, longword btt, byte vl)
        : bitmap(bm), bootTime(bt), bootTimeType(btt), vibrationLevel(vl) {}
};

#endif /* _OPower_h_DEFINED */
