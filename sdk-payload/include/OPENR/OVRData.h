/*
 * OPENR/OVRData.h - internal payload describing a data vector exchanged with
 * the virtual robot (robot-api 6.8). Not used by applications.
 */
#ifndef _OVRData_h_DEFINED
#define _OVRData_h_DEFINED

#include <OPENR/ODataFormats.h>

const size_t ovrdataMAX_SIZE = 8;

struct OVRData {
    OStatus        status;
    ODataType      type;
    MemoryRegionID dataVectorID;
    longword       offset;

    OVRData() : status(oUNDEF), type(odataUNDEF), dataVectorID(0), offset(0) {}
    OVRData(OStatus s, ODataType t, MemoryRegionID id, longword off)
        : status(s), type(t), dataVectorID(id), offset(off) {}
};

OPENR_STATIC_CHECK(sizeof(OVRData) == 16, OVRData_16);

#endif /* _OVRData_h_DEFINED */
