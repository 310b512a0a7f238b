// strlcpy - BSD/newlib bounded copy: copies at most size-1 bytes, always terminates
// (if size > 0), returns strlen(src). glibc has it only from 2.38.
#include <Types.h>

#if defined(__GLIBC__) && !__GLIBC_PREREQ(2, 38)
extern "C" size_t strlcpy(char* dst, const char* src, size_t size)
{
    size_t len = strlen(src);
    if (size > 0) {
        size_t n = len < size - 1 ? len : size - 1;
        memcpy(dst, src, n);
        dst[n] = '\0';
    }
    return len;
}
#endif
