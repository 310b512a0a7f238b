//
// Gain.cc
//

#include "Gain.h"

short Clip<short>(short v)
{
    return (v < 0) ? 0 : ((v > Range<short>::Max()) ? Range<short>::Max() : v);
}
