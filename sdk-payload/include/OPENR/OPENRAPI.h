/*
 * OPENR/OPENRAPI.h - the OPENR:: robot API (robot-api 4). Implemented by the
 * runtime library; every function returns an OStatus.
 */
#ifndef _OPENRAPI_h_DEFINED
#define _OPENRAPI_h_DEFINED

#include <OPENR/OPENR.h>
#include <OPENR/ODataFormats.h>
#include <OPENR/OPrimitiveControl.h>
#include <OPENR/OPower.h>
#include <OPENR/MWInformationTypes.h>

namespace OPENR {

/* primitives */
OStatus OpenPrimitive(const char* locator, OPrimitiveID* primitiveID);
OStatus ClosePrimitive(OPrimitiveID primitiveID);
OStatus ControlPrimitive(OPrimitiveID primitiveID, OPrimitiveRequest request,
                         void* param, size_t paramSize,
                         void* result, size_t resultSize);

/* shared-memory data vectors */
OStatus NewCommandVectorData(size_t numCommands, MemoryRegionID* memID,
                             OCommandVectorData** baseAddr);
OStatus DeleteCommandVectorData(MemoryRegionID memID);
OStatus NewSoundVectorData(size_t numSounds, size_t dataSize,
                           MemoryRegionID* memID, OSoundVectorData** baseAddr);
OStatus DeleteSoundVectorData(MemoryRegionID memID);
OStatus NewCdtVectorData(MemoryRegionID* memID, OCdtVectorData** baseAddr);
OStatus DeleteCdtVectorData(MemoryRegionID memID);
OStatus SetCdtVectorData(MemoryRegionID memID);
OStatus NewSensorFrameVectorData(size_t numSensors, MemoryRegionID* memID,
                                 OSensorFrameVectorData** baseAddr);
OStatus DeleteSensorFrameVectorData(MemoryRegionID memID);
OStatus NewFbkImageVectorData(MemoryRegionID* memID, OFbkImageVectorData** baseAddr);
OStatus DeleteFbkImageVectorData(MemoryRegionID memID);

/* joint gains, joint and sensor values */
OStatus EnableJointGain(OPrimitiveID primitiveID);
OStatus DisableJointGain(OPrimitiveID primitiveID);
OStatus SetJointGain(OPrimitiveID primitiveID,
                     word pg, word ig, word dg, word ps, word is, word ds);
OStatus RegisterDefaultJointGain(OPrimitiveID primitiveID,
                                 word pg, word ig, word dg, word ps, word is, word ds);
OStatus SetDefaultJointGain(OPrimitiveID primitiveID);
OStatus GetJointGain(OPrimitiveID primitiveID,
                     word* pg, word* ig, word* dg, word* ps, word* is, word* ds);
OStatus GetDefaultJointGain(OPrimitiveID primitiveID,
                            word* pg, word* ig, word* dg, word* ps, word* is, word* ds);
OStatus GetJointValue(OPrimitiveID primitiveID, OJointValue* value);
OStatus GetSensorValue(OPrimitiveID primitiveID, OSensorValue* value);

/* synchronisation keys */
OStatus NewSyncKey(OVRSyncKey* key);
OStatus CancelSyncKey(OVRSyncKey key);
OStatus DivideSyncKey(OVRSyncKey key, OVRSyncKey* key1, OVRSyncKey* key2);

/* power, boot, time, volume */
OStatus SetMotorPower(OPower power);
OStatus Shutdown(const OBootCondition& bootCondition);
OStatus GetBootCondition(OBootCondition* bootCondition);
OStatus GetPowerStatus(OPowerStatus* powerStatus);
OStatus ObservePowerStatus(const OPowerStatus& notifyStatus, const OServiceEntry& entry);
OStatus UnobservePowerStatus(const OServiceEntry& entry);
OStatus SetTime(const OTime& time);
OStatus GetTime(OTime* time);
OStatus SetTimeDifference(sbyte timeDifference);
OStatus GetTimeDifference(sbyte* timeDifference);
OStatus SetVolumeSwitch(OVolumeSwitch volumeSwitch);
OStatus GetVolumeSwitch(OVolumeSwitch* volumeSwitch);
OStatus Fatal(OFatal fatal);
OStatus GetMemoryStickStatus(OMemoryStickStatus* status);

/* robot design and design data */
OStatus GetRobotDesign(char* design);
OStatus FindDesignData(const char* keyword, ODesignDataID* id, byte** data, size_t* size);
OStatus DeleteDesignData(ODesignDataID id);

/* level-1 (middleware information) */
OStatus RequireMWInfo(MWIID id);
OStatus CancelMWInfo(MWIID id);
OStatus IsMWInfoRequired(MWIID id, bool* required);

} /* namespace OPENR */

#endif /* _OPENRAPI_h_DEFINED */
