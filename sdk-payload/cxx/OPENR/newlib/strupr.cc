// strupr - newlib's in-place upper-casing of a string.
#include <Types.h>

extern "C" char* strupr(char* s)
{
    for (char* p = s; *p != '\0'; p++) *p = (char)toupper((unsigned char)*p);
    return s;
}
