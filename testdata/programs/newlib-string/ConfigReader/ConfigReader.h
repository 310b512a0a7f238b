//
// ConfigReader.h
//

#ifndef ConfigReader_h_DEFINED
#define ConfigReader_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class ConfigReader : public OObject {
public:
    ConfigReader();
    virtual ~ConfigReader() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void Apply(char* key, char* value);

    char name[16];
    char team[8];
    char mode[6];     // deliberately short: strlcpy truncates
    int  player;
};

#endif // ConfigReader_h_DEFINED
