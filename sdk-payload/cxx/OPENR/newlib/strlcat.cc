// strlcat - BSD/newlib bounded append: the result holds at most size-1 bytes, returns
// the length it tried to create (strlen(src) + the initial length of dst, at most size).
#include <Types.h>

#if defined(__GLIBC__) && !__GLIBC_PREREQ(2, 38)
extern "C" size_t strlcat(char* dst, const char* src, size_t size)
{
    size_t dlen = strnlen(dst, size);
    if (dlen == size) return size + strlen(src);
    return dlen + strlcpy(dst + dlen, src, size - dlen);
}
#endif
