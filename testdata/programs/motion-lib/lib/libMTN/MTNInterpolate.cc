//
// MTNInterpolate.cc
//

#include "MTNFile.h"

slongword
MTNInterpolate(slongword from, slongword to, int step, int numSteps)
{
    if (numSteps <= 0) return to;
    return from + step * ((to - from) / numSteps);
}
