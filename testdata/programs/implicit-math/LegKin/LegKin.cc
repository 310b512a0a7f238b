//
// LegKin.cc
//
// Leg kinematics of the kind every 2004 walking engine had, using sin, cos,
// tan, atan2, sqrt, fabs, M_PI and M_PI_2 -- and no #include <math.h>: with
// gcc 3.3 the OPEN-R and libstdc++ headers brought the math library along.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "LegKin.h"

static const double UPPER_LEG = 69.5;   // mm
static const double LOWER_LEG = 76.4;   // mm

static double deg2rad(double deg) { return deg * M_PI / 180.0; }
static double rad2deg(double rad) { return rad * 180.0 / M_PI; }

LegKin::LegKin()
{
}

OStatus
LegKin::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

void
LegKin::ForwardKinematics(double shoulderDeg, double kneeDeg, double* x, double* z)
{
    double a = deg2rad(shoulderDeg);
    double b = deg2rad(kneeDeg);
    *x = UPPER_LEG * sin(a) + LOWER_LEG * sin(a + b);
    *z = -(UPPER_LEG * cos(a) + LOWER_LEG * cos(a + b));
}

OStatus
LegKin::DoStart(const OSystemEvent& event)
{
    double x, z;
    ForwardKinematics(30.0, 45.0, &x, &z);
    double reach = sqrt(x * x + z * z);
    double angle = rad2deg(atan2(x, fabs(z)));
    OSYSPRINT(("LegKin : foot x = %.3f mm, z = %.3f mm\n", x, z));
    OSYSPRINT(("LegKin : reach = %.3f mm, angle = %.3f deg\n", reach, angle));

    // Slope of a 10 degree ramp and the step rise over 40 mm.
    double slope = tan(deg2rad(10.0));
    OSYSPRINT(("LegKin : tan(10 deg) = %.5f, rise over 40 mm = %.3f mm\n", slope, 40.0 * slope));

    double quarter = sin(M_PI_2) + cos(M_PI);
    OSYSPRINT(("LegKin : sin(pi/2) + cos(pi) = %.1f, fabs(-2.5) = %.1f\n", quarter, fabs(-2.5)));
    return oSUCCESS;
}

OStatus
LegKin::DoStop(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus
LegKin::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}
