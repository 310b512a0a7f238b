//
// Crash.h
//

#ifndef Crash_h_DEFINED
#define Crash_h_DEFINED

#include <OPENR/OObject.h>

class Crash : public OObject {
public:
    Crash();
    virtual ~Crash() {}

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    int  ReadFaultNumber();
    void CommitFault(int fault);
};

#endif // Crash_h_DEFINED
