/*
 * OPENR/ODataArchive.h - access to ODA data archives (ers7-model 15).
 * Declared for completeness; implemented by the runtime library.
 */
#ifndef _ODataArchive_h_DEFINED
#define _ODataArchive_h_DEFINED

#include <Types.h>
#include <OPENR/OStatus.h>

typedef longword ODataArchiveMagic;
const ODataArchiveMagic odamagicOSND  = 0x444e534f;   /* 'OSND' */
const ODataArchiveMagic odamagicODAR  = 0x5241444f;   /* 'ODAR' */
const ODataArchiveMagic odamagicOMTN  = 0x4e544d4f;   /* 'OMTN' */
const ODataArchiveMagic odamagicWAVE  = 0x45564157;   /* 'WAVE' */
const ODataArchiveMagic odamagicMIDI  = 0x4944494d;   /* 'MIDI' */
const ODataArchiveMagic odamagicLED   = 0x0044454c;   /* 'LED'  */
const ODataArchiveMagic odamagicSYN   = 0x004e5953;   /* 'SYN'  */
const ODataArchiveMagic odamagicSTT   = 0x00545453;   /* 'STT'  */
const ODataArchiveMagic odamagicUNDEF = 0xffffffff;

typedef longword ODataArchiveID;
const size_t         odaMAX_SIZE  = 32;
const ODataArchiveID odaID_UNDEF  = 0xffffffff;

namespace ODataArchive {

OStatus Load(const char* path, ODataArchiveID* id);
OStatus New(size_t numFiles, ODataArchiveID* id);
OStatus Delete(ODataArchiveID id);
OStatus Find(ODataArchiveID id, const char* name, int* index);
int     GetNumFiles(ODataArchiveID id);
ODataArchiveMagic GetMagic(ODataArchiveID id, int index);
const char*       GetName(ODataArchiveID id, int index);
size_t            GetSize(ODataArchiveID id, int index);
byte*             GetData(ODataArchiveID id, int index);
size_t            GetOffset(ODataArchiveID id, int index);
OStatus SetData(ODataArchiveID id, int index, ODataArchiveMagic magic,
                const char* name, const byte* data, size_t size);
OStatus Save(ODataArchiveID id, const char* path);

} /* namespace ODataArchive */

#endif /* _ODataArchive_h_DEFINED */
