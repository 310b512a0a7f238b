//
// Legacy.h
//

#ifndef Legacy_h_DEFINED
#define Legacy_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Legacy : public OObject {
public:
    Legacy();
    virtual ~Legacy() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    // gcc 3.3 accepted in-class initialisers for static const double.
    static const double kGain = 0.5;
    static const int    kMaxScale = 8;

    void ReadConfig();
    void AskName();
    void PointerRoundTrip();
    void ListDataDirectory();

    char name[32];
    int  count;
    int  scale[kMaxScale];
    int  numScale;
    int  askName;
    byte checksum;      // sum of all config bytes, modulo 256
};

#endif // Legacy_h_DEFINED
