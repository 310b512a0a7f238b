//
// Calib.h
//

#ifndef Calib_h_DEFINED
#define Calib_h_DEFINED

#include <stdexcept>
#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class Calib : public OObject {
public:
    Calib();
    virtual ~Calib() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    void LoadCalibration();

    double offset[3];   // joint offsets read from CALIB.DAT, in degrees
};

#endif // Calib_h_DEFINED
