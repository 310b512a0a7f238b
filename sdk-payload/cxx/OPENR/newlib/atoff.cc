// atoff - newlib's float atof.
#include <Types.h>

extern "C" float atoff(const char* s)
{
    return (float)atof(s);
}
