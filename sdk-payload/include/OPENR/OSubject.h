/*
 * OPENR/OSubject.h - sending side of inter-object communication
 * (object-model 2.6, 2.8). Implemented by the runtime library.
 * IsReady()/IsAnyReady()/IsAllReady() return counts, not booleans.
 */
#ifndef _OSubject_h_DEFINED
#define _OSubject_h_DEFINED

#include <Types.h>
#include <list>
#include <OPENR/OPENR.h>
#include <OPENR/ObjcommTypes.h>
#include <OPENR/ObjcommMessages.h>
#include <OPENR/OObserverInfo.h>
#include <OPENR/OShmPtr.h>
#include <OPENR/ObjcommEvent.h>

using std::cout;
using std::endl;
using std::list;

class OSubject {
public:
    OSubject();
    ~OSubject();

    OStatus          SetReadyEntry(const OServiceEntry& entry);
    const SubjectID& GetID() const;

    OStatus SetBufferSize(size_t size);
    size_t  GetBufferSize() const;
    OStatus SetNotifyUnitSize(size_t size);
    size_t  GetNotifyUnitSize() const;

    OStatus SetData(RCRegion* region);
    OStatus SetData(const OObserverInfo& info, RCRegion* region);
    OStatus SetData(const ObserverID& id, RCRegion* region);
    OStatus SetData(const void* buf, size_t size);
    OStatus SetData(const OObserverInfo& info, const void* buf, size_t size);
    OStatus SetData(const ObserverID& id, const void* buf, size_t size);
    OStatus SetData(const OShmPtrBase& ptr);
    OStatus SetData(const OObserverInfo& info, const OShmPtrBase& ptr);
    OStatus SetData(const ObserverID& id, const OShmPtrBase& ptr);
    /* legacy overloads: declared, not implemented (as on the robot) */
    OStatus SetData(MemoryRegionID memID, size_t offset, size_t size);
    OStatus SetData(const OObserverInfo& info, MemoryRegionID memID, size_t offset, size_t size);
    OStatus SetData(const ObserverID& id, MemoryRegionID memID, size_t offset, size_t size);
    OStatus SetData(const OMemoryLocator& locator);
    OStatus SetData(const OObserverInfo& info, const OMemoryLocator& locator);
    OStatus SetData(const ObserverID& id, const OMemoryLocator& locator);

    OStatus NotifyObserver(const OObserverInfo& info);
    OStatus NotifyObserver(const ObserverID& id);
    OStatus NotifyObservers();

    size_t  RemainBuffer(const OObserverInfo& info) const;
    size_t  RemainBuffer(const ObserverID& id) const;
    size_t  RemainBuffer() const;

    OStatus ClearBuffer(const OObserverInfo& info);
    OStatus ClearBuffer(const ObserverID& id);
    OStatus ClearBuffer();

    OStatus ControlHandler(const OControlMessage& msg, OStatus status = oSUCCESS);
    OStatus ControlHandler(OControlMessage* msg);
    OStatus ReadyHandler(const OReadyMessage& msg);
    OStatus ReadyHandler(OReadyMessage* msg);

    int NumberOfObservers() const;
    ObserverConstIterator begin() const;
    ObserverConstIterator end() const;
    ObserverConstIterator FindObserver(const ObserverID& id) const;

    int ReadyStatus(const OObserverInfo& info) const;
    int ReadyStatus(const ObserverID& id) const;
    int IsAllReady() const;
    int IsAnyReady() const;
    int IsReady() const;
    int IsReady(const OObserverInfo& info) const;
    int IsReady(const ObserverID& id) const;

private:
    OSubject(const OSubject&);
    OSubject& operator=(const OSubject&);

    SubjectID                 id_;
    std::list<OObserverInfo>  observers_;
    ONotifyMessage*           notifyMessage_;
    size_t                    maxBufferSize_;    /* 0 = automatic */
    size_t                    notifyUnitSize_;   /* default 1 */
};

#endif /* _OSubject_h_DEFINED */
