/*
 * openr_host.h - the private ABI between an OPEN-R object (.BIN) and the cargo-openr
 * runtime that loads it.  Not an OPEN-R header: programs never include it.
 *
 * The runtime defines one exported table, `openr_runtime_api_v1`; the archives in
 * OPEN_R/lib find it with dlsym(RTLD_DEFAULT) the first time they need it, so it is
 * usable from static constructors that run inside dlopen().  Every call identifies the
 * calling object by its thread (one thread per object), so no context pointer is passed.
 * When no runtime is present (a .BIN loaded by another program) the table is absent and
 * the wrappers behave like plain libc.
 */
#ifndef OPENR_HOST_H
#define OPENR_HOST_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OPENR_HOST_ABI_VERSION 1

struct openr_host_api {
    unsigned int abi_version;      /* OPENR_HOST_ABI_VERSION */
    unsigned int size;             /* sizeof(struct openr_host_api) of the runtime */

    /* Maps an object-visible path (/MS/...) to a host path in `out`.  `create` != 0
     * allows the last component to be missing (it is then named in upper case).
     * Returns 0, or -1 with errno set (ENOENT outside /MS, EACCES on escape). */
    int (*map_path)(const char* path, int create, char* out, size_t out_len);

    /* exit() inside an object: stops that object only.  Does not return. */
    void (*object_exit)(int status);
};

/* Returns the runtime's table, or NULL when the object runs outside cargo-openr. */
const struct openr_host_api* openr_host(void);

#ifdef __cplusplus
}
#endif

#endif /* OPENR_HOST_H */
