// fs_wrap.cc - the libc calls mkbin redirects with -Wl,--wrap (object-model 1.5, 5.6).
//
// Objects see the Memory Stick as /MS/...: every path-taking call is mapped through the
// runtime (case-insensitive 8.3 names, confined to the stick).  strtok gets per-thread
// state because all objects share one C library.  exit() stops only the calling object.
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

// A mapped path, or the original one when no runtime is present.
class MappedPath {
public:
    MappedPath(const char* path, bool create) : path_(path), ok_(true)
    {
        const struct openr_host_api* api = openr_host();
        if (api == 0 || path == 0) return;
        if (api->map_path(path, create ? 1 : 0, buf_, sizeof buf_) != 0) {
            ok_ = false;
            return;
        }
        path_ = buf_;
    }
    bool ok() const { return ok_; }
    const char* c_str() const { return path_; }

private:
    const char* path_;
    bool ok_;
    char buf_[PATH_MAX];
};

bool creates(int flags) { return (flags & O_CREAT) != 0; }
bool creates(const char* mode) { return mode != 0 && (mode[0] == 'w' || mode[0] == 'a'); }

mode_t mode_arg(int flags, va_list ap)
{
    // The robot ignores the mode; the host needs one for O_CREAT.
    return creates(flags) ? static_cast<mode_t>(va_arg(ap, int)) : 0;
}

} // namespace

#define OPENR_MAP_OR_FAIL(var, path, create, failure) \
    MappedPath var(path, create);                      \
    if (!var.ok()) return failure

extern "C" {

int __wrap_open(const char* path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_arg(flags, ap);
    va_end(ap);
    OPENR_MAP_OR_FAIL(p, path, creates(flags), -1);
    return __real_open(p.c_str(), flags, mode ? mode : 0666);
}

int __wrap_open64(const char* path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    mode_t mode = mode_arg(flags, ap);
    va_end(ap);
    OPENR_MAP_OR_FAIL(p, path, creates(flags), -1);
    return __real_open64(p.c_str(), flags, mode ? mode : 0666);
}

int __wrap_creat(const char* path, mode_t mode)
{
    OPENR_MAP_OR_FAIL(p, path, true, -1);
    return __real_creat(p.c_str(), mode);
}

FILE* __wrap_fopen(const char* path, const char* mode)
{
    OPENR_MAP_OR_FAIL(p, path, creates(mode), 0);
    return __real_fopen(p.c_str(), mode);
}

FILE* __wrap_fopen64(const char* path, const char* mode)
{
    OPENR_MAP_OR_FAIL(p, path, creates(mode), 0);
    return __real_fopen64(p.c_str(), mode);
}

FILE* __wrap_freopen(const char* path, const char* mode, FILE* f)
{
    OPENR_MAP_OR_FAIL(p, path, creates(mode), 0);
    return __real_freopen(p.c_str(), mode, f);
}

int __wrap_stat(const char* path, struct stat* st)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_stat(p.c_str(), st);
}

int __wrap_lstat(const char* path, struct stat* st)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_lstat(p.c_str(), st);
}

int __wrap_stat64(const char* path, struct stat64* st)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_stat64(p.c_str(), st);
}

int __wrap_lstat64(const char* path, struct stat64* st)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_lstat64(p.c_str(), st);
}

int __wrap_access(const char* path, int how)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_access(p.c_str(), how);
}

DIR* __wrap_opendir(const char* path)
{
    OPENR_MAP_OR_FAIL(p, path, false, 0);
    return __real_opendir(p.c_str());
}

struct dirent* __wrap_readdir(DIR* dir)
{
    struct dirent* e = __real_readdir(dir);
    // FAT stores names upper case; objects compare against upper-case 8.3 names.
    if (e != 0 && openr_host() != 0)
        for (char* c = e->d_name; *c; ++c) *c = static_cast<char>(toupper(static_cast<unsigned char>(*c)));
    return e;
}

int __wrap_mkdir(const char* path, mode_t mode)
{
    OPENR_MAP_OR_FAIL(p, path, true, -1);
    return __real_mkdir(p.c_str(), mode ? mode : 0777);
}

int __wrap_rmdir(const char* path)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_rmdir(p.c_str());
}

int __wrap_unlink(const char* path)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_unlink(p.c_str());
}

int __wrap_remove(const char* path)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_remove(p.c_str());
}

int __wrap_rename(const char* from, const char* to)
{
    OPENR_MAP_OR_FAIL(a, from, false, -1);
    OPENR_MAP_OR_FAIL(b, to, true, -1);
    return __real_rename(a.c_str(), b.c_str());
}

int __wrap_truncate(const char* path, off_t len)
{
    OPENR_MAP_OR_FAIL(p, path, false, -1);
    return __real_truncate(p.c_str(), len);
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
