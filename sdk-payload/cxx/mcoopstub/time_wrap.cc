// time_wrap.cc - sleeps inside objects follow the runtime's virtual clock (mkbin wraps
// usleep, sleep and nanosleep), so a run at --speed max or while paused keeps the
// program's own timing in step with the robot's.
#include <errno.h>
#include <time.h>
#include <unistd.h>

#include "openr_host.h"

extern "C" {
int __real_usleep(useconds_t);
unsigned int __real_sleep(unsigned int);
int __real_nanosleep(const struct timespec*, struct timespec*);

int __wrap_usleep(useconds_t usec)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return __real_usleep(usec);
    api->sleep_ns(static_cast<unsigned long long>(usec) * 1000ULL);
    return 0;
}

unsigned int __wrap_sleep(unsigned int seconds)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return __real_sleep(seconds);
    api->sleep_ns(static_cast<unsigned long long>(seconds) * 1000000000ULL);
    return 0;
}

int __wrap_nanosleep(const struct timespec* req, struct timespec* rem)
{
    const openr_host_api* api = openr_host();
    if (api == 0) return __real_nanosleep(req, rem);
    if (req == 0 || req->tv_nsec < 0 || req->tv_nsec >= 1000000000L || req->tv_sec < 0) {
        errno = EINVAL;
        return -1;
    }
    api->sleep_ns(static_cast<unsigned long long>(req->tv_sec) * 1000000000ULL + req->tv_nsec);
    if (rem != 0) rem->tv_sec = rem->tv_nsec = 0;
    return 0;
}
}
