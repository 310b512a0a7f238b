//
// Clock.cc : milliseconds since boot, from the OPEN-R system time.
//
// "int ::GetNowMSec()" declares a global function with a qualified name
// before any declaration of it: gcc 3.3 accepted it.
//

#include <MCOOP.h>

int ::GetNowMSec();

int ::GetNowMSec()
{
    SystemTime now;
    GetSystemTime(&now);
    return now.seconds * 1000 + now.useconds / 1000;
}
