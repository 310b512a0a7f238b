/*
 * OPENR/DataManager.h - observer-side record of received regions: which
 * local region came from which subject region (used by OObserver to return
 * regions on the next ASSERT/DEASSERT). Implemented by the runtime library.
 */
#ifndef _DataManager_h_DEFINED
#define _DataManager_h_DEFINED

#include <list>
#include <Types.h>
#include <OPENR/OPENR.h>
#include <OPENR/ObjcommTypes.h>
#include <OPENR/RCRegion.h>

class DataManager {
public:
    struct Record {
        SubjectID subject;
        RCRegion* local;    /* observer-side region */
        RCRegion* source;   /* the subject's region (srcRCR) */
    };

    DataManager();
    ~DataManager();

    OStatus   Add(const SubjectID& subject, RCRegion* local, RCRegion* source);
    /* Removes every record of `subject`, releases the local regions and
       stores up to `max` source pointers; returns how many were stored. */
    int       Collect(const SubjectID& subject, RCRegion** sources, int max);
    SubjectID FindSender(RCRegion* local) const;
    /* Removes the record of one observer-side region, releases it and returns its
       subject and source pointer (host extension for system observers). */
    bool      CollectOne(RCRegion* local, SubjectID* subject, RCRegion** source);
    void      Clear();

private:
    DataManager(const DataManager&);
    DataManager& operator=(const DataManager&);

    std::list<Record> records_;
};

#endif /* _DataManager_h_DEFINED */
