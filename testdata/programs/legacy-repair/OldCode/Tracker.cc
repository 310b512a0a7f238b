//
// Tracker.cc
//

#include "Tracker.h"

Tracker::Tracker(double g) : gain(g)
{
}

void
Tracker::Track(double x, double y, double* delta_pan, double* delta_tilt)
{
    *delta_pan  = -x * gain;
    *delta_tilt = -y * gain;
}

void
Tracker::Limit(double max, double* delta_pan, double* delta_tilt) const
{
    if (*delta_pan  >  max) *delta_pan  =  max;
    if (*delta_pan  < -max) *delta_pan  = -max;
    if (*delta_tilt >  max) *delta_tilt =  max;
    if (*delta_tilt < -max) *delta_tilt = -max;
}
