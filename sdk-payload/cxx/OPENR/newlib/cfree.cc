// cfree - newlib's (and old glibc's) alias of free.
#include <Types.h>

#if defined(__GLIBC__) && __GLIBC_PREREQ(2, 26)
extern "C" void cfree(void* p)
{
    free(p);
}
#endif
