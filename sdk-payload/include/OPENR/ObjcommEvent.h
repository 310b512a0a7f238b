/*
 * OPENR/ObjcommEvent.h - events passed to the Connect, Control, Ready and
 * Notify functions of a core class (object-model 2.4).
 * The destructors of OReadyEvent, OConnectEvent and OControlEvent are
 * defined by the runtime library.
 */
#ifndef _ObjcommEvent_h_DEFINED
#define _ObjcommEvent_h_DEFINED

#include <OPENR/ObjcommTypes.h>
#include <OPENR/ObjcommMessages.h>
#include <OPENR/OSubjectInfo.h>

/* subject side: an observer asserted or deasserted ready */
class OReadyEvent {
public:
    OReadyEvent(int index, ObserverID id, ObjcommCommand command)
        : index_(index), observerID_(id), command_(command) {}
    ~OReadyEvent();

    int               SbjIndex() const { return index_; }
    const ObserverID& SenderID() const { return observerID_; }
    bool IsAssert() const { return command_ == objcommCMD_ASSERT_READY; }
    bool IsDeassert() const { return command_ == objcommCMD_DEASSERT_READY; }

private:
    int            index_;
    ObserverID     observerID_;
    ObjcommCommand command_;
};

/* observer side: the service manager connects/disconnects a subject */
class OConnectEvent {
public:
    OConnectEvent(int index, char* name, OConnectCmd command)
        : index_(index), name_(name), command_(command) {}
    ~OConnectEvent();

    int         ObsIndex() const { return index_; }
    const char* SubName() const { return name_; }
    bool IsConnect() const { return command_ == oconnectcmdCONNECT; }
    bool IsDisconnect() const {
        return command_ == oconnectcmdDISCONNECT || command_ == oconnectcmdDISCONNECTALL;
    }

private:
    int         index_;
    char*       name_;
    OConnectCmd command_;
};

/* subject side: an observer asks to be added/removed */
class OControlEvent {
public:
    OControlEvent(int index, char* name, ObjcommCommand command)
        : index_(index), observerID_(), name_(name), command_(command) {}
    OControlEvent(int index, ObserverID id, char* name, ObjcommCommand command)
        : index_(index), observerID_(id), name_(name), command_(command) {}
    ~OControlEvent();

    int               SbjIndex() const { return index_; }
    const char*       SubName() const { return name_; }
    const ObserverID& SenderID() const { return observerID_; }

    /* Host deviation: the 2.2 protocol delivers 7 (or 5 for a self
       connection) for "add" and 8 (or 6) for "remove"; Sony compared with 1/2
       only. */
    bool IsAddObserver() const {
        return command_ == objcommCMD_ADDOBSERVER ||
               command_ == objcommCMD_ADDOBSERVER_SELF ||
               command_ == objcommCMD_ADDOBSERVER_V22;
    }
    bool IsRemoveObserver() const {
        return command_ == objcommCMD_REMOVEOBSERVER ||
               command_ == objcommCMD_REMOVEOBSERVER_SELF ||
               command_ == objcommCMD_REMOVEOBSERVER_V22;
    }

private:
    int            index_;
    ObserverID     observerID_;
    char*          name_;
    ObjcommCommand command_;
};

/* observer side: data arrived */
class ONotifyEvent {
public:
    ONotifyEvent() : index_(0), subjectInfo_(), numOfData_(0), numOfNotify_(0) {
        for (int i = 0; i < MAX_NUM_DATA; i++) data_[i] = 0;
    }

    void SetIndex(int index) { index_ = index; }
    void SetSubjectInfo(const OSubjectInfo& info) { subjectInfo_ = info; }
    void SetNumOfData(int n) { numOfData_ = n; }
    void SetNumOfNotify(int n) { numOfNotify_ = n; }
    void SetData(int i, RCRegion* r) {
        if (i >= 0 && i < MAX_NUM_DATA) data_[i] = r;
    }

    int                 ObsIndex() const { return index_; }
    const OSubjectInfo& SenderID() const { return subjectInfo_; }
    int                 NumOfData() const { return numOfData_; }
    int                 NumOfNotify() const { return numOfNotify_; }

    RCRegion* RCData(int i) const {
        if (i < 0 || i >= numOfData_ || i >= MAX_NUM_DATA) return 0;
        RCRegion* r = data_[i];
        if (r == 0 || r->NumberOfReference() <= 0) return 0;
        return r;
    }
    const void* Data(int i) const {
        RCRegion* r = RCData(i);
        return r != 0 ? (const void*)r->Base() : (const void*)0;
    }
    /* array of the Base() pointers; overwritten by the next call */
    const void** Data() const;   /* runtime library */

private:
    int          index_;
    OSubjectInfo subjectInfo_;
    int          numOfData_;
    int          numOfNotify_;
    RCRegion*    data_[MAX_NUM_DATA];
};

#endif /* _ObjcommEvent_h_DEFINED */
