// fs_wrap.cc - the libc calls mkbin redirects with -Wl,--wrap (object-model 1.5, 5.6).
//
// Objects see the Memory Stick as /MS/...: the runtime executable defines every
// path-taking libc entry point and maps (or refuses) the calls that come from objects
// and the libraries working for them (sdk-runtime/src/interpose).  The path wrappers
// here only hand on to those (__real_open binds to the runtime's open first), so a call
// is mapped exactly once, whichever way it comes.  readdir gives FAT's upper-case names,
// strtok gets per-thread state because all objects share one C library, and exit()
// stops only the calling object.
#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "openr_host.h"

extern "C" {
int __real_open(const char*, int, ...);
int __real_open64(const char*, int, ...);
int __real_creat(const char*, mode_t);
FILE* __real_fopen(const char*, const char*);
FILE* __real_fopen64(const char*, const char*);
FILE* __real_freopen(const char*, const char*, FILE*);
int __real_stat(const char*, struct stat*);
int __real_lstat(const char*, struct stat*);
int __real_stat64(const char*, struct stat64*);
int __real_lstat64(const char*, struct stat64*);
int __real_access(const char*, int);
DIR* __real_opendir(const char*);
struct dirent* __real_readdir(DIR*);
int __real_mkdir(const char*, mode_t);
int __real_rmdir(const char*);
int __real_unlink(const char*);
int __real_remove(const char*);
int __real_rename(const char*, const char*);
int __real_truncate(const char*, off_t);
char* __real_strtok(char*, const char*);
void __real_exit(int) __attribute__((noreturn));
}

namespace {

mode_t mode_arg(int flags, va_list ap)
{
    // The robot ignores the mode; the host needs one for O_CREAT.
    return (flags & O_CREAT) != 0 ? static_cast<mode_t>(va_arg(ap, int)) : 0666;
}

} // namespace

extern "C" {

int __wrap_open(const char* path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_arg(flags, ap);
    va_end(ap);
    return __real_open(path, flags, mode);
}

int __wrap_open64(const char* path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_arg(flags, ap);
    va_end(ap);
    return __real_open64(path, flags, mode);
}

int __wrap_creat(const char* path, mode_t mode) { return __real_creat(path, mode); }
FILE* __wrap_fopen(const char* path, const char* mode) { return __real_fopen(path, mode); }
FILE* __wrap_fopen64(const char* path, const char* mode) { return __real_fopen64(path, mode); }
FILE* __wrap_freopen(const char* path, const char* mode, FILE* f) { return __real_freopen(path, mode, f); }
int __wrap_stat(const char* path, struct stat* st) { return __real_stat(path, st); }
int __wrap_lstat(const char* path, struct stat* st) { return __real_lstat(path, st); }
int __wrap_stat64(const char* path, struct stat64* st) { return __real_stat64(path, st); }
int __wrap_lstat64(const char* path, struct stat64* st) { return __real_lstat64(path, st); }
int __wrap_access(const char* path, int how) { return __real_access(path, how); }
DIR* __wrap_opendir(const char* path) { return __real_opendir(path); }
int __wrap_mkdir(const char* path, mode_t mode) { return __real_mkdir(path, mode ? mode : 0777); }
int __wrap_rmdir(const char* path) { return __real_rmdir(path); }
int __wrap_unlink(const char* path) { return __real_unlink(path); }
int __wrap_remove(const char* path) { return __real_remove(path); }
int __wrap_rename(const char* from, const char* to) { return __real_rename(from, to); }
int __wrap_truncate(const char* path, off_t len) { return __real_truncate(path, len); }

struct dirent* __wrap_readdir(DIR* dir)
{
    struct dirent* e = __real_readdir(dir);
    // FAT stores names upper case; objects compare against upper-case 8.3 names.
    if (e != 0 && openr_host() != 0)
        for (char* c = e->d_name; *c; ++c) *c = static_cast<char>(toupper(static_cast<unsigned char>(*c)));
    return e;
}

char* __wrap_strtok(char* s, const char* delim)
{
    // One strtok state per object thread (the robot gave each object its own libc).
    static __thread char* save;
    return strtok_r(s, delim, &save);
}

void __wrap_exit(int status)
{
    const struct openr_host_api* api = openr_host();
    if (api != 0 && api->object_exit != 0) api->object_exit(status);
    __real_exit(status);
}

} // extern "C"
