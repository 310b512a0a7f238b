//
// Permissive.cc
//

#include "Permissive.h"

static int numServos = 0;

Servo::Servo(int i) : id(i)
{
    numServos++;
}

int
Servo::Id() const
{
    return id;
}

int
Servo::Scaled(int value, int scale = 2) const
{
    return value * scale;
}

int
ServoCount()
{
    return numServos;
}
