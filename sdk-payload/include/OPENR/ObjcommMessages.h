/*
 * OPENR/ObjcommMessages.h - messages of the subject/observer protocol
 * (object-model 2.5, 2.8). Host layout: pointer and size_t fields are
 * host-sized; names and order follow the robot.
 */
#ifndef _ObjcommMessages_h_DEFINED
#define _ObjcommMessages_h_DEFINED

#include <Types.h>
#include <OPENR/OPENR.h>
#include <OPENR/OPENRMessages.h>
#include <OPENR/OMemoryLocator.h>
#include <OPENR/ObjcommTypes.h>
#include <OPENR/SharedMemoryAllocator.h>
#include <OPENR/RCRegion.h>

/* message types (a separate numbering space from OPENRMessages.h) */
const OMessageType omsgCONTROL           = 12;
const OMessageType omsgCONTROL_REPLY     = 13;
const OMessageType omsgREADY             = 14;
const OMessageType omsgNOTIFY            = 15;
const OMessageType omsgCONTROL_V21       = 256;
const OMessageType omsgCONTROL_REPLY_V21 = 257;
const OMessageType omsgREADY_V21         = 258;
const OMessageType omsgNOTIFY_V21        = 259;
const OMessageType omsgNOTIFY_L10        = 260;
const OMessageType omsgREADY_V22         = 261;
const OMessageType omsgNOTIFY_V22        = 262;

/* maximum number of regions in one notification */
#define MAX_NUM_DATA 13

/* observer -> subject: connection request (to the subject's Control entry) */
struct OControlMessage {
    OMessageType   msgType;
    ObjcommCommand command;
    ObserverID     observerID;
    size_t         d_skip;
    size_t         d_min;
    size_t         d_max;
    char           subName[128];

    OControlMessage()
        : msgType(omsgCONTROL), command(objcommCMD_UNDEF), observerID(),
          d_skip(0), d_min(1), d_max(1) {
        subName[0] = '\0';
    }
    OControlMessage(ObjcommCommand cmd, const ObserverID& id,
                    size_t skip, size_t dmin, size_t dmax, const char* name)
        : msgType(omsgCONTROL), command(cmd), observerID(id),
          d_skip(skip), d_min(dmin), d_max(dmax) {
        subName[0] = '\0';
        if (name != 0) {
            strncpy(subName, name, sizeof(subName) - 1);
            subName[sizeof(subName) - 1] = '\0';
        }
    }
};

/* subject -> observer: answer to OControlMessage */
struct OControlReplyMessage {
    OMessageType   msgType;
    OStatus        status;
    SubjectID      subjectID;
    MemoryRegionID memID;      /* carries the subject's objcomm version (4) */

    OControlReplyMessage()
        : msgType(omsgCONTROL_REPLY), status(oUNDEF), subjectID(), memID(0) {}
    OControlReplyMessage(OStatus st, const SubjectID& id, MemoryRegionID mem)
        : msgType(omsgCONTROL_REPLY), status(st), subjectID(id), memID(mem) {}
};

/* observer -> subject: ASSERT/DEASSERT-READY, returning received regions */
struct OReadyMessage {
    OMessageType   msgType;
    ObjcommCommand command;
    ObserverID     observerID;
    int            numOfData;
    RCRegion*      rcRegion[MAX_NUM_DATA];

    /* Sony initialises `command` with objcommCOMMAND_UNDEF (5); kept. */
    OReadyMessage()
        : msgType(omsgREADY_V22), command(objcommCOMMAND_UNDEF), observerID(), numOfData(0) {
        for (int i = 0; i < MAX_NUM_DATA; i++) rcRegion[i] = 0;
    }
    OReadyMessage(ObjcommCommand cmd, const ObserverID& id)
        : msgType(omsgREADY_V22), command(cmd), observerID(id), numOfData(0) {
        for (int i = 0; i < MAX_NUM_DATA; i++) rcRegion[i] = 0;
    }
};

/* one region descriptor of a notification */
struct TransferedData {
    RCRegion*      srcRCR;   /* the subject's own region */
    MemoryRegionID memID;
    unsigned int   offset;
    size_t         size;
};

/* subject -> observer: data notification */
struct ONotifyMessage {
    OMessageType   msgType;
    SubjectID      subjectID;
    short          numOfData;
    short          numOfNotify;
    TransferedData data[MAX_NUM_DATA];

    ONotifyMessage() : msgType(omsgNOTIFY_V22), subjectID(), numOfData(0), numOfNotify(0) {}
    ONotifyMessage(const SubjectID& id)
        : msgType(omsgNOTIFY_V22), subjectID(id), numOfData(0), numOfNotify(0) {}

    OStatus Write(RCRegion* r) {
        if (numOfData >= MAX_NUM_DATA || r == 0) return oFAIL;
        TransferedData& d = data[numOfData];
        d.srcRCR = r;
        d.memID  = r->MemID();
        d.offset = r->Offset();
        d.size   = r->Size();
        numOfData++;
        return oSUCCESS;
    }
    void Clear() { numOfData = 0; numOfNotify = 0; }
    size_t GetSizeOfMessage() const {
        return sizeof(ONotifyMessage) - sizeof(TransferedData) * (MAX_NUM_DATA - numOfData);
    }
    int NumberOfData() const { return numOfData; }
    int NumberOfNotify() const { return numOfNotify; }
};

/* ---- objcomm 1.0 leftovers (declared, unused) ---------------------------- */

const int    objcommMAX_NUM_UNLOCK = 29;
const size_t MAX_MESSAGE_SIZE      = 256;

struct OChunkSHM {
    MemoryRegionID memID;
    size_t         offset;
    size_t         size;
};

struct OChunkMSG {
    size_t size;
    byte   data[1];
};

struct OReadyMessageV10 {
    OMessageType   msgType;
    ObjcommCommand command;
    ObserverID     observerID;
    int            numOfUnlock;
    MemoryRegionID unlock[objcommMAX_NUM_UNLOCK];
};

struct ONotifyMessageV10 {
    OMessageType    msgType;
    SubjectID       subjectID;
    ObjcommDataType dataType;
    OChunkSHM       chunk;
};

const size_t HEADER_SIZE = sizeof(OMessageType) + sizeof(SubjectID) + sizeof(ObjcommDataType);

#endif /* _ObjcommMessages_h_DEFINED */
