//
// Registry.cc
//

#include "Registry.h"

int Registry::instances = 0;

int
RegistryCount()
{
    return Registry::instances;
}
