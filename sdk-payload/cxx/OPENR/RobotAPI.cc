// RobotAPI.cc - the OPENR:: hardware families (robot-api 4.1-4.4): primitives, data
// vectors, joint gains, joint and sensor readings, sync keys.  The virtual robot lives
// in the runtime; these only move arguments across openr_host.h.
#include <string.h>

#include <OPENR/OPENRAPI.h>

#include "openr_host.h"

namespace {

const openr_host_api* host() { return openr_host(); }

// The vectors are allocated by the runtime so that their layout has one source.
template <class V>
OStatus newVector(int kind, size_t n, size_t dataSize, MemoryRegionID* memID, V** base)
{
    const openr_host_api* api = host();
    if (api == 0) return oFAIL;
    if (memID == 0 || base == 0) return oINVALID_ARG;
    unsigned int id = 0;
    void* p = 0;
    OStatus st = api->new_vector(kind, n, dataSize, &id, &p);
    if (st != oSUCCESS) return st;
    *memID = id;
    *base = static_cast<V*>(p);
    return oSUCCESS;
}

OStatus deleteVector(MemoryRegionID memID)
{
    const openr_host_api* api = host();
    return api == 0 ? oFAIL : api->delete_vector(memID);
}

OStatus gain(int op, OPrimitiveID id, word* g)
{
    const openr_host_api* api = host();
    return api == 0 ? oFAIL : api->joint_gain(op, id, g);
}

OStatus readGains(int op, OPrimitiveID id, word* pg, word* ig, word* dg, word* ps, word* is, word* ds)
{
    word g[6] = {0, 0, 0, 0, 0, 0};
    OStatus st = gain(op, id, g);
    // On any error all six outputs are 0 (robot-api 4.3).
    word* out[6] = {pg, ig, dg, ps, is, ds};
    for (int i = 0; i < 6; i++)
        if (out[i] != 0) *out[i] = st == oSUCCESS ? g[i] : 0;
    return st;
}

} // namespace

namespace OPENR {

OStatus OpenPrimitive(const char* locator, OPrimitiveID* primitiveID)
{
    if (primitiveID != 0) *primitiveID = oprimitiveID_UNDEF;
    if (locator == 0 || primitiveID == 0) return oINVALID_ARG;
    const openr_host_api* api = host();
    if (api == 0) return oFAIL;
    unsigned int id = oprimitiveID_UNDEF;
    OStatus st = api->open_primitive(locator, &id);
    if (st == oSUCCESS) *primitiveID = id;
    return st;
}

OStatus ClosePrimitive(OPrimitiveID primitiveID)
{
    const openr_host_api* api = host();
    return api == 0 ? oFAIL : api->close_primitive(primitiveID);
}

OStatus ControlPrimitive(OPrimitiveID primitiveID, OPrimitiveRequest request, void* param,
                         size_t paramSize, void* result, size_t resultSize)
{
    if (openr_rp_unavailable("ControlPrimitive")) return oFAIL;
    const openr_host_api* api = host();
    return api == 0 ? oFAIL
                    : api->control_primitive(primitiveID, request, param, paramSize, result, resultSize);
}

OStatus NewCommandVectorData(size_t numCommands, MemoryRegionID* memID, OCommandVectorData** baseAddr)
{
    return newVector(OPENR_VECTOR_COMMAND, numCommands, 0, memID, baseAddr);
}

OStatus DeleteCommandVectorData(MemoryRegionID memID) { return deleteVector(memID); }

OStatus NewSoundVectorData(size_t numSounds, size_t dataSize, MemoryRegionID* memID,
                           OSoundVectorData** baseAddr)
{
    if (openr_rp_unavailable("NewSoundVectorData")) return oFAIL;
    return newVector(OPENR_VECTOR_SOUND, numSounds, dataSize, memID, baseAddr);
}

OStatus DeleteSoundVectorData(MemoryRegionID memID) { if (openr_rp_unavailable("DeleteSoundVectorData")) return oFAIL; return deleteVector(memID); }

OStatus NewCdtVectorData(MemoryRegionID* memID, OCdtVectorData** baseAddr)
{
    if (openr_rp_unavailable("NewCdtVectorData")) return oFAIL;
    return newVector(OPENR_VECTOR_CDT, 8, 0, memID, baseAddr);
}

OStatus DeleteCdtVectorData(MemoryRegionID memID) { if (openr_rp_unavailable("DeleteCdtVectorData")) return oFAIL; return deleteVector(memID); }

OStatus SetCdtVectorData(MemoryRegionID memID)
{
    if (openr_rp_unavailable("SetCdtVectorData")) return oFAIL;
    const openr_host_api* api = host();
    return api == 0 ? oFAIL : api->set_cdt(memID);
}

OStatus NewSensorFrameVectorData(size_t numSensors, MemoryRegionID* memID,
                                 OSensorFrameVectorData** baseAddr)
{
    return newVector(OPENR_VECTOR_SENSOR, numSensors, 0, memID, baseAddr);
}

OStatus DeleteSensorFrameVectorData(MemoryRegionID memID) { return deleteVector(memID); }

OStatus NewFbkImageVectorData(MemoryRegionID* memID, OFbkImageVectorData** baseAddr)
{
    return newVector(OPENR_VECTOR_IMAGE, 4, 0, memID, baseAddr);
}

OStatus DeleteFbkImageVectorData(MemoryRegionID memID) { return deleteVector(memID); }

OStatus EnableJointGain(OPrimitiveID id) { return gain(OPENR_GAIN_ENABLE, id, 0); }
OStatus DisableJointGain(OPrimitiveID id) { return gain(OPENR_GAIN_DISABLE, id, 0); }
OStatus SetDefaultJointGain(OPrimitiveID id) { return gain(OPENR_GAIN_SET_DEFAULT, id, 0); }

OStatus SetJointGain(OPrimitiveID id, word pg, word ig, word dg, word ps, word is, word ds)
{
    word g[6] = {pg, ig, dg, ps, is, ds};
    return gain(OPENR_GAIN_SET, id, g);
}

OStatus RegisterDefaultJointGain(OPrimitiveID id, word pg, word ig, word dg, word ps, word is, word ds)
{
    word g[6] = {pg, ig, dg, ps, is, ds};
    return gain(OPENR_GAIN_REGISTER_DEFAULT, id, g);
}

OStatus GetJointGain(OPrimitiveID id, word* pg, word* ig, word* dg, word* ps, word* is, word* ds)
{
    return readGains(OPENR_GAIN_GET, id, pg, ig, dg, ps, is, ds);
}

OStatus GetDefaultJointGain(OPrimitiveID id, word* pg, word* ig, word* dg, word* ps, word* is, word* ds)
{
    return readGains(OPENR_GAIN_GET_DEFAULT, id, pg, ig, dg, ps, is, ds);
}

OStatus GetJointValue(OPrimitiveID id, OJointValue* value)
{
    if (value == 0) return oINVALID_ARG;
    const openr_host_api* api = host();
    return api == 0 ? oFAIL : api->joint_value(id, value);
}

OStatus GetSensorValue(OPrimitiveID id, OSensorValue* value)
{
    if (value == 0) return oINVALID_ARG;
    const openr_host_api* api = host();
    return api == 0 ? oFAIL : api->sensor_value(id, value);
}

OStatus NewSyncKey(OVRSyncKey* key)
{
    const openr_host_api* api = host();
    if (key == 0) return oINVALID_ARG;
    unsigned int k = ovrsynckeyUNDEF;
    OStatus st = api == 0 ? oFAIL : api->sync_key(OPENR_SYNC_NEW, 0, &k, 0);
    *key = st == oSUCCESS ? k : ovrsynckeyUNDEF;
    return st;
}

OStatus CancelSyncKey(OVRSyncKey key)
{
    const openr_host_api* api = host();
    return api == 0 ? oFAIL : api->sync_key(OPENR_SYNC_CANCEL, key, 0, 0);
}

OStatus DivideSyncKey(OVRSyncKey key, OVRSyncKey* key1, OVRSyncKey* key2)
{
    const openr_host_api* api = host();
    if (key1 == 0 || key2 == 0) return oINVALID_ARG;
    unsigned int a = ovrsynckeyUNDEF, b = ovrsynckeyUNDEF;
    OStatus st = api == 0 ? oFAIL : api->sync_key(OPENR_SYNC_DIVIDE, key, &a, &b);
    *key1 = a;
    *key2 = b;
    return st;
}

OStatus SetVolumeSwitch(OVolumeSwitch volumeSwitch)
{
    const openr_host_api* api = host();
    unsigned char v = volumeSwitch;
    return api == 0 ? oFAIL : api->volume_switch(1, &v);
}

OStatus GetVolumeSwitch(OVolumeSwitch* volumeSwitch)
{
    const openr_host_api* api = host();
    if (volumeSwitch == 0) return oINVALID_ARG;
    unsigned char v = 0;
    OStatus st = api == 0 ? oFAIL : api->volume_switch(0, &v);
    *volumeSwitch = v;
    return st;
}

} // namespace OPENR
