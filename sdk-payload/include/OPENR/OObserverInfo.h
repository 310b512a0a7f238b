/*
 * OPENR/OObserverInfo.h - a connected observer as seen by a subject: an
 * opaque handle to the subject's per-observer record (_OObserverInfo, owned
 * by the runtime library).
 */
#ifndef _OObserverInfo_h_DEFINED
#define _OObserverInfo_h_DEFINED

#include <OPENR/ObjcommTypes.h>
#include <OPENR/RCRegion.h>

struct _OObserverInfo;   /* defined by the runtime library */

class OObserverInfo {
public:
    OObserverInfo() : info_(0) {}
    explicit OObserverInfo(_OObserverInfo* info) : info_(info) {}

    const ObserverID& GetObserverID() const;   /* runtime library */

    _OObserverInfo* GetInfo() const { return info_; }
    bool IsValid() const { return info_ != 0; }

    bool operator==(const OObserverInfo& o) const { return info_ == o.info_; }
    bool operator!=(const OObserverInfo& o) const { return info_ != o.info_; }

private:
    _OObserverInfo* info_;
};

typedef OObserverInfo ObserverInfo;   /* legacy name */

typedef std::list<OObserverInfo>::iterator       ObserverIterator;
typedef std::list<OObserverInfo>::const_iterator ObserverConstIterator;

#endif /* _OObserverInfo_h_DEFINED */
