/*
 * OPENR/OPENRMessages.h - system message types and the message structures
 * delivered to object entries (object-model 2.5, robot-api 6.8).
 */
#ifndef _OPENRMessages_h_DEFINED
#define _OPENRMessages_h_DEFINED

#include <string.h>
#include <SystemError.h>
#include <OPENR/OPENR.h>
#include <OPENR/ODataFormats.h>
#include <OPENR/OVRData.h>
#include <OPENR/OTime.h>
#include <OPENR/OPower.h>
#include <OPENR/OSyslog.h>
#include <OPENR/MWInformationTypes.h>

typedef longword OMessageType;

const OMessageType OMessageSystemBase  = 0;
const OMessageType OMessageRoboticBase = 1024;

const OMessageType omsgNULL             = OMessageSystemBase + 0;
const OMessageType omsgSYS_ERROR        = OMessageSystemBase + 1;
const OMessageType omsgOSTATUS          = OMessageSystemBase + 2;
const OMessageType omsgREASON           = OMessageSystemBase + 3;
const OMessageType omsgOID              = OMessageSystemBase + 4;
const OMessageType omsgSYSOBJ_INFO      = OMessageSystemBase + 5;
const OMessageType omsgCONNECT          = OMessageSystemBase + 6;
const OMessageType omsgSERVICE_NAME     = OMessageSystemBase + 7;
const OMessageType omsgSERVICE_ENTRY    = OMessageSystemBase + 8;
const OMessageType omsgSERVICE_BINDING  = OMessageSystemBase + 9;
const OMessageType omsgMEMORY_REGION_ID = OMessageSystemBase + 10;
const OMessageType omsgMWINFO_ID        = OMessageSystemBase + 11;
const OMessageType omsgSYSLOG           = OMessageSystemBase + 12;
const OMessageType omsgROBOT_DESIGN     = OMessageSystemBase + 13;
const OMessageType omsgDESIGN_KEYWORD   = OMessageSystemBase + 14;
const OMessageType omsgDESIGN_DATA      = OMessageSystemBase + 15;
const OMessageType omsgFATAL            = OMessageSystemBase + 16;
const OMessageType omsgMEMORY_STICK     = OMessageSystemBase + 17;

const OMessageType omsgPRIMITIVE_LOCATOR    = OMessageRoboticBase + 0;
const OMessageType omsgPRIMITIVE_ID         = OMessageRoboticBase + 1;
const OMessageType omsgVR_DATA              = OMessageRoboticBase + 2;
const OMessageType omsgVR_CONTROL           = OMessageRoboticBase + 3;
const OMessageType omsgTIME                 = OMessageRoboticBase + 4;
const OMessageType omsgPOWER_MODE           = OMessageRoboticBase + 5;
const OMessageType omsgPOWER_STATUS         = OMessageRoboticBase + 6;
const OMessageType omsgMOTOR_POWER          = OMessageRoboticBase + 7;
const OMessageType omsgPLUNGER              = OMessageRoboticBase + 8;
const OMessageType omsgALARM                = OMessageRoboticBase + 9;
const OMessageType omsgOBSERVE_POWER_STATUS = OMessageRoboticBase + 10;
const OMessageType omsgVOLUME               = OMessageRoboticBase + 11;
const OMessageType omsgBMN_DATA_STREAM      = OMessageRoboticBase + 12;
const OMessageType omsgSTATION_REGISTER     = OMessageRoboticBase + 13;
const OMessageType omsgBOOT_CONDITION       = OMessageRoboticBase + 14;
const OMessageType omsgBMN_MODE             = OMessageRoboticBase + 15;
const OMessageType omsgBMN_SPECIAL_MODE     = OMessageRoboticBase + 16;

/* reply of the life-cycle hooks and of Connect */
struct OStatusMessage {
    OMessageType msgType;
    OStatus      status;

    OStatusMessage() : msgType(omsgOSTATUS), status(oUNDEF) {}
    OStatusMessage(OStatus s) : msgType(omsgOSTATUS), status(s) {}
};

/* argument of the Init/Start/Stop/Destroy entries */
struct OReasonMessage {
    OMessageType msgType;
    OReason      reason;
    size_t       paramSize;
    byte         param[128];   /* oreasonPARAM_MAX_SIZE */

    OReasonMessage(OReason r = oreasonUNDEF)
        : msgType(omsgREASON), reason(r), paramSize(0) {
        memset(param, 0, sizeof(param));
    }
    OReasonMessage(OReason r, const void* p, size_t size)
        : msgType(omsgREASON), reason(r), paramSize(0) {
        memset(param, 0, sizeof(param));
        if (size > sizeof(param)) size = sizeof(param);
        if (p != 0 && size > 0) memcpy(param, p, size);
        paramSize = size;
    }
};

/* sent by the service manager to an observer's Connect entry */
struct OConnectMessage {
    OMessageType  msgType;
    OConnectCmd   command;
    OServiceEntry entry;        /* the subject's registered (Control) entry */
    char          subName[128]; /* oserviceNAME_MAX + 1 */

    OConnectMessage() : msgType(omsgCONNECT), command(oconnectcmdCONNECT), entry() {
        subName[0] = '\0';
    }
    OConnectMessage(OConnectCmd cmd) : msgType(omsgCONNECT), command(cmd), entry() {
        subName[0] = '\0';
    }
};

/* sent to the entry given to OPENR::ObservePowerStatus() */
struct OPowerStatusMessage {
    OMessageType msgType;
    OPowerStatus powerStatus;

    OPowerStatusMessage() : msgType(omsgPOWER_STATUS), powerStatus() {}
    OPowerStatusMessage(const OPowerStatus& ps) : msgType(omsgPOWER_STATUS), powerStatus(ps) {}
};

#endif /* _OPENRMessages_h_DEFINED */
