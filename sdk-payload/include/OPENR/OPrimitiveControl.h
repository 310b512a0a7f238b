/*
 * OPENR/OPrimitiveControl.h - request codes and parameter structures of
 * OPENR::ControlPrimitive() (robot-api 5).
 */
#ifndef _OPrimitiveControl_h_DEFINED
#define _OPrimitiveControl_h_DEFINED

#include <OPENR/OPENR.h>
#include <OPENR/ODataFormats.h>

/* request code bases */
const OPrimitiveRequest oprmreqCOMMON_BASE  = 0;
const OPrimitiveRequest oprmreqSPEAKER_BASE = 128;
const OPrimitiveRequest oprmreqMIC_BASE     = 256;
const OPrimitiveRequest oprmreqCAM_BASE     = 384;
const OPrimitiveRequest oprmreqBT_BASE      = 512;
const OPrimitiveRequest oprmreqJOINT2_BASE  = 640;
const OPrimitiveRequest oprmreqLED2_BASE    = 768;
const OPrimitiveRequest oprmreqSENSOR_BASE  = 896;
const OPrimitiveRequest oprmreqLED3_BASE    = 1024;
const OPrimitiveRequest oprmreqJOINT4_BASE  = 1152;
const OPrimitiveRequest oprmreqPRIVATE_BASE = 1048576;
const OPrimitiveRequest oprmreqUNDEF        = 0xffffffff;

/* speaker */
const OPrimitiveRequest oprmreqSPEAKER_MUTE_ON            = 128;
const OPrimitiveRequest oprmreqSPEAKER_MUTE_OFF           = 129;
const OPrimitiveRequest oprmreqSPEAKER_SET_VOLUME         = 130;
const OPrimitiveRequest oprmreqSPEAKER_SET_SOUND_TYPE     = 131;
const OPrimitiveRequest oprmreqSPEAKER_GET_SOUND_TYPE     = 132;
const OPrimitiveRequest oprmreqSPEAKER_SET_VOLUME_MIDI    = 133;
const OPrimitiveRequest oprmreqSPEAKER_MASTER_TUNING_MIDI = 134;
/* microphone */
const OPrimitiveRequest oprmreqMIC_UNI     = 256;
const OPrimitiveRequest oprmreqMIC_OMNI    = 257;
const OPrimitiveRequest oprmreqMIC_ALC_ON  = 258;
const OPrimitiveRequest oprmreqMIC_ALC_OFF = 259;
/* camera */
const OPrimitiveRequest oprmreqCAM_SET_WHITE_BALANCE = 384;
const OPrimitiveRequest oprmreqCAM_SET_GAIN          = 385;
const OPrimitiveRequest oprmreqCAM_SET_SHUTTER_SPEED = 386;
const OPrimitiveRequest oprmreqCAM_GET_CDT_TABLE     = 387;
const OPrimitiveRequest oprmreqCAM_AE_ON             = 388;
const OPrimitiveRequest oprmreqCAM_AE_OFF            = 389;
const OPrimitiveRequest oprmreqCAM_AWB_ON            = 390;
const OPrimitiveRequest oprmreqCAM_AWB_OFF           = 391;
/* bluetooth */
const OPrimitiveRequest oprmreqBT_ATTACH = 512;
const OPrimitiveRequest oprmreqBT_DETACH = 513;
/* immediate commands */
const OPrimitiveRequest oprmreqJOINT2_SET_COMMAND = 640;
const OPrimitiveRequest oprmreqJOINT2_GET_VALUE   = 641;
const OPrimitiveRequest oprmreqLED2_SET_COMMAND   = 768;
const OPrimitiveRequest oprmreqSENSOR_WATCH_BT_SWITCH = 896;
const OPrimitiveRequest oprmreqLED3_SET_COMMAND   = 1024;
const OPrimitiveRequest oprmreqJOINT4_SET_COMMAND = 1152;

/* speaker constants */
typedef longword OSpeakerSoundType;
const OSpeakerSoundType ospksndMONO8K8B     = 0;
const OSpeakerSoundType ospksndMONO11K8B    = 1;
const OSpeakerSoundType ospksndMONO16K8B    = 2;
const OSpeakerSoundType ospksndMONO16K16B   = 3;
const OSpeakerSoundType ospksndSTEREO16K16B = 4;

typedef longword OSpeakerVolume;
const OSpeakerVolume ospkvolinfdB = 0x8000;
const OSpeakerVolume ospkvol25dB  = 0xe700;
const OSpeakerVolume ospkvol18dB  = 0xee00;
const OSpeakerVolume ospkvol10dB  = 0xf600;

/* camera parameters */
const longword ocamparamUNDEF            = 0;
const longword ocamparamWB_INDOOR_MODE   = 1;
const longword ocamparamWB_OUTDOOR_MODE  = 2;
const longword ocamparamWB_FL_MODE       = 3;
const longword ocamparamGAIN_LOW         = 1;
const longword ocamparamGAIN_MID         = 2;
const longword ocamparamGAIN_HIGH        = 3;
const longword ocamparamSHUTTER_SLOW     = 1;
const longword ocamparamSHUTTER_MID      = 2;
const longword ocamparamSHUTTER_FAST     = 3;

typedef longword OBtSwitchEvent;
const OBtSwitchEvent obtswitcheventUNDEF         = 0;
const OBtSwitchEvent obtswitcheventVALUE_CHANGED = 1;

/* parameter structures */
struct OPrimitiveControl_SpeakerVolume {
    longword volume;
    OPrimitiveControl_SpeakerVolume() : volume(ospkvolinfdB) {}
    OPrimitiveControl_SpeakerVolume(OSpeakerVolume v) : volume(v) {}
};

struct OPrimitiveControl_SpeakerSoundType {
    OSpeakerSoundType type;
    OPrimitiveControl_SpeakerSoundType() : type(ospksndMONO8K8B) {}
    OPrimitiveControl_SpeakerSoundType(OSpeakerSoundType t) : type(t) {}
};

struct OPrimitiveControl_MasterTuningMIDI {
    sword value;
    OPrimitiveControl_MasterTuningMIDI() : value(0) {}
    OPrimitiveControl_MasterTuningMIDI(sword v) : value(v) {}
};

struct OPrimitiveControl_CameraParam {
    longword camparam;
    OPrimitiveControl_CameraParam() : camparam(ocamparamUNDEF) {}
    OPrimitiveControl_CameraParam(longword p) : camparam(p) {}
};

struct OPrimitiveControl_Cdt {
    longword index;
    byte     table[100];
};

struct OPrimitiveControl_JointCommandValue2 {
    OJointCommandValue2 command;
    OPrimitiveControl_JointCommandValue2() { command.value = 0; command.padding = 0; }
    OPrimitiveControl_JointCommandValue2(slongword v) { command.value = v; command.padding = 0; }
};

struct OPrimitiveControl_JointValue {
    OJointValue jval;
};

struct OPrimitiveControl_LEDCommandValue2 {
    OLEDCommandValue2 command;
    OPrimitiveControl_LEDCommandValue2() {
        command.led = oledOFF; command.period = 0; command.reserved = 0;
    }
    OPrimitiveControl_LEDCommandValue2(OLEDValue led) {
        command.led = led; command.period = 0; command.reserved = 0;
    }
};

struct OPrimitiveControl_BtSwitchWatcherInfo {
    OBtSwitchEvent event;
    OServiceEntry  entry;
};

struct OPrimitiveControl_BtSwitchEvent {
    OBtSwitchEvent event;
    OSwitchValue   value;
};

struct OPrimitiveControl_LEDCommandValue3 {
    OLEDCommandValue3 command;
    OPrimitiveControl_LEDCommandValue3() {
        command.intensity = 0; command.mode = oled3_MODE_UNDEF;
        command.period = 0; command.reserved = 0;
    }
    OPrimitiveControl_LEDCommandValue3(sword intensity, OLED3Mode mode) {
        command.intensity = intensity; command.mode = mode;
        command.period = 0; command.reserved = 0;
    }
};

struct OPrimitiveControl_JointCommandValue4 {
    OJointCommandValue4 command;
    OPrimitiveControl_JointCommandValue4() {
        command.value = ojoint4_STATE0; command.period = 1; command.reserved = 0;
    }
    OPrimitiveControl_JointCommandValue4(OJointValue4 v) {
        command.value = v; command.period = 1; command.reserved = 0;
    }
};

#endif /* _OPrimitiveControl_h_DEFINED */
