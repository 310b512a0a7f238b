// OSubject.cc - sending side of the subject/observer protocol (object-model 2.6, 2.8).
#include <string.h>

#include <OPENR/OSubject.h>
#include <OPENR/OSyslog.h>

#include "objcomm_internal.h"
#include "openr_host.h"

OControlReplyMessage* objcommSelfReply = 0;

namespace {

const size_t kMinQueueSize = 14;

_OObserverInfo* rec(const OObserverInfo& info)
{
    return info.GetInfo();
}

// Drops the oldest complete unit (or, with none, the oldest entry) of a queue.
void dropOldest(_OObserverInfo* o)
{
    std::vector<RCRegion*>& q = o->queue;
    size_t k = 0;
    while (k < q.size() && q[k] != OBJCOMM_END_MARKER) k++;
    if (k < q.size()) {
        for (size_t i = 0; i < k; i++) q[i]->RemoveReference();
        q.erase(q.begin(), q.begin() + (k + 1));
        o->n_notify--;
    } else if (!q.empty()) {
        q.front()->RemoveReference();
        q.erase(q.begin());
    }
    o->n_data = (int)q.size();
}

void clearQueue(_OObserverInfo* o)
{
    for (size_t i = 0; i < o->queue.size(); i++) {
        if (o->queue[i] != OBJCOMM_END_MARKER) o->queue[i]->RemoveReference();
    }
    o->queue.clear();
    o->n_data = 0;
    o->n_notify = 0;
    o->skip_counter = 0;
}

} // namespace

OSubject::OSubject()
    : id_(), observers_(), notifyMessage_(new ONotifyMessage()), maxBufferSize_(0),
      notifyUnitSize_(1)
{
    memset(notifyMessage_->data, 0, sizeof(notifyMessage_->data));
}

OSubject::~OSubject()
{
    for (std::list<OObserverInfo>::iterator it = observers_.begin(); it != observers_.end(); ++it) {
        clearQueue(rec(*it));
        delete rec(*it);
    }
    observers_.clear();
    delete notifyMessage_;
}

OStatus OSubject::SetReadyEntry(const OServiceEntry& entry)
{
    if (!observers_.empty()) {
        OSYSLOG1((osyslogERROR, "OSubject::SetReadyEntry() : observers are already connected"));
        return oALREADY_EXIST;
    }
    id_ = entry;
    return oSUCCESS;
}

const SubjectID& OSubject::GetID() const
{
    return id_;
}

OStatus OSubject::SetBufferSize(size_t size)
{
    if (!observers_.empty()) return oALREADY_EXIST;
    maxBufferSize_ = size;
    return oSUCCESS;
}

size_t OSubject::GetBufferSize() const
{
    return maxBufferSize_;
}

OStatus OSubject::SetNotifyUnitSize(size_t size)
{
    if (!observers_.empty()) return oALREADY_EXIST;
    notifyUnitSize_ = size;
    return oSUCCESS;
}

size_t OSubject::GetNotifyUnitSize() const
{
    return notifyUnitSize_;
}

/* ---- SetData (2.8.3) ---- */

OStatus OSubject::SetData(RCRegion* region)
{
    OStatus result = oSUCCESS;
    for (std::list<OObserverInfo>::iterator it = observers_.begin(); it != observers_.end(); ++it) {
        OStatus st = SetData(*it, region);
        if (st != oSUCCESS) result = st;
    }
    return result;
}

OStatus OSubject::SetData(const OObserverInfo& info, RCRegion* region)
{
    _OObserverInfo* o = rec(info);
    if (o == 0 || region == 0) return oINVALID_ARG;
    if (o->ready_flag < 0) return oSUCCESS;           // deasserted: discard
    if (o->skip_counter != o->d_skip) return oSUCCESS; // sub-sampling

    OStatus status = oSUCCESS;
    bool full = o->n_data >= (int)o->q_size - 1;
    if (o->n_notify >= (int)o->d_max || full) {
        if (full && o->n_notify < (int)o->d_max) {
            status = o->n_notify < (int)o->d_min ? oFATAL : oOVERFLOW;
            OSYSLOG1((osyslogERROR, "OSubject::SetData() : buffer of an observer is full, "
                      "oldest data dropped (%s)", status == oFATAL ? "oFATAL" : "oOVERFLOW"));
        }
        dropOldest(o);
    }
    o->queue.push_back(region);
    o->n_data = (int)o->queue.size();
    region->AddReference();
    return status;
}

OStatus OSubject::SetData(const ObserverID& id, RCRegion* region)
{
    ObserverConstIterator it = FindObserver(id);
    if (it == observers_.end()) return oNOT_FOUND;
    return SetData(*it, region);
}

OStatus OSubject::SetData(const void* buf, size_t size)
{
    RCRegion* r = new RCRegion(size);
    if (r->Base() == 0 && size > 0) {
        r->RemoveReference();
        return oNO_MEMORY;
    }
    if (size > 0) memcpy(r->Base(), buf, size);
    OStatus st = SetData(r);
    r->RemoveReference();
    return st;
}

OStatus OSubject::SetData(const OObserverInfo& info, const void* buf, size_t size)
{
    RCRegion* r = new RCRegion(size);
    if (r->Base() == 0 && size > 0) {
        r->RemoveReference();
        return oNO_MEMORY;
    }
    if (size > 0) memcpy(r->Base(), buf, size);
    OStatus st = SetData(info, r);
    r->RemoveReference();
    return st;
}

OStatus OSubject::SetData(const ObserverID& id, const void* buf, size_t size)
{
    ObserverConstIterator it = FindObserver(id);
    if (it == observers_.end()) return oNOT_FOUND;
    return SetData(*it, buf, size);
}

OStatus OSubject::SetData(const OShmPtrBase& ptr)
{
    if (ptr.RCRPtr() == 0) return oINVALID_ARG;
    return SetData(ptr.RCRPtr());
}

OStatus OSubject::SetData(const OObserverInfo& info, const OShmPtrBase& ptr)
{
    if (ptr.RCRPtr() == 0) return oINVALID_ARG;
    return SetData(info, ptr.RCRPtr());
}

OStatus OSubject::SetData(const ObserverID& id, const OShmPtrBase& ptr)
{
    if (ptr.RCRPtr() == 0) return oINVALID_ARG;
    return SetData(id, ptr.RCRPtr());
}

/* ---- notification (2.8.3) ---- */

// Sends whole pending units, oldest first, at most MAX_NUM_DATA regions, if the observer
// asserted ready and at least d_min units wait.
static OStatus sendNotify(const SubjectID& self, ONotifyMessage* m, _OObserverInfo* o)
{
    if (o->ready_flag <= 0 || o->n_notify < (int)o->d_min || o->queue.empty()) return oSUCCESS;
    m->msgType = omsgNOTIFY_V22;
    m->subjectID = self;
    m->Clear();
    std::vector<RCRegion*>& q = o->queue;
    size_t pos = 0;
    int units = 0;
    int regions = 0;
    while (pos < q.size()) {
        size_t end = pos;
        while (end < q.size() && q[end] != OBJCOMM_END_MARKER) end++;
        if (end == q.size()) break;   // unfinished unit
        int count = (int)(end - pos);
        if (regions + count > MAX_NUM_DATA) break;
        for (size_t i = pos; i < end; i++) m->Write(q[i]);
        regions += count;
        units++;
        pos = end + 1;
    }
    if (units == 0) return oSUCCESS;
    m->numOfNotify = (short)units;

    const openr_host_api* api = openr_host();
    if (api == 0 || api->send(o->id.GetOID().GetAddress(), o->id.GetSelector(), m,
                              sizeof(ONotifyMessage)) != 0) {
        OSYSLOG1((osyslogERROR, "OSubject : cannot send a notification to an observer"));
        return oFAIL;
    }
    // The references taken by SetData now travel with the message; the observer's next
    // ASSERT/DEASSERT-READY returns them.
    q.erase(q.begin(), q.begin() + pos);
    o->n_data = (int)q.size();
    o->n_notify -= units;
    o->ready_flag = 0;
    return oSUCCESS;
}

OStatus OSubject::NotifyObserver(const OObserverInfo& info)
{
    _OObserverInfo* o = rec(info);
    if (o == 0) return oINVALID_ARG;
    if (o->skip_counter < o->d_skip) {
        o->skip_counter++;
    } else {
        o->skip_counter = 0;
    }
    if (o->queue.empty() || o->queue.back() == OBJCOMM_END_MARKER) return oSUCCESS;
    o->queue.push_back(OBJCOMM_END_MARKER);
    o->n_data = (int)o->queue.size();
    o->n_notify++;
    return sendNotify(id_, notifyMessage_, o);
}

OStatus OSubject::NotifyObserver(const ObserverID& id)
{
    ObserverConstIterator it = FindObserver(id);
    if (it == observers_.end()) return oNOT_FOUND;
    return NotifyObserver(*it);
}

OStatus OSubject::NotifyObservers()
{
    OStatus result = oSUCCESS;
    for (std::list<OObserverInfo>::iterator it = observers_.begin(); it != observers_.end(); ++it) {
        OStatus st = NotifyObserver(*it);
        if (st != oSUCCESS) result = st;
    }
    return result;
}

/* ---- buffer state ---- */

size_t OSubject::RemainBuffer(const OObserverInfo& info) const
{
    _OObserverInfo* o = rec(info);
    if (o == 0) return 0;
    long remain = (long)o->q_size - (long)o->n_data - 1;
    return remain > 0 ? (size_t)remain : 0;
}

size_t OSubject::RemainBuffer(const ObserverID& id) const
{
    ObserverConstIterator it = FindObserver(id);
    if (it == observers_.end()) return 0;
    return RemainBuffer(*it);
}

size_t OSubject::RemainBuffer() const
{
    if (observers_.empty()) return 0;
    size_t least = (size_t)-1;
    for (std::list<OObserverInfo>::const_iterator it = observers_.begin(); it != observers_.end(); ++it) {
        size_t r = RemainBuffer(*it);
        if (r < least) least = r;
    }
    return least;
}

OStatus OSubject::ClearBuffer(const OObserverInfo& info)
{
    _OObserverInfo* o = rec(info);
    if (o == 0) return oINVALID_ARG;
    clearQueue(o);
    return oSUCCESS;
}

OStatus OSubject::ClearBuffer(const ObserverID& id)
{
    ObserverConstIterator it = FindObserver(id);
    if (it == observers_.end()) return oNOT_FOUND;
    return ClearBuffer(*it);
}

OStatus OSubject::ClearBuffer()
{
    for (std::list<OObserverInfo>::iterator it = observers_.begin(); it != observers_.end(); ++it) {
        clearQueue(rec(*it));
    }
    return oSUCCESS;
}

/* ---- protocol handlers (2.8.1, 2.8.2) ---- */

OStatus OSubject::ControlHandler(const OControlMessage& msg, OStatus status)
{
    if (msg.msgType == omsgCONTROL_V21) {
        OSYSLOG1((osyslogERROR, "OSubject::ControlHandler() : objcomm version 2.1 observers "
                  "are not supported"));
        return oFAIL;
    }
    if (msg.msgType != omsgCONTROL) return oWRONG_MESSAGE;

    bool self = false;
    bool add = false;
    switch (msg.command) {
    case objcommCMD_ADDOBSERVER_SELF:    self = true; add = true; break;
    case objcommCMD_ADDOBSERVER_V22:
    case objcommCMD_ADDOBSERVER:         add = true; break;
    case objcommCMD_REMOVEOBSERVER_SELF: self = true; break;
    case objcommCMD_REMOVEOBSERVER_V22:
    case objcommCMD_REMOVEOBSERVER:      break;
    default:
        return oUNKNOWN_COMMAND;
    }

    OStatus result = status;
    if (add) {
        if (status != oSUCCESS) {
            OSYSLOG1((osyslogWARNING, "OSubject::ControlHandler() : observer refused (%s)",
                      msg.subName));
        } else {
            ObserverConstIterator found = FindObserver(msg.observerID);
            _OObserverInfo* o = found != observers_.end() ? rec(*found) : new _OObserverInfo();
            o->id = msg.observerID;
            o->d_skip = msg.d_skip;
            o->d_min = msg.d_min;
            o->d_max = msg.d_max;
            o->ready_flag = 0;
            o->n_notify = 0;
            o->n_data = 0;
            o->skip_counter = 0;
            if (maxBufferSize_ > 0) {
                o->q_size = maxBufferSize_;
            } else {
                size_t want = msg.d_max * (notifyUnitSize_ + 1);
                o->q_size = want > kMinQueueSize ? want : kMinQueueSize;
            }
            o->version = msg.command == objcommCMD_ADDOBSERVER ? objcommVERSION10 : objcommVERSION22;
            if (found == observers_.end()) {
                o->queue.reserve(o->q_size);
                observers_.push_back(OObserverInfo(o));
            }
        }
    } else if (status == oSUCCESS) {
        result = oNOT_FOUND;
        for (std::list<OObserverInfo>::iterator it = observers_.begin(); it != observers_.end(); ++it) {
            if (rec(*it)->id == msg.observerID) {
                clearQueue(rec(*it));
                delete rec(*it);
                observers_.erase(it);
                result = oSUCCESS;
                break;
            }
        }
    }

    OControlReplyMessage reply(result, id_, objcommVERSION22);
    if (self) {
        if (objcommSelfReply != 0) *objcommSelfReply = reply;
    } else {
        const openr_host_api* api = openr_host();
        if (api != 0) api->reply(&reply, sizeof(reply));
    }
    return result;
}

OStatus OSubject::ControlHandler(OControlMessage* msg)
{
    if (msg == 0) return oINVALID_ARG;
    return ControlHandler(*msg, oSUCCESS);
}

OStatus OSubject::ReadyHandler(const OReadyMessage& msg)
{
    if (msg.msgType == omsgREADY_V21) {
        OSYSLOG1((osyslogERROR, "OSubject::ReadyHandler() : objcomm version 2.1 observers "
                  "are not supported"));
        return oFAIL;
    }
    if (msg.msgType != omsgREADY_V22) return oWRONG_MESSAGE;

    OStatus result = oSUCCESS;
    ObserverConstIterator it = FindObserver(msg.observerID);
    if (it == observers_.end()) {
        result = oNOT_FOUND;
    } else {
        _OObserverInfo* o = rec(*it);
        if (msg.command == objcommCMD_ASSERT_READY) {
            o->ready_flag = 1;
            sendNotify(id_, notifyMessage_, o);
        } else if (msg.command == objcommCMD_DEASSERT_READY) {
            o->ready_flag = -1;
            clearQueue(o);
        }
    }
    // The observer returns the regions it received from us: drop their references
    // (also for an observer that is gone, so nothing leaks).
    int n = msg.numOfData < MAX_NUM_DATA ? msg.numOfData : MAX_NUM_DATA;
    for (int i = 0; i < n; i++) {
        if (msg.rcRegion[i] != 0) msg.rcRegion[i]->RemoveReference();
    }
    return result;
}

OStatus OSubject::ReadyHandler(OReadyMessage* msg)
{
    if (msg == 0) return oINVALID_ARG;
    return ReadyHandler(*msg);
}

/* ---- observers ---- */

int OSubject::NumberOfObservers() const
{
    return (int)observers_.size();
}

ObserverConstIterator OSubject::begin() const
{
    return observers_.begin();
}

ObserverConstIterator OSubject::end() const
{
    return observers_.end();
}

ObserverConstIterator OSubject::FindObserver(const ObserverID& id) const
{
    for (ObserverConstIterator it = observers_.begin(); it != observers_.end(); ++it) {
        if (rec(*it)->id == id) return it;
    }
    return observers_.end();
}

int OSubject::ReadyStatus(const OObserverInfo& info) const
{
    _OObserverInfo* o = rec(info);
    return o != 0 ? o->ready_flag : 0;
}

int OSubject::ReadyStatus(const ObserverID& id) const
{
    ObserverConstIterator it = FindObserver(id);
    return it != observers_.end() ? rec(*it)->ready_flag : 0;
}

int OSubject::IsAllReady() const
{
    int asserted = 0;
    for (ObserverConstIterator it = observers_.begin(); it != observers_.end(); ++it) {
        int flag = rec(*it)->ready_flag;
        if (flag == 0) return 0;
        if (flag > 0) asserted++;
    }
    return asserted;
}

int OSubject::IsAnyReady() const
{
    int asserted = 0;
    for (ObserverConstIterator it = observers_.begin(); it != observers_.end(); ++it) {
        if (rec(*it)->ready_flag > 0) asserted++;
    }
    return asserted;
}

int OSubject::IsReady() const
{
    return IsAnyReady();
}

int OSubject::IsReady(const OObserverInfo& info) const
{
    return ReadyStatus(info) > 0 ? 1 : 0;
}

int OSubject::IsReady(const ObserverID& id) const
{
    return ReadyStatus(id) > 0 ? 1 : 0;
}
