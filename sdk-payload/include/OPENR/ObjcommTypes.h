/*
 * OPENR/ObjcommTypes.h - identifiers and constants of inter-object
 * communication (object-model 2.2, 2.5).
 */
#ifndef _ObjcommTypes_h_DEFINED
#define _ObjcommTypes_h_DEFINED

#include <iostream>
#include <string.h>
#include <list>
#include <OPENR/OPENR.h>

/* Old code uses these unqualified (Sony's header declared them globally). */
using std::cout;
using std::endl;
using std::ostream;
using std::list;

/* a subject is identified by its Ready entry, an observer by its Notify entry */
typedef OServiceEntry SubjectID;
typedef OServiceEntry ObserverID;

#define ENTRY2SUBJECTID(entry)  (entry)
#define ENTRY2OBSERVERID(entry) (entry)

typedef int ObjcommMessageType;
const ObjcommMessageType objcommMSG_UNDEF = 0;
const ObjcommMessageType objcommNOTIFY    = 1;
const ObjcommMessageType objcommCONTROL   = 2;
const ObjcommMessageType objcommREADY     = 3;

typedef int ObjcommDataType;
const ObjcommDataType objcommDATA_TYPE_UNDEF = 0;
const ObjcommDataType objcommDATA_TYPE_MSG   = 1;
const ObjcommDataType objcommDATA_TYPE_SHM   = 2;

typedef int ObjcommStatus;
const ObjcommStatus objcommSUCCESS             = 0;
const ObjcommStatus objcommNOTIFY_UNDEF        = 1;
const ObjcommStatus objcommFRAMENUMBER_UNDEF   = 2;
const ObjcommStatus objcommADDOBSERVER_FAIL    = 3;
const ObjcommStatus objcommREMOVEOBSERVER_FAIL = 4;
const ObjcommStatus objcommCOMMAND_UNDEF       = 5;

typedef int ObjcommCommand;
const ObjcommCommand objcommCMD_UNDEF               = 0;
const ObjcommCommand objcommCMD_ADDOBSERVER         = 1;
const ObjcommCommand objcommCMD_REMOVEOBSERVER      = 2;
const ObjcommCommand objcommCMD_ASSERT_READY        = 3;
const ObjcommCommand objcommCMD_DEASSERT_READY      = 4;
const ObjcommCommand objcommCMD_ADDOBSERVER_SELF    = 5;
const ObjcommCommand objcommCMD_REMOVEOBSERVER_SELF = 6;
const ObjcommCommand objcommCMD_ADDOBSERVER_V22     = 7;
const ObjcommCommand objcommCMD_REMOVEOBSERVER_V22  = 8;

typedef unsigned int ObjcommVersion;
const ObjcommVersion objcommVERSION10      = 1;
const ObjcommVersion objcommVERSION20      = 2;
const ObjcommVersion objcommVERSION21      = 3;
const ObjcommVersion objcommVERSION22      = 4;
const ObjcommVersion objcommVERSION_UNDEF  = 0xffffffff;

/* debug printers (SubjectID and ObserverID are the same type); runtime library */
std::ostream& operator<<(std::ostream& os, const OServiceEntry& entry);

#endif /* _ObjcommTypes_h_DEFINED */
