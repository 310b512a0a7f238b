// strlwr - newlib's in-place lower-casing of a string (one archive member per function,
// so a program that defines its own strlwr still links).
#include <Types.h>

extern "C" char* strlwr(char* s)
{
    for (char* p = s; *p != '\0'; p++) *p = (char)tolower((unsigned char)*p);
    return s;
}
