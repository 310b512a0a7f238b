/*
 * OPENR/ODataFormats.h - shared-memory data vectors exchanged with the
 * (virtual) robot: command, sensor, sound, image and colour-detection-table
 * vectors (robot-api 6).
 *
 * Host layout: every field that is size_t or a pointer on the robot is a
 * 32-bit longword here, so each structure keeps the robot's exact byte layout
 * (ODataVectorInfo 192 bytes, info[] at byte 192, OCommandInfo 32,
 * OSensorValue/OJointValue 16, OSoundInfo 64, OFbkImageInfo 32,
 * OCdtInfo 144). Offsets are relative to the start of the vector.
 */
#ifndef _ODataFormats_h_DEFINED
#define _ODataFormats_h_DEFINED

#include <OPENR/OPENR.h>
#include <OPENR/OUnits.h>

/* ------------------------------------------------------------------------ */
/* value constants                                                          */

typedef longword OSwitchValue;
const OSwitchValue oswitchOFF = 0;
const OSwitchValue oswitchON  = 1;

typedef longword OLEDValue;
const OLEDValue oledOFF = 0;
const OLEDValue oledON  = 1;

typedef word OLED3Mode;
const OLED3Mode oled3_MODE_A     = 0;
const OLED3Mode oled3_MODE_B     = 1;
const OLED3Mode oled3_MODE_UNDEF = 0xffff;

typedef longword OJointValue3;
const OJointValue3 ojoint3_STATE0      = 0;
const OJointValue3 ojoint3_STATE1      = 1;
const OJointValue3 ojoint3_STATE_UNDEF = 0xffffffff;

typedef longword OJointValue4;
const OJointValue4 ojoint4_STATE0      = 0;
const OJointValue4 ojoint4_STATE1      = 1;
const OJointValue4 ojoint4_STATE_UNDEF = 0xffffffff;

const size_t   ocommandMAX_FRAMES         = 16;
const size_t   osensorframeMAX_FRAMES     = 16;
const word     osensorframeINVALID_SIGNAL = 0xffff;
const slongword opsdINVALID_VALUE         = 0;

/* ------------------------------------------------------------------------ */
/* common vector header (192 bytes)                                          */

struct ODataVectorInfo {
    MemoryRegionID memRegionID;   /*   0 region holding the vector            */
    longword       physAddr;      /*   4 (void* on the robot) always 0 here   */
    longword       offset;        /*   8 offset of the vector in the region   */
    longword       totalSize;     /*  12 size of the region                   */
    ODataType      type;          /*  16 odata..._VECTOR                      */
    longword       infoOffset;    /*  20 always 192                           */
    longword       infoSize;      /*  24 size of one info element             */
    longword       maxNumData;    /*  28 allocated slots                      */
    longword       numData;       /*  32 valid slots                          */
    OVRSyncKey     syncKey;       /*  36                                      */
    longword       wait;          /*  40 delay in 8 ms frames                 */
    longword       optOffset;     /*  44                                      */
    longword       optSize;       /*  48                                      */
    longword       padding[3];    /*  52                                      */
    byte           optional[128]; /*  64 (odataOPTIONAL_MAX)                  */
};

/* ------------------------------------------------------------------------ */
/* command vectors (effector input)                                          */

struct OCommandInfo {
    ODataType    type;         /*  0 */
    OPrimitiveID primitiveID;  /*  4 */
    longword     frameNumber;  /*  8 written by the system */
    longword     numFrames;    /* 12 */
    longword     frameSize;    /* 16 */
    longword     dataOffset;   /* 20 from the start of the vector */
    longword     dataSize;     /* 24 */
    longword     padding;      /* 28 */

    void Set(ODataType t, OPrimitiveID id, size_t nframes) {
        type        = t;
        primitiveID = id;
        numFrames   = (longword)nframes;
    }
};

struct OCommandValue {
    slongword value[2];
};

struct OCommandData {
    OCommandValue value[16];   /* ocommandMAX_FRAMES */
};

struct OCommandVectorData {
    ODataVectorInfo vectorInfo;
    OCommandInfo    info[1];

    void          SetNumData(size_t n) { vectorInfo.numData = (longword)n; }
    OCommandInfo* GetInfo(int index) { return &info[index]; }
    OCommandData* GetData(int index) {
        return (OCommandData*)((byte*)&vectorInfo + info[index].dataOffset);
    }
};

struct OJointCommandValue2 {
    slongword value;     /* micro-radians */
    slongword padding;
};

struct OJointCommandValue3 {
    OJointValue3 value;
    word         reserved;
    word         padding;
};

struct OJointCommandValue4 {
    OJointValue4 value;
    word         period;   /* frames of 8 ms */
    word         reserved;
};

struct OLEDCommandValue2 {
    OLEDValue led;
    word      period;      /* frames of 8 ms */
    word      reserved;
};

struct OLEDCommandValue3 {
    sword     intensity;   /* 0..255 */
    OLED3Mode mode;
    word      period;      /* frames of 8 ms */
    word      reserved;
};

/* legacy command values */
struct OLEDCommandValue {
    OLEDValue led;
    word      period;      /* units of 16 frames */
    word      padding;
};

struct OJointCommandValue {
    slongword value;
    byte      p;
    byte      i;
    byte      d;
    byte      padding;

    void Set(slongword val, byte kp, byte ki, byte kd) {
        value = val; p = kp; i = ki; d = kd; padding = 0;
    }
};

typedef word OCameraRequest;
const OCameraRequest ocamreqAE_OFF       = 0;
const OCameraRequest ocamreqAE_ON        = 1;
const OCameraRequest ocamreqSET_AWB_MODE = 2;
const OCameraRequest ocamreqDRAW_BOX     = 3;

const byte ocamparamAWB_AUTO_MODE    = 0;
const byte ocamparamAWB_INDOOR_MODE  = 1;
const byte ocamparamAWB_OUTDOOR_MODE = 2;
const byte ocamparamAWB_USER_MODE    = 3;
const byte ocamparamAWB_FL_MODE      = 4;
const byte ocamparamBOX1             = 1;
const byte ocamparamBOX2             = 2;

struct OCameraCommandValue {
    OCameraRequest request;
    byte           param[6];
};

struct ORawJointCommandValue {
    word signal;
    byte p;
    byte i;
    byte d;
    byte padding[3];

    void Set(word sig, byte kp, byte ki, byte kd) {
        signal = sig; p = kp; i = ki; d = kd;
        padding[0] = padding[1] = padding[2] = 0;
    }
};

struct ORawJointCommandValue2 {
    word signal;
    word padding[3];
};

struct ORawCameraCommandValue {
    word signal;
    word padding[3];
    void Set(word sig) { signal = sig; }
};

struct ORawLEDCommandValue {
    word signal;
    word padding[3];
    void Set(word sig) { signal = sig; }
};

/* ------------------------------------------------------------------------ */
/* sensor frame vectors                                                      */

struct OSensorFrameInfo {
    ODataType    type;         /*  0 */
    OPrimitiveID primitiveID;  /*  4 */
    longword     frameNumber;  /*  8 frame number of frame[0] */
    longword     numFrames;    /* 12 */
    longword     frameSize;    /* 16 */
    longword     dataOffset;   /* 20 */
    longword     dataSize;     /* 24 */
    longword     padding;      /* 28 */
};

struct OSensorValue {
    slongword value;
    word      signal;
    word      padding[5];
};

typedef OSensorValue OAcceleration;
typedef OSensorValue OAngularVelocity;
typedef OSensorValue OTemperature;
typedef OSensorValue OForce;
typedef OSensorValue OPressure;
typedef OSensorValue OLength;

struct OSwitchStatus {
    OSwitchValue value;
    word         signal;
    word         padding[5];
};

struct OJointValue {
    slongword value;      /*  0 micro-radians */
    word      signal;     /*  4 raw feedback */
    sword     pwmDuty;    /*  6 */
    slongword refValue;   /*  8 commanded value */
    word      refSignal;  /* 12 */
    word      padding;    /* 14 */

    OJointValue() {}
    OJointValue(slongword v, word s, sword pwm, slongword rv, word rs)
        : value(v), signal(s), pwmDuty(pwm), refValue(rv), refSignal(rs), padding(0) {}
};

struct OSensorFrameData {
    OSensorValue frame[16];   /* osensorframeMAX_FRAMES */
};

struct OSensorFrameVectorData {
    ODataVectorInfo  vectorInfo;
    OSensorFrameInfo info[1];

    void              SetNumData(size_t n) { vectorInfo.numData = (longword)n; }
    OSensorFrameInfo* GetInfo(int index) { return &info[index]; }
    OSensorFrameData* GetData(int index) {
        return (OSensorFrameData*)((byte*)&vectorInfo + info[index].dataOffset);
    }
};

/* ------------------------------------------------------------------------ */
/* sound vectors                                                             */

typedef word OSoundFormat;
const OSoundFormat osoundformatUNDEF    = 0;
const OSoundFormat osoundformatPCM      = 1;
const OSoundFormat osoundformatUSB_MIDI = 2;
const OSoundFormat osoundformatSMF      = 3;

typedef word OSoundChannel;
const OSoundChannel osoundchannelUNDEF  = 0;
const OSoundChannel osoundchannelMONO   = 1;
const OSoundChannel osoundchannelSTEREO = 2;

struct OSoundInfo {
    ODataType     type;            /*  0 */
    OPrimitiveID  primitiveID;     /*  4 */
    longword      frameNumber;     /*  8 */
    longword      frameSize;       /* 12 */
    longword      dataOffset;      /* 16 */
    longword      maxDataSize;     /* 20 */
    longword      dataSize;        /* 24 */
    OSoundFormat  format;          /* 28 */
    OSoundChannel channel;         /* 30 */
    word          samplingRate;    /* 32 */
    word          bitsPerSample;   /* 34 */
    longword      actualDataSize;  /* 36 */
    longword      padding[6];      /* 40 */

    void Set(ODataType t, OPrimitiveID id, size_t dsize) {
        type        = t;
        primitiveID = id;
        dataSize    = (longword)dsize;
    }
};

struct OSoundSampleStereo16 {
    sword L;
    sword R;
};

struct OSoundVectorData {
    ODataVectorInfo vectorInfo;
    OSoundInfo      info[1];

    void        SetNumData(size_t n) { vectorInfo.numData = (longword)n; }
    OSoundInfo* GetInfo(int index) { return &info[index]; }
    byte*       GetData(int index) {
        return (byte*)&vectorInfo + info[index].dataOffset;
    }
};

/* ------------------------------------------------------------------------ */
/* filter-bank image vectors                                                 */

typedef int OFbkImageLayer;
const OFbkImageLayer ofbkimageLAYER_H = 0;
const OFbkImageLayer ofbkimageLAYER_M = 1;
const OFbkImageLayer ofbkimageLAYER_L = 2;
const OFbkImageLayer ofbkimageLAYER_C = 3;

struct OFbkImageInfo {
    ODataType    type;         /*  0 */
    OPrimitiveID primitiveID;  /*  4 */
    longword     frameNumber;  /*  8 */
    longword     dataOffset;   /* 12 */
    longword     dataSize;     /* 16 */
    longword     width;        /* 20 */
    longword     height;       /* 24 */
    longword     padding;      /* 28 */
};

struct OFbkImageVectorData {
    ODataVectorInfo vectorInfo;
    OFbkImageInfo   info[1];

    void           SetNumData(size_t n) { vectorInfo.numData = (longword)n; }
    OFbkImageInfo* GetInfo(int index) { return &info[index]; }
    byte*          GetData(int index) {
        return (byte*)&vectorInfo + info[index].dataOffset;
    }
    void SetPrimitiveID(OPrimitiveID id) {
        for (longword i = 0; i < vectorInfo.numData; i++) info[i].primitiveID = id;
    }
};

/* ------------------------------------------------------------------------ */
/* colour detection tables                                                   */

typedef longword OCdtChannel;
const OCdtChannel ocdtCHANNEL_UNDEF = 0x00;
const OCdtChannel ocdtCHANNEL0      = 0x01;
const OCdtChannel ocdtCHANNEL1      = 0x02;
const OCdtChannel ocdtCHANNEL2      = 0x04;
const OCdtChannel ocdtCHANNEL3      = 0x08;
const OCdtChannel ocdtCHANNEL4      = 0x10;
const OCdtChannel ocdtCHANNEL5      = 0x20;
const OCdtChannel ocdtCHANNEL6      = 0x40;
const OCdtChannel ocdtCHANNEL7      = 0x80;
const int         ocdtNUM_CHANNELS  = 8;
const int         ocdtMAX_Y_SEGMENT = 32;

const longword ocdtCr_MIN_MASK = 0x000000ff;
const longword ocdtCr_MAX_MASK = 0x0000ff00;
const longword ocdtCb_MIN_MASK = 0x00ff0000;
const longword ocdtCb_MAX_MASK = 0xff000000;
const longword ocdtINIT        = 0x80808080;

struct OCdtInfo {
    ODataType    type;          /*   0 odataCDT */
    OPrimitiveID primitiveID;   /*   4 camera */
    OCdtChannel  channel;       /*   8 */
    longword     table[32];     /*  12 ocdtMAX_Y_SEGMENT entries */
    longword     padding;       /* 140 */

    void Init(OPrimitiveID prmID, OCdtChannel chan) {
        type        = odataCDT;
        primitiveID = prmID;
        channel     = chan;
        for (int i = 0; i < 32; i++) table[i] = ocdtINIT;
    }
    void Set(int y_segment, byte cr_max, byte cr_min, byte cb_max, byte cb_min) {
        table[y_segment] = ((longword)cr_min)
                         | ((longword)cr_max << 8)
                         | ((longword)cb_min << 16)
                         | ((longword)cb_max << 24);
    }
};

struct OCdtVectorData {
    ODataVectorInfo vectorInfo;
    OCdtInfo        info[8];   /* ocdtNUM_CHANNELS */

    void      SetNumData(size_t n) { vectorInfo.numData = (longword)n; }
    OCdtInfo* GetInfo(int index) { return &info[index]; }
};

/* ------------------------------------------------------------------------ */
/* obsolete / internal formats                                               */

struct OPrimitiveInfo {
    ODataType      type;
    OPrimitiveID   primitiveID;
    OPrimitiveType primitiveType;
    OSensorType    sensorType;
    longword       primitiveStatus;
    longword       padding[3];
    char           locator[128];
};

struct OPrimitiveMapData {
    ODataVectorInfo vectorInfo;
    OPrimitiveInfo  info[1];

    void            SetNumData(size_t n) { vectorInfo.numData = (longword)n; }
    OPrimitiveInfo* GetInfo(int index) { return &info[index]; }
};

struct OCPCInfo {
    ODataType type;
    word      cpcClass;
    word      cpcSubClass;
    word      cpcType;
    word      numReceptors;
};

struct OCPCTreeData {
    ODataVectorInfo vectorInfo;
    OCPCInfo        info[1];

    void      SetNumData(size_t n) { vectorInfo.numData = (longword)n; }
    OCPCInfo* GetInfo(int index) { return &info[index]; }
};

/* ------------------------------------------------------------------------ */
/* layout checks (robot-api 6)                                               */

OPENR_STATIC_CHECK(sizeof(ODataVectorInfo) == 192, ODataVectorInfo_192);
OPENR_STATIC_CHECK(offsetof(ODataVectorInfo, optional) == 64, ODataVectorInfo_optional_64);
OPENR_STATIC_CHECK(sizeof(OCommandInfo) == 32, OCommandInfo_32);
OPENR_STATIC_CHECK(offsetof(OCommandVectorData, info) == 192, OCommandVectorData_info_192);
OPENR_STATIC_CHECK(sizeof(OCommandValue) == 8, OCommandValue_8);
OPENR_STATIC_CHECK(sizeof(OCommandData) == 128, OCommandData_128);
OPENR_STATIC_CHECK(sizeof(OJointCommandValue2) == 8, OJointCommandValue2_8);
OPENR_STATIC_CHECK(sizeof(OJointCommandValue3) == 8, OJointCommandValue3_8);
OPENR_STATIC_CHECK(sizeof(OJointCommandValue4) == 8, OJointCommandValue4_8);
OPENR_STATIC_CHECK(sizeof(OLEDCommandValue2) == 8, OLEDCommandValue2_8);
OPENR_STATIC_CHECK(sizeof(OLEDCommandValue3) == 8, OLEDCommandValue3_8);
OPENR_STATIC_CHECK(sizeof(OSensorFrameInfo) == 32, OSensorFrameInfo_32);
OPENR_STATIC_CHECK(offsetof(OSensorFrameVectorData, info) == 192, OSensorFrameVectorData_info_192);
OPENR_STATIC_CHECK(sizeof(OSensorValue) == 16, OSensorValue_16);
OPENR_STATIC_CHECK(sizeof(OJointValue) == 16, OJointValue_16);
OPENR_STATIC_CHECK(sizeof(OSwitchStatus) == 16, OSwitchStatus_16);
OPENR_STATIC_CHECK(sizeof(OSensorFrameData) == 256, OSensorFrameData_256);
OPENR_STATIC_CHECK(sizeof(OSoundInfo) == 64, OSoundInfo_64);
OPENR_STATIC_CHECK(offsetof(OSoundVectorData, info) == 192, OSoundVectorData_info_192);
OPENR_STATIC_CHECK(sizeof(OFbkImageInfo) == 32, OFbkImageInfo_32);
OPENR_STATIC_CHECK(offsetof(OFbkImageVectorData, info) == 192, OFbkImageVectorData_info_192);
OPENR_STATIC_CHECK(sizeof(OCdtInfo) == 144, OCdtInfo_144);
OPENR_STATIC_CHECK(sizeof(OCdtVectorData) == 192 + 8 * 144, OCdtVectorData_1344);
OPENR_STATIC_CHECK(sizeof(OPrimitiveInfo) == 160, OPrimitiveInfo_160);
OPENR_STATIC_CHECK(sizeof(OCPCInfo) == 12, OCPCInfo_12);

#endif /* _ODataFormats_h_DEFINED */
