/*
 * OPENR/OPENR.h - common OPEN-R types and constants (object-model 2.2,
 * robot-api 1 and 6.1): service entries, reasons, selectors of the hook
 * entries, primitive/sensor/device/data type codes.
 */
#ifndef _OPENR_h_DEFINED
#define _OPENR_h_DEFINED

#include <string.h>
#include <OID.h>
#include <Types.h>
#include <OPENR/OStatus.h>

/* selectors of the four life-cycle entries */
const Selector oentryINIT    = 0;
const Selector oentrySTART   = 1;
const Selector oentrySTOP    = 2;
const Selector oentryDESTROY = 3;
const Selector oentryBASE    = 4;

/* name lengths (without the terminating NUL) */
const size_t oserviceNAME_MAX       = 127;
const size_t oobjectNAME_MAX        = 63;
const size_t orobotdesignNAME_MAX   = 31;
const size_t odesignkeywordNAME_MAX = 127;
const size_t ovrNAME_MAX            = 31;
const size_t ovrPATH_MAX            = 127;

/* frame numbers */
const longword oframeMAX_NUMBER     = 0x0ffffff0;
const longword oframeINVALID_NUMBER = 0xffffffff;

/*
 * OServiceEntry: one entry (selector) of one object.
 */
struct OServiceEntry {
    OID      oid;
    Selector selector;

    OServiceEntry() : oid(), selector(UNDEF) {}
    OServiceEntry(const OID& o, Selector s) : oid(o), selector(s) {}
    OServiceEntry(const OServiceEntry& e) : oid(e.oid), selector(e.selector) {}
    OServiceEntry& operator=(const OServiceEntry& e) {
        oid = e.oid;
        selector = e.selector;
        return *this;
    }

    void Set(const OID& o, Selector s) { oid = o; selector = s; }
    const OID& GetOID() const { return oid; }
    Selector   GetSelector() const { return selector; }
    bool IsValid() const { return oid.IsValid() && selector != UNDEF; }
    void MakeInvalid() { oid.MakeInvalid(); selector = UNDEF; }

    friend bool operator==(const OServiceEntry& a, const OServiceEntry& b) {
        return a.oid == b.oid && a.selector == b.selector;
    }
    friend bool operator!=(const OServiceEntry& a, const OServiceEntry& b) {
        return !(a == b);
    }
    friend bool operator<(const OServiceEntry& a, const OServiceEntry& b) {
        if (a.oid != b.oid) return a.oid < b.oid;
        return a.selector < b.selector;
    }
};

/* reasons of the life-cycle messages */
typedef longword OReason;
const OReason oreasonUNDEF    = 0xffffffff;
const OReason oreasonBOOT     = 0;
const OReason oreasonSHUTDOWN = 1;
const size_t  oreasonPARAM_MAX_SIZE = 128;

typedef longword OMemoryStickStatus;
const OMemoryStickStatus omemorystickUNDEF           = 0xffffffff;
const OMemoryStickStatus omemorystickNOT_EXIST       = 0;
const OMemoryStickStatus omemorystickWRITE_PROTECTED = 1;
const OMemoryStickStatus omemorystickWRITABLE        = 2;

struct OBootParam {
    OMemoryStickStatus memoryStickStatus;
    OBootParam() : memoryStickStatus(omemorystickUNDEF) {}
    OBootParam(OMemoryStickStatus s) : memoryStickStatus(s) {}
};

struct OShutdownParam {
    bool batteryEnough;
    OShutdownParam() : batteryEnough(true) {}
    OShutdownParam(bool b) : batteryEnough(b) {}
};

typedef longword OConnectCmd;
const OConnectCmd oconnectcmdCONNECT       = 0;
const OConnectCmd oconnectcmdDISCONNECT    = 1;
const OConnectCmd oconnectcmdDISCONNECTALL = 2;

typedef longword OFatal;
const OFatal ofatalUNDEF        = 0xffffffff;
const OFatal ofatalMEMORY_STICK = 0;
const OFatal ofatalPAUSE_SW     = 1;
const OFatal ofatalORB          = 2;

typedef longword ODesignDataID;
const ODesignDataID odesigndataID_UNDEF = 0xffffffff;

/* reserved design-data keyword: FindDesignData() returns an OCPUInfo */
const char* const odesignkeywordCPUINFO = "SYS_CPUINFO";

struct OCPUInfo {
    longword sclk;           /* system clock, Hz */
    longword pclk;           /* pipeline clock, Hz */
    longword processorID;
    byte     reserved[244];
};

OPENR_STATIC_CHECK(sizeof(OCPUInfo) == 256, OCPUInfo_256);

typedef longword OPrimitiveID;
const OPrimitiveID oprimitiveID_UNDEF = 0xffffffff;

typedef longword OVRSyncKey;
const OVRSyncKey ovrsynckeyUNDEF            = 0xffffffff;
const size_t     ovrsynckeyMAX_SIZE         = 8;
const size_t     ovrsynckeyMAX_NUM_KEY      = 8;
const size_t     ovrsynckeyMAX_NUM_DIVISION = 16;

typedef longword OVRRequest;
const OVRRequest ovrreqUNDEF = 0xffffffff;
const size_t ovrctrlPARAM_MAX_SIZE = 192;
const size_t ovrctrlDEVICE_MAX     = 32;

typedef byte OVolumeSwitch;
const OVolumeSwitch ovolumeSW0 = 0;
const OVolumeSwitch ovolumeSW1 = 1;
const OVolumeSwitch ovolumeSW2 = 2;
const OVolumeSwitch ovolumeSW3 = 3;

typedef longword OPrimitiveRequest;
const size_t oprmctrlPARAM_MAX_SIZE = 176;

typedef longword OCPCModelID;
const OCPCModelID ocpcmodelID_UNDEF = 0xffffffff;

typedef longword OAsyncReqID;
const size_t      oasyncReqID_MAX_SIZE = 32;
const OAsyncReqID oasyncReqID_UNDEF    = 0xffffffff;

typedef longword ODeviceID;

/* primitive types (OpenPrimitive locator type names in comments) */
typedef longword OPrimitiveType;
const OPrimitiveType oprimitiveUNDEF          = 0;
const OPrimitiveType oprimitiveCOORDINATE     = 1;   /* "Coordinate" */
const OPrimitiveType oprimitiveRECEPTOR       = 2;   /* "Receptor" */
const OPrimitiveType oprimitivePLUG           = 3;   /* "Plug" */
const OPrimitiveType oprimitiveLINK           = 4;   /* "Link" */
const OPrimitiveType oprimitiveJOINT          = 5;   /* "Joint" */
const OPrimitiveType oprimitiveSENSOR         = 6;   /* "Sensor" */
const OPrimitiveType oprimitiveSPEAKER        = 7;   /* "Speaker" */
const OPrimitiveType oprimitiveMIC            = 8;   /* "Mic" */
const OPrimitiveType oprimitiveFBKIMAGESENSOR = 9;   /* "FbkImageSensor" */
const OPrimitiveType oprimitiveLED            = 10;  /* "LED" */
const OPrimitiveType oprimitiveJOINT2         = 11;  /* "Joint2" */
const OPrimitiveType oprimitiveLED2           = 12;  /* "LED2" */
const OPrimitiveType oprimitiveJOINT3         = 13;  /* "Joint3" */
const OPrimitiveType oprimitiveJOINT4         = 14;  /* "Joint4" */
const OPrimitiveType oprimitiveBLUETOOTH      = 15;  /* "Bluetooth" */
const OPrimitiveType oprimitiveLED3           = 16;  /* "LED3" */

/* sensor types */
typedef longword OSensorType;
const OSensorType osensorUNDEF          = 0;
const OSensorType osensorSWITCH         = 1;
const OSensorType osensorACCELEROMETER  = 2;
const OSensorType osensorGYROMETER      = 3;
const OSensorType osensorTACTILE_SENSOR = 4;
const OSensorType osensorTHERMOMETER    = 5;
const OSensorType osensorPSD            = 6;
const OSensorType osensorROTARY_SENSOR  = 7;
const OSensorType osensorBT_SWITCH      = 8;
const OSensorType osensorRAW_SENSOR     = 9;
const OSensorType osensorTM_SENSOR      = 10;

/* device types */
typedef longword ODeviceType;
const ODeviceType odevtypeUNDEF = 0;
const ODeviceType odevtypeHUB   = 1;
const ODeviceType odevtypeSERVO = 2;   /* "Servo" */
const ODeviceType odevtypeAUDIO = 3;   /* "Audio" */
const ODeviceType odevtypeFBK   = 4;   /* "Fbk" */

typedef byte SensorType;
typedef byte AttachedParts;
typedef byte AttachedPosition;

/* data types (robot-api 6.1) */
typedef longword ODataType;
const ODataType odataUNDEF               = 0;
const ODataType odataNO_DIMENSION        = 1;
const ODataType odataLENGTH              = 2;
const ODataType odataMASS                = 3;
const ODataType odataTIME                = 4;
const ODataType odataDATE                = 5;
const ODataType odataANGULAR             = 6;
const ODataType odataVELOCITY            = 7;
const ODataType odataFORCE               = 8;
const ODataType odataACCELERATION        = 9;
const ODataType odataANGULAR_VELOCITY    = 10;
const ODataType odataTEMPERATURE         = 11;
const ODataType odataPRESSURE            = 12;
const ODataType odataPERCENTAGE          = 13;
const ODataType odataSWITCH              = 14;
const ODataType odataLED                 = 15;
const ODataType odataSOUND               = 16;
const ODataType odataIMAGE               = 17;
const ODataType odataJOINT_VALUE         = 18;
const ODataType odataFBK_YCrCb           = 19;
const ODataType odataFBK_CDT             = 20;
const ODataType odataCDT                 = 21;
const ODataType odataPRIMITIVE_INFO      = 22;
const ODataType odataCPC_INFO            = 23;
const ODataType odataFBK_YCrCb_HPF       = 24;
const ODataType odataJOINT_COMMAND       = 256;
const ODataType odataCAMERA_COMMAND      = 257;
const ODataType odataLED_COMMAND         = 258;
const ODataType odataJOINT_COMMAND2      = 259;
const ODataType odataLED_COMMAND2        = 260;
const ODataType odataJOINT_COMMAND3      = 261;
const ODataType odataJOINT_COMMAND4      = 262;
const ODataType odataLED_COMMAND3        = 263;
const ODataType odataRAW_JOINT_COMMAND   = 512;
const ODataType odataRAW_CAMERA_COMMAND  = 513;
const ODataType odataRAW_LED_COMMAND     = 514;
const ODataType odataRAW_JOINT_COMMAND2  = 515;
const ODataType odataCOMMAND_VECTOR      = 1024;
const ODataType odataSENSOR_FRAME_VECTOR = 1025;
const ODataType odataSOUND_VECTOR        = 1026;
const ODataType odataFBKIMAGE_VECTOR     = 1027;
const ODataType odataCDT_VECTOR          = 1028;
const ODataType odataPRIMITIVE_MAP       = 1029;
const ODataType odataCPC_TREE            = 1030;
const ODataType odataDONT_CARE           = 0xffffffff;

const size_t odataOPTIONAL_MAX = 128;

#endif /* _OPENR_h_DEFINED */
