// apsys.cc - raw console and file I/O of apsys.h (object-model 3).
//
// fd 1 and 2 are the console: a write goes out in one piece through the runtime, so it
// is never interleaved with other objects' messages.  Other descriptors (fd 0 = stdin
// included) are plain read(2)/write(2).
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <apsys.h>

#include "openr_host.h"

namespace {

void consoleWrite(const char* text, size_t len)
{
    const openr_host_api* api = openr_host();
    if (api != 0) {
        api->console_write(text, len);
    } else {
        fflush(stdout);
        fwrite(text, 1, len, stdout);
        fflush(stdout);
    }
}

} // namespace

extern "C" {

int apsysWrite(int fd, const void* buf, int size)
{
    if (size < 0 || (buf == 0 && size > 0)) return -1;
    if (fd == 1 || fd == 2) {
        consoleWrite(static_cast<const char*>(buf), (size_t)size);
        return size;
    }
    ssize_t n;
    do {
        n = write(fd, buf, (size_t)size);
    } while (n < 0 && errno == EINTR);
    return (int)n;
}

int apsysRead(int fd, void* buf, int size)
{
    if (size < 0 || (buf == 0 && size > 0)) return -1;
    if (fd == 0) fflush(stdout);   // show a prompt before blocking on input
    ssize_t n;
    do {
        n = read(fd, buf, (size_t)size);
    } while (n < 0 && errno == EINTR);
    return (int)n;
}

void apsysPut(const char* str)
{
    if (str != 0) consoleWrite(str, strlen(str));
}

void apsysPutHex(unsigned int value)
{
    char buf[16];
    int n = snprintf(buf, sizeof(buf), "%08x", value);
    consoleWrite(buf, (size_t)n);
}

} // extern "C"
