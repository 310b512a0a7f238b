//
// LegKin.h
//

#ifndef LegKin_h_DEFINED
#define LegKin_h_DEFINED

#include <OPENR/OObject.h>
#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include "def.h"

class LegKin : public OObject {
public:
    LegKin();
    virtual ~LegKin() {}

    OSubject*  subject[numOfSubject];
    OObserver* observer[numOfObserver];

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

private:
    // A 2-link leg in the sagittal plane (upper leg, lower leg, in mm).
    void ForwardKinematics(double shoulderDeg, double kneeDeg, double* x, double* z);
};

#endif // LegKin_h_DEFINED
