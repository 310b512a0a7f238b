/*
 * OPENR/OSubjectInfo.h - a connected subject as seen by an observer:
 * its ID plus its protocol version.
 */
#ifndef _OSubjectInfo_h_DEFINED
#define _OSubjectInfo_h_DEFINED

#include <OPENR/ObjcommTypes.h>

class OSubjectInfo : public SubjectID {
public:
    OSubjectInfo() : SubjectID(), version_(objcommVERSION_UNDEF) {}
    OSubjectInfo(const SubjectID& id, ObjcommVersion version = objcommVERSION22)
        : SubjectID(id), version_(version) {}

    const SubjectID& GetSubjectID() const { return *this; }
    ObjcommVersion   GetVersion() const { return version_; }
    void Set(const SubjectID& id, ObjcommVersion version) {
        SubjectID::operator=(id);
        version_ = version;
    }
    void SetVersion(ObjcommVersion version) { version_ = version; }

private:
    ObjcommVersion version_;
};

typedef std::list<OSubjectInfo>::iterator       SubjectIterator;
typedef std::list<OSubjectInfo>::const_iterator SubjectConstIterator;

#endif /* _OSubjectInfo_h_DEFINED */
