//
// FileSys.h
//

#ifndef FileSys_h_DEFINED
#define FileSys_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class FileSys : public OObject {
public:
    FileSys();
    virtual ~FileSys() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void WriteWithStdio();
    void ReadWithPosix();
    void StatAndRename();
    void CaseInsensitiveNames();
    void Directories();
    void Streams();
    void ListDirectory();
    void EscapeAttempt();

    void Result(const char* step, bool ok);
};

#endif // FileSys_h_DEFINED
