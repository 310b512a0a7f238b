// OObserver.cc - receiving side of the subject/observer protocol (object-model 2.7, 2.8).
#include <string.h>

#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <OPENR/OObserver.h>
#include <OPENR/OSyslog.h>

#include "objcomm_internal.h"
#include "openr_host.h"

namespace {

// Sony's observer waits this long for a subject's OControlReplyMessage.
const unsigned int kControlTimeoutMs = 15000;

OID selfOID()
{
    OID self;
    WhoAmI(&self);
    return self;
}

// Self connection (2.8.1 step 6): runs this object's own entry for `selector` with `msg`
// (a direct in-object invocation instead of a message); the subject answers through
// objcommSelfReply.
bool invokeOwnEntry(Selector selector, const OControlMessage& msg, OControlReplyMessage* reply)
{
    for (int i = 0; ObjectEntryTable[i].selector != UNDEF; i++) {
        if (ObjectEntryTable[i].selector != selector) continue;
        // A copy with some slack after it, as the runtime gives to every entry.
        union {
            char   bytes[sizeof(OControlMessage) + 64];
            double align;
        } buf;
        memset(buf.bytes, 0, sizeof(buf.bytes));
        memcpy(buf.bytes, &msg, sizeof(msg));
        OControlReplyMessage* saved = objcommSelfReply;
        objcommSelfReply = reply;
        reinterpret_cast<void (*)(void*)>(ObjectEntryTable[i].entry)(buf.bytes);
        objcommSelfReply = saved;
        return true;
    }
    return false;
}

// Sends an OControlMessage to a subject's Control entry and waits for its reply.
OStatus control(const OServiceEntry& entry, OControlMessage ctl, OControlReplyMessage* reply,
                ObjcommCommand remote, ObjcommCommand self)
{
    *reply = OControlReplyMessage();
    if (entry.GetOID() == selfOID()) {
        ctl.command = self;
        if (!invokeOwnEntry(entry.GetSelector(), ctl, reply)) return oNOT_FOUND;
    } else {
        ctl.command = remote;
        const openr_host_api* api = openr_host();
        if (api == 0) return oFAIL;
        size_t got = 0;
        int rc = api->call(entry.GetOID().GetAddress(), entry.GetSelector(), &ctl, sizeof(ctl),
                           reply, sizeof(*reply), &got, kControlTimeoutMs);
        if (rc != 0) {
            OSYSLOG1((osyslogERROR, "OObserver : no answer from subject %s (%s)", ctl.subName,
                      rc == -3 ? "timeout" : "unknown object"));
            return rc == -3 ? oFAIL : oINVALID_OID;
        }
        if (got < sizeof(*reply)) return oREFUSED;
    }
    if (reply->msgType != omsgCONTROL_REPLY || reply->status != oSUCCESS) return oREFUSED;
    return oSUCCESS;
}

} // namespace

OObserver::OObserver()
    : id_(), d_skip_(0), d_min_(1), d_max_(1), subjects_(), dataManager_(new DataManager()),
      memoryMapAgent_(new MemoryMapAgent()), readyMessage_(new OReadyMessage())
{
}

OObserver::~OObserver()
{
    delete dataManager_;   // releases the regions still held
    delete memoryMapAgent_;
    delete readyMessage_;
}

OStatus OObserver::SetNotifyEntry(const OServiceEntry& entry)
{
    if (!subjects_.empty()) {
        OSYSLOG1((osyslogERROR, "OObserver::SetNotifyEntry() : subjects are already connected"));
        return oALREADY_EXIST;
    }
    id_ = entry;
    return oSUCCESS;
}

/* ---- connection (2.8.1) ---- */

OStatus OObserver::ConnectHandler(const OConnectMessage& msg, OStatus status)
{
    OStatus result;
    if (msg.msgType != omsgCONNECT) {
        result = oWRONG_MESSAGE;
    } else if (!id_.IsValid()) {
        result = oNOT_INITIALIZED;
    } else if (status != oSUCCESS) {
        result = status;   // refused by the Connect function
    } else if (msg.command == oconnectcmdCONNECT) {
        OControlMessage ctl(objcommCMD_ADDOBSERVER_V22, id_, d_skip_, d_min_, d_max_, msg.subName);
        OControlReplyMessage reply;
        result = control(msg.entry, ctl, &reply, objcommCMD_ADDOBSERVER_V22,
                         objcommCMD_ADDOBSERVER_SELF);
        if (result == oSUCCESS) {
            SubjectConstIterator it = subjects_.begin();
            while (it != subjects_.end() && !(it->GetSubjectID() == reply.subjectID)) ++it;
            if (it == subjects_.end()) subjects_.push_back(OSubjectInfo(reply.subjectID, objcommVERSION22));
        } else {
            OSYSLOG1((osyslogWARNING, "OObserver::ConnectHandler() : connection to %s refused",
                      msg.subName));
        }
    } else if (msg.command == oconnectcmdDISCONNECT || msg.command == oconnectcmdDISCONNECTALL) {
        OControlMessage ctl(objcommCMD_REMOVEOBSERVER_V22, id_, d_skip_, d_min_, d_max_, msg.subName);
        OControlReplyMessage reply;
        result = control(msg.entry, ctl, &reply, objcommCMD_REMOVEOBSERVER_V22,
                         objcommCMD_REMOVEOBSERVER_SELF);
        if (result == oSUCCESS) {
            // Give back what we still hold from it, then forget it.
            DeassertReady(reply.subjectID);
            for (std::list<OSubjectInfo>::iterator it = subjects_.begin(); it != subjects_.end(); ++it) {
                if (it->GetSubjectID() == reply.subjectID) {
                    subjects_.erase(it);
                    break;
                }
            }
        }
    } else {
        result = oUNKNOWN_COMMAND;
    }

    OStatusMessage answer(result);
    const openr_host_api* api = openr_host();
    if (api != 0) api->reply(&answer, sizeof(answer));
    return result;
}

OStatus OObserver::ConnectHandler(OConnectMessage* msg)
{
    if (msg == 0) return oINVALID_ARG;
    return ConnectHandler(*msg, oSUCCESS);
}

/* ---- notification (2.8.2) ---- */

OStatus OObserver::NotifyHandler(const ONotifyMessage& msg, ONotifyEvent* event)
{
    if (msg.msgType != omsgNOTIFY_V22) return oWRONG_MESSAGE;
    OSubjectInfo info(msg.subjectID, objcommVERSION22);
    for (SubjectConstIterator it = subjects_.begin(); it != subjects_.end(); ++it) {
        if (it->GetSubjectID() == msg.subjectID) {
            info = *it;
            break;
        }
    }
    int n = msg.numOfData;
    if (n < 0) n = 0;
    if (n > MAX_NUM_DATA) n = MAX_NUM_DATA;
    for (int k = 0; k < n; k++) {
        const TransferedData& d = msg.data[k];
        char* base = static_cast<char*>(memoryMapAgent_->Attach(d.memID));
        RCRegion* r = new RCRegion(d.memID, d.offset, base != 0 ? base + d.offset : 0, d.size);
        dataManager_->Add(msg.subjectID, r, d.srcRCR);
        if (event != 0) event->SetData(k, r);
    }
    if (event != 0) {
        event->SetSubjectInfo(info);
        event->SetNumOfData(n);
        event->SetNumOfNotify(msg.numOfNotify);
    }
    return oSUCCESS;
}

OStatus OObserver::NotifyHandler(ONotifyMessage* msg, ONotifyEvent* event)
{
    if (msg == 0) return oINVALID_ARG;
    return NotifyHandler(*msg, event);
}

/* ---- ready (2.8.2) ---- */

namespace {

// Returns everything received from `subject` (the observer-side handles lose their
// reference, the subject's own pointers travel back) with an ASSERT/DEASSERT-READY.
OStatus sendReady(const ObserverID& self, DataManager* dm, OReadyMessage* m,
                  const SubjectID& subject, ObjcommCommand command)
{
    *m = OReadyMessage(command, self);
    m->numOfData = dm->Collect(subject, m->rcRegion, MAX_NUM_DATA);
    const openr_host_api* api = openr_host();
    if (api == 0 || api->send(subject.GetOID().GetAddress(), subject.GetSelector(), m,
                              sizeof(OReadyMessage)) != 0) {
        OSYSLOG1((osyslogERROR, "OObserver : cannot send %s to a subject",
                  command == objcommCMD_ASSERT_READY ? "ASSERT-READY" : "DEASSERT-READY"));
        return oFAIL;
    }
    return oSUCCESS;
}

} // namespace

OStatus OObserver::AssertReady()
{
    if (subjects_.empty()) return oFAIL;
    for (SubjectConstIterator it = subjects_.begin(); it != subjects_.end(); ++it) {
        sendReady(id_, dataManager_, readyMessage_, *it, objcommCMD_ASSERT_READY);
    }
    return oSUCCESS;
}

OStatus OObserver::DeassertReady()
{
    if (subjects_.empty()) return oFAIL;
    for (SubjectConstIterator it = subjects_.begin(); it != subjects_.end(); ++it) {
        sendReady(id_, dataManager_, readyMessage_, *it, objcommCMD_DEASSERT_READY);
    }
    return oSUCCESS;
}

OStatus OObserver::AssertReady(const SubjectID& id)
{
    for (SubjectConstIterator it = subjects_.begin(); it != subjects_.end(); ++it) {
        if (it->GetSubjectID() == id) {
            sendReady(id_, dataManager_, readyMessage_, id, objcommCMD_ASSERT_READY);
            return oSUCCESS;
        }
    }
    return oFAIL;
}

OStatus OObserver::DeassertReady(const SubjectID& id)
{
    for (SubjectConstIterator it = subjects_.begin(); it != subjects_.end(); ++it) {
        if (it->GetSubjectID() == id) {
            sendReady(id_, dataManager_, readyMessage_, id, objcommCMD_DEASSERT_READY);
            return oSUCCESS;
        }
    }
    return oFAIL;
}

OStatus OObserver::AssertReadyFor(RCRegion* received)
{
    SubjectID subject;
    RCRegion* source = 0;
    if (!dataManager_->CollectOne(received, &subject, &source)) return oNOT_FOUND;
    *readyMessage_ = OReadyMessage(objcommCMD_ASSERT_READY, id_);
    readyMessage_->numOfData = 1;
    readyMessage_->rcRegion[0] = source;
    const openr_host_api* api = openr_host();
    if (api == 0 || api->send(subject.GetOID().GetAddress(), subject.GetSelector(), readyMessage_,
                              sizeof(OReadyMessage)) != 0)
        return oFAIL;
    return oSUCCESS;
}

OStatus OObserver::AssertReady(const OSubjectInfo& info)
{
    return AssertReady(info.GetSubjectID());
}

OStatus OObserver::DeassertReady(const OSubjectInfo& info)
{
    return DeassertReady(info.GetSubjectID());
}

/* ---- queries ---- */

SubjectConstIterator OObserver::begin() const
{
    return subjects_.begin();
}

SubjectConstIterator OObserver::end() const
{
    return subjects_.end();
}

SubjectID OObserver::FindSender(RCRegion* region) const
{
    return dataManager_->FindSender(region);
}

int OObserver::NumberOfSubjects() const
{
    return (int)subjects_.size();
}

const ObserverID& OObserver::GetID() const
{
    return id_;
}

const ObserverID& OObserver::GetObserverID() const
{
    return id_;
}
