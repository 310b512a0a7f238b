/*
 * OPENR/OObserver.h - receiving side of inter-object communication
 * (object-model 2.7, 2.8). Implemented by the runtime library.
 */
#ifndef _OObserver_h_DEFINED
#define _OObserver_h_DEFINED

#include <iostream>
#include <list>
#include <Types.h>
#include <OPENR/OPENR.h>
#include <OPENR/ObjcommTypes.h>
#include <OPENR/ObjcommMessages.h>
#include <OPENR/ObjcommEvent.h>
#include <OPENR/DataManager.h>
#include <OPENR/MemoryMapAgent.h>
#include <OPENR/OSubjectInfo.h>

using std::cout;
using std::endl;
using std::list;

class OObserver {
public:
    OObserver();
    virtual ~OObserver();

    OStatus SetNotifyEntry(const OServiceEntry& entry);

    void SetSkip(size_t skip) { d_skip_ = skip; }
    void SetBufCtrlParam(size_t skip, size_t dmin, size_t dmax) {
        d_skip_ = skip;
        d_min_  = dmin;
        d_max_  = dmax;
    }

    OStatus ConnectHandler(const OConnectMessage& msg, OStatus status = oSUCCESS);
    OStatus ConnectHandler(OConnectMessage* msg);
    OStatus NotifyHandler(const ONotifyMessage& msg, ONotifyEvent* event);
    OStatus NotifyHandler(ONotifyMessage* msg, ONotifyEvent* event);

    OStatus AssertReady();
    OStatus DeassertReady();
    OStatus AssertReady(const SubjectID& id);
    OStatus DeassertReady(const SubjectID& id);
    OStatus AssertReady(const OSubjectInfo& info);
    OStatus DeassertReady(const OSubjectInfo& info);

    SubjectConstIterator begin() const;
    SubjectConstIterator end() const;
    SubjectID            FindSender(RCRegion* region) const;
    int                  NumberOfSubjects() const;

    const ObserverID& GetID() const;
    const ObserverID& GetObserverID() const;   /* legacy name of GetID() */

    /* Host extension (not in Sony's API), for system observers that finish the data of
       one notification piece by piece, as the effector and speaker do (robot-api 8.2.3):
       releases one received region and sends ASSERT-READY returning only that region
       to its subject. */
    OStatus AssertReadyFor(RCRegion* received);

private:
    OObserver(const OObserver&);
    OObserver& operator=(const OObserver&);

    ObserverID               id_;
    size_t                   d_skip_;   /* default 0 */
    size_t                   d_min_;    /* default 1 */
    size_t                   d_max_;    /* default 1 */
    std::list<OSubjectInfo>  subjects_;
    DataManager*             dataManager_;
    MemoryMapAgent*          memoryMapAgent_;
    OReadyMessage*           readyMessage_;
};

#endif /* _OObserver_h_DEFINED */
